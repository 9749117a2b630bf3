/* SPDX-License-Identifier: MIT */
/* What every variant of the TCM instance shares, written once: the checks
 * of an init, reset, counts, status and events. The per-sample engine is
 * src/tcm_engine.h, instantiated per variant. */
#include "hyst_util.h"

#include <stdint.h>

int hyst_ranges_overlap(const void *a, size_t na, const void *b, size_t nb)
{
    /* Compared as integers: relational operators on pointers into different
     * objects are undefined. */
    const uintptr_t pa = (uintptr_t)a, pb = (uintptr_t)b;
    return pa < pb + nb && pb < pa + na;
}

int hyst_block_overlap(const void *x, size_t xsize, const void *y, size_t ysize, size_t n)
{
    if (y == x && ysize <= xsize) {
        return 0;
    }
    return hyst_ranges_overlap(x, n * xsize, y, n * ysize);
}

/* n entries of `size` bytes take at most half the address space. By sums,
 * not a division: a core without one (Cortex-M0) links no division
 * routine for this check. */
static int hyst_fits_half(size_t n, size_t size)
{
    const size_t half = (size_t)-1 / 2u;
    size_t bytes = 0u, k;
    for (k = 0u; k < size; ++k) {
        if (n > half - bytes) { /* bytes + n > half, without overflow */
            return 0;
        }
        bytes += n;
    }
    return 1;
}

hyst_status_t hyst_check_memory(const hyst_tcm_t *S, const void *xltp, const void *yltp,
                                const void *xrtp, const void *yrtp, size_t capacity,
                                size_t xsize, size_t ysize, unsigned long layout)
{
    const void *arrays[4];
    size_t sizes[4];
    size_t i, j;
    if (S == NULL || xltp == NULL || yltp == NULL || xrtp == NULL || yrtp == NULL) {
        return HYST_ERR_NULL;
    }
    if (layout != HYST_LAYOUT) {
        return HYST_ERR_LAYOUT;
    }
    if (capacity < 2u || !hyst_fits_half(capacity, xsize > ysize ? xsize : ysize)) {
        return HYST_ERR_CAPACITY;
    }
    arrays[0] = xltp;
    arrays[1] = yltp;
    arrays[2] = xrtp;
    arrays[3] = yrtp;
    sizes[0] = sizes[2] = capacity * xsize;
    sizes[1] = sizes[3] = capacity * ysize;
    for (i = 0u; i < 4u; ++i) {
        if (hyst_ranges_overlap(arrays[i], sizes[i], S, sizeof *S)) {
            return HYST_ERR_OVERLAP;
        }
        for (j = i + 1u; j < 4u; ++j) {
            if (hyst_ranges_overlap(arrays[i], sizes[i], arrays[j], sizes[j])) {
                return HYST_ERR_OVERLAP;
            }
        }
    }
    return HYST_OK;
}

hyst_status_t hyst_check_init(const hyst_tcm_t *S, const hyst_curve_t *curve,
                              unsigned curve_variant, const void *xltp, const void *yltp,
                              const void *xrtp, const void *yrtp, size_t capacity, size_t xsize,
                              size_t ysize, unsigned long layout)
{
    hyst_status_t st =
        hyst_check_memory(S, xltp, yltp, xrtp, yrtp, capacity, xsize, ysize, layout);
    if (st == HYST_OK) {
        st = hyst_curve_check(curve);
    }
    if (st == HYST_ERR_ARG && (curve->kind == (unsigned)HYST_CURVE_EVERETT_GRID ||
                               curve->kind == (unsigned)HYST_CURVE_EVERETT_GRID_INV)) {
        st = hyst_everett_grid_check_(curve);
    }
    if (st == HYST_ERR_ARG && (curve->kind == (unsigned)HYST_CURVE_SPLINE ||
                               curve->kind == (unsigned)HYST_CURVE_SPLINE_INV ||
                               curve->kind == (unsigned)HYST_CURVE_SPLINE_INV_TABLE)) {
        st = hyst_spline_check_(curve);
    }
    if (st == HYST_OK && curve->variant != curve_variant) {
        st = HYST_ERR_LAYOUT;
    }
    return st;
}

void hyst_reset(hyst_tcm_t *S)
{
    if (S == NULL || S->layout != HYST_LAYOUT) {
        return;
    }
    switch (S->variant) {
    case HYST_VARIANT_F32: hyst_f32_reset_(S); break;
#if HYST_ENABLE_F64
    case HYST_VARIANT_F64: hyst_f64_reset_(S); break;
#endif
    case HYST_VARIANT_CODE: hyst_code_reset_(S); break;
    case HYST_VARIANT_Q31: hyst_q31_reset_(S); break;
    case HYST_VARIANT_Q31_INV: hyst_q31_inv_reset_(S); break;
    default: break; /* not initialised */
    }
}

#if !(defined(__GNUC__) || defined(__clang__))
void hyst_barrier_(void) {}
#endif

hyst_status_t hyst_post_request_(hyst_tcm_t *S, unsigned *counter)
{
    ++*counter; /* written by this context only */
    HYST_BARRIER(); /* the request's data before the flag that routes the step to it */
    ((volatile hyst_tcm_t *)S)->horner = HYST_HORNER_REQUEST_;
    return HYST_OK;
}

hyst_status_t hyst_codes_deadband_check_(const hyst_tcm_t *S, unsigned variant,
                                         uint_least32_t codes)
{
    if (S == NULL) {
        return HYST_ERR_NULL;
    }
    if (S->variant != variant || codes > (uint_least32_t)(S->hi.code - S->lo.code)) {
        return HYST_ERR_ARG;
    }
    return HYST_OK;
}

hyst_status_t hyst_codes_request_deadband_(hyst_tcm_t *S, unsigned variant, uint_least32_t codes)
{
    const hyst_status_t st = hyst_codes_deadband_check_(S, variant, codes);
    if (st != HYST_OK) {
        return st;
    }
    S->req_width.code = (hyst_code_word_t)codes; /* before the counter */
    return hyst_post_request_(S, &S->req_deadband);
}

/* An instance whose variant's engine can serve requests. */
static int initialised(const hyst_tcm_t *S)
{
    return S->layout == HYST_LAYOUT &&
           (S->variant == (unsigned)HYST_VARIANT_F32 || S->variant == (unsigned)HYST_VARIANT_CODE ||
            S->variant == (unsigned)HYST_VARIANT_Q31 || S->variant == (unsigned)HYST_VARIANT_Q31_INV
#if HYST_ENABLE_F64
            || S->variant == (unsigned)HYST_VARIANT_F64
#endif
           );
}

hyst_status_t hyst_request_reset(hyst_tcm_t *S)
{
    if (S == NULL) {
        return HYST_ERR_NULL;
    }
    return initialised(S) ? hyst_post_request_(S, &S->req_reset) : HYST_ERR_ARG;
}

hyst_status_t hyst_request_clear_events(hyst_tcm_t *S)
{
    if (S == NULL) {
        return HYST_ERR_NULL;
    }
    return initialised(S) ? hyst_post_request_(S, &S->req_clear) : HYST_ERR_ARG;
}

int hyst_request_pending(const hyst_tcm_t *S)
{
    const volatile hyst_tcm_t *V = S;
    return S != NULL && (V->req_reset != V->done_reset || V->req_clear != V->done_clear ||
                         V->req_deadband != V->done_deadband);
}

int hyst_status(const hyst_tcm_t *S) { return S != NULL ? S->status : HYST_ERR_NULL; }

unsigned hyst_events(const hyst_tcm_t *S) { return S != NULL ? S->events : 0u; }

void hyst_clear_events(hyst_tcm_t *S)
{
    if (S != NULL) {
        S->events = 0u;
        ++S->seq;
    }
}

/* n_ltp and n_rtp as one consistent pair, read from any context: the step
 * changes them only with seq. */
static void counts(const hyst_tcm_t *S, size_t *nl, size_t *nr)
{
    const volatile hyst_tcm_t *V = S;
    unsigned attempt;
    for (attempt = 0u; attempt < HYST_READ_ATTEMPTS; ++attempt) {
        const unsigned long seq = V->seq;
        HYST_BARRIER();
        *nl = V->n_ltp;
        *nr = V->n_rtp;
        HYST_BARRIER();
        /* a volatile re-read: the stepping context may have changed it
         * (cppcheck takes it for the value read above) */
        /* cppcheck-suppress knownConditionTrueFalse */
        if (seq == V->seq) {
            break;
        }
    }
}

size_t hyst_ltp_count(const hyst_tcm_t *S) { return S != NULL ? S->n_ltp - 1u : 0u; }

size_t hyst_rtp_count(const hyst_tcm_t *S) { return S != NULL ? S->n_rtp : 0u; }

size_t hyst_tp_count(const hyst_tcm_t *S)
{
    size_t nl = 1u, nr = 0u;
    if (S != NULL) {
        counts(S, &nl, &nr);
    }
    return nl - 1u + nr;
}

int hyst_rising(const hyst_tcm_t *S)
{
    size_t nl = 1u, nr = 1u;
    if (S != NULL) {
        counts(S, &nl, &nr);
    }
    return nl > nr;
}

size_t hyst_capacity(const hyst_tcm_t *S) { return S != NULL ? S->capacity : 0u; }
