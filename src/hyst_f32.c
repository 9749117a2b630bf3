/* SPDX-License-Identifier: MIT */
/* The f32 variant: float inputs and outputs (hyst_f32_*). src/variant_real.h
 * writes its functions once for both real types, as static functions named
 * *_impl; the public names are defined here, one line each, so that a
 * search for a name finds its definition. */
#include "num_f32.h"
#include "variant_real.h"

float hyst_f32_curve_eval(const hyst_curve_t *curve, float x)
{
    return hyst_f32_curve_eval_impl(curve, x);
}

hyst_status_t hyst_f32_curve_everett_inverse_table(hyst_curve_t *inv, const hyst_curve_t *fwd,
                                                   float *table, size_t rows, size_t intervals)
{
    return hyst_f32_curve_everett_inverse_table_impl(inv, fwd, table, rows, intervals);
}

hyst_status_t hyst_f32_curve_everett_inverse_table_const(hyst_curve_t *inv, const hyst_curve_t *fwd,
                                                         const float *table, size_t rows,
                                                         size_t intervals,
                                                         const hyst_table_seal_t *seal)
{
    return hyst_f32_curve_everett_inverse_table_const_impl(inv, fwd, table, rows, intervals, seal);
}

hyst_status_t hyst_f32_curve_from_pwl_(hyst_curve_t *curve, const float *x, const float *y,
                                       size_t n, unsigned long layout)
{
    return hyst_f32_curve_from_pwl_impl(curve, x, y, n, layout);
}

float hyst_f32_curve_g(const hyst_curve_t *curve, float d)
{
    return hyst_f32_curve_g_impl(curve, d);
}

hyst_status_t hyst_f32_curve_inverse_table(hyst_curve_t *inv, const hyst_curve_t *fwd, float *table,
                                           size_t intervals)
{
    return hyst_f32_curve_inverse_table_impl(inv, fwd, table, intervals);
}

hyst_status_t hyst_f32_curve_inverse_table_const(hyst_curve_t *inv, const hyst_curve_t *fwd,
                                                 const float *table, size_t intervals,
                                                 const hyst_table_seal_t *seal)
{
    return hyst_f32_curve_inverse_table_const_impl(inv, fwd, table, intervals, seal);
}

float hyst_f32_error_bound(const hyst_tcm_t *S)
{
    return hyst_f32_error_bound_impl(S);
}

hyst_status_t hyst_f32_init_(hyst_tcm_t *S, const hyst_poly_t *f0, float *xltp, float *yltp,
                             float *xrtp, float *yrtp, size_t capacity, unsigned long layout)
{
    return hyst_f32_init_impl(S, f0, xltp, yltp, xrtp, yrtp, capacity, layout);
}

hyst_status_t hyst_f32_init_curve_(hyst_tcm_t *S, const hyst_curve_t *curve, float *xltp,
                                   float *yltp, float *xrtp, float *yrtp, size_t capacity,
                                   unsigned long layout)
{
    return hyst_f32_init_curve_impl(S, curve, xltp, yltp, xrtp, yrtp, capacity, layout);
}

hyst_status_t hyst_f32_init_kind_(hyst_tcm_t *S, const hyst_curve_t *curve, hyst_kind_t kind,
                                  float *xltp, float *yltp, float *xrtp, float *yrtp, size_t capacity,
                                  unsigned long layout)
{
    return hyst_f32_init_kind_impl(S, curve, kind, xltp, yltp, xrtp, yrtp, capacity, layout);
}

const void *hyst_f32_kind_poly(const hyst_curve_t *curve, unsigned variant)
{
    return hyst_f32_bind_poly(curve, variant);
}

const void *hyst_f32_kind_pwl(const hyst_curve_t *curve, unsigned variant)
{
    return hyst_f32_bind_pwl(curve, variant);
}

const void *hyst_f32_kind_inverse(const hyst_curve_t *curve, unsigned variant)
{
    return hyst_f32_bind_inverse(curve, variant);
}

const void *hyst_f32_kind_inverse_table(const hyst_curve_t *curve, unsigned variant)
{
    return hyst_f32_bind_inverse_table(curve, variant);
}

const void *hyst_f32_kind_everett(const hyst_curve_t *curve, unsigned variant)
{
    return hyst_f32_bind_everett(curve, variant);
}

const void *hyst_f32_kind_everett_inverse(const hyst_curve_t *curve, unsigned variant)
{
    return hyst_f32_bind_everett_inverse(curve, variant);
}

const void *hyst_f32_kind_everett_inverse_table(const hyst_curve_t *curve, unsigned variant)
{
    return hyst_f32_bind_everett_inverse_table(curve, variant);
}

const void *hyst_f32_kind_everett_grid(const hyst_curve_t *curve, unsigned variant)
{
    return hyst_f32_bind_everett_grid(curve, variant);
}

const void *hyst_f32_kind_everett_grid_inverse(const hyst_curve_t *curve, unsigned variant)
{
    return hyst_f32_bind_everett_grid_inverse(curve, variant);
}

const void *hyst_f32_kind_spline(const hyst_curve_t *curve, unsigned variant)
{
    return hyst_f32_bind_spline(curve, variant);
}

const void *hyst_f32_kind_spline_inverse_table(const hyst_curve_t *curve, unsigned variant)
{
    return hyst_f32_bind_spline_inverse_table(curve, variant);
}

hyst_status_t hyst_f32_init_sealed_(hyst_tcm_t *S, const hyst_f32_sealed_poly_t *sealed,
                                    float *xltp, float *yltp, float *xrtp, float *yrtp,
                                    size_t capacity, unsigned long layout)
{
    return hyst_f32_init_sealed_impl(S, sealed, xltp, yltp, xrtp, yrtp, capacity, layout);
}

hyst_status_t hyst_f32_init_inverse_sealed_(hyst_tcm_t *S, hyst_curve_t *inv,
                                            const hyst_f32_sealed_inverse_t *sealed,
                                            const float *table, float *xltp, float *yltp,
                                            float *xrtp, float *yrtp, size_t capacity,
                                            unsigned long layout)
{
    return hyst_f32_init_inverse_sealed_impl(S, inv, sealed, table, xltp, yltp, xrtp, yrtp,
                                              capacity, layout);
}

hyst_status_t hyst_f32_init_inverse_exact_(hyst_tcm_t *S, hyst_curve_t *inv, const hyst_poly_t *f0,
                                           float *xltp, float *yltp, float *xrtp, float *yrtp,
                                           size_t capacity, unsigned long layout)
{
    return hyst_f32_init_inverse_exact_impl(S, inv, f0, xltp, yltp, xrtp, yrtp, capacity, layout);
}

hyst_status_t hyst_f32_init_inverse_table_(hyst_tcm_t *S, hyst_curve_t *inv, const hyst_poly_t *f0,
                                           float *table, size_t intervals, float *xltp, float *yltp,
                                           float *xrtp, float *yrtp, size_t capacity,
                                           unsigned long layout)
{
    return hyst_f32_init_inverse_table_impl(S, inv, f0, table, intervals, xltp, yltp, xrtp, yrtp,
                                            capacity, layout);
}

float hyst_f32_input(const hyst_tcm_t *S)
{
    return hyst_f32_input_impl(S);
}

float hyst_f32_output(const hyst_tcm_t *S)
{
    return hyst_f32_output_impl(S);
}

hyst_status_t hyst_f32_pi_check(const float *r, const float *w, size_t n)
{
    return hyst_f32_pi_check_impl(r, w, n);
}

hyst_status_t hyst_f32_pi_init_(hyst_pi_t *P, const float *r, const float *w, float *z, size_t n,
                                unsigned long layout)
{
    return hyst_f32_pi_init_impl(P, r, w, z, n, layout);
}

hyst_status_t hyst_f32_pi_init_inverse_(hyst_pi_t *inv, const hyst_pi_t *fwd, float *r_inv,
                                        float *w_inv, float *z_inv, unsigned long layout)
{
    return hyst_f32_pi_init_inverse_impl(inv, fwd, r_inv, w_inv, z_inv, layout);
}

hyst_status_t hyst_f32_pi_inverse_params(const float *r, const float *w, size_t n, float *r_inv,
                                         float *w_inv)
{
    return hyst_f32_pi_inverse_params_impl(r, w, n, r_inv, w_inv);
}

hyst_status_t hyst_f32_pi_loading_curve(hyst_curve_t *curve, const float *r, const float *w,
                                        size_t n, float hi, float *bx, float *by)
{
    return hyst_f32_pi_loading_curve_impl(curve, r, w, n, hi, bx, by);
}

float hyst_f32_pi_output(const hyst_pi_t *P)
{
    return hyst_f32_pi_output_impl(P);
}

hyst_status_t hyst_f32_pi_process(hyst_pi_t *P, const float *x, float *y, size_t n)
{
    return hyst_f32_pi_process_impl(P, x, y, n);
}

float hyst_f32_pi_step(hyst_pi_t *P, float x)
{
    return hyst_f32_pi_step_impl(P, x);
}

hyst_status_t hyst_f32_process(hyst_tcm_t *S, const float *x, float *y, size_t n)
{
    return hyst_f32_process_impl(S, x, y, n);
}

hyst_status_t hyst_f32_request_deadband(hyst_tcm_t *S, float width)
{
    return hyst_f32_request_deadband_impl(S, width);
}

float hyst_f32_rounding_bound(const hyst_tcm_t *S)
{
    return hyst_f32_rounding_bound_impl(S);
}

hyst_status_t hyst_f32_seal_inverse_table(hyst_f32_sealed_inverse_t *out, const hyst_curve_t *inv)
{
    return hyst_f32_seal_inverse_table_impl(out, inv);
}

hyst_status_t hyst_f32_seal_poly_(hyst_f32_sealed_poly_t *out, const hyst_poly_t *f0,
                                  unsigned long layout)
{
    return hyst_f32_seal_poly_impl(out, f0, layout);
}

hyst_status_t hyst_f32_set_deadband(hyst_tcm_t *S, float width)
{
    return hyst_f32_set_deadband_impl(S, width);
}

float hyst_f32_step(hyst_tcm_t *S, float x)
{
    return hyst_f32_step_impl(S, x);
}
