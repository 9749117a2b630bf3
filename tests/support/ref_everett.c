/* SPDX-License-Identifier: MIT */
#include "ref_everett.h"

#include <string.h>

double ref_everett_e(const hyst_everett_t *e, double a, double b)
{
    const double span = (double)e->hi - (double)e->lo;
    const double w = (a - b) / span, t = (b - (double)e->lo) / span;
    double sum = 0.0, w_i = 1.0;
    unsigned i, j;
    for (i = 1u; i <= e->degree; ++i) {
        double t_j = 1.0;
        w_i *= w; /* powers by products: pow() is most of the emulated tests' time */
        for (j = 0u; i + j <= e->degree; ++j) {
            sum += (double)e->e[i - 1u][j] * w_i * t_j;
            t_j *= t;
        }
    }
    return sum;
}

void ref_everett_init(ref_everett_t *r, const hyst_everett_t *e)
{
    r->e = e;
    r->fn = NULL;
    r->tx[0] = (double)e->lo;
    r->ty[0] = (double)e->y_lo;
    r->n = 1;
    r->x = (double)e->lo;
    r->y = (double)e->y_lo;
}

/* LTPs at even places (A0 first): rising iff the newest is one. */
static void push(ref_everett_t *r)
{
    if (r->n < REF_EVERETT_TPS) {
        r->tx[r->n] = r->x;
        r->ty[r->n++] = r->y;
    }
}

double ref_everett_step(ref_everett_t *r, double x)
{
    const int rising = (r->n - 1) % 2 == 0;
    if (x > r->x) {
        if (!rising) {
            push(r);
        }
        while (r->n >= 3 && x >= r->tx[r->n - 2]) {
            r->n -= 2;
        }
        r->y = r->ty[r->n - 1] + (r->fn != NULL ? r->fn(x, r->tx[r->n - 1])
                                                : ref_everett_e(r->e, x, r->tx[r->n - 1]));
    } else if (x < r->x) {
        if (rising) {
            push(r);
        }
        while (r->n >= 3 && x <= r->tx[r->n - 2]) {
            r->n -= 2;
        }
        r->y = r->ty[r->n - 1] - (r->fn != NULL ? r->fn(r->tx[r->n - 1], x)
                                                : ref_everett_e(r->e, r->tx[r->n - 1], x));
        if (x <= (double)r->e->lo) { /* every loop closed: back at A0, rising next */
            r->n = 1;
            r->y = (double)r->e->y_lo;
        }
    }
    r->x = x;
    return r->y;
}

hyst_everett_t ref_everett_random(rng_t *rng)
{
    hyst_everett_t e;
    unsigned i, j, t_max;
    const double scale = rng_range(rng, 0.5, 20.0);
    memset(&e, 0, sizeof e);
    e.degree = 1u + rng_below(rng, (unsigned)HYST_EVERETT_MAX_DEGREE);
    /* ends exact in float: the reference's domain is the instance's */
    e.lo = (hyst_wide_t)(float)rng_range(rng, -50.0, 50.0);
    e.hi = (hyst_wide_t)(float)((double)e.lo + rng_range(rng, 1.0, 100.0));
    e.y_lo = (hyst_wide_t)rng_range(rng, -10.0, 10.0);
    /* half of them at most linear in t, the identification's usual E (the
     * engine derives their branches by a shorter path) */
    t_max = rng_below(rng, 2u) == 0u ? 1u : e.degree;
    for (i = 1u; i <= e.degree; ++i) {
        for (j = 0u; i + j <= e.degree && j <= t_max; ++j) {
            e.e[i - 1u][j] = (hyst_wide_t)(scale * rng_range(rng, -1.5, 1.0) / (double)(i + j));
        }
    }
    e.e[0][0] = (hyst_wide_t)(scale * rng_range(rng, 1.0, 3.0));
    return e;
}

double ref_everett_walk(rng_t *rng, double *v, double lo, double hi)
{
    if (rng_below(rng, 10u) == 0u) {
        *v = rng_range(rng, lo, hi);
    } else {
        *v += (hi - lo) * rng_range(rng, -0.05, 0.05);
    }
    *v = *v < lo ? lo : (*v > hi ? hi : *v);
    return *v;
}

double ref_everett_response(const ref_everett_t *r, double x, ref_everett_t *scratch)
{
    scratch->e = r->e;
    scratch->fn = r->fn;
    scratch->n = r->n;
    scratch->x = r->x;
    scratch->y = r->y;
    memcpy(scratch->tx, r->tx, (size_t)r->n * sizeof r->tx[0]);
    memcpy(scratch->ty, r->ty, (size_t)r->n * sizeof r->ty[0]);
    return ref_everett_step(scratch, x);
}

double ref_everett_inverse(const ref_everett_t *r, double y, ref_everett_t *scratch)
{
    double a = r->e->lo, b = r->e->hi;
    int k;
    for (k = 0; k < 200 && b - a > 0.0; ++k) {
        const double m = 0.5 * (a + b);
        if (m <= a || m >= b) {
            break;
        }
        if (ref_everett_response(r, m, scratch) < y) {
            a = m;
        } else {
            b = m;
        }
    }
    return 0.5 * (a + b);
}
