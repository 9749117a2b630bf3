/* SPDX-License-Identifier: MIT */
/* Deliberately simple TCM reference for tests: double precision, one flat
 * list of turning points scanned linearly, f0 evaluated on raw coefficients.
 * Shares no code with the library, so agreement means something. */
#ifndef REF_TCM_H
#define REF_TCM_H

#define REF_MAX_TP 8192
#define REF_MAX_DEGREE 9
#define REF_MAX_KNOTS 33

typedef struct {
    double c[REF_MAX_DEGREE + 1]; /* highest power first */
    unsigned degree;
    double lo, hi;
    double x[REF_MAX_TP], y[REF_MAX_TP]; /* [0] = A0; even index LTP, odd RTP */
    long n;
    double xp, yp;
    int inverse;     /* ref_init_inverse(): the model in the (y, x) plane */
    double flo, fhi; /* its f0's domain */
    /* ref_init_spline(): f0 the cubic Hermite through these knots (uniform
     * on [lo, hi]), in the Hermite basis, instead of c */
    unsigned knots;  /* 0: f0 is c */
    double sv[REF_MAX_KNOTS], ss[REF_MAX_KNOTS];
} ref_tcm_t;

void ref_init(ref_tcm_t *r, const double *c, unsigned degree, double lo, double hi);
/* The compensator of the TCM with f0 = c on [lo, hi]: a TCM on
 * [f0(lo), f0(hi)] whose branches are f0^-1's, solved by bisection. */
void ref_init_inverse(ref_tcm_t *r, const double *c, unsigned degree, double lo, double hi);
/* The same with f0 a spline of `intervals` uniform intervals on [lo, hi],
 * its values and slopes at the knots; inverse: its compensator. */
void ref_init_spline(ref_tcm_t *r, unsigned intervals, const double *value, const double *slope,
                     double lo, double hi, int inverse);
double ref_f0(const ref_tcm_t *r, double x);
double ref_step(ref_tcm_t *r, double x);
long ref_tp_count(const ref_tcm_t *r); /* TPs excluding A0 */

#endif
