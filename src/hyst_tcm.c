/* The TCM engine with real inputs: validation, admission of samples, and the
 * shared engine (tcm_engine.inc) over hyst_real_t. */
#include "hyst/tcm.h"
#include "hyst_internal.h"

#include <float.h>
#include <stdint.h>

/* HYST_KEYED_SEARCH (config.h): search by bit patterns when hyst_real_t
 * is IEEE 754 binary32 or binary64. */
#if defined(HYST_USE_DOUBLE)
#define HYST_REAL_MANT_DIG_ DBL_MANT_DIG
#define HYST_REAL_MAX_EXP_ DBL_MAX_EXP
#else
#define HYST_REAL_MANT_DIG_ FLT_MANT_DIG
#define HYST_REAL_MAX_EXP_ FLT_MAX_EXP
#endif
#if HYST_KEYED_SEARCH && FLT_RADIX == 2 && HYST_REAL_MANT_DIG_ == 24 && HYST_REAL_MAX_EXP_ == 128
#define TCM_KEY_T int32_t
#define TCM_UKEY_T uint32_t
#elif HYST_KEYED_SEARCH && FLT_RADIX == 2 && HYST_REAL_MANT_DIG_ == 53 && HYST_REAL_MAX_EXP_ == 1024
#define TCM_KEY_T int64_t
#define TCM_UKEY_T uint64_t
#endif
#ifdef TCM_KEY_T
typedef char tcm_key_fits[sizeof(TCM_KEY_T) == sizeof(hyst_real_t) ? 1 : -1];
#endif

/* Out-of-line so the common path stays short: NaN/Inf or outside [lo, hi].
 * Returns 0 if the sample must be ignored, else 1 with *x clamped. */
static int admit_slow(hyst_t *S, hyst_real_t *x)
{
    const hyst_real_t v = *x;
    const hyst_real_t z = v - v;
    if (z != z) {
        S->status = HYST_ERR_NONFINITE;
        S->events |= HYST_EVENT_NONFINITE;
        return 0;
    }
    *x = v < S->curve.lo ? S->curve.lo : S->curve.hi;
    S->status = HYST_WARN_CLAMPED;
    S->events |= HYST_EVENT_CLAMPED;
    return 1;
}

static int tcm_admit(hyst_t *S, hyst_real_t x, hyst_real_t *out)
{
    *out = x;
    return (x >= S->curve.lo && x <= S->curve.hi) || admit_slow(S, out);
}

#define TCM_S hyst_t
#define TCM_X hyst_real_t
#define TCM_ARG hyst_real_t
#define TCM_IN hyst_real_t
#define TCM_LO(S) ((S)->curve.lo)
#define TCM_HI(S) ((S)->curve.hi)
#define TCM_R(a) (a)
#define TCM_D(a, b) ((a) - (b))
#define TCM_MID(a, b) ((a) + ((b) - (a)) * HYST_REAL_C(0.5))
#define TCM_NORM(a) ((a) + HYST_REAL_C(0.0)) /* -0 + +0 = +0 */
#include "tcm_engine.inc"

hyst_status_t hyst_init_curve(hyst_t *S, const hyst_curve_t *curve,
                              hyst_real_t *xltp, hyst_real_t *yltp,
                              hyst_real_t *xrtp, hyst_real_t *yrtp,
                              size_t capacity)
{
    const hyst_status_t st = tcm_check(S, xltp, yltp, xrtp, yrtp, capacity);
    if (curve == NULL) {
        return HYST_ERR_NULL;
    }
    if (st != HYST_OK) {
        return st;
    }
    if (hyst_curve_check(curve) != HYST_OK) {
        return HYST_ERR_ARG;
    }
    S->curve = *curve;
    tcm_attach(S, xltp, yltp, xrtp, yrtp, capacity);
    return HYST_OK;
}

hyst_status_t hyst_init(hyst_t *S, const hyst_poly_t *f0, hyst_real_t *xltp,
                        hyst_real_t *yltp, hyst_real_t *xrtp, hyst_real_t *yrtp,
                        size_t capacity)
{
    hyst_curve_t curve;
    hyst_status_t st = tcm_check(S, xltp, yltp, xrtp, yrtp, capacity);
    if (st == HYST_OK) {
        st = hyst_curve_from_poly(&curve, f0);
    }
    return st != HYST_OK ? st : hyst_init_curve(S, &curve, xltp, yltp, xrtp, yrtp, capacity);
}

void hyst_reset(hyst_t *S) { tcm_reset(S); }

void hyst_tcm_resume(hyst_t *S, hyst_real_t x, hyst_real_t y, const hyst_tcm_book_t *book)
{
    size_t i;
    /* The keyed search needs +0 where a TP is zero; snapshots of earlier
     * versions may hold -0 (an equal value: nothing else changes). */
    for (i = 0u; i < S->n_ltp; ++i) {
        S->xltp[i] = TCM_NORM(S->xltp[i]);
    }
    for (i = 0u; i < S->n_rtp; ++i) {
        S->xrtp[i] = TCM_NORM(S->xrtp[i]);
    }
    S->forgot = book->forgot;
    S->forgot_level = book->forgot_level;
    S->db_reach = book->db_reach;
    S->db_err = book->db_err;
    tcm_set_detour(S);
    settle_idle(S, x);
    S->y_prev = y;
}

hyst_status_t hyst_set_deadband(hyst_t *S, hyst_real_t width)
{
    if (S == NULL) {
        return HYST_ERR_NULL;
    }
    if (!(width >= 0 && width - width == 0)) { /* negative, NaN or infinite */
        return HYST_ERR_ARG;
    }
    S->deadband = width;
    tcm_set_detour(S);
    return HYST_OK;
}

hyst_real_t hyst_step(hyst_t *S, hyst_real_t x)
{
    return step(S, x);
}

hyst_status_t hyst_process(hyst_t *S, const hyst_real_t *x, hyst_real_t *y,
                           size_t n)
{
    return tcm_process(S, x, y, n);
}
