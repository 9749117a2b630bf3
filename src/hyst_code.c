/* SPDX-License-Identifier: MIT */
/* The code variant (hyst_code_*): integer DAC codes in, float out. The
 * engine over hyst_code_word_t inputs; curves are f32 curves in user units,
 * evaluated out of line by the f32 variant's copy. */
#include "hyst/code.h"

#include "num_f32.h"
#include "num_ops.h"
#include "hyst_util.h"

/* Out of line: the common path is one compare. */
static hyst_code_word_t hyst_code_clamp_slow(hyst_tcm_t *S, uint_least32_t code)
{
    S->status = HYST_WARN_CLAMPED;
    S->events |= HYST_EVENT_CLAMPED;
    return code < S->lo.code ? S->lo.code : S->hi.code;
}

static int hyst_code_admit(hyst_tcm_t *S, uint_least32_t code, hyst_code_word_t *out)
{
    *out = code >= S->lo.code && code <= S->hi.code ? (hyst_code_word_t)code
                                                    : hyst_code_clamp_slow(S, code);
    return 1;
}

#define TCM_NAME(n) hyst_code_##n
#define TCM_VARIANT HYST_VARIANT_CODE
#define TCM_X hyst_code_word_t
#define TCM_XF code
#define TCM_Y float
#define TCM_YF f32
#define TCM_ARG uint_least32_t
#define TCM_IN hyst_code_word_t
#define TCM_R(a) ((float)(a))
/* exact integer difference (a >= b), then one conversion */
#define TCM_D(a, b) ((float)(uint_least32_t)((uint_least32_t)(a) - (uint_least32_t)(b)))
#define TCM_MID(a, b) ((hyst_code_word_t)((a) + ((b) - (a)) / 2u))
#define TCM_NORM(a) (a)
#define TCM_ADMIT(S, x, out) hyst_code_admit((S), (x), (out))
#define TCM_CURVE_G(c, d) hyst_f32_curve_g_other_((c), (d))
#define TCM_INV_TABLE_G(c, s) hyst_f32_inv_table_g_((c), (s))
#define TCM_SPLINE_G(c, s) hyst_f32_spline_g_((c), (s))
#define TCM_SPLINE_TABLE_G(c, s) hyst_f32_spline_table_g_((c), (s))
#include "tcm_engine.h"
#include "kinds.h"

/* Checked set-up of an instance whose memory and curve were checked: the
 * code range (HYST_ERR_DOMAIN) and the unit of G, then attach. Out of line:
 * both inits call it, and one copy of attach() is enough flash. */
static TCM_NOINLINE hyst_status_t hyst_code_attach_range(
    hyst_tcm_t *S, const hyst_curve_t *curve, const hyst_code_kind_t *kind,
    uint_least32_t code_lo, uint_least32_t code_hi,
    hyst_code_word_t *xltp, float *yltp, hyst_code_word_t *xrtp, float *yrtp, size_t capacity)
{
    hyst_wide_t unit;
    if (!(code_lo < code_hi) || code_hi > HYST_CODE_MAX) {
        return HYST_ERR_DOMAIN;
    }
    /* G takes d * unit: a code difference is d in user units times
     * (hi - lo) / (code_hi - code_lo), folded in once, for every kind. */
    unit = (hyst_wide_t)curve->unit.f32 * ((hyst_wide_t)curve->hi.f32 - (hyst_wide_t)curve->lo.f32) /
           (hyst_wide_t)(code_hi - code_lo);
    hyst_code_attach(S, curve, kind, (hyst_code_word_t)code_lo, (hyst_code_word_t)code_hi, (float)unit,
                     xltp, yltp, xrtp, yrtp, capacity);
    return HYST_OK;
}

hyst_status_t hyst_code_init_curve_(hyst_tcm_t *S, const hyst_curve_t *curve,
                                    uint_least32_t code_lo, uint_least32_t code_hi,
                                    hyst_code_word_t *xltp, float *yltp, hyst_code_word_t *xrtp,
                                    float *yrtp, size_t capacity, unsigned long layout)
{
    const hyst_status_t st =
        hyst_check_init(S, curve, HYST_VARIANT_F32, xltp, yltp, xrtp, yrtp, capacity,
                        sizeof(hyst_code_word_t), sizeof(float), layout);
    return st != HYST_OK ? st
                         : hyst_code_attach_range(S, curve, hyst_code_kind_of(curve), code_lo,
                                                  code_hi, xltp, yltp, xrtp, yrtp, capacity);
}

hyst_status_t hyst_code_init_kind_(hyst_tcm_t *S, const hyst_curve_t *curve, hyst_kind_t kind,
                                   uint_least32_t code_lo, uint_least32_t code_hi,
                                   hyst_code_word_t *xltp, float *yltp, hyst_code_word_t *xrtp,
                                   float *yrtp, size_t capacity, unsigned long layout)
{
    const hyst_code_kind_t *ops = NULL;
    hyst_status_t st = hyst_check_init(S, curve, HYST_VARIANT_F32, xltp, yltp, xrtp, yrtp,
                                       capacity, sizeof(hyst_code_word_t), sizeof(float), layout);
    if (st == HYST_OK) {
        st = hyst_code_named_kind(kind, curve, &ops);
    }
    return st != HYST_OK ? st
                         : hyst_code_attach_range(S, curve, ops, code_lo, code_hi, xltp, yltp,
                                                  xrtp, yrtp, capacity);
}

const void *hyst_code_kind_poly(const hyst_curve_t *curve, unsigned variant)
{
    return hyst_code_bind_poly(curve, variant);
}

const void *hyst_code_kind_pwl(const hyst_curve_t *curve, unsigned variant)
{
    return hyst_code_bind_pwl(curve, variant);
}

const void *hyst_code_kind_inverse(const hyst_curve_t *curve, unsigned variant)
{
    return hyst_code_bind_inverse(curve, variant);
}

const void *hyst_code_kind_inverse_table(const hyst_curve_t *curve, unsigned variant)
{
    return hyst_code_bind_inverse_table(curve, variant);
}

const void *hyst_code_kind_everett(const hyst_curve_t *curve, unsigned variant)
{
    return hyst_code_bind_everett(curve, variant);
}

const void *hyst_code_kind_everett_inverse(const hyst_curve_t *curve, unsigned variant)
{
    return hyst_code_bind_everett_inverse(curve, variant);
}

const void *hyst_code_kind_everett_inverse_table(const hyst_curve_t *curve, unsigned variant)
{
    return hyst_code_bind_everett_inverse_table(curve, variant);
}

const void *hyst_code_kind_everett_grid(const hyst_curve_t *curve, unsigned variant)
{
    return hyst_code_bind_everett_grid(curve, variant);
}

const void *hyst_code_kind_everett_grid_inverse(const hyst_curve_t *curve, unsigned variant)
{
    return hyst_code_bind_everett_grid_inverse(curve, variant);
}

const void *hyst_code_kind_spline(const hyst_curve_t *curve, unsigned variant)
{
    return hyst_code_bind_spline(curve, variant);
}

const void *hyst_code_kind_spline_inverse_table(const hyst_curve_t *curve, unsigned variant)
{
    return hyst_code_bind_spline_inverse_table(curve, variant);
}

hyst_status_t hyst_code_init_(hyst_tcm_t *S, const hyst_poly_t *f0, uint_least32_t code_lo,
                              uint_least32_t code_hi, hyst_code_word_t *xltp, float *yltp,
                              hyst_code_word_t *xrtp, float *yrtp, size_t capacity,
                              unsigned long layout)
{
    hyst_curve_t curve;
    hyst_status_t st = hyst_check_memory(S, xltp, yltp, xrtp, yrtp, capacity,
                                         sizeof(hyst_code_word_t), sizeof(float), layout);
    if (st == HYST_OK) {
        st = hyst_curve_poly_(&curve, f0, HYST_VARIANT_F32, layout);
    }
    if (st == HYST_OK) {
        st = hyst_code_attach_range(S, &curve, &hyst_code_ops_poly, code_lo, code_hi, xltp, yltp, xrtp, yrtp,
                                    capacity);
    }
    if (st == HYST_OK) {
        S->curve = NULL; /* a polynomial is copied whole into the instance */
    }
    return st;
}

hyst_status_t hyst_code_set_deadband(hyst_tcm_t *S, uint_least32_t codes)
{
    const hyst_status_t st = hyst_codes_deadband_check_(S, (unsigned)HYST_VARIANT_CODE, codes);
    if (st != HYST_OK) {
        return st;
    }
    hyst_code_bind_skip(S);
    S->deadband.code = (hyst_code_word_t)codes;
    hyst_code_set_detour(S);
    ++S->seq;
    return HYST_OK;
}

hyst_status_t hyst_code_request_deadband(hyst_tcm_t *S, uint_least32_t codes)
{
    const hyst_status_t st = hyst_codes_deadband_check_(S, (unsigned)HYST_VARIANT_CODE, codes);
    if (st != HYST_OK) {
        return st;
    }
    hyst_code_bind_skip(S); /* before the request is posted */
    return hyst_codes_request_deadband_(S, (unsigned)HYST_VARIANT_CODE, codes);
}

float hyst_code_step(hyst_tcm_t *S, uint_least32_t code) { return hyst_code_sample(S, code); }

hyst_status_t hyst_code_process(hyst_tcm_t *S, const hyst_code_word_t *x, float *y, size_t n)
{
    return hyst_code_block(S, x, y, n);
}

float hyst_code_output(const hyst_tcm_t *S) { return S != NULL ? hyst_code_view(S).y : 0; }

uint_least32_t hyst_code_input(const hyst_tcm_t *S)
{
    return S != NULL ? hyst_code_view(S).x : 0u;
}

float hyst_code_rounding_bound(const hyst_tcm_t *S) { return S != NULL ? S->rounding.f32 : 0; }

float hyst_code_error_bound(const hyst_tcm_t *S)
{
    return S != NULL ? hyst_code_view(S).bound : 0;
}
