/* SPDX-License-Identifier: MIT */
/* A plain double reference of the asymmetric kind (curve.h, hyst_everett_t),
 * sharing no code with the library: E straight from its coefficients, and
 * Madelung's rules on a list of turning points. Used by the tests and the
 * fuzz harness. */
#ifndef REF_EVERETT_H
#define REF_EVERETT_H

#include "hyst/hyst.h"

#define REF_EVERETT_TPS 1024

typedef struct {
    const hyst_everett_t *e;
    double tx[REF_EVERETT_TPS], ty[REF_EVERETT_TPS];
    int n;
    double x, y;
} ref_everett_t;

/* E(a, b), a >= b. */
double ref_everett_e(const hyst_everett_t *e, double a, double b);
void ref_everett_init(ref_everett_t *r, const hyst_everett_t *e);
/* The output at x (inside [lo, hi]); stacked TPs: r->n - 1. */
double ref_everett_step(ref_everett_t *r, double x);

#endif
