/* SPDX-License-Identifier: MIT */
/**
 * @file inverse.h
 * @brief The inverse TCM: a feedforward compensator (docs/theory.md).
 *
 * The inverse of a TCM with curve f0 on [lo, hi] is a TCM in the (y, x)
 * plane with curve f0^-1 on [f0(lo), f0(hi)]: the same engine (hyst_tcm_t,
 * hyst_*_step()) on an inverse curve (hyst_curve_inverse()). Its input is
 * the desired displacement, its output the drive that produces it on the
 * model:
 * @code
 * HYST_DEFINE_INVERSE(comp, 4096);     // instance, TP arrays, inverse table
 * if (HYST_INIT_INVERSE(comp, &f0) != HYST_OK) { handle_error(); }
 * for (;;) { dac_write(hyst_step(&comp, desired_position())); }
 * @endcode
 * A desired output outside [f0(lo), f0(hi)] is clamped to it and reported
 * (hyst_status() == HYST_WARN_CLAMPED, event HYST_EVENT_CLAMPED).
 * The turning points are desired outputs: HYST_CAPACITY(Nu) suffices when
 * they take at most Nu distinct values.
 */
#ifndef HYST_INVERSE_H
#define HYST_INVERSE_H

#include "hyst/curve.h"
#include "hyst/tcm.h"

#ifdef __cplusplus
extern "C" {
#endif

/**
 * @name Compensator of a polynomial model, exact
 * @brief Initialises @p S as the inverse of the TCM with the polynomial @p f0,
 *        evaluated exactly (the reference: tests, host tools; the firmware's
 *        compensator is the tabulated one below).
 *
 * hyst_*_curve_from_poly() and hyst_curve_inverse() into @p inv (caller
 * storage that must outlive the instance), then hyst_*_init_curve(), in this
 * order (a curve error is reported before an instance error). g^-1 costs at
 * most 2 HYST_INV_MAX_ITER evaluations of f0 per sample, and the drive is
 * non-decreasing in the desired output along a branch. Firmware wants the
 * tabulated compensator below (HYST_INIT_INVERSE), about ten times cheaper.
 * For a curve of another kind (piecewise linear, PI loading curve) call
 * hyst_curve_inverse() and hyst_*_init_curve() directly.
 * @return HYST_OK, HYST_ERR_NULL, HYST_ERR_LAYOUT, HYST_ERR_CAPACITY,
 *         HYST_ERR_OVERLAP, a curve error or HYST_ERR_NOT_INVERTIBLE.
 */
/**@{*/
hyst_status_t hyst_f32_init_inverse_exact_(hyst_tcm_t *S, hyst_curve_t *inv,
                                           const hyst_poly_t *f0, float *xltp, float *yltp,
                                           float *xrtp, float *yrtp, size_t capacity,
                                           unsigned long layout);
#define hyst_f32_init_inverse_exact(S, inv, f0, xltp, yltp, xrtp, yrtp, capacity)              \
    hyst_f32_init_inverse_exact_((S), (inv), (f0), (xltp), (yltp), (xrtp), (yrtp), (capacity), \
                                 HYST_LAYOUT)
#if HYST_ENABLE_F64
hyst_status_t hyst_f64_init_inverse_exact_(hyst_tcm_t *S, hyst_curve_t *inv,
                                           const hyst_poly_t *f0, double *xltp, double *yltp,
                                           double *xrtp, double *yrtp, size_t capacity,
                                           unsigned long layout);
#define hyst_f64_init_inverse_exact(S, inv, f0, xltp, yltp, xrtp, yrtp, capacity)              \
    hyst_f64_init_inverse_exact_((S), (inv), (f0), (xltp), (yltp), (xrtp), (yrtp), (capacity), \
                                 HYST_LAYOUT)
#endif
#define hyst_init_inverse_exact HYST_DEFAULT_NAME_(init_inverse_exact)
/**@}*/

/**
 * @name Compensator of a polynomial model, tabulated
 * @brief As the exact compensator, with the inverse tabulated
 *        (hyst_*_curve_inverse_table()) into @p table, caller storage of
 *        HYST_INV_TABLE_LEN(@p intervals) numbers that must outlive the
 *        instance: a sample costs an index and one cubic, inline (the
 *        intervals next to a flat point of f0 are evaluated exactly), and
 *        the error against the exact inverse is at most
 *        hyst_curve_inverse_error(@p inv) of the drive range.
 * @return as the exact compensator, and HYST_ERR_ARG for @p intervals
 *         outside 1 .. 2^20.
 */
/**@{*/
hyst_status_t hyst_f32_init_inverse_table_(hyst_tcm_t *S, hyst_curve_t *inv,
                                           const hyst_poly_t *f0, float *table,
                                           size_t intervals, float *xltp, float *yltp,
                                           float *xrtp, float *yrtp, size_t capacity,
                                           unsigned long layout);
#define hyst_f32_init_inverse_table(S, inv, f0, table, intervals, xltp, yltp, xrtp, yrtp,     \
                                    capacity)                                                \
    hyst_f32_init_inverse_table_((S), (inv), (f0), (table), (intervals), (xltp), (yltp),     \
                                 (xrtp), (yrtp), (capacity), HYST_LAYOUT)
#if HYST_ENABLE_F64
hyst_status_t hyst_f64_init_inverse_table_(hyst_tcm_t *S, hyst_curve_t *inv,
                                           const hyst_poly_t *f0, double *table,
                                           size_t intervals, double *xltp, double *yltp,
                                           double *xrtp, double *yrtp, size_t capacity,
                                           unsigned long layout);
#define hyst_f64_init_inverse_table(S, inv, f0, table, intervals, xltp, yltp, xrtp, yrtp,     \
                                    capacity)                                                \
    hyst_f64_init_inverse_table_((S), (inv), (f0), (table), (intervals), (xltp), (yltp),     \
                                 (xrtp), (yrtp), (capacity), HYST_LAYOUT)
#endif
#define hyst_init_inverse_table HYST_DEFAULT_NAME_(init_inverse_table)
/**@}*/

/**
 * @name Tabulated compensator sealed ahead of time
 * @brief The tabulated compensator's prepared curve (hyst_*_init_inverse_table()),
 *        made and measured on the host (`hyst header --compensator --sealed`,
 *        hyst_*_seal_inverse_table()) and sealed with a CRC-32 over its
 *        numbers and every number of its table, so that firmware takes both
 *        from flash with hyst_*_init_inverse_sealed(): integer checks only,
 *        no table built or measured, no curve construction.
 *
 * hyst_*_seal_inverse_table() seals a curve made by
 * hyst_*_curve_inverse_table() (or hyst_*_init_inverse_table()) with its
 * table: HYST_ERR_ARG for another kind; it measures the table first, every
 * piece as hyst_*_curve_inverse_table_const() does, and refuses one changed
 * since its build or claiming less than its measured error (HYST_ERR_CURVE,
 * nothing written). The init checks the arrays, the
 * caller's layout, the degree and intervals, then the seal over the struct
 * and @p table (HYST_ERR_CRC when a number of either differs from the ones
 * sealed), writes the curve into @p inv (caller storage that, like
 * @p table, must outlive the instance) and gives the instance
 * hyst_*_init_inverse_table() makes, bit for bit.
 */
/**@{*/
typedef struct hyst_f32_sealed_inverse {
    unsigned long seal;       /**< CRC-32 of the format, kind, variant, numbers and table */
    unsigned degree;          /**< the forward polynomial's n */
    float lo, hi;             /**< the compensator's domain: f0(lo), f0(hi) */
    float y_lo, y_hi;         /**< its drives there: lo, hi */
    float unit;               /**< table intervals per output step */
    float span, u_per_d;      /**< the drive's span hi - lo and its inverse */
    float a[HYST_MAX_DEGREE]; /**< the forward G's coefficients (the exact intervals) */
    unsigned long intervals;  /**< N: the table holds HYST_INV_TABLE_LEN(N) numbers */
    unsigned long exact;      /**< intervals evaluated exactly */
    float max_err;            /**< hyst_curve_inverse_error() of the build (a float) */
} hyst_f32_sealed_inverse_t;
hyst_status_t hyst_f32_seal_inverse_table(hyst_f32_sealed_inverse_t *out, const hyst_curve_t *inv);
hyst_status_t hyst_f32_init_inverse_sealed_(hyst_tcm_t *S, hyst_curve_t *inv,
                                            const hyst_f32_sealed_inverse_t *sealed,
                                            const float *table, float *xltp, float *yltp,
                                            float *xrtp, float *yrtp, size_t capacity,
                                            unsigned long layout);
#define hyst_f32_init_inverse_sealed(S, inv, sealed, table, xltp, yltp, xrtp, yrtp, capacity) \
    hyst_f32_init_inverse_sealed_((S), (inv), (sealed), (table), (xltp), (yltp), (xrtp),      \
                                  (yrtp), (capacity), HYST_LAYOUT)
#if HYST_ENABLE_F64
typedef struct hyst_f64_sealed_inverse {
    unsigned long seal;        /**< CRC-32 of the format, kind, variant, numbers and table */
    unsigned degree;           /**< the forward polynomial's n */
    double lo, hi;             /**< the compensator's domain: f0(lo), f0(hi) */
    double y_lo, y_hi;         /**< its drives there: lo, hi */
    double unit;               /**< table intervals per output step */
    double span, u_per_d;      /**< the drive's span hi - lo and its inverse */
    double a[HYST_MAX_DEGREE]; /**< the forward G's coefficients (the exact intervals) */
    unsigned long intervals;   /**< N: the table holds HYST_INV_TABLE_LEN(N) numbers */
    unsigned long exact;       /**< intervals evaluated exactly */
    float max_err;             /**< hyst_curve_inverse_error() of the build (a float) */
} hyst_f64_sealed_inverse_t;
hyst_status_t hyst_f64_seal_inverse_table(hyst_f64_sealed_inverse_t *out, const hyst_curve_t *inv);
hyst_status_t hyst_f64_init_inverse_sealed_(hyst_tcm_t *S, hyst_curve_t *inv,
                                            const hyst_f64_sealed_inverse_t *sealed,
                                            const double *table, double *xltp, double *yltp,
                                            double *xrtp, double *yrtp, size_t capacity,
                                            unsigned long layout);
#define hyst_f64_init_inverse_sealed(S, inv, sealed, table, xltp, yltp, xrtp, yrtp, capacity) \
    hyst_f64_init_inverse_sealed_((S), (inv), (sealed), (table), (xltp), (yltp), (xrtp),      \
                                  (yrtp), (capacity), HYST_LAYOUT)
#endif
#ifdef HYST_USE_DOUBLE
typedef hyst_f64_sealed_inverse_t hyst_sealed_inverse_t;
#else
typedef hyst_f32_sealed_inverse_t hyst_sealed_inverse_t;
#endif
#define hyst_seal_inverse_table HYST_DEFAULT_NAME_(seal_inverse_table)
#define hyst_init_inverse_sealed HYST_DEFAULT_NAME_(init_inverse_sealed)
/** The sealed compensator on an instance declared by a DEFINE macro; @p inv
 *  a hyst_curve_t that outlives it, @p table the sealed table. */
#define HYST_INIT_INVERSE_SEALED(name, inv, sealed, table)                                 \
    HYST_DEFAULT_NAME_(init_inverse_sealed_)(&(name), (inv), (sealed), (table),           \
                                             HYST_ARRAYS_(name), HYST_LAYOUT)
/**@}*/

/** A compensator's instance, arrays, inverse curve and table of HYST_INV_TABLE
 *  intervals, statically (default variant). */
#define HYST_DEFINE_INVERSE(name, nu)                                   \
    static hyst_curve_t name##_curve;                                   \
    static hyst_real_t name##_table[HYST_INV_TABLE_LEN(HYST_INV_TABLE)]; \
    HYST_DEFINE(name, nu)

/** The tabulated compensator (hyst_init_inverse_table()) on an instance
 *  declared by HYST_DEFINE_INVERSE(). */
#define HYST_INIT_INVERSE(name, f0)                                                        \
    HYST_DEFAULT_NAME_(init_inverse_table_)(&(name), &name##_curve, (f0), name##_table,   \
                                            HYST_INV_TABLE, HYST_ARRAYS_(name), HYST_LAYOUT)

/** The exact compensator (hyst_init_inverse_exact()) on an instance declared by
 *  HYST_DEFINE_INVERSE() (its table unused). */
#define HYST_INIT_INVERSE_EXACT(name, f0)                                                   \
    HYST_DEFAULT_NAME_(init_inverse_exact_)(&(name), &name##_curve, (f0),                   \
                                            HYST_ARRAYS_(name), HYST_LAYOUT)

#ifdef __cplusplus
}
#endif

#endif /* HYST_INVERSE_H */
