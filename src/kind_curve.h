/* SPDX-License-Identifier: MIT */
/* The curve kinds evaluated out of line (piecewise linear and its inverse,
 * the inverted polynomial, the tabulated inverse's exact intervals), a curve
 * kind of the engine (src/tcm_engine.h, TCM_NAME(kind_t)): G is the curve's
 * g (src/curve_eval.h, TCM_CURVE_G); every sample of the first three is
 * slow, the tabulated inverse's pieces are evaluated by emit()'s case 0.
 * Included by src/kinds.h after the engine. */
#ifndef HYST_KIND_CURVE_H
#define HYST_KIND_CURVE_H

static TCM_NOINLINE TCM_Y TCM_NAME(curve_kind_g)(const hyst_tcm_t *S, TCM_Y u)
{
    return TCM_CURVE_G(S->curve, u);
}

/* The tabulated inverse's pieces for the fast path (emit()'s case 0,
 * S->degree 0); the other curves have none: every sample slow. */
static void TCM_NAME(curve_attach)(hyst_tcm_t *S, const hyst_curve_t *curve)
{
    if (curve->kind == (unsigned)HYST_CURVE_INV_TABLE) {
        S->table.TCM_YF = curve->u.inv_table.table.TCM_YF;
    }
}

static const TCM_NAME(kind_t) TCM_NAME(kind_curve) = {.g = TCM_NAME(curve_kind_g),
                                                      .attach = TCM_NAME(curve_attach)};

#endif /* HYST_KIND_CURVE_H */
