/* SPDX-License-Identifier: MIT */
#include "ref_tcm.h"

void ref_init(ref_tcm_t *r, const double *c, unsigned degree, double lo, double hi)
{
    unsigned k;
    for (k = 0; k <= degree; ++k) {
        r->c[k] = c[k];
    }
    r->degree = degree;
    r->knots = 0;
    r->lo = lo;
    r->hi = hi;
    r->n = 1;
    r->x[0] = lo;
    r->y[0] = ref_f0(r, lo);
    r->xp = lo;
    r->yp = r->y[0];
    r->inverse = 0;
    r->flo = lo;
    r->fhi = hi;
}

void ref_init_inverse(ref_tcm_t *r, const double *c, unsigned degree, double lo, double hi)
{
    ref_init(r, c, degree, lo, hi);
    r->inverse = 1;
    r->lo = ref_f0(r, lo);
    r->hi = ref_f0(r, hi);
    r->x[0] = r->xp = r->lo;
    r->y[0] = r->yp = lo;
}

void ref_init_spline(ref_tcm_t *r, unsigned intervals, const double *value, const double *slope,
                     double lo, double hi, int inverse)
{
    unsigned k;
    for (k = 0; k <= intervals; ++k) {
        r->sv[k] = value[k];
        r->ss[k] = slope[k];
    }
    r->degree = 0;
    r->c[0] = 0.0;
    r->knots = intervals + 1u;
    r->lo = r->flo = lo;
    r->hi = r->fhi = hi;
    r->inverse = inverse;
    if (inverse) {
        r->lo = ref_f0(r, lo);
        r->hi = ref_f0(r, hi);
    }
    r->n = 1;
    r->x[0] = r->xp = r->lo;
    r->y[0] = r->yp = inverse ? lo : ref_f0(r, lo);
}

/* The Hermite basis on the interval holding x. */
static double spline_f0(const ref_tcm_t *r, double x)
{
    const unsigned n = r->knots - 1u;
    const double h = (r->fhi - r->flo) / n;
    unsigned k = 0;
    double t, t2, t3;
    while (k + 1u < n && x >= r->flo + (k + 1u) * h) {
        ++k;
    }
    t = (x - (r->flo + k * h)) / h;
    t2 = t * t;
    t3 = t2 * t;
    return (2 * t3 - 3 * t2 + 1) * r->sv[k] + (t3 - 2 * t2 + t) * h * r->ss[k] +
           (-2 * t3 + 3 * t2) * r->sv[k + 1u] + (t3 - t2) * h * r->ss[k + 1u];
}

double ref_f0(const ref_tcm_t *r, double x)
{
    double acc = 0.0;
    unsigned k;
    if (r->knots > 0u) {
        return spline_f0(r, x);
    }
    for (k = 0; k <= r->degree; ++k) {
        acc = acc * x + r->c[k];
    }
    return acc;
}

static double g(const ref_tcm_t *r, double d)
{
    double a = 0.0, b = r->fhi - r->flo;
    int it;
    if (!r->inverse) {
        return ref_f0(r, r->lo + d) - ref_f0(r, r->lo);
    }
    for (it = 0; it < 200; ++it) { /* f0(flo + v) - f0(flo) = d */
        const double m = 0.5 * (a + b);
        if (!(m > a && m < b)) {
            break;
        }
        if (ref_f0(r, r->flo + m) - ref_f0(r, r->flo) < d) {
            a = m;
        } else {
            b = m;
        }
    }
    return 0.5 * (a + b);
}

double ref_step(ref_tcm_t *r, double x)
{
    int rising;
    long top;
    if (x < r->lo) {
        x = r->lo;
    }
    if (x > r->hi) {
        x = r->hi;
    }
    if (x == r->xp) {
        return r->yp;
    }
    rising = ((r->n - 1) % 2) == 0; /* top is an LTP */
    if ((x > r->xp) != rising) {    /* reversal: previous point is a TP */
        r->x[r->n] = r->xp;
        r->y[r->n] = r->yp;
        r->n++;
        rising = !rising;
    }
    for (;;) { /* wipe out, one pair at a time */
        if (r->n < 2) {
            break;
        }
        if (rising && x >= r->x[r->n - 2]) {
            r->n -= 2;
        } else if (!rising && x <= r->x[r->n - 2]) {
            if (r->n == 2) { /* back at A0 */
                r->n = 1;
                rising = 1;
                break;
            }
            r->n -= 2;
        } else {
            break;
        }
    }
    top = r->n - 1;
    r->yp = rising ? r->y[top] + g(r, x - r->x[top]) : r->y[top] - g(r, r->x[top] - x);
    r->xp = x;
    return r->yp;
}

long ref_tp_count(const ref_tcm_t *r)
{
    return r->n - 1;
}
