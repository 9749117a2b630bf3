/* SPDX-License-Identifier: MIT */
/* The f64 variant: double inputs and outputs (hyst_f64_*). */
#include "hyst/config.h"
#if HYST_ENABLE_F64
#include "num_f64.h"
#include "variant_real.h"
#else
typedef int hyst_f64_disabled; /* an empty translation unit is not ISO C */
#endif
