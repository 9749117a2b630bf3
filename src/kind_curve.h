/* SPDX-License-Identifier: MIT */
/* The curve kinds evaluated out of line (piecewise linear and its inverse,
 * the inverted polynomial), a curve kind of the engine (src/tcm_engine.h,
 * TCM_NAME(kind_t)): G is the curve's g (src/curve_eval.h, TCM_CURVE_G);
 * every sample is slow. Included by src/kinds.h after the engine. */
#ifndef HYST_KIND_CURVE_H
#define HYST_KIND_CURVE_H

static TCM_NOINLINE TCM_Y TCM_NAME(curve_kind_g)(const hyst_tcm_t *S, TCM_Y u)
{
    return TCM_CURVE_G(S->curve, u);
}

/* Nothing for the fast path: S->degree 0 and no table, every sample slow. */
static void TCM_NAME(curve_attach)(hyst_tcm_t *S, const hyst_curve_t *curve)
{
    (void)S;
    (void)curve;
}

static const TCM_NAME(kind_t) TCM_NAME(ops_curve) = {.g = TCM_NAME(curve_kind_g),
                                                      .slow = TCM_NAME(step_slow),
                                                      .attach = TCM_NAME(curve_attach)};

#endif /* HYST_KIND_CURVE_H */
