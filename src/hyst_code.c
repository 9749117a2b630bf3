/* The TCM engine over integer DAC codes: code range set-up, clamping, and
 * the shared engine (tcm_engine.inc) over hyst_code_word_t. */
#include "hyst/code.h"

/* Out of line: the common path is one compare. */
static hyst_code_word_t clamp_slow(hyst_code_t *S, uint_least32_t code)
{
    S->status = HYST_WARN_CLAMPED;
    S->events |= HYST_EVENT_CLAMPED;
    return code < S->lo ? S->lo : S->hi;
}

static int tcm_admit(hyst_code_t *S, uint_least32_t code, hyst_code_word_t *out)
{
    *out = code >= S->lo && code <= S->hi ? (hyst_code_word_t)code : clamp_slow(S, code);
    return 1;
}

#define TCM_S hyst_code_t
#define TCM_X hyst_code_word_t
#define TCM_ARG uint_least32_t
#define TCM_IN hyst_code_word_t
#define TCM_LO(S) ((S)->lo)
#define TCM_HI(S) ((S)->hi)
#define TCM_R(a) ((hyst_real_t)(a))
/* exact integer difference (a >= b), then one conversion */
#define TCM_D(a, b) ((hyst_real_t)(uint_least32_t)((uint_least32_t)(a) - (uint_least32_t)(b)))
#define TCM_MID(a, b) ((hyst_code_word_t)((a) + ((b) - (a)) / 2u))
#define TCM_NORM(a) (a)
#include "tcm_engine.inc"

hyst_status_t hyst_code_init_curve(hyst_code_t *S, const hyst_curve_t *curve,
                                   uint_least32_t code_lo, uint_least32_t code_hi,
                                   hyst_code_word_t *xltp, hyst_real_t *yltp,
                                   hyst_code_word_t *xrtp, hyst_real_t *yrtp,
                                   size_t capacity)
{
    const hyst_status_t st = tcm_check(S, xltp, yltp, xrtp, yrtp, capacity);
    if (curve == NULL) {
        return HYST_ERR_NULL;
    }
    if (st != HYST_OK) {
        return st;
    }
    if (!(code_lo < code_hi) || code_hi > HYST_CODE_MAX) {
        return HYST_ERR_DOMAIN;
    }
    if (hyst_curve_check(curve) != HYST_OK) {
        return HYST_ERR_ARG;
    }
    /* g takes d * inv_span (curve.h): a code difference is d in user units
     * times (hi - lo) / (code_hi - code_lo), folded in once, for every kind. */
    S->curve = *curve;
    S->curve.inv_span = (hyst_real_t)((hyst_wide_t)curve->inv_span *
                                      ((hyst_wide_t)curve->hi - (hyst_wide_t)curve->lo) /
                                      (hyst_wide_t)(code_hi - code_lo));
    S->lo = (hyst_code_word_t)code_lo;
    S->hi = (hyst_code_word_t)code_hi;
    tcm_attach(S, xltp, yltp, xrtp, yrtp, capacity);
    return HYST_OK;
}

hyst_status_t hyst_code_init(hyst_code_t *S, const hyst_poly_t *f0, uint_least32_t code_lo,
                             uint_least32_t code_hi, hyst_code_word_t *xltp,
                             hyst_real_t *yltp, hyst_code_word_t *xrtp, hyst_real_t *yrtp,
                             size_t capacity)
{
    hyst_curve_t curve;
    hyst_status_t st = tcm_check(S, xltp, yltp, xrtp, yrtp, capacity);
    if (st == HYST_OK) {
        st = hyst_curve_from_poly(&curve, f0);
    }
    return st != HYST_OK ? st
                         : hyst_code_init_curve(S, &curve, code_lo, code_hi, xltp, yltp, xrtp,
                                                yrtp, capacity);
}

void hyst_code_reset(hyst_code_t *S) { tcm_reset(S); }

hyst_status_t hyst_code_set_deadband(hyst_code_t *S, uint_least32_t codes)
{
    if (S == NULL) {
        return HYST_ERR_NULL;
    }
    if (codes > (uint_least32_t)(S->hi - S->lo)) {
        return HYST_ERR_ARG;
    }
    S->deadband = (hyst_code_word_t)codes;
    tcm_set_detour(S);
    return HYST_OK;
}

hyst_real_t hyst_code_step(hyst_code_t *S, uint_least32_t code)
{
    return step(S, code);
}

hyst_status_t hyst_code_process(hyst_code_t *S, const hyst_code_word_t *x, hyst_real_t *y,
                                size_t n)
{
    return tcm_process(S, x, y, n);
}
