/* SPDX-License-Identifier: MIT */
/* The q31 variant (hyst_q31_*): integer codes in, fixed point out, for cores
 * without an FPU. The engine over hyst_code_word_t inputs and hyst_q31_t
 * outputs; the scaling and the error bound are stated in include/hyst/q31.h.
 * Set-up in hyst_wide_t, per sample integers only. */
#include <string.h>

#include "hyst/q31.h"

#include "hyst_util.h"

/* Number type descriptor: src/num_q31.h, shared with the compensator. */
#define NUM_NAME(n) hyst_q31_##n
#define NUM_VARIANT HYST_VARIANT_Q31
#include "num_q31.h"
#include "num_ops.h"

/* Out of line: the common path is one compare. */
static hyst_code_word_t hyst_q31_clamp_slow(hyst_tcm_t *S, uint_least32_t code)
{
    S->status = HYST_WARN_CLAMPED;
    S->events |= HYST_EVENT_CLAMPED;
    return code < S->lo.code ? S->lo.code : S->hi.code;
}

static int hyst_q31_admit(hyst_tcm_t *S, uint_least32_t code, hyst_code_word_t *out)
{
    *out = code >= S->lo.code && code <= S->hi.code ? (hyst_code_word_t)code
                                                    : hyst_q31_clamp_slow(S, code);
    return 1;
}

/* Only polynomials are prepared for this variant: never called. */
static hyst_q31_t hyst_q31_no_other(const hyst_curve_t *curve, hyst_q31_t v)
{
    (void)curve;
    (void)v;
    return 0;
}

#define TCM_NAME(n) hyst_q31_##n
#define TCM_VARIANT HYST_VARIANT_Q31
#define TCM_X hyst_code_word_t
#define TCM_XF code
#define TCM_Y hyst_q31_t
#define TCM_YF q31
#define TCM_ARG uint_least32_t
#define TCM_IN hyst_code_word_t
#define TCM_R(a) ((hyst_q31_t)(a))
#define TCM_D(a, b) ((hyst_q31_t)(uint_least32_t)((uint_least32_t)(a) - (uint_least32_t)(b)))
#define TCM_MID(a, b) ((hyst_code_word_t)((a) + ((b) - (a)) / 2u))
#define TCM_NORM(a) (a)
#define TCM_ADMIT(S, x, out) hyst_q31_admit((S), (x), (out))
#define TCM_G_OTHER(c, d) hyst_q31_no_other((c), (d))
/* d * unit is exact: halve the argument, not the code difference */
#define TCM_G_HALF(S, d) TCM_NAME(g_of)((S), (d) * (S)->unit.q31 / 2, 1)
#define TCM_ADD_BOUND(a, e) ((a) = hyst_q31_add_bound((a), (e)))
#define TCM_POLY_ONLY 1 /* kind_poly alone */
#include "tcm_engine.h"
#include "kind_poly.h"

#define Q31_ONE_U ((hyst_wide_t)((hyst_q31_t)1 << HYST_Q31_U_BITS))
#define Q31_SPAN ((hyst_wide_t)((hyst_q31_t)1 << HYST_Q31_SPAN_BITS))
#define Q31_LIMIT ((hyst_wide_t)2147483647L)

/* Rounds w (|w| < 2^31 checked by the caller) to the nearest integer. */
static hyst_q31_t q31_round(hyst_wide_t w)
{
    return (hyst_q31_t)(w < 0 ? w - (hyst_wide_t)0.5 : w + (hyst_wide_t)0.5);
}

/* The fixed-point curve of f0 (hyst_util.h): coefficients of G(v / c) in
 * the coefficients' format, with the overflow proof and the error bound. */
int hyst_q31_curve_(hyst_curve_t *q, const hyst_wide_t *g, unsigned n, hyst_wide_t range,
                    hyst_wide_t c)
{
    /* q units per real output unit, coefficients 2^GUARD coarser */
    const hyst_wide_t per_coef =
        Q31_SPAN / range / (hyst_wide_t)((hyst_q31_t)1 << HYST_Q31_GUARD_BITS);
    const hyst_wide_t v_max = c > 1 ? c : 1;
    hyst_wide_t b[HYST_MAX_DEGREE + 1], partial = 0, cmax_n = 1, c_pow = 1, bound;
    unsigned j, i;
    for (j = 1u; j <= n; ++j) {
        c_pow *= c;
        cmax_n *= v_max;
        b[j] = g[j] / c_pow * per_coef; /* multiplies v^j */
        if (!(hyst_wide_abs(b[j]) < Q31_LIMIT)) {
            return 0;
        }
    }
    /* Partial sum i (i = 0..n-1) of Horner's rule: b_n v^i + ... + b_(n-i),
     * at most sum |b| v_max^k after rounding each coefficient by 1/2, plus
     * one truncated step (< 1) per multiply, each grown by v_max. */
    for (i = 0u; i < n; ++i) {
        const hyst_wide_t truncated = i > 0u ? 1 : 0;
        partial = partial * v_max + hyst_wide_abs(b[n - i]) + (hyst_wide_t)0.5 + truncated;
        if (!(partial < Q31_LIMIT)) {
            return 0;
        }
    }
    for (j = 1u; j <= n; ++j) {
        q->u.poly.a[n - j].q31 = q31_round(b[j]);
    }
    /* q31.h: (n / 2 + n - 1) v_max^n coefficient LSBs, plus the final
     * truncation, rounded up */
    bound = ((hyst_wide_t)n * (hyst_wide_t)1.5 - 1) * cmax_n *
                (hyst_wide_t)((hyst_q31_t)1 << HYST_Q31_GUARD_BITS) + 2;
    q->rounding.q31 = (hyst_q31_t)bound;
    return 1;
}

/* The frame of a q31 polynomial curve, as both inits attach it: the outputs
 * at the ends (its codes and G's argument per code are the instance's:
 * attach()'s arguments). */
HYST_INLINE void q31_frame(hyst_curve_t *q, unsigned n)
{
    memset(q, 0, sizeof *q);
    q->kind = HYST_CURVE_POLY;
    q->variant = HYST_VARIANT_Q31;
    q->layout = HYST_LAYOUT;
    q->u.poly.degree = n;
    q->y_lo.q31 = -((hyst_q31_t)1 << (HYST_Q31_SPAN_BITS - 1));
    q->y_hi.q31 = (hyst_q31_t)1 << (HYST_Q31_SPAN_BITS - 1);
}

/* The q31 curve of f0 on codes code_lo..code_hi (set-up in hyst_wide_t),
 * and G's argument per code in *unit. */
HYST_INLINE hyst_status_t q31_prepare(hyst_curve_t *q, hyst_q31_t *unit, const hyst_poly_t *f0,
                                      uint_least32_t code_lo, uint_least32_t code_hi,
                                      unsigned long layout)
{
    /* The curve's checks (domain, coefficients, monotonicity) in
     * hyst_wide_t, its rounding bound for double (hyst_q31_curve_() states this
     * variant's), and G not rounded to a real variant's numbers. */
    hyst_wide_t g[HYST_MAX_DEGREE + 1], range = 0, c;
    unsigned n, k;
    const hyst_status_t st = hyst_poly_check_(f0, g, layout);
    if (st != HYST_OK) {
        return st;
    }
    if (!(code_lo < code_hi) || code_hi > (uint_least32_t)HYST_CODE_MAX) {
        return HYST_ERR_DOMAIN;
    }
    n = f0->degree;
    for (k = 1u; k <= n; ++k) {
        range += g[k];
    }
    /* v = d * unit in Q30 (exact); d = N gives v <= 2^30 + N / 2 < 2^31 */
    *unit = q31_round(Q31_ONE_U / (hyst_wide_t)(code_hi - code_lo));
    c = (hyst_wide_t)(code_hi - code_lo) * (hyst_wide_t)*unit / Q31_ONE_U;
    q31_frame(q, n);
    if (!(range > 0) || !hyst_q31_curve_(q, g, n, range, c)) {
        return HYST_ERR_COEFF;
    }
    return HYST_OK;
}

hyst_status_t hyst_q31_init_(hyst_tcm_t *S, const hyst_poly_t *f0, uint_least32_t code_lo,
                             uint_least32_t code_hi, hyst_code_word_t *xltp, hyst_q31_t *yltp,
                             hyst_code_word_t *xrtp, hyst_q31_t *yrtp, size_t capacity,
                             unsigned long layout)
{
    hyst_curve_t q;
    hyst_q31_t unit = 0; /* set by q31_prepare() when it succeeds */
    hyst_status_t st = hyst_check_memory(S, xltp, yltp, xrtp, yrtp, capacity,
                                         sizeof(hyst_code_word_t), sizeof(hyst_q31_t), layout);
    if (st == HYST_OK) {
        st = q31_prepare(&q, &unit, f0, code_lo, code_hi, layout);
    }
    if (st != HYST_OK) {
        return st;
    }
    hyst_q31_attach(S, &q, &hyst_q31_ops_poly, (hyst_code_word_t)code_lo, (hyst_code_word_t)code_hi, unit,
                    xltp, yltp, xrtp, yrtp, capacity);
    S->curve = NULL; /* the polynomial is copied whole into the instance */
    return HYST_OK;
}

hyst_status_t hyst_q31_seal_poly_(hyst_q31_sealed_poly_t *out, const hyst_poly_t *f0,
                                  uint_least32_t code_lo, uint_least32_t code_hi,
                                  unsigned long layout)
{
    hyst_q31_sealed_poly_t c;
    hyst_curve_t q;
    hyst_q31_t unit = 0;
    unsigned k;
    const hyst_status_t st =
        out == NULL ? HYST_ERR_NULL : q31_prepare(&q, &unit, f0, code_lo, code_hi, layout);
    if (st != HYST_OK) {
        return st;
    }
    q.unit.q31 = unit;
    q.lo.code = (hyst_code_word_t)code_lo; /* sealed with the numbers */
    q.hi.code = (hyst_code_word_t)code_hi;
    memset(&c, 0, sizeof c);
    c.seal = hyst_poly_seal_crc_(&q);
    c.degree = q.u.poly.degree;
    c.code_lo = code_lo;
    c.code_hi = code_hi;
    c.unit = unit;
    c.rounding = q.rounding.q31;
    for (k = 0u; k < c.degree; ++k) {
        c.a[k] = q.u.poly.a[k].q31;
    }
    *out = c;
    return HYST_OK;
}

/* Checks only what the seal cannot vouch for (the memory, the layout, the
 * degree that bounds the copy, codes the stored words hold) and the seal.
 * The engine's attach() inlined here (flatten): its one other call, in
 * hyst_q31_init_(), stays inlined there too, as before this init existed. */
#if defined(__GNUC__)
__attribute__((flatten))
#endif
hyst_status_t hyst_q31_init_sealed_(hyst_tcm_t *S, const hyst_q31_sealed_poly_t *sealed,
                                    hyst_code_word_t *xltp, hyst_q31_t *yltp,
                                    hyst_code_word_t *xrtp, hyst_q31_t *yrtp, size_t capacity,
                                    unsigned long layout)
{
    hyst_curve_t q;
    unsigned k;
    hyst_status_t st = hyst_check_memory(S, xltp, yltp, xrtp, yrtp, capacity,
                                         sizeof(hyst_code_word_t), sizeof(hyst_q31_t), layout);
    if (st != HYST_OK || sealed == NULL) {
        return st != HYST_OK ? st : HYST_ERR_NULL;
    }
    if (sealed->degree < 1u || sealed->degree > HYST_MAX_DEGREE) {
        return HYST_ERR_DEGREE;
    }
    if (!(sealed->code_lo < sealed->code_hi) ||
        sealed->code_hi > (uint_least32_t)HYST_CODE_MAX) {
        return HYST_ERR_DOMAIN;
    }
    q31_frame(&q, sealed->degree);
    q.unit.q31 = sealed->unit;
    q.lo.code = (hyst_code_word_t)sealed->code_lo;
    q.hi.code = (hyst_code_word_t)sealed->code_hi;
    q.rounding.q31 = sealed->rounding;
    for (k = 0u; k < HYST_MAX_DEGREE; ++k) { /* a select, not a copy: no memcpy() linked */
        q.u.poly.a[k].q31 = k < sealed->degree ? sealed->a[k] : 0;
    }
    if (hyst_poly_seal_crc_(&q) != (sealed->seal & 0xFFFFFFFFul)) {
        return HYST_ERR_CRC;
    }
    hyst_q31_attach(S, &q, &hyst_q31_ops_poly, q.lo.code, q.hi.code, q.unit.q31, xltp, yltp, xrtp, yrtp,
                    capacity);
    S->curve = NULL;
    return HYST_OK;
}

hyst_wide_t hyst_q31_to_real(const hyst_poly_t *f0, hyst_q31_t q)
{
    hyst_wide_t y_lo, y_hi;
    if (f0 == NULL) {
        return 0;
    }
    y_lo = hyst_poly_eval(f0, f0->lo);
    y_hi = hyst_poly_eval(f0, f0->hi);
    return (y_lo + y_hi) / 2 + (hyst_wide_t)q * (y_hi - y_lo) / Q31_SPAN;
}

hyst_status_t hyst_q31_set_deadband(hyst_tcm_t *S, uint_least32_t codes)
{
    const hyst_status_t st = hyst_codes_deadband_check_(S, (unsigned)HYST_VARIANT_Q31, codes);
    if (st != HYST_OK) {
        return st;
    }
    hyst_q31_bind_skip(S);
    S->deadband.code = (hyst_code_word_t)codes;
    hyst_q31_set_detour(S);
    ++S->seq;
    return HYST_OK;
}

hyst_status_t hyst_q31_request_deadband(hyst_tcm_t *S, uint_least32_t codes)
{
    const hyst_status_t st = hyst_codes_deadband_check_(S, (unsigned)HYST_VARIANT_Q31, codes);
    if (st != HYST_OK) {
        return st;
    }
    hyst_q31_bind_skip(S); /* before the request is posted */
    return hyst_codes_request_deadband_(S, (unsigned)HYST_VARIANT_Q31, codes);
}

hyst_q31_t hyst_q31_step(hyst_tcm_t *S, uint_least32_t code) { return hyst_q31_sample(S, code); }

hyst_status_t hyst_q31_process(hyst_tcm_t *S, const hyst_code_word_t *x, hyst_q31_t *y,
                               size_t n)
{
    return hyst_q31_block(S, x, y, n);
}

hyst_q31_t hyst_q31_output(const hyst_tcm_t *S) { return S != NULL ? hyst_q31_view(S).y : 0; }

uint_least32_t hyst_q31_input(const hyst_tcm_t *S) { return S != NULL ? hyst_q31_view(S).x : 0u; }

hyst_q31_t hyst_q31_rounding_bound(const hyst_tcm_t *S) { return S != NULL ? S->rounding.q31 : 0; }

hyst_q31_t hyst_q31_error_bound(const hyst_tcm_t *S)
{
    return S != NULL ? hyst_q31_view(S).bound : 0;
}
