/* Private to the curve module: the out-of-line kinds of g. */
#ifndef HYST_CURVE_IMPL_H
#define HYST_CURVE_IMPL_H

#include "hyst/curve.h"
#include "hyst_internal.h"

/* PWL and PWL_INV: f(x) by binary search and linear interpolation, x clamped. */
hyst_real_t hyst_pwl_eval_(const hyst_curve_t *curve, hyst_real_t x);

/* Inverse of a PWL or PWL_INV curve (axes swapped); HYST_ERR_NOT_INVERTIBLE
 * if the values are not strictly increasing. */
hyst_status_t hyst_pwl_inverse_(hyst_curve_t *inv, const hyst_curve_t *fwd);

/* POLY_INV: g^-1(e), monotone, <= 2 HYST_INV_MAX_ITER bisections of G. */
hyst_real_t hyst_poly_inv_g_(const hyst_curve_t *curve, hyst_real_t e);

#endif
