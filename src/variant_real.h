/* SPDX-License-Identifier: MIT */
/* A real variant (f32, f64): the engine over one real type for inputs and
 * outputs, its out-of-line curve kinds and its public functions. Included
 * once by src/hyst_f32.c and src/hyst_f64.c after their number type
 * descriptor; everything generated is named by NUM_NAME. */
#ifndef HYST_VARIANT_REAL_H
#define HYST_VARIANT_REAL_H

#include "hyst/pi.h"
#include "hyst/tcm.h"
#include "hyst/inverse.h"

#include "num_ops.h"
#include "hyst_util.h"
#include "curve_eval.h"

/* Out of line so the common path stays short: NaN/Inf or outside [lo, hi].
 * Returns 0 if the sample must be ignored, else 1 with *x clamped. */
static int NUM_NAME(admit_slow)(hyst_tcm_t *S, NUM_T *x)
{
    const NUM_T v = *x;
    if (!NUM_NAME(is_finite)(v)) {
        S->status = HYST_ERR_NONFINITE;
        S->events |= HYST_EVENT_NONFINITE;
        return 0;
    }
    *x = v < S->lo.NUM_F ? S->lo.NUM_F : S->hi.NUM_F;
    S->status = HYST_WARN_CLAMPED;
    S->events |= HYST_EVENT_CLAMPED;
    return 1;
}

static int NUM_NAME(admit)(hyst_tcm_t *S, NUM_T x, NUM_T *out)
{
    *out = x;
    return (x >= S->lo.NUM_F && x <= S->hi.NUM_F) || NUM_NAME(admit_slow)(S, out);
}

#define TCM_NAME(n) NUM_NAME(n)
#define TCM_VARIANT NUM_VARIANT
#define TCM_X NUM_T
#define TCM_XF NUM_F
#define TCM_Y NUM_T
#define TCM_YF NUM_F
#define TCM_ARG NUM_T
#define TCM_IN NUM_T
#define TCM_R(a) (a)
#define TCM_D(a, b) ((a) - (b))
#define TCM_MID(a, b) ((a) + ((b) - (a)) * NUM_C(0.5))
#define TCM_NORM(a) ((a) + NUM_C(0.0)) /* -0 + +0 = +0 */
#define TCM_REAL_INPUT 1
#define TCM_ADMIT(S, x, out) NUM_NAME(admit)((S), (x), (out))
#define TCM_CURVE_G(c, d) NUM_NAME(curve_g_other_)((c), (d))
#ifdef NUM_KEY_T
#define TCM_KEY_T NUM_KEY_T
#define TCM_UKEY_T NUM_UKEY_T
#endif
#include "tcm_engine.h"
#include "kinds.h"

static hyst_status_t NUM_NAME(init_curve_impl)(hyst_tcm_t *S, const hyst_curve_t *curve, NUM_T *xltp,
                                    NUM_T *yltp, NUM_T *xrtp, NUM_T *yrtp, size_t capacity,
                                    unsigned long layout)
{
    const hyst_status_t st = hyst_check_init(S, curve, NUM_VARIANT, xltp, yltp, xrtp, yrtp,
                                             capacity, sizeof(NUM_T), sizeof(NUM_T), layout);
    if (st != HYST_OK) {
        return st;
    }
    NUM_NAME(attach)(S, curve, NUM_NAME(kind_of)(curve), curve->lo.NUM_F, curve->hi.NUM_F,
                     curve->unit.NUM_F, xltp, yltp, xrtp, yrtp, capacity);
    return HYST_OK;
}

static hyst_status_t NUM_NAME(init_impl)(hyst_tcm_t *S, const hyst_poly_t *f0, NUM_T *xltp, NUM_T *yltp,
                              NUM_T *xrtp, NUM_T *yrtp, size_t capacity, unsigned long layout)
{
    hyst_curve_t curve;
    hyst_status_t st = hyst_check_memory(S, xltp, yltp, xrtp, yrtp, capacity, sizeof(NUM_T),
                                         sizeof(NUM_T), layout);
    if (st == HYST_OK) {
        st = hyst_curve_poly_(&curve, f0, NUM_VARIANT, layout);
    }
    if (st != HYST_OK) {
        return st;
    }
    /* A polynomial is copied whole into the instance: no curve to keep. */
    NUM_NAME(attach)(S, &curve, &NUM_NAME(kind_poly), curve.lo.NUM_F, curve.hi.NUM_F, curve.unit.NUM_F, xltp,
                     yltp, xrtp, yrtp, capacity);
    S->curve = NULL;
    return HYST_OK;
}

/* A compensator of f0: its inverse curve into *inv (exact by bisection, or
 * tabulated into table if `tabulate`), then the instance. */
static hyst_status_t NUM_NAME(init_inverse_of)(hyst_tcm_t *S, hyst_curve_t *inv,
                                               const hyst_poly_t *f0, int tabulate, NUM_T *table,
                                               size_t intervals, NUM_T *xltp, NUM_T *yltp,
                                               NUM_T *xrtp, NUM_T *yrtp, size_t capacity,
                                               unsigned long layout)
{
    hyst_curve_t fwd, curve;
    /* curve errors first, then the instance's (inverse.h) */
    hyst_status_t st = inv == NULL ? HYST_ERR_NULL : hyst_curve_poly_(&fwd, f0, NUM_VARIANT, layout);
    if (st == HYST_OK) {
        st = tabulate ? NUM_NAME(curve_inverse_table_impl)(&curve, &fwd, table, intervals)
                      : hyst_curve_inverse(&curve, &fwd);
    }
    if (st == HYST_OK) {
        st = hyst_check_memory(S, xltp, yltp, xrtp, yrtp, capacity, sizeof(NUM_T), sizeof(NUM_T),
                               layout);
    }
    if (st != HYST_OK) {
        return st;
    }
    *inv = curve; /* checked above: attach without checking again */
    /* the inverted polynomial or its table: both the out-of-line kind */
    NUM_NAME(attach)(S, inv, &NUM_NAME(kind_curve), inv->lo.NUM_F, inv->hi.NUM_F, inv->unit.NUM_F,
                     xltp, yltp, xrtp, yrtp, capacity);
    return HYST_OK;
}

static hyst_status_t NUM_NAME(init_inverse_exact_impl)(hyst_tcm_t *S, hyst_curve_t *inv,
                                            const hyst_poly_t *f0, NUM_T *xltp, NUM_T *yltp,
                                            NUM_T *xrtp, NUM_T *yrtp, size_t capacity,
                                            unsigned long layout)
{
    return NUM_NAME(init_inverse_of)(S, inv, f0, 0, NULL, 0u, xltp, yltp, xrtp, yrtp, capacity,
                                     layout);
}

static hyst_status_t NUM_NAME(init_inverse_table_impl)(hyst_tcm_t *S, hyst_curve_t *inv,
                                            const hyst_poly_t *f0, NUM_T *table,
                                            size_t intervals, NUM_T *xltp, NUM_T *yltp,
                                            NUM_T *xrtp, NUM_T *yrtp, size_t capacity,
                                            unsigned long layout)
{
    return NUM_NAME(init_inverse_of)(S, inv, f0, 1, table, intervals, xltp, yltp, xrtp, yrtp,
                                     capacity, layout);
}

/* The deadband checks shared by the immediate call and the request. */
static hyst_status_t NUM_NAME(deadband_check)(const hyst_tcm_t *S, NUM_T width)
{
    if (S == NULL) {
        return HYST_ERR_NULL;
    }
    if (S->variant != (unsigned)NUM_VARIANT || !(width >= 0 && NUM_NAME(is_finite)(width))) {
        return HYST_ERR_ARG;
    }
    return HYST_OK;
}

static hyst_status_t NUM_NAME(set_deadband_impl)(hyst_tcm_t *S, NUM_T width)
{
    const hyst_status_t st = NUM_NAME(deadband_check)(S, width);
    if (st != HYST_OK) {
        return st;
    }
    S->deadband.NUM_F = width;
    NUM_NAME(set_detour)(S);
    ++S->seq;
    return HYST_OK;
}

static hyst_status_t NUM_NAME(request_deadband_impl)(hyst_tcm_t *S, NUM_T width)
{
    const hyst_status_t st = NUM_NAME(deadband_check)(S, width);
    if (st != HYST_OK) {
        return st;
    }
    S->req_width.NUM_F = width; /* before the counter: the step reads it after */
    return hyst_post_request_(S, &S->req_deadband);
}

HYST_INLINE NUM_T NUM_NAME(step_impl)(hyst_tcm_t *S, NUM_T x) { return NUM_NAME(sample)(S, x); }

HYST_INLINE hyst_status_t NUM_NAME(process_impl)(hyst_tcm_t *S, const NUM_T *x, NUM_T *y, size_t n)
{
    return NUM_NAME(block)(S, x, y, n);
}

HYST_INLINE NUM_T NUM_NAME(output_impl)(const hyst_tcm_t *S) { return S != NULL ? NUM_NAME(view)(S).y : 0; }

HYST_INLINE NUM_T NUM_NAME(input_impl)(const hyst_tcm_t *S) { return S != NULL ? NUM_NAME(view)(S).x : 0; }

HYST_INLINE NUM_T NUM_NAME(rounding_bound_impl)(const hyst_tcm_t *S) { return S != NULL ? S->rounding.NUM_F : 0; }

HYST_INLINE NUM_T NUM_NAME(error_bound_impl)(const hyst_tcm_t *S)
{
    return S != NULL ? NUM_NAME(view)(S).bound : 0;
}

#include "pi_model.h"

#endif /* HYST_VARIANT_REAL_H */
