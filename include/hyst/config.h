/**
 * @file config.h
 * @brief Compile-time configuration of hyst: real type, limits, hooks.
 *
 * Every option has a default here. Override them with compiler definitions
 * (-DHYST_USE_DOUBLE) or collect them in a file of your own and build with
 * -DHYST_CONFIG_FILE="my_hyst_config.h"; never edit the library sources.
 */
#ifndef HYST_CONFIG_H
#define HYST_CONFIG_H

#ifdef HYST_CONFIG_FILE
#include HYST_CONFIG_FILE
#endif

#include <stddef.h>

/** Highest polynomial degree of f0 an instance can hold (at least 9). */
#ifndef HYST_MAX_DEGREE
#define HYST_MAX_DEGREE 9
#endif
#if HYST_MAX_DEGREE < 1
#error "HYST_MAX_DEGREE must be at least 1"
#endif

/**
 * @brief Real type of every sample and stored turning point.
 *
 * float by default (the DSP28335 and Cortex-M4F FPUs are single precision);
 * define HYST_USE_DOUBLE for reference-grade host builds.
 */
#ifdef HYST_USE_DOUBLE
typedef double hyst_real_t;
#define HYST_REAL_C(v) (v)
#else
typedef float hyst_real_t;
#define HYST_REAL_C(v) (v##f)
#endif

/**
 * @brief Real type of one-off computations (curve set-up at init).
 *
 * double by default so that coefficients in raw units (DAC codes) convert
 * without cancellation; define HYST_NO_DOUBLE on targets where double math
 * must not be linked (init then runs in hyst_real_t).
 */
#ifdef HYST_NO_DOUBLE
typedef hyst_real_t hyst_wide_t;
#else
typedef double hyst_wide_t;
#endif

/**
 * @brief Search the turning points by the bit patterns of the reals.
 *
 * 1 (default): hyst_real_t values are compared as integers of the same size
 * in the binary search, one instruction fewer per probe on FPUs that move
 * flags (Cortex-M4F, C28x); exact for IEEE 754 binary32/binary64 whose byte
 * order is the integers' (every target hyst knows), and used only for those
 * formats. 0: compare reals. Off by default under -ffast-math, which need
 * not keep the sign of zero the search relies on.
 */
#ifndef HYST_KEYED_SEARCH
#if defined(__FAST_MATH__)
#define HYST_KEYED_SEARCH 0
#else
#define HYST_KEYED_SEARCH 1
#endif
#endif

/** Inline that the compiler may not decline: the per-sample path. */
#if defined(__GNUC__) || defined(__clang__)
#define HYST_INLINE static inline __attribute__((always_inline))
#else
#define HYST_INLINE static inline
#endif

/**
 * @brief Timing hooks around the per-sample computation (GPIO set/clear).
 *
 * Compiled out unless HYST_USE_TIMING_HOOK is defined; then the port provides
 * hyst_port_timing_begin()/hyst_port_timing_end() (see port/template).
 */
#ifdef HYST_USE_TIMING_HOOK
void hyst_port_timing_begin(void);
void hyst_port_timing_end(void);
#define HYST_TIMING_BEGIN() hyst_port_timing_begin()
#define HYST_TIMING_END() hyst_port_timing_end()
#else
#define HYST_TIMING_BEGIN() ((void)0)
#define HYST_TIMING_END() ((void)0)
#endif

#endif /* HYST_CONFIG_H */
