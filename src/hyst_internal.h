/* Library-internal entry points shared between modules; not installed. */
#ifndef HYST_INTERNAL_H
#define HYST_INTERNAL_H

#include "hyst/tcm.h"

/* Re-derives the per-sample cache of S from its TP arrays and counts, with
 * (x, y) as the last valid sample (snapshot restore). */
void hyst_tcm_resume(hyst_t *S, hyst_real_t x, hyst_real_t y);

/* Finite test without libm: NaN fails v == v, +-Inf gives Inf - Inf = NaN. */
HYST_INLINE int hyst_wide_is_finite(hyst_wide_t v)
{
    const hyst_wide_t z = v - v;
    return z == z;
}

#endif
