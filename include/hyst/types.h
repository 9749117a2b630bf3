/* SPDX-License-Identifier: MIT */
/**
 * @file types.h
 * @brief The number types of hyst and the named variants built on them.
 *
 * Every numeric variant is a named set of symbols, as in CMSIS-DSP, and all
 * of them link into one program:
 *
 * | variant | prefix       | stored input          | output, stored outputs |
 * |---------|--------------|-----------------------|------------------------|
 * | f32     | hyst_f32_    | float                 | float                  |
 * | f64     | hyst_f64_    | double                | double                 |
 * | code    | hyst_code_   | hyst_code_word_t code | float                  |
 * | q31     | hyst_q31_    | hyst_code_word_t code | hyst_q31_t (fixed)     |
 *
 * The unsuffixed names (hyst_step, hyst_real_t...) are the default variant:
 * f32, or f64 when HYST_USE_DOUBLE is defined where they are used.
 * Instances of every variant share one struct (hyst_tcm_t, tcm.h); its
 * numbers are hyst_num_t, read through the member of the variant.
 */
#ifndef HYST_TYPES_H
#define HYST_TYPES_H

#include <stddef.h>
#include <stdint.h>

#include "hyst/config.h"

#ifdef __cplusplus
extern "C" {
#endif

/**
 * @brief Type of one-off computations (curve set-up, identification).
 *
 * double so that coefficients in raw units convert without cancellation;
 * float with HYST_NO_DOUBLE, on targets where double must not be linked.
 */
#ifdef HYST_NO_DOUBLE
typedef float hyst_wide_t;
#define HYST_WIDE_C(v) (v##f)
#else
typedef double hyst_wide_t;
#define HYST_WIDE_C(v) (v)
#endif
/** @def HYST_WIDE_C
 *  @brief A constant of hyst_wide_t (HYST_WIDE_C(0.585)): a hyst_poly_t
 *         written once for either setting of HYST_NO_DOUBLE, without a
 *         conversion warning in either. */

/** Stored DAC code of the code variant: HYST_CODE_BITS fit. */
#if HYST_CODE_BITS <= 16
typedef uint_least16_t hyst_code_word_t;
#else
typedef uint_least32_t hyst_code_word_t;
#endif

/** Fixed-point output of the q31 variant (q31.h): at least 32 bits, signed
 *  (int_least32_t: `long` where int has 16 bits). */
typedef int_least32_t hyst_q31_t;

/** Largest code: 2^HYST_CODE_BITS - 1. */
#define HYST_CODE_MAX ((((uint_least32_t)1) << HYST_CODE_BITS) - 1u)

/** @brief One number of an instance, in the type of its variant. */
typedef union hyst_num {
    float f32;              /**< f32 variant; outputs of the code variant */
#if HYST_ENABLE_F64
    double f64;             /**< f64 variant */
#endif
    hyst_code_word_t code;  /**< inputs of the code and q31 variants */
    hyst_q31_t q31;         /**< outputs of the q31 variant; the q31 compensator's numbers */
} hyst_num_t;

/** @brief A caller-owned array of an instance, typed by its variant. */
typedef union hyst_ptr {
    float *f32;
#if HYST_ENABLE_F64
    double *f64;
#endif
    hyst_code_word_t *code;
    hyst_q31_t *q31;
} hyst_ptr_t;

/** @brief A read-only caller-owned array (breakpoints, PI parameters). */
typedef union hyst_cptr {
    const float *f32;
#if HYST_ENABLE_F64
    const double *f64;
#endif
    const hyst_q31_t *q31;
} hyst_cptr_t;

/** @brief The variants (stored in every instance and curve). */
typedef enum hyst_variant {
    HYST_VARIANT_F32 = 1,  /**< float in, float out */
    HYST_VARIANT_F64 = 2,  /**< double in, double out */
    HYST_VARIANT_CODE = 3, /**< integer codes in, float out (f32 curves) */
    HYST_VARIANT_Q31 = 4,  /**< integer codes in, fixed point out (q31.h) */
    HYST_VARIANT_Q31_INV = 5 /**< q31 compensator: fixed point in and out (q31.h) */
} hyst_variant_t;

/**
 * @brief Real type of the default variant: float, or double with
 *        HYST_USE_DOUBLE.
 */
#ifdef HYST_USE_DOUBLE
typedef double hyst_real_t;
#define HYST_REAL_C(v) (v)
#define HYST_DEFAULT_VARIANT HYST_VARIANT_F64
#define HYST_DEFAULT_NAME_(name) hyst_f64_##name
#define HYST_R f64 /**< member of hyst_num_t of the default variant */
#else
typedef float hyst_real_t;
#define HYST_REAL_C(v) (v##f)
#define HYST_DEFAULT_VARIANT HYST_VARIANT_F32
#define HYST_DEFAULT_NAME_(name) hyst_f32_##name
#define HYST_R f32 /**< member of hyst_num_t of the default variant */
#endif

#ifdef __cplusplus
}
#endif

#endif /* HYST_TYPES_H */
