/* SPDX-License-Identifier: MIT */
/* Number type descriptor: float (the f32 variant, and the outputs of the
 * code variant). Included once by a variant's translation unit, before the
 * templates (src/num_ops.h, src/curve_eval.h, src/tcm_engine.h...). */
#ifndef HYST_NUM_DESCRIPTOR
#define HYST_NUM_DESCRIPTOR
#include <float.h>

#include "hyst/config.h"
#include "hyst_util.h"
#include <stdint.h>

#define NUM_T float                 /* the C type */
#define NUM_F f32                   /* its member of hyst_num_t, hyst_ptr_t, hyst_cptr_t */
#define NUM_NAME(n) hyst_f32_##n    /* public and generated names */
#define NUM_VARIANT HYST_VARIANT_F32
#define NUM_C(v) (v##f)             /* a constant of the type */
#define NUM_EPS ((float)FLT_EPSILON) /* its rounding unit */
#define NUM_MULADD(a, b, c) HYST_F32_MULADD(a, b, c) /* src/hyst_util.h */
#define NUM_SQRT(v) sqrtf(v)       /* <math.h>, where a template uses it */
#if HYST_KEYED_SEARCH && FLT_RADIX == 2 && FLT_MANT_DIG == 24 && FLT_MAX_EXP == 128
#define NUM_KEY_T int32_t           /* integer of the same size: keyed search */
#define NUM_UKEY_T uint32_t
#endif
#endif
