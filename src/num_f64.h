/* SPDX-License-Identifier: MIT */
/* Number type descriptor: double (the f64 variant); see src/num_f32.h. */
#ifndef HYST_NUM_DESCRIPTOR
#define HYST_NUM_DESCRIPTOR
#include <float.h>

#include "hyst/config.h"
#include <stdint.h>

#define NUM_T double
#define NUM_F f64
#define NUM_NAME(n) hyst_f64_##n
#define NUM_VARIANT HYST_VARIANT_F64
#define NUM_C(v) (v)
#define NUM_EPS ((double)DBL_EPSILON)
#define NUM_SQRT(v) sqrt(v) /* <math.h>, where a template uses it */
#if HYST_KEYED_SEARCH && FLT_RADIX == 2 && DBL_MANT_DIG == 53 && DBL_MAX_EXP == 1024
#define NUM_KEY_T int64_t
#define NUM_UKEY_T uint64_t
#endif
#endif
