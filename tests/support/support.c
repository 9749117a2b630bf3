/* SPDX-License-Identifier: MIT */
#include "support.h"

#include <math.h>
#include <string.h>

const double paper_eq20_coeffs[4] = {-6.1876e-6, 1.1949e-3, 8.6444e-2, 5.8517e-1};

const hyst_poly_t paper_eq20 = {
    3u, HYST_REAL_C(0.0), HYST_REAL_C(40.0),
    {HYST_REAL_C(-6.1876e-6), HYST_REAL_C(1.1949e-3), HYST_REAL_C(8.6444e-2),
     HYST_REAL_C(5.8517e-1)}};

void rng_seed(rng_t *r, uint32_t seed)
{
    r->s = seed ? seed : 0x9E3779B9u;
}

uint32_t rng_u32(rng_t *r) /* xorshift32 */
{
    uint32_t x = r->s;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    r->s = x;
    return x;
}

double rng_unit(rng_t *r)
{
    return (double)(rng_u32(r) >> 8) / 16777216.0;
}

double rng_range(rng_t *r, double a, double b)
{
    return a + (b - a) * rng_unit(r);
}

uint32_t rng_below(rng_t *r, uint32_t n)
{
    return (uint32_t)(rng_unit(r) * (double)n);
}

hyst_real_t rng_walk(rng_t *r, double *x, double lo, double hi)
{
    const double next = *x + rng_range(r, -0.02, 0.02) * (hi - lo);
    *x = next < lo ? lo : next > hi ? hi : next;
    return (hyst_real_t)*x;
}

double dabs(double v) { return v < 0 ? -v : v; }

double real_ulp(double m)
{
    const hyst_real_t v = (hyst_real_t)m;
    return (double)(NEXT(v, REAL_INF) - v);
}

double rng_gauss(rng_t *r)
{
    const double u1 = 1.0 - rng_unit(r), u2 = rng_unit(r);
    return sqrt(-2.0 * log(u1)) * cos(6.283185307179586 * u2);
}

int paper_levels(double lo, double hi, double *levels)
{
    const double span = hi - lo;
    int n = 0;
    int k;
    for (k = 0; k < 7; ++k) { /* shrink: peaks hi, hi - s, ...; valleys lo + s, ... */
        levels[n++] = hi - span * 0.0625 * k;
        levels[n++] = lo + span * 0.0625 * (k + 1);
    }
    for (k = 6; k >= 0; --k) { /* grow back through the same levels */
        levels[n++] = hi - span * 0.0625 * k;
        if (k > 0) {
            levels[n++] = lo + span * 0.0625 * k;
        }
    }
    levels[n++] = lo;
    return n;
}

long ramp_path(double start, const double *levels, int n_levels, double step,
               hyst_real_t *out, long max)
{
    long count = 0;
    double at = start;
    int i;
    for (i = 0; i < n_levels; ++i) {
        const double target = levels[i];
        const double dist = target > at ? target - at : at - target;
        long steps = (long)(dist / step) + 1;
        long k;
        for (k = 1; k <= steps && count < max; ++k) {
            const double v = k == steps ? target : at + (target - at) * (double)k / (double)steps;
            out[count++] = (hyst_real_t)v;
        }
        at = target;
    }
    return count;
}

hyst_poly_t poly_monomial(unsigned degree, double lo, double hi)
{
    hyst_poly_t f = {0};
    f.degree = degree;
    f.lo = (hyst_real_t)lo;
    f.hi = (hyst_real_t)hi;
    f.coeffs[0] = 1;
    return f;
}

hyst_poly_t poly_random_increasing(rng_t *r, unsigned degree)
{
    hyst_poly_t f = {0};
    double scale = 1.0;
    unsigned j;
    f.degree = degree;
    f.lo = (hyst_real_t)rng_range(r, 0.0, 5.0);
    f.hi = (hyst_real_t)((double)f.lo + rng_range(r, 1.0, 4000.0));
    for (j = 0u; j <= degree; ++j) {
        f.coeffs[degree - j] = (hyst_real_t)(rng_range(r, 0.1, 2.0) / scale);
        scale *= (double)f.hi;
    }
    return f;
}

hyst_spline_t spline_random(rng_t *r, unsigned intervals, int flat, int steep, int zeros)
{
    hyst_spline_t f;
    const double lo = rng_range(r, -50.0, 50.0), span = rng_range(r, 0.5, 200.0);
    const double h = span / intervals;
    double step[HYST_SPLINE_MAX_INTERVALS];
    unsigned k;
    memset(&f, 0, sizeof f);
    f.intervals = intervals;
    f.lo = (hyst_wide_t)lo;
    f.hi = (hyst_wide_t)(lo + span);
    f.value[0] = (hyst_wide_t)rng_range(r, -10.0, 10.0);
    for (k = 0u; k < intervals; ++k) {
        if (flat && rng_below(r, 5u) == 0u) {
            step[k] = 0.0;
        } else if (steep && rng_below(r, 6u) == 0u) {
            step[k] = rng_range(r, 3.0, 30.0);
        } else {
            step[k] = rng_range(r, 0.01, 3.0);
        }
        f.value[k + 1u] = (hyst_wide_t)((double)f.value[k] + step[k]);
    }
    if (!(f.value[intervals] > f.value[0])) {
        f.value[intervals] += 1;
        step[intervals - 1u] += 1.0;
    }
    for (k = 0u; k <= intervals; ++k) {
        const double left = k > 0u ? step[k - 1u] / h : step[k] / h;
        const double right = k < intervals ? step[k] / h : step[k - 1u] / h;
        const double m = left < right ? left : right;
        f.slope[k] = (hyst_wide_t)(zeros && rng_below(r, 4u) == 0u ? 0.0 : m * rng_range(r, 0.0, 3.0));
    }
    return f;
}

/* Horner's rule in double-double (fma gives each product's error exactly):
 * about 106 bits, so coefficients expanded about 0 that cancel by 2^60 on
 * the domain still leave 2^-46 of the result. */
double poly_eval_exact(const hyst_wide_t *c, unsigned degree, double x)
{
    double hi = (double)c[0], lo = 0.0;
    unsigned k;
    for (k = 1u; k <= degree; ++k) {
        double p = hi * x, e = fma(hi, x, -p) + lo * x, s, t;
        hi = p + e; /* (p, e) normalised */
        lo = e - (hi - p);
        s = hi + (double)c[k];
        t = s - hi;
        lo += (hi - (s - t)) + ((double)c[k] - t);
        hi = s + lo;
        lo = lo - (hi - s);
    }
    return hi + lo;
}
