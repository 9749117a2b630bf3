/* The compensator: the TCM engine on the inverse of a polynomial curve. */
#include "hyst/inverse.h"

hyst_status_t hyst_init_inverse(hyst_t *S, const hyst_poly_t *f0, hyst_real_t *xltp,
                                hyst_real_t *yltp, hyst_real_t *xrtp, hyst_real_t *yrtp,
                                size_t capacity)
{
    hyst_curve_t curve;
    hyst_status_t st = hyst_curve_from_poly(&curve, f0);
    if (st == HYST_OK) {
        st = hyst_curve_inverse(&curve, &curve);
    }
    /* hyst_init_curve() checks the instance and its memory */
    return st == HYST_OK ? hyst_init_curve(S, &curve, xltp, yltp, xrtp, yrtp, capacity) : st;
}
