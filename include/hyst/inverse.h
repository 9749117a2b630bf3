/**
 * @file inverse.h
 * @brief The inverse TCM: a feedforward compensator (METHOD.md section 8).
 *
 * The inverse of a TCM with curve f0 on [lo, hi] is a TCM in the (y, x)
 * plane with curve f0^-1 on [f0(lo), f0(hi)]: the same engine (hyst_t,
 * hyst_step()) on an inverse curve (hyst_curve_inverse()). Its input is the
 * desired displacement, its output the drive that produces it on the model:
 * @code
 * HYST_DEFINE(comp, 4096);
 * if (HYST_INIT_INVERSE(comp, &f0) != HYST_OK) { handle_error(); }
 * for (;;) { dac_write(hyst_step(&comp, desired_position())); }
 * @endcode
 * A desired output outside [f0(lo), f0(hi)] is clamped to it and reported
 * (hyst_status() == HYST_WARN_CLAMPED, event HYST_EVENT_CLAMPED).
 * The turning points are desired outputs: HYST_CAPACITY(Nu) suffices when
 * they take at most Nu distinct values.
 */
#ifndef HYST_INVERSE_H
#define HYST_INVERSE_H

#include "hyst/curve.h"
#include "hyst/tcm.h"

#ifdef __cplusplus
extern "C" {
#endif

/**
 * @brief Initialises @p S as the inverse (compensator) of the TCM with the
 *        polynomial @p f0.
 *
 * hyst_curve_from_poly(), hyst_curve_inverse(), hyst_init_curve(), in this
 * order (a curve error is reported before an instance error). g^-1 costs
 * at most 2 HYST_INV_MAX_ITER evaluations of f0 per sample, and the drive is
 * non-decreasing in the desired output along a branch. For a curve of another
 * kind (piecewise linear, PI loading curve) call hyst_curve_inverse() and
 * hyst_init_curve() directly.
 *
 * @param[out] S         instance, starts at (f0(lo), lo).
 * @param[in]  f0        forward major ascending curve.
 * @param[in]  xltp,yltp,xrtp,yrtp four arrays of @p capacity entries each.
 * @param[in]  capacity  entries per array, >= 2.
 * @return HYST_OK, HYST_ERR_NULL, HYST_ERR_CAPACITY, a curve error or
 *         HYST_ERR_NOT_INVERTIBLE.
 */
hyst_status_t hyst_init_inverse(hyst_t *S, const hyst_poly_t *f0, hyst_real_t *xltp,
                                hyst_real_t *yltp, hyst_real_t *xrtp, hyst_real_t *yrtp,
                                size_t capacity);

/** hyst_init_inverse() on an instance declared by HYST_DEFINE(). */
#define HYST_INIT_INVERSE(name, f0)                                          \
    hyst_init_inverse(&(name), (f0), name##_xltp, name##_yltp, name##_xrtp,  \
                      name##_yrtp, sizeof(name##_xltp) / sizeof(name##_xltp[0]))

#ifdef __cplusplus
}
#endif

#endif /* HYST_INVERSE_H */
