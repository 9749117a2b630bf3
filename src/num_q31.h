/* SPDX-License-Identifier: MIT */
/* Number type descriptor of the q31 variants (src/hyst_q31.c: the model,
 * src/hyst_q31_inv.c: its compensator), for src/num_ops.h: hyst_q31_t
 * numbers, Horner's products in fixed point, the saturating error bound and
 * the tabulated inverse's cubic. The including file defines NUM_NAME and
 * NUM_VARIANT first. Scaling: include/hyst/q31.h. */
#ifndef HYST_NUM_Q31_H
#define HYST_NUM_Q31_H

#include "hyst/q31.h"

#include "hyst_util.h"

#if !defined(NUM_NAME) || !defined(NUM_VARIANT)
#error "num_q31.h: define NUM_NAME and NUM_VARIANT first"
#endif

#define NUM_T hyst_q31_t
#define NUM_F q31
#define NUM_C(v) (v)
#define NUM_EPS 1
#define NUM_FIXED 1
/* Horner's step in the coefficients' format (v in Q30): the high part of
 * a 64-bit product, one SMULL and a shift on Cortex-M3 (>> of a negative
 * value is arithmetic on every supported compiler). G's final product lands
 * in the output's format, HYST_Q31_GUARD_BITS finer. */
#define NUM_MUL(a, b) ((hyst_q31_t)(((int_least64_t)(a) * (b)) >> HYST_Q31_U_BITS))
#define NUM_MUL_G(a, b) \
    ((hyst_q31_t)(((int_least64_t)(a) * (b)) >> (HYST_Q31_U_BITS - HYST_Q31_GUARD_BITS)))

/* An error bound plus e >= 0, saturated at HYST_Q31_BOUND_MAX (merges add
 * up; each e is below 2^30, so the test cannot overflow). */
static hyst_q31_t NUM_NAME(add_bound)(hyst_q31_t a, hyst_q31_t e)
{
    return a >= HYST_Q31_BOUND_MAX - e ? HYST_Q31_BOUND_MAX : a + e;
}

/* The compensator's table (q31.h, "Compensator") at an output step u in
 * 0..2^28 (q): s = u N / 2^28 by one 32 x 32 -> 64-bit product with the
 * table's scale tab[-1] = 16 N, whose high word is the interval k and low
 * word the position in it (Q32). A marked interval gives a negative value. */
HYST_INLINE uint_least64_t NUM_NAME(table_s)(const hyst_q31_t *tab, hyst_q31_t u)
{
    return (uint_least64_t)(uint_least32_t)u * (uint_least32_t)tab[-1];
}

/* The interval k of an output step u. */
HYST_INLINE unsigned long NUM_NAME(table_interval)(const hyst_q31_t *tab, hyst_q31_t u)
{
    return (unsigned long)(NUM_NAME(table_s)(tab, u) >> 32);
}

HYST_INLINE hyst_q31_t NUM_NAME(table_g)(const hyst_q31_t *tab, hyst_q31_t u)
{
    const uint_least64_t s = NUM_NAME(table_s)(tab, u);
    return hyst_q31_cubic_(tab + 4u * (unsigned long)(s >> 32), HYST_Q31_MID_(s));
}

#endif /* HYST_NUM_Q31_H */
