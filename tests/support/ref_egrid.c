/* SPDX-License-Identifier: MIT */
#include "ref_egrid.h"

#include <string.h>

static double overlap(double lo1, double hi1, double lo2, double hi2)
{
    const double lo = lo1 > lo2 ? lo1 : lo2, hi = hi1 < hi2 ? hi1 : hi2;
    return hi > lo ? hi - lo : 0.0;
}

double ref_egrid_e(const hyst_everett_grid_t *g, double a, double b)
{
    double sum = 0.0;
    unsigned i, j;
    for (i = 0u; i < g->intervals; ++i) {
        const double ai = (double)g->knots[i], ai1 = (double)g->knots[i + 1u];
        for (j = 0u; j <= i; ++j) {
            const double bj = (double)g->knots[j], bj1 = (double)g->knots[j + 1u];
            const double w = (double)g->weight[i * (i + 1u) / 2u + j];
            if (w == 0.0) {
                continue; /* adds +0: skipped, the sum unchanged */
            }
            if (j < i) { /* a rectangle: a' in [b, a] of interval i, b' in [b, a] of interval j */
                const double da = overlap(ai, ai1, b, a), db = overlap(bj, bj1, b, a);
                if (da > 0.0 && db > 0.0) { /* otherwise adds +0 */
                    sum += w * da * db / ((ai1 - ai) * (bj1 - bj));
                }
            } else { /* a triangle: b <= b' <= a' <= a inside interval i */
                const double d = overlap(ai, ai1, b, a);
                sum += w * d * d / ((ai1 - ai) * (ai1 - ai));
            }
        }
    }
    return sum;
}

static const hyst_everett_grid_t *current;

static double current_e(double a, double b) { return ref_egrid_e(current, a, b); }

void ref_egrid_init(ref_everett_t *r, hyst_everett_t *domain, const hyst_everett_grid_t *g)
{
    memset(domain, 0, sizeof *domain);
    domain->degree = 1u;
    domain->lo = g->knots[0];
    domain->hi = g->knots[g->intervals];
    domain->y_lo = g->y_lo;
    current = g;
    ref_everett_init(r, domain);
    r->fn = current_e;
}

hyst_everett_grid_t ref_egrid_random(rng_t *rng, unsigned max_k)
{
    hyst_everett_grid_t g;
    const double scale = rng_range(rng, 0.5, 20.0);
    double x;
    unsigned i;
    memset(&g, 0, sizeof g);
    g.intervals = 1u + rng_below(rng, max_k);
    x = (double)(float)rng_range(rng, -50.0, 50.0);
    g.knots[0] = (hyst_wide_t)x;
    for (i = 1u; i <= g.intervals; ++i) {
        x += rng_range(rng, 0.3, 20.0);
        g.knots[i] = (hyst_wide_t)(float)x;
    }
    g.y_lo = (hyst_wide_t)rng_range(rng, -10.0, 10.0);
    for (i = 0u; i < HYST_EVERETT_GRID_CELLS(g.intervals); ++i) {
        const unsigned kind = rng_below(rng, 40u);
        g.weight[i] = (hyst_wide_t)(kind < 8u ? 0.0 : scale * rng_unit(rng) * (kind < 13u ? 10.0 : 1.0));
    }
    g.weight[0] += (hyst_wide_t)(scale * 0.1); /* a positive sum */
    return g;
}
