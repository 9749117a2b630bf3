/* SPDX-License-Identifier: MIT */
/* The f64 variant: double inputs and outputs (hyst_f64_*), as src/hyst_f32.c. */
#include "hyst/config.h"
#if HYST_ENABLE_F64
#include "num_f64.h"
#include "variant_real.h"

double hyst_f64_curve_eval(const hyst_curve_t *curve, double x)
{
    return hyst_f64_curve_eval_impl(curve, x);
}

hyst_status_t hyst_f64_curve_everett_inverse_table(hyst_curve_t *inv, const hyst_curve_t *fwd,
                                                   double *table, size_t rows, size_t intervals)
{
    return hyst_f64_curve_everett_inverse_table_impl(inv, fwd, table, rows, intervals);
}

hyst_status_t hyst_f64_curve_everett_inverse_table_const(hyst_curve_t *inv, const hyst_curve_t *fwd,
                                                         const double *table, size_t rows,
                                                         size_t intervals,
                                                         const hyst_table_seal_t *seal)
{
    return hyst_f64_curve_everett_inverse_table_const_impl(inv, fwd, table, rows, intervals, seal);
}

hyst_status_t hyst_f64_curve_from_pwl_(hyst_curve_t *curve, const double *x, const double *y,
                                       size_t n, unsigned long layout)
{
    return hyst_f64_curve_from_pwl_impl(curve, x, y, n, layout);
}

double hyst_f64_curve_g(const hyst_curve_t *curve, double d)
{
    return hyst_f64_curve_g_impl(curve, d);
}

hyst_status_t hyst_f64_curve_inverse_table(hyst_curve_t *inv, const hyst_curve_t *fwd,
                                           double *table, size_t intervals)
{
    return hyst_f64_curve_inverse_table_impl(inv, fwd, table, intervals);
}

hyst_status_t hyst_f64_curve_inverse_table_const(hyst_curve_t *inv, const hyst_curve_t *fwd,
                                                 const double *table, size_t intervals,
                                                 const hyst_table_seal_t *seal)
{
    return hyst_f64_curve_inverse_table_const_impl(inv, fwd, table, intervals, seal);
}

double hyst_f64_error_bound(const hyst_tcm_t *S)
{
    return hyst_f64_error_bound_impl(S);
}

hyst_status_t hyst_f64_init_(hyst_tcm_t *S, const hyst_poly_t *f0, double *xltp, double *yltp,
                             double *xrtp, double *yrtp, size_t capacity, unsigned long layout)
{
    return hyst_f64_init_impl(S, f0, xltp, yltp, xrtp, yrtp, capacity, layout);
}

hyst_status_t hyst_f64_init_curve_(hyst_tcm_t *S, const hyst_curve_t *curve, double *xltp,
                                   double *yltp, double *xrtp, double *yrtp, size_t capacity,
                                   unsigned long layout)
{
    return hyst_f64_init_curve_impl(S, curve, xltp, yltp, xrtp, yrtp, capacity, layout);
}

hyst_status_t hyst_f64_init_kind_(hyst_tcm_t *S, const hyst_curve_t *curve, hyst_kind_t kind,
                                  double *xltp, double *yltp, double *xrtp, double *yrtp, size_t capacity,
                                  unsigned long layout)
{
    return hyst_f64_init_kind_impl(S, curve, kind, xltp, yltp, xrtp, yrtp, capacity, layout);
}

const void *hyst_f64_kind_poly(const hyst_curve_t *curve, unsigned variant)
{
    return hyst_f64_bind_poly(curve, variant);
}

const void *hyst_f64_kind_pwl(const hyst_curve_t *curve, unsigned variant)
{
    return hyst_f64_bind_pwl(curve, variant);
}

const void *hyst_f64_kind_inverse(const hyst_curve_t *curve, unsigned variant)
{
    return hyst_f64_bind_inverse(curve, variant);
}

const void *hyst_f64_kind_inverse_table(const hyst_curve_t *curve, unsigned variant)
{
    return hyst_f64_bind_inverse_table(curve, variant);
}

const void *hyst_f64_kind_everett(const hyst_curve_t *curve, unsigned variant)
{
    return hyst_f64_bind_everett(curve, variant);
}

const void *hyst_f64_kind_everett_inverse(const hyst_curve_t *curve, unsigned variant)
{
    return hyst_f64_bind_everett_inverse(curve, variant);
}

const void *hyst_f64_kind_everett_inverse_table(const hyst_curve_t *curve, unsigned variant)
{
    return hyst_f64_bind_everett_inverse_table(curve, variant);
}

const void *hyst_f64_kind_everett_grid(const hyst_curve_t *curve, unsigned variant)
{
    return hyst_f64_bind_everett_grid(curve, variant);
}

const void *hyst_f64_kind_everett_grid_inverse(const hyst_curve_t *curve, unsigned variant)
{
    return hyst_f64_bind_everett_grid_inverse(curve, variant);
}

const void *hyst_f64_kind_spline(const hyst_curve_t *curve, unsigned variant)
{
    return hyst_f64_bind_spline(curve, variant);
}

const void *hyst_f64_kind_spline_inverse_table(const hyst_curve_t *curve, unsigned variant)
{
    return hyst_f64_bind_spline_inverse_table(curve, variant);
}

hyst_status_t hyst_f64_init_sealed_(hyst_tcm_t *S, const hyst_f64_sealed_poly_t *sealed,
                                    double *xltp, double *yltp, double *xrtp, double *yrtp,
                                    size_t capacity, unsigned long layout)
{
    return hyst_f64_init_sealed_impl(S, sealed, xltp, yltp, xrtp, yrtp, capacity, layout);
}

hyst_status_t hyst_f64_init_inverse_sealed_(hyst_tcm_t *S, hyst_curve_t *inv,
                                            const hyst_f64_sealed_inverse_t *sealed,
                                            const double *table, double *xltp, double *yltp,
                                            double *xrtp, double *yrtp, size_t capacity,
                                            unsigned long layout)
{
    return hyst_f64_init_inverse_sealed_impl(S, inv, sealed, table, xltp, yltp, xrtp, yrtp,
                                              capacity, layout);
}

hyst_status_t hyst_f64_init_inverse_exact_(hyst_tcm_t *S, hyst_curve_t *inv, const hyst_poly_t *f0,
                                           double *xltp, double *yltp, double *xrtp, double *yrtp,
                                           size_t capacity, unsigned long layout)
{
    return hyst_f64_init_inverse_exact_impl(S, inv, f0, xltp, yltp, xrtp, yrtp, capacity, layout);
}

hyst_status_t hyst_f64_init_inverse_table_(hyst_tcm_t *S, hyst_curve_t *inv, const hyst_poly_t *f0,
                                           double *table, size_t intervals, double *xltp,
                                           double *yltp, double *xrtp, double *yrtp,
                                           size_t capacity, unsigned long layout)
{
    return hyst_f64_init_inverse_table_impl(S, inv, f0, table, intervals, xltp, yltp, xrtp, yrtp,
                                            capacity, layout);
}

double hyst_f64_input(const hyst_tcm_t *S)
{
    return hyst_f64_input_impl(S);
}

double hyst_f64_output(const hyst_tcm_t *S)
{
    return hyst_f64_output_impl(S);
}

hyst_status_t hyst_f64_pi_check(const double *r, const double *w, size_t n)
{
    return hyst_f64_pi_check_impl(r, w, n);
}

hyst_status_t hyst_f64_pi_init_(hyst_pi_t *P, const double *r, const double *w, double *z, size_t n,
                                unsigned long layout)
{
    return hyst_f64_pi_init_impl(P, r, w, z, n, layout);
}

hyst_status_t hyst_f64_pi_init_inverse_(hyst_pi_t *inv, const hyst_pi_t *fwd, double *r_inv,
                                        double *w_inv, double *z_inv, unsigned long layout)
{
    return hyst_f64_pi_init_inverse_impl(inv, fwd, r_inv, w_inv, z_inv, layout);
}

hyst_status_t hyst_f64_pi_inverse_params(const double *r, const double *w, size_t n, double *r_inv,
                                         double *w_inv)
{
    return hyst_f64_pi_inverse_params_impl(r, w, n, r_inv, w_inv);
}

hyst_status_t hyst_f64_pi_loading_curve(hyst_curve_t *curve, const double *r, const double *w,
                                        size_t n, double hi, double *bx, double *by)
{
    return hyst_f64_pi_loading_curve_impl(curve, r, w, n, hi, bx, by);
}

double hyst_f64_pi_output(const hyst_pi_t *P)
{
    return hyst_f64_pi_output_impl(P);
}

hyst_status_t hyst_f64_pi_process(hyst_pi_t *P, const double *x, double *y, size_t n)
{
    return hyst_f64_pi_process_impl(P, x, y, n);
}

double hyst_f64_pi_step(hyst_pi_t *P, double x)
{
    return hyst_f64_pi_step_impl(P, x);
}

hyst_status_t hyst_f64_process(hyst_tcm_t *S, const double *x, double *y, size_t n)
{
    return hyst_f64_process_impl(S, x, y, n);
}

hyst_status_t hyst_f64_request_deadband(hyst_tcm_t *S, double width)
{
    return hyst_f64_request_deadband_impl(S, width);
}

double hyst_f64_rounding_bound(const hyst_tcm_t *S)
{
    return hyst_f64_rounding_bound_impl(S);
}

hyst_status_t hyst_f64_seal_inverse_table(hyst_f64_sealed_inverse_t *out, const hyst_curve_t *inv)
{
    return hyst_f64_seal_inverse_table_impl(out, inv);
}

hyst_status_t hyst_f64_seal_poly_(hyst_f64_sealed_poly_t *out, const hyst_poly_t *f0,
                                  unsigned long layout)
{
    return hyst_f64_seal_poly_impl(out, f0, layout);
}

hyst_status_t hyst_f64_set_deadband(hyst_tcm_t *S, double width)
{
    return hyst_f64_set_deadband_impl(S, width);
}

double hyst_f64_step(hyst_tcm_t *S, double x)
{
    return hyst_f64_step_impl(S, x);
}

#else
typedef int hyst_f64_disabled; /* an empty translation unit is not ISO C */
#endif
