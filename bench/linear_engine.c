/* SPDX-License-Identifier: MIT */
/* The f32 engine with a linear scan instead of the binary search, named
 * bench_lin_*: what the search buys (bench_target.c, BENCH_LINEAR). It scans
 * down from the newest TP, so a sample costs one comparison per TP it wipes
 * out; same results, since the arrays are sorted. Benchmarks only. */
#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>

#include "hyst/config.h"

#define HYST_NUM_DESCRIPTOR
#define NUM_T float
#define NUM_F f32
#define NUM_NAME(n) bench_lin_##n
#define NUM_VARIANT HYST_VARIANT_F32
#define NUM_C(v) (v##f)
#define NUM_EPS ((float)FLT_EPSILON)
#define NUM_SQRT(v) sqrtf(v)

static size_t bench_lin_scan_below(const float *xltp, size_t n, float x)
{
    while (n > 0u && !(xltp[n - 1u] < x)) {
        --n;
    }
    return n;
}

static size_t bench_lin_scan_above(const float *xrtp, size_t n, float x)
{
    while (n > 0u && !(xrtp[n - 1u] > x)) {
        --n;
    }
    return n;
}

#define TCM_LTP_BELOW(a, n, x) bench_lin_scan_below((a), (n), (x))
#define TCM_RTP_ABOVE(a, n, x) bench_lin_scan_above((a), (n), (x))
/* the variant's functions are static (*_impl), written out by its
 * translation unit; this one writes out only the two below */
#if defined(__GNUC__)
#pragma GCC diagnostic ignored "-Wunused-function"
#endif
#include "variant_real.h"

/* The two public names bench_target.c calls (src/hyst_f32.c writes them
 * out the same way). */
float bench_lin_step(hyst_tcm_t *S, float x);
float bench_lin_step(hyst_tcm_t *S, float x) { return bench_lin_step_impl(S, x); }

hyst_status_t bench_lin_init_(hyst_tcm_t *S, const hyst_poly_t *f0, float *xltp, float *yltp,
                              float *xrtp, float *yrtp, size_t capacity, unsigned long layout);
hyst_status_t bench_lin_init_(hyst_tcm_t *S, const hyst_poly_t *f0, float *xltp, float *yltp,
                              float *xrtp, float *yrtp, size_t capacity, unsigned long layout)
{
    return bench_lin_init_impl(S, f0, xltp, yltp, xrtp, yrtp, capacity, layout);
}
