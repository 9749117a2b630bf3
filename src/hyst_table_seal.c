/* SPDX-License-Identifier: MIT */
/* Seals of what is built ahead of time (curve.h): a tabulated inverse (a
 * checksum of the table as stored, its shape and the error its build
 * measured) and a polynomial curve's prepared numbers, so that firmware
 * takes them from flash without building them again, and refuses them
 * damaged. */
#include <float.h>
#include <stdint.h>

#include "hyst_util.h"

hyst_wide_t hyst_table_err_(hyst_wide_t err)
{
    float f = (float)err;
    if ((hyst_wide_t)f < err) { /* rounded down: the next float up */
        f += f * FLT_EPSILON;
    }
    return (hyst_wide_t)f;
}

/* Numbers of a table of this kind and shape. */
static unsigned long table_len(unsigned kind, unsigned long rows, unsigned long intervals)
{
    return kind == (unsigned)HYST_CURVE_EVERETT_INV_TABLE
               ? HYST_EVERETT_INV_TABLE_LEN(rows, intervals)
               : HYST_INV_TABLE_LEN(intervals);
}

/* The checksum: kind, variant, shape, the error as a float, every number. */
static unsigned long table_crc(unsigned kind, unsigned variant, hyst_cptr_t table,
                               unsigned long rows, unsigned long intervals, hyst_wide_t max_err)
{
    const unsigned long n = table_len(kind, rows, intervals);
    unsigned long crc = hyst_crc_word_(0ul, kind);
    crc = hyst_crc_word_(crc, variant);
    crc = hyst_crc_word_(crc, rows);
    crc = hyst_crc_word_(crc, intervals);
    crc = hyst_crc_real_(crc, max_err, HYST_VARIANT_F32);
    return hyst_crc_table_(crc, table, (size_t)n, variant);
}

static int real_variant(unsigned variant)
{
    return variant == (unsigned)HYST_VARIANT_F32
#if HYST_ENABLE_F64
           || variant == (unsigned)HYST_VARIANT_F64
#endif
        ;
}

hyst_status_t hyst_curve_table_seal(const hyst_curve_t *inv, hyst_table_seal_t *seal)
{
    const hyst_status_t st = hyst_curve_check(inv);
    unsigned long rows, intervals;
    hyst_cptr_t table;
    hyst_wide_t err;
    if (st != HYST_OK || seal == NULL) {
        return st != HYST_OK ? st : HYST_ERR_NULL;
    }
    if (!real_variant(inv->variant)) {
        return HYST_ERR_ARG;
    }
    if (inv->kind == (unsigned)HYST_CURVE_EVERETT_INV_TABLE) {
        rows = (unsigned long)inv->u.everett.rows;
        intervals = (unsigned long)inv->u.everett.intervals;
        table = inv->u.everett.table;
        err = inv->u.everett.max_err;
    } else if (inv->kind == (unsigned)HYST_CURVE_INV_TABLE) {
        rows = 0ul;
        intervals = (unsigned long)inv->u.inv_table.intervals;
        table = inv->u.inv_table.table;
        err = inv->u.inv_table.max_err;
    } else {
        return HYST_ERR_ARG;
    }
    seal->max_err = hyst_table_err_(err);
    seal->crc = table_crc(inv->kind, inv->variant, table, rows, intervals, seal->max_err);
    return HYST_OK;
}

hyst_status_t hyst_table_seal_check_(unsigned kind, unsigned variant, hyst_cptr_t table,
                                     size_t rows, size_t intervals, const hyst_table_seal_t *seal)
{
    const hyst_wide_t err = seal->max_err;
    if (!(err >= 0 && err <= 1) || hyst_table_err_(err) != err ||
        table_crc(kind, variant, table, (unsigned long)rows, (unsigned long)intervals, err) !=
            (seal->crc & 0xFFFFFFFFul)) {
        return HYST_ERR_CRC;
    }
    return HYST_OK;
}

int hyst_table_shape_ok_(hyst_cptr_t table, size_t base, size_t intervals, unsigned variant)
{
    const hyst_wide_t end = hyst_cptr_get(table, base + 4u * intervals, variant);
    hyst_wide_t knot = 0;
    size_t k;
    unsigned i;
    if (!hyst_wide_is_finite(end) || !(end >= 0)) {
        return 0;
    }
    for (k = 0u; k < intervals; ++k) {
        const hyst_wide_t c0 = hyst_cptr_get(table, base + 4u * k, variant);
        for (i = 1u; i < 4u; ++i) {
            const hyst_wide_t c = hyst_cptr_get(table, base + 4u * k + i, variant);
            if (!hyst_wide_is_finite(c) || (c0 < 0 && c != 0)) {
                return 0;
            }
        }
        if (c0 < 0) { /* solved instead: the mark, -1 0 0 0 */
            if (c0 != -1) {
                return 0;
            }
        } else if (!(c0 >= knot && c0 <= end)) { /* NaN too */
            return 0;
        } else {
            knot = c0;
        }
    }
    return 1;
}

/* Bumped when the sealed numbers change meaning: an old seal is refused. */
#define POLY_SEAL_FORMAT 0x48535031ul /* "HSP1" */

unsigned long hyst_poly_seal_crc_(const hyst_curve_t *curve)
{
    const unsigned v = curve->variant;
    const unsigned x = v == (unsigned)HYST_VARIANT_Q31 ? (unsigned)HYST_VARIANT_CODE : v;
    const unsigned n = curve->u.poly.degree;
    unsigned long crc = hyst_crc_word_(0ul, POLY_SEAL_FORMAT);
    unsigned k;
    crc = hyst_crc_word_(crc, curve->kind);
    crc = hyst_crc_word_(crc, v);
    crc = hyst_crc_word_(crc, n);
    crc = hyst_crc_num_(crc, &curve->lo, x);
    crc = hyst_crc_num_(crc, &curve->hi, x);
    crc = hyst_crc_num_(crc, &curve->y_lo, v);
    crc = hyst_crc_num_(crc, &curve->y_hi, v);
    crc = hyst_crc_num_(crc, &curve->unit, v);
    crc = hyst_crc_num_(crc, &curve->rounding, v);
    for (k = 0u; k < n && k < HYST_MAX_DEGREE; ++k) {
        crc = hyst_crc_num_(crc, &curve->u.poly.a[k], v);
    }
    return crc & 0xFFFFFFFFul;
}

hyst_wide_t hyst_wide_of_float_(float v)
{
#if !defined(HYST_NO_DOUBLE) && DBL_MANT_DIG == 53 && DBL_MAX_EXP == 1024 && FLT_MANT_DIG == 24 && \
    FLT_MAX_EXP == 128
    /* IEEE binary32 to binary64 by its fields: exact, and integer work only */
    union {
        float r;
        uint32_t u;
    } f;
    union {
        hyst_wide_t r;
        uint64_t u;
    } d;
    uint32_t exp, man;
    f.r = v;
    exp = (f.u >> 23) & 0xFFu;
    man = f.u & 0x7FFFFFu;
    d.u = (uint64_t)(f.u >> 31) << 63;
    if (exp == 0xFFu) {
        d.u |= (uint64_t)0x7FFu << 52 | (uint64_t)man << 29; /* Inf, NaN */
    } else if (exp != 0u || man != 0u) {
        uint32_t e = exp + (1023u - 127u);
        if (exp == 0u) { /* subnormal: normalised */
            e = 1023u - 126u;
            while ((man & 0x800000u) == 0u) {
                man <<= 1u;
                --e;
            }
            man &= 0x7FFFFFu;
        }
        d.u |= (uint64_t)e << 52 | (uint64_t)man << 29;
    }
    return d.r;
#else
    return (hyst_wide_t)v;
#endif
}

#define INVERSE_SEAL_FORMAT 0x48534931ul /* "HSI1" */

unsigned long hyst_inverse_seal_crc_(const hyst_curve_t *inv, const hyst_num_t *max_err)
{
    const unsigned v = inv->variant;
    const unsigned n = inv->u.inv_table.fwd.degree;
    const unsigned long len = HYST_INV_TABLE_LEN((unsigned long)inv->u.inv_table.intervals);
    const hyst_num_t *const num[7] = {&inv->lo,   &inv->hi,   &inv->y_lo,
                                      &inv->y_hi, &inv->unit, &inv->u.inv_table.span,
                                      &inv->u.inv_table.u_per_d};
    unsigned long crc = hyst_crc_word_(0ul, INVERSE_SEAL_FORMAT), i;
    unsigned k;
    crc = hyst_crc_word_(crc, inv->kind);
    crc = hyst_crc_word_(crc, v);
    crc = hyst_crc_word_(crc, n);
    crc = hyst_crc_word_(crc, (unsigned long)inv->u.inv_table.intervals);
    crc = hyst_crc_word_(crc, (unsigned long)inv->u.inv_table.exact);
    crc = hyst_crc_num_(crc, max_err, (unsigned)HYST_VARIANT_F32);
    for (k = 0u; k < 7u; ++k) {
        crc = hyst_crc_num_(crc, num[k], v);
    }
    for (k = 0u; k < n && k < HYST_MAX_DEGREE; ++k) {
        crc = hyst_crc_num_(crc, &inv->u.inv_table.fwd.a[k], v);
    }
    for (i = 0ul; i < len; ++i) {
        hyst_num_t t;
        if (v == (unsigned)HYST_VARIANT_F32) {
            t.f32 = inv->u.inv_table.table.f32[i];
        }
#if HYST_ENABLE_F64
        else {
            t.f64 = inv->u.inv_table.table.f64[i];
        }
#endif
        crc = hyst_crc_num_(crc, &t, v);
    }
    return crc & 0xFFFFFFFFul;
}
