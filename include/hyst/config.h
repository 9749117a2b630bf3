/* SPDX-License-Identifier: MIT */
/**
 * @file config.h
 * @brief Every compile-time option of hyst, with its default.
 *
 * Override an option with a compiler definition (-DHYST_MAX_DEGREE=5), or
 * collect them in a file of your own and build with
 * -DHYST_CONFIG_FILE="my_hyst_config.h"; never edit the library sources.
 * With CMake, the layout options (below) and HYST_USE_DOUBLE are cache
 * variables of the same name: the hyst target then exports the definition
 * to everything that links it; the others are compiler definitions.
 *
 * | option              | default | meaning                                                    | layout |
 * |---------------------|---------|------------------------------------------------------------|--------|
 * | HYST_USE_DOUBLE     | off     | the unsuffixed names (hyst_step, hyst_t...) mean f64, not f32 | no  |
 * | HYST_ENABLE_F64     | see below | the f64 variant exists (0: numbers are 4 bytes)         | yes    |
 * | HYST_MAX_DEGREE     | 9       | highest polynomial degree of a curve (>= 1)                | yes    |
 * | HYST_INV_KNOTS      | 16      | intervals of the start table of an inverted polynomial      | yes    |
 * | HYST_INV_MAX_ITER   | 12      | bound on the work of an inverted polynomial per sample      | no     |
 * | HYST_INV_TABLE      | 256     | intervals of a compensator's inverse table (HYST_DEFINE_INVERSE) | no |
 * | HYST_INV_TABLE_TOL  | 5e-6    | error of an inverse table's interval, of the drive range, above which it is evaluated exactly | no |
 * | HYST_EVERETT_INV_ROWS | 16    | anchors - 1 per direction of the asymmetric compensator's table | no |
 * | HYST_EVERETT_INV_INTERVALS | 32 | intervals per anchor of that table                       | no     |
 * | HYST_MAX_ROUNDING   | 1e-4    | largest rounding bound of a branch evaluation init accepts, of the output range | no |
 * | HYST_CODE_BITS      | 16      | widest DAC code of the code variant (1..24)                 | yes    |
 * | HYST_MONOTONE_DEPTH | 20      | dyadic depth of the monotonicity proof at init              | no     |
 * | HYST_NO_DOUBLE      | off     | init-time arithmetic in float (targets without double; hyst_poly_t holds floats) | yes |
 * | HYST_KEYED_SEARCH   | 1       | search turning points by IEEE bit patterns (0 under -ffast-math) | no |
 * | HYST_F32_FMA        | see below | the f32 variant's marked multiply-adds rounded once (fused) | no |
 *
 * HYST_ENABLE_F64 defaults to 1 where double is a 64-bit type with hardware
 * support or on hosts, and to 0 on 32-bit Arm cores without a double FPU
 * (Cortex-M0..M4F: instances and curves then hold 4-byte numbers) and where
 * double is a float (AVR, C28x without fpu64).
 *
 * HYST_F32_FMA defaults to 1 where the compiler reports a fused
 * single-precision instruction (Cortex-M4F, M7, M33 with an FPU) and to 0
 * elsewhere; the CMake build sets it to 1 on hosts (the C library's fmaf),
 * so that float32 results there equal a Cortex-M4F's bit for bit
 * (docs/porting.md, "Floating point").
 *
 * "layout" options change the size of public structs. Every translation
 * unit that includes hyst and the library itself must agree on them; the
 * init functions compare the caller's HYST_LAYOUT with the library's and
 * refuse a mismatch with HYST_ERR_LAYOUT (instead of corrupting memory).
 */
#ifndef HYST_CONFIG_H
#define HYST_CONFIG_H

#ifdef HYST_CONFIG_FILE
#include HYST_CONFIG_FILE
#endif

#ifndef HYST_ENABLE_F64
#include <float.h>
#if DBL_MANT_DIG < 53
#define HYST_ENABLE_F64 0 /* double is a float here (AVR, C28x without fpu64) */
#elif defined(__arm__) && !(defined(__ARM_FP) && (__ARM_FP & 8))
#define HYST_ENABLE_F64 0 /* 32-bit Arm without a double FPU: 4-byte numbers (set 1 for f64) */
#else
#define HYST_ENABLE_F64 1
#endif
#endif

#ifndef HYST_MAX_DEGREE
#define HYST_MAX_DEGREE 9
#endif
#if HYST_MAX_DEGREE < 1 || HYST_MAX_DEGREE > 63
#error "HYST_MAX_DEGREE must be 1..63"
#endif

/* Largest rounding bound of a polynomial branch evaluation that init
 * accepts, as a fraction of the output range (curve.h, "rounding"). */
#ifndef HYST_MAX_ROUNDING
#define HYST_MAX_ROUNDING 1e-4
#endif

#ifndef HYST_INV_KNOTS
#define HYST_INV_KNOTS 16
#endif
#if HYST_INV_KNOTS < 1 || HYST_INV_KNOTS > 255
#error "HYST_INV_KNOTS must be 1..255"
#endif

#ifndef HYST_INV_MAX_ITER
#define HYST_INV_MAX_ITER 12
#endif
#if HYST_INV_MAX_ITER < 1
#error "HYST_INV_MAX_ITER must be at least 1"
#endif

/* The compensator's inverse table (curve.h, hyst_*_curve_inverse_table):
 * intervals of the table HYST_DEFINE_INVERSE declares, and the error, as a
 * fraction of the drive range, above which an interval is evaluated
 * exactly instead (docs/pi_and_inverse.md: the size/error trade-off). */
#ifndef HYST_INV_TABLE
#define HYST_INV_TABLE 256
#endif
#if HYST_INV_TABLE < 1
#error "HYST_INV_TABLE must be at least 1"
#endif
#ifndef HYST_INV_TABLE_TOL
#define HYST_INV_TABLE_TOL 5e-6
#endif
/* The asymmetric compensator's table (curve.h,
 * hyst_*_curve_everett_inverse_table): anchors - 1 per direction, and
 * intervals per anchor (docs/pi_and_inverse.md: the size/error trade-off). */
#ifndef HYST_EVERETT_INV_ROWS
#define HYST_EVERETT_INV_ROWS 16
#endif
#ifndef HYST_EVERETT_INV_INTERVALS
#define HYST_EVERETT_INV_INTERVALS 32
#endif

#ifndef HYST_CODE_BITS
#define HYST_CODE_BITS 16
#endif
#if HYST_CODE_BITS < 1 || HYST_CODE_BITS > 24
#error "HYST_CODE_BITS must be 1..24"
#endif

#ifndef HYST_MONOTONE_DEPTH
#define HYST_MONOTONE_DEPTH 20
#endif

#ifndef HYST_F32_FMA
#if defined(__ARM_FEATURE_FMA) || defined(__FP_FAST_FMAF)
#define HYST_F32_FMA 1
#else
#define HYST_F32_FMA 0
#endif
#endif

#ifndef HYST_KEYED_SEARCH
#if defined(__FAST_MATH__)
#define HYST_KEYED_SEARCH 0
#else
#define HYST_KEYED_SEARCH 1
#endif
#endif

#if defined(HYST_USE_DOUBLE) && !HYST_ENABLE_F64
#error "HYST_USE_DOUBLE needs HYST_ENABLE_F64"
#endif

/** @cond */
#ifdef HYST_NO_DOUBLE
#define HYST_WIDE_FLOAT_ 1ul /* hyst_wide_t is float: hyst_poly_t and hyst_everett_t shrink */
#else
#define HYST_WIDE_FLOAT_ 0ul
#endif
/** @endcond */

/**
 * @brief Fingerprint of the layout options, as this translation unit sees
 *        them (compared by every init and curve constructor with the
 *        library's own): every option that changes a public struct.
 */
#define HYST_LAYOUT                                                              \
    (((unsigned long)HYST_MAX_DEGREE) | ((unsigned long)HYST_INV_KNOTS << 6) |   \
     ((unsigned long)HYST_CODE_BITS << 14) | ((unsigned long)HYST_ENABLE_F64 << 19) | \
     (HYST_WIDE_FLOAT_ << 20))

/** Inline that the compiler may not decline: the per-sample path. */
#if defined(__GNUC__) || defined(__clang__)
#define HYST_INLINE static inline __attribute__((always_inline))
#else
#define HYST_INLINE static inline
#endif

#endif /* HYST_CONFIG_H */
