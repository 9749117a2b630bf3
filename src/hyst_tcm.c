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
    if (capacity < 2u || capacity > (size_t)-1 / 2u / (xsize > ysize ? xsize : ysize)) {
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
    default: break; /* not initialised */
    }
}

int hyst_status(const hyst_tcm_t *S) { return S != NULL ? S->status : HYST_ERR_NULL; }

unsigned hyst_events(const hyst_tcm_t *S) { return S != NULL ? S->events : 0u; }

void hyst_clear_events(hyst_tcm_t *S)
{
    if (S != NULL) {
        S->events = 0u;
    }
}

size_t hyst_ltp_count(const hyst_tcm_t *S) { return S != NULL ? S->n_ltp - 1u : 0u; }

size_t hyst_rtp_count(const hyst_tcm_t *S) { return S != NULL ? S->n_rtp : 0u; }

size_t hyst_tp_count(const hyst_tcm_t *S) { return S != NULL ? S->n_ltp - 1u + S->n_rtp : 0u; }

int hyst_rising(const hyst_tcm_t *S) { return S != NULL && S->n_ltp > S->n_rtp; }

size_t hyst_capacity(const hyst_tcm_t *S) { return S != NULL ? S->capacity : 0u; }
