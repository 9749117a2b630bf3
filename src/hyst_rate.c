/* SPDX-License-Identifier: MIT */
/* The rate term (rate.h): the checks and accessors written once; the
 * per-sample functions of each real variant from src/rate_model.h. */
#include "hyst/rate.h"

#include "hyst_util.h"

#include <float.h>
#include <string.h>

/* The init of every real variant: the instance is built aside and copied
 * whole, so an error writes nothing. a = 1 / tau must be a normal number of
 * the type (a subnormal a loses its precision, and cores that flush
 * subnormals would freeze the low-pass). */
static hyst_status_t init_any(hyst_rate_t *R, hyst_wide_t tau, hyst_wide_t weight,
                              hyst_wide_t x_rest, unsigned variant, unsigned long layout)
{
    const hyst_wide_t least =
        variant == (unsigned)HYST_VARIANT_F32 ? (hyst_wide_t)FLT_MIN : HYST_WIDE_MIN;
    const hyst_wide_t top =
        variant == (unsigned)HYST_VARIANT_F32 ? (hyst_wide_t)FLT_MAX : HYST_WIDE_MAX;
    hyst_rate_t out;
    hyst_wide_t w;
    if (R == NULL) {
        return HYST_ERR_NULL;
    }
    if (layout != HYST_LAYOUT) {
        return HYST_ERR_LAYOUT;
    }
    memset(&out, 0, sizeof out);
    if (!hyst_wide_is_finite(tau) || !(tau >= 1)) {
        return HYST_ERR_ARG;
    }
    (void)hyst_num_set(&out.alpha, variant, 1 / tau);
    if (!(hyst_num_get(&out.alpha, variant) >= least)) {
        return HYST_ERR_ARG;
    }
    if (!hyst_num_set(&out.weight, variant, weight)) { /* NaN fails too */
        return HYST_ERR_WEIGHTS;
    }
    /* the drive limit: |x|, |p| <= L keeps x - p, v and w v finite */
    w = hyst_wide_abs(hyst_num_get(&out.weight, variant));
    (void)hyst_num_set(&out.x_limit, variant, top / (4 * (w > 1 ? w : 1)));
    if (!hyst_wide_is_finite(x_rest) ||
        !(hyst_wide_abs(x_rest) <= hyst_num_get(&out.x_limit, variant)) ||
        !hyst_num_set(&out.last, variant, x_rest)) {
        return HYST_ERR_NONFINITE;
    }
    (void)hyst_num_set(&out.state, variant, 0);
    out.variant = variant;
    out.status = HYST_OK;
    *R = out;
    return HYST_OK;
}

#define NUM_T float
#define NUM_F f32
#define NUM_NAME(n) hyst_f32_##n
#define NUM_VARIANT HYST_VARIANT_F32
#define NUM_MULADD(a, b, c) HYST_F32_MULADD(a, b, c)
#include "rate_model.h"
#undef NUM_T
#undef NUM_F
#undef NUM_NAME
#undef NUM_VARIANT
#undef NUM_MULADD

hyst_status_t hyst_f32_rate_init_(hyst_rate_t *R, hyst_wide_t tau, hyst_wide_t weight,
                                  hyst_wide_t x_rest, unsigned long layout)
{
    return init_any(R, tau, weight, x_rest, HYST_VARIANT_F32, layout);
}

hyst_status_t hyst_f32_rate_reset(hyst_rate_t *R, float x_rest)
{
    return hyst_f32_rate_reset_impl(R, x_rest);
}

float hyst_f32_rate_output(const hyst_rate_t *R)
{
    return hyst_f32_rate_output_impl(R);
}

float hyst_f32_rate_step(hyst_rate_t *R, float x)
{
    return hyst_f32_rate_step_impl(R, x);
}

#if HYST_ENABLE_F64
#define NUM_T double
#define NUM_F f64
#define NUM_NAME(n) hyst_f64_##n
#define NUM_VARIANT HYST_VARIANT_F64
#define NUM_MULADD(a, b, c) ((a) * (b) + (c))
#include "rate_model.h"
#undef NUM_T
#undef NUM_F
#undef NUM_NAME
#undef NUM_VARIANT
#undef NUM_MULADD

hyst_status_t hyst_f64_rate_init_(hyst_rate_t *R, hyst_wide_t tau, hyst_wide_t weight,
                                  hyst_wide_t x_rest, unsigned long layout)
{
    return init_any(R, tau, weight, x_rest, HYST_VARIANT_F64, layout);
}

hyst_status_t hyst_f64_rate_reset(hyst_rate_t *R, double x_rest)
{
    return hyst_f64_rate_reset_impl(R, x_rest);
}

double hyst_f64_rate_output(const hyst_rate_t *R)
{
    return hyst_f64_rate_output_impl(R);
}

double hyst_f64_rate_step(hyst_rate_t *R, double x)
{
    return hyst_f64_rate_step_impl(R, x);
}
#endif

int hyst_rate_status(const hyst_rate_t *R) { return R != NULL ? R->status : HYST_ERR_NULL; }

unsigned hyst_rate_events(const hyst_rate_t *R) { return R != NULL ? R->events : 0u; }

void hyst_rate_clear_events(hyst_rate_t *R)
{
    if (R != NULL) {
        ++R->seq;
        R->events = 0u;
    }
}
