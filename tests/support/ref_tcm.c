/* SPDX-License-Identifier: MIT */
#include "ref_tcm.h"

void ref_init(ref_tcm_t *r, const double *c, unsigned degree, double lo, double hi)
{
    unsigned k;
    for (k = 0; k <= degree; ++k) {
        r->c[k] = c[k];
    }
    r->degree = degree;
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

double ref_f0(const ref_tcm_t *r, double x)
{
    double acc = 0.0;
    unsigned k;
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
