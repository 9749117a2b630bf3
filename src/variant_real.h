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
#define TCM_INV_TABLE_G(c, s) NUM_NAME(inv_table_g_)((c), (s))
#define TCM_SPLINE_G(c, s) NUM_NAME(spline_g_)((c), (s))
#define TCM_SPLINE_TABLE_G(c, s) NUM_NAME(spline_table_g_)((c), (s))
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

/* The kind named by the caller (src/kinds.h's binders): only its code is
 * referenced. */
static hyst_status_t NUM_NAME(init_kind_impl)(hyst_tcm_t *S, const hyst_curve_t *curve,
                                              hyst_kind_t kind, NUM_T *xltp, NUM_T *yltp,
                                              NUM_T *xrtp, NUM_T *yrtp, size_t capacity,
                                              unsigned long layout)
{
    const NUM_NAME(kind_t) *ops = NULL;
    hyst_status_t st = hyst_check_init(S, curve, NUM_VARIANT, xltp, yltp, xrtp, yrtp, capacity,
                                       sizeof(NUM_T), sizeof(NUM_T), layout);
    if (st == HYST_OK) {
        st = NUM_NAME(named_kind)(kind, curve, &ops);
    }
    if (st != HYST_OK) {
        return st;
    }
    NUM_NAME(attach)(S, curve, ops, curve->lo.NUM_F, curve->hi.NUM_F, curve->unit.NUM_F, xltp,
                     yltp, xrtp, yrtp, capacity);
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
    NUM_NAME(attach)(S, &curve, &NUM_NAME(ops_poly), curve.lo.NUM_F, curve.hi.NUM_F, curve.unit.NUM_F, xltp,
                     yltp, xrtp, yrtp, capacity);
    S->curve = NULL;
    return HYST_OK;
}

/* The variant's sealed structs (curve.h, inverse.h), named by its number
 * member (hyst_f32_..., hyst_f64_...) whatever NUM_NAME prefixes. */
#define VARIANT_PASTE_(a, b, c) a##b##c
#define VARIANT_TYPE_(a, b, c) VARIANT_PASTE_(a, b, c)
#define NUM_SEALED_POLY_T VARIANT_TYPE_(hyst_, NUM_F, _sealed_poly_t)
#define NUM_SEALED_INVERSE_T VARIANT_TYPE_(hyst_, NUM_F, _sealed_inverse_t)

/* The prepared numbers of a polynomial curve as the sealed struct holds
 * them (curve.h), and back: the same curve either way. */
static hyst_status_t NUM_NAME(seal_poly_impl)(NUM_SEALED_POLY_T *out, const hyst_poly_t *f0,
                                              unsigned long layout)
{
    NUM_SEALED_POLY_T c;
    hyst_curve_t curve;
    unsigned k;
    hyst_status_t st = out == NULL ? HYST_ERR_NULL
                                   : hyst_curve_poly_(&curve, f0, NUM_VARIANT, layout);
    if (st != HYST_OK) {
        return st;
    }
    memset(&c, 0, sizeof c);
    c.seal = hyst_poly_seal_crc_(&curve);
    c.degree = curve.u.poly.degree;
    c.lo = curve.lo.NUM_F;
    c.hi = curve.hi.NUM_F;
    c.y_lo = curve.y_lo.NUM_F;
    c.y_hi = curve.y_hi.NUM_F;
    c.unit = curve.unit.NUM_F;
    c.rounding = curve.rounding.NUM_F;
    for (k = 0u; k < c.degree; ++k) {
        c.a[k] = curve.u.poly.a[k].NUM_F;
    }
    *out = c;
    return HYST_OK;
}

/* Checks only what the seal cannot vouch for (the memory, the layout, the
 * degree that bounds the copy) and the seal: no curve construction. */
static hyst_status_t NUM_NAME(init_sealed_impl)(hyst_tcm_t *S, const NUM_SEALED_POLY_T *c,
                                                NUM_T *xltp, NUM_T *yltp, NUM_T *xrtp,
                                                NUM_T *yrtp, size_t capacity, unsigned long layout)
{
    hyst_curve_t curve;
    unsigned k;
    hyst_status_t st = hyst_check_memory(S, xltp, yltp, xrtp, yrtp, capacity, sizeof(NUM_T),
                                         sizeof(NUM_T), layout);
    if (st != HYST_OK || c == NULL) {
        return st != HYST_OK ? st : HYST_ERR_NULL;
    }
    if (c->degree < 1u || c->degree > HYST_MAX_DEGREE) {
        return HYST_ERR_DEGREE;
    }
    memset(&curve, 0, sizeof curve);
    curve.kind = HYST_CURVE_POLY;
    curve.variant = NUM_VARIANT;
    curve.layout = HYST_LAYOUT;
    curve.u.poly.degree = c->degree;
    curve.lo.NUM_F = c->lo;
    curve.hi.NUM_F = c->hi;
    curve.y_lo.NUM_F = c->y_lo;
    curve.y_hi.NUM_F = c->y_hi;
    curve.unit.NUM_F = c->unit;
    curve.rounding.NUM_F = c->rounding;
    for (k = 0u; k < HYST_MAX_DEGREE; ++k) { /* a select, not a copy: no memcpy() linked */
        curve.u.poly.a[k].NUM_F = k < c->degree ? c->a[k] : 0;
    }
    if (hyst_poly_seal_crc_(&curve) != (c->seal & 0xFFFFFFFFul)) {
        return HYST_ERR_CRC;
    }
    /* as init_impl(): the polynomial is copied whole into the instance */
    NUM_NAME(attach)(S, &curve, &NUM_NAME(ops_poly), curve.lo.NUM_F, curve.hi.NUM_F, curve.unit.NUM_F, xltp,
                     yltp, xrtp, yrtp, capacity);
    S->curve = NULL;
    return HYST_OK;
}

/* A tabulated compensator's curve (built) as the sealed struct holds it. */
static hyst_status_t NUM_NAME(seal_inverse_table_impl)(NUM_SEALED_INVERSE_T *out,
                                                       const hyst_curve_t *inv)
{
    NUM_SEALED_INVERSE_T c;
    hyst_num_t err;
    unsigned k;
    const hyst_status_t st = hyst_curve_check(inv);
    if (st != HYST_OK || out == NULL) {
        return st != HYST_OK ? st : HYST_ERR_NULL;
    }
    if (inv->variant != (unsigned)NUM_VARIANT || inv->kind != (unsigned)HYST_CURVE_INV_TABLE) {
        return HYST_ERR_ARG;
    }
    if (hyst_inverse_table_measure_(inv) != HYST_OK) { /* a table changed since its build */
        return HYST_ERR_CURVE;
    }
    err.f32 = (float)hyst_table_err_(inv->u.inv_table.max_err); /* a float already */
    memset(&c, 0, sizeof c);
    c.seal = hyst_inverse_seal_crc_(inv, &err);
    c.degree = inv->u.inv_table.fwd.degree;
    c.lo = inv->lo.NUM_F;
    c.hi = inv->hi.NUM_F;
    c.y_lo = inv->y_lo.NUM_F;
    c.y_hi = inv->y_hi.NUM_F;
    c.unit = inv->unit.NUM_F;
    c.span = inv->u.inv_table.span.NUM_F;
    c.u_per_d = inv->u.inv_table.u_per_d.NUM_F;
    for (k = 0u; k < c.degree; ++k) {
        c.a[k] = inv->u.inv_table.fwd.a[k].NUM_F;
    }
    c.intervals = (unsigned long)inv->u.inv_table.intervals;
    c.exact = (unsigned long)inv->u.inv_table.exact;
    c.max_err = err.f32;
    *out = c;
    return HYST_OK;
}

/* The sealed compensator: checks what the seal cannot vouch for (the
 * memory, the layout, the degree and intervals that bound the reads) and
 * the seal over the struct and the table; binds the tabulated inverse's
 * kind as the build's init does. */
static hyst_status_t NUM_NAME(init_inverse_sealed_impl)(hyst_tcm_t *S, hyst_curve_t *inv,
                                                        const NUM_SEALED_INVERSE_T *c,
                                                        const NUM_T *table, NUM_T *xltp,
                                                        NUM_T *yltp, NUM_T *xrtp, NUM_T *yrtp,
                                                        size_t capacity, unsigned long layout)
{
    hyst_curve_t curve;
    hyst_num_t err;
    unsigned k;
    hyst_status_t st = hyst_check_memory(S, xltp, yltp, xrtp, yrtp, capacity, sizeof(NUM_T),
                                         sizeof(NUM_T), layout);
    if (st != HYST_OK || inv == NULL || c == NULL || table == NULL) {
        return st != HYST_OK ? st : HYST_ERR_NULL;
    }
    if (c->degree < 1u || c->degree > HYST_MAX_DEGREE) {
        return HYST_ERR_DEGREE;
    }
    if (c->intervals < 1ul || c->intervals > 1048576ul || c->exact > c->intervals) {
        return HYST_ERR_ARG;
    }
    memset(&curve, 0, sizeof curve);
    curve.kind = HYST_CURVE_INV_TABLE;
    curve.variant = NUM_VARIANT;
    curve.layout = HYST_LAYOUT;
    curve.lo.NUM_F = c->lo;
    curve.hi.NUM_F = c->hi;
    curve.y_lo.NUM_F = c->y_lo;
    curve.y_hi.NUM_F = c->y_hi;
    curve.unit.NUM_F = c->unit;
    curve.u.inv_table.fwd.degree = c->degree;
    for (k = 0u; k < c->degree; ++k) {
        curve.u.inv_table.fwd.a[k].NUM_F = c->a[k];
    }
    curve.u.inv_table.span.NUM_F = c->span;
    curve.u.inv_table.u_per_d.NUM_F = c->u_per_d;
    curve.u.inv_table.table.NUM_F = table;
    curve.u.inv_table.intervals = (size_t)c->intervals;
    curve.u.inv_table.exact = (size_t)c->exact;
    err.f32 = c->max_err;
    if (hyst_inverse_seal_crc_(&curve, &err) != (c->seal & 0xFFFFFFFFul)) {
        return HYST_ERR_CRC;
    }
    curve.u.inv_table.max_err = hyst_wide_of_float_(c->max_err);
    *inv = curve;
    NUM_NAME(attach)(S, inv, &NUM_NAME(ops_inv_table), inv->lo.NUM_F, inv->hi.NUM_F, inv->unit.NUM_F,
                     xltp, yltp, xrtp, yrtp, capacity);
    return HYST_OK;
}

/* A compensator of f0 once its inverse curve is built (st: the build's
 * status; curve errors first, then the instance's: inverse.h): the curve
 * into *inv, then the instance on it, of kind `kind`. */
static hyst_status_t NUM_NAME(attach_inverse)(hyst_tcm_t *S, hyst_curve_t *inv, hyst_status_t st,
                                            const hyst_curve_t *curve,
                                            const NUM_NAME(kind_t) *kind, NUM_T *xltp,
                                            NUM_T *yltp, NUM_T *xrtp, NUM_T *yrtp,
                                            size_t capacity, unsigned long layout)
{
    if (st == HYST_OK) {
        st = hyst_check_memory(S, xltp, yltp, xrtp, yrtp, capacity, sizeof(NUM_T), sizeof(NUM_T),
                               layout);
    }
    if (st != HYST_OK) {
        return st;
    }
    *inv = *curve; /* checked above: attach without checking again */
    NUM_NAME(attach)(S, inv, kind, inv->lo.NUM_F, inv->hi.NUM_F, inv->unit.NUM_F, xltp, yltp, xrtp,
                     yrtp, capacity);
    return HYST_OK;
}

/* The compensators' builds are separate calls, so that a firmware that
 * tabulates links no bisection set-up, and one that bisects no table. */
static hyst_status_t NUM_NAME(init_inverse_exact_impl)(hyst_tcm_t *S, hyst_curve_t *inv,
                                            const hyst_poly_t *f0, NUM_T *xltp, NUM_T *yltp,
                                            NUM_T *xrtp, NUM_T *yrtp, size_t capacity,
                                            unsigned long layout)
{
    hyst_curve_t fwd, curve;
    hyst_status_t st = inv == NULL ? HYST_ERR_NULL : hyst_curve_poly_(&fwd, f0, NUM_VARIANT, layout);
    if (st == HYST_OK) {
        st = hyst_curve_inverse(&curve, &fwd);
    }
    return NUM_NAME(attach_inverse)(S, inv, st, &curve, &NUM_NAME(ops_curve), xltp, yltp, xrtp,
                                  yrtp, capacity, layout);
}

static hyst_status_t NUM_NAME(init_inverse_table_impl)(hyst_tcm_t *S, hyst_curve_t *inv,
                                            const hyst_poly_t *f0, NUM_T *table,
                                            size_t intervals, NUM_T *xltp, NUM_T *yltp,
                                            NUM_T *xrtp, NUM_T *yrtp, size_t capacity,
                                            unsigned long layout)
{
    hyst_curve_t fwd, curve;
    hyst_status_t st = inv == NULL ? HYST_ERR_NULL : hyst_curve_poly_(&fwd, f0, NUM_VARIANT, layout);
    if (st == HYST_OK) {
        st = NUM_NAME(curve_inverse_table_impl)(&curve, &fwd, table, intervals);
    }
    return NUM_NAME(attach_inverse)(S, inv, st, &curve, &NUM_NAME(ops_inv_table), xltp, yltp, xrtp,
                                  yrtp, capacity, layout);
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
    NUM_NAME(bind_skip)(S);
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
    NUM_NAME(bind_skip)(S); /* before the counter, as the width */
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
