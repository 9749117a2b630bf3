/* Library-internal entry points shared between modules; not installed. */
#ifndef HYST_INTERNAL_H
#define HYST_INTERNAL_H

#include "hyst/tcm.h"

/* What bounded memory keeps besides the TPs: the stack level of the
 * shallowest live merge ((size_t)-1: none), its error bound, and the
 * deadband window (widest skipped reversal and its bound). */
typedef struct {
    size_t forgot_level;
    hyst_real_t forgot;
    hyst_real_t db_reach;
    hyst_real_t db_err;
} hyst_tcm_book_t;

/* Re-derives the per-sample cache of S from its TP arrays and counts, with
 * (x, y) as the last valid sample and the saved bookkeeping (snapshot
 * restore). */
void hyst_tcm_resume(hyst_t *S, hyst_real_t x, hyst_real_t y, const hyst_tcm_book_t *book);

/* Finite test without libm: NaN fails v == v, +-Inf gives Inf - Inf = NaN. */
HYST_INLINE int hyst_wide_is_finite(hyst_wide_t v)
{
    const hyst_wide_t z = v - v;
    return z == z;
}

#endif
