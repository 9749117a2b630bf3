/* SPDX-License-Identifier: MIT */
/* The symmetric polynomial kind (HYST_CURVE_POLY, the paper's TCM with
 * f0's G), a curve kind of the engine (src/tcm_engine.h, TCM_NAME(kind_t)):
 * G is one polynomial for every branch, its coefficients copied into the
 * instance at init; the fast path and the engine's slow sample evaluate
 * them (Horner's rule, src/num_ops.h). Included after the engine by every
 * variant (src/kinds.h; the q31 model, src/hyst_q31.c, alone). */
#ifndef HYST_KIND_POLY_H
#define HYST_KIND_POLY_H

/* f0's G of degree n = 1..HYST_MAX_DEGREE (the curve's check): S->degree
 * and S->coef, lowest power first (the curve's a[0] is the highest). */
static void TCM_NAME(poly_attach)(hyst_tcm_t *S, const hyst_curve_t *curve)
{
    const unsigned n = curve->u.poly.degree;
    unsigned k;
    S->degree = n;
    for (k = 0u; k < n; ++k) {
        YV(S->coef[n - 1u - k]) = YV(curve->u.poly.a[k]);
    }
}

/* Its deadband bound is the engine's for a polynomial branch (skip()):
 * no loop_error. */
static const TCM_NAME(kind_t) TCM_NAME(ops_poly) = {.slow = TCM_NAME(step_slow),
                                                     .attach = TCM_NAME(poly_attach)};

#endif /* HYST_KIND_POLY_H */
