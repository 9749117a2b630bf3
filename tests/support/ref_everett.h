/* SPDX-License-Identifier: MIT */
/* A plain double reference of the asymmetric kind (curve.h, hyst_everett_t),
 * sharing no code with the library: E straight from its coefficients, and
 * Madelung's rules on a list of turning points. Used by the tests and the
 * fuzz harness. */
#ifndef REF_EVERETT_H
#define REF_EVERETT_H

#include "hyst/hyst.h"
#include "support.h"

#define REF_EVERETT_TPS 1024

typedef struct {
    const hyst_everett_t *e;
    /* E itself if not NULL (a plant that is no polynomial; e gives the
     * domain and y_lo): set after ref_everett_init() */
    double (*fn)(double a, double b);
    double tx[REF_EVERETT_TPS], ty[REF_EVERETT_TPS];
    int n;
    double x, y;
} ref_everett_t;

/* E(a, b), a >= b. */
double ref_everett_e(const hyst_everett_t *e, double a, double b);
void ref_everett_init(ref_everett_t *r, const hyst_everett_t *e);
/* The output at x (inside [lo, hi]); stacked TPs: r->n - 1. */
double ref_everett_step(ref_everett_t *r, double x);

/* A random E of degree 1..HYST_EVERETT_MAX_DEGREE on a random domain:
 * coefficients in [-1.5, 1] / (i + j) with a dominant positive width term,
 * scaled; about one in four is not monotone (init decides). */
hyst_everett_t ref_everett_random(rng_t *rng);
/* The next sample of a random walk over [lo, hi] with jumps (one in ten);
 * *v: the walk's state, start it at any point of the domain. */
double ref_everett_walk(rng_t *rng, double *v, double lo, double hi);

/* The reference's output if its next input were x; r unchanged (scratch:
 * a reference to work in). */
double ref_everett_response(const ref_everett_t *r, double x, ref_everett_t *scratch);
/* The exact inverse: the input whose response is y (the response increases
 * with x from y_lo at lo to y_hi at hi, whatever the state), bisected. */
double ref_everett_inverse(const ref_everett_t *r, double y, ref_everett_t *scratch);

#endif
