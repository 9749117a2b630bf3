/* The compensator: the TCM engine on the inverse of a polynomial curve. */
#include "hyst/inverse.h"

hyst_status_t hyst_init_inverse(hyst_t *S, const hyst_poly_t *f0, hyst_real_t *xltp,
                                hyst_real_t *yltp, hyst_real_t *xrtp, hyst_real_t *yrtp,
                                size_t capacity)
{
    hyst_curve_t curve;
    hyst_status_t st;
    if (S == NULL || xltp == NULL || yltp == NULL || xrtp == NULL || yrtp == NULL) {
        return HYST_ERR_NULL;
    }
    if (capacity < 2u) {
        return HYST_ERR_CAPACITY;
    }
    st = hyst_curve_from_poly(&curve, f0);
    if (st == HYST_OK) {
        st = hyst_curve_inverse(&curve, &curve);
    }
    if (st != HYST_OK) {
        return st;
    }
    return hyst_init_curve(S, &curve, xltp, yltp, xrtp, yrtp, capacity);
}
