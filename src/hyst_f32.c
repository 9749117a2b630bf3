/* SPDX-License-Identifier: MIT */
/* The f32 variant: float inputs and outputs (hyst_f32_*). */
#include "num_f32.h"
#include "variant_real.h"
