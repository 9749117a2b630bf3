/* SPDX-License-Identifier: MIT */
/* Deliberately simple TCM reference for tests: double precision, one flat
 * list of turning points scanned linearly, f0 evaluated on raw coefficients.
 * Shares no code with the library, so agreement means something. */
#ifndef REF_TCM_H
#define REF_TCM_H

#define REF_MAX_TP 8192
#define REF_MAX_DEGREE 9

typedef struct {
    double c[REF_MAX_DEGREE + 1]; /* highest power first */
    unsigned degree;
    double lo, hi;
    double x[REF_MAX_TP], y[REF_MAX_TP]; /* [0] = A0; even index LTP, odd RTP */
    long n;
    double xp, yp;
    int inverse;     /* ref_init_inverse(): the model in the (y, x) plane */
    double flo, fhi; /* its f0's domain */
} ref_tcm_t;

void ref_init(ref_tcm_t *r, const double *c, unsigned degree, double lo, double hi);
/* The compensator of the TCM with f0 = c on [lo, hi]: a TCM on
 * [f0(lo), f0(hi)] whose branches are f0^-1's, solved by bisection. */
void ref_init_inverse(ref_tcm_t *r, const double *c, unsigned degree, double lo, double hi);
double ref_f0(const ref_tcm_t *r, double x);
double ref_step(ref_tcm_t *r, double x);
long ref_tp_count(const ref_tcm_t *r); /* TPs excluding A0 */

#endif
