/* SPDX-License-Identifier: MIT */
/* Inverse curves f0^-1 for a compensator (docs/theory.md), written once for
 * every variant: the axes swapped, and for a polynomial the start table of
 * its monotone inversion (evaluated per sample by src/curve_eval.h). */
#include "hyst_util.h"

/* G(u) in hyst_wide_t, from the coefficients the samples will use. */
static hyst_wide_t unit_g(const hyst_curve_poly_t *p, unsigned variant, hyst_wide_t u)
{
    hyst_wide_t acc = hyst_num_get(&p->a[0], variant);
    unsigned i;
    for (i = 1u; i < p->degree; ++i) {
        acc = acc * u + hyst_num_get(&p->a[i], variant);
    }
    return acc * u;
}

/* The start table: bisection in hyst_wide_t (init time, cost irrelevant). */
static void fill_knots(hyst_curve_t *c, hyst_wide_t range)
{
    hyst_wide_t from = 0;
    unsigned k, it;
    (void)hyst_num_set(&c->u.poly_inv.knot_u[0], c->variant, 0);
    (void)hyst_num_set(&c->u.poly_inv.knot_u[HYST_INV_KNOTS], c->variant, 1);
    for (k = 1u; k < HYST_INV_KNOTS; ++k) {
        /* k / K first: range * k overflows once range > DBL_MAX / K */
        const hyst_wide_t e = range * ((hyst_wide_t)k / (hyst_wide_t)HYST_INV_KNOTS);
        hyst_wide_t a = from, b = 1;
        for (it = 0u; it < 80u; ++it) {
            const hyst_wide_t m = (a + b) / 2;
            if (m <= a || m >= b) {
                break;
            }
            if (unit_g(&c->u.poly_inv.fwd, c->variant, m) < e) {
                a = m;
            } else {
                b = m;
            }
        }
        from = a;
        (void)hyst_num_set(&c->u.poly_inv.knot_u[k], c->variant, a);
    }
}

/* Inverse of a PWL or PWL_INV curve: the same points, axes swapped (exact). */
static hyst_status_t pwl_inverse(hyst_curve_t *inv, const hyst_curve_t *fwd)
{
    hyst_curve_t out = *fwd;
    size_t i;
    for (i = 1u; i < fwd->u.pwl.n; ++i) { /* strictly increasing values */
        if (!(hyst_cptr_get(fwd->u.pwl.y, i, fwd->variant) >
              hyst_cptr_get(fwd->u.pwl.y, i - 1u, fwd->variant))) {
            return HYST_ERR_NOT_INVERTIBLE;
        }
    }
    out.kind = fwd->kind == (unsigned)HYST_CURVE_PWL ? HYST_CURVE_PWL_INV : HYST_CURVE_PWL;
    out.lo = fwd->y_lo;
    out.hi = fwd->y_hi;
    out.y_lo = fwd->lo;
    out.y_hi = fwd->hi;
    out.u.pwl.x = fwd->u.pwl.y;
    out.u.pwl.y = fwd->u.pwl.x;
    *inv = out;
    return HYST_OK;
}

hyst_status_t hyst_curve_inverse(hyst_curve_t *inv, const hyst_curve_t *fwd)
{
    hyst_curve_t out;
    hyst_wide_t range, lo, hi;
    hyst_status_t st = hyst_curve_check(fwd);
    if (inv == NULL) {
        return HYST_ERR_NULL;
    }
    if (st != HYST_OK) {
        return st;
    }
    if (fwd->kind == (unsigned)HYST_CURVE_PWL || fwd->kind == (unsigned)HYST_CURVE_PWL_INV) {
        return pwl_inverse(inv, fwd);
    }
    out = *fwd; /* swap the axes; the polynomial stays the forward one */
    out.lo = fwd->y_lo;
    out.hi = fwd->y_hi;
    out.y_lo = fwd->lo;
    out.y_hi = fwd->hi;
    lo = hyst_num_get(&out.lo, out.variant);
    hi = hyst_num_get(&out.hi, out.variant);
    if (fwd->kind == (unsigned)HYST_CURVE_POLY_INV) { /* as hyst_curve_poly_() set it */
        const hyst_curve_poly_t p = fwd->u.poly_inv.fwd;
        out.kind = HYST_CURVE_POLY;
        out.u.poly = p;
        (void)hyst_num_set(&out.unit, out.variant, 1 / (hi - lo));
        *inv = out;
        return HYST_OK;
    }
    /* A non-constant polynomial accepted as increasing is strictly
     * increasing: its inverse exists. Refuse only a degenerate range. */
    range = unit_g(&fwd->u.poly, fwd->variant, 1);
    if (!(range > 0) || !(hi > lo)) {
        return HYST_ERR_NOT_INVERTIBLE;
    }
    out.kind = HYST_CURVE_POLY_INV;
    out.u.poly_inv.fwd = fwd->u.poly;
    (void)hyst_num_set(&out.unit, out.variant, 1); /* g^-1 takes the output difference itself */
    (void)hyst_num_set(&out.u.poly_inv.span, out.variant,
                       hyst_num_get(&fwd->hi, fwd->variant) - hyst_num_get(&fwd->lo, fwd->variant));
    (void)hyst_num_set(&out.u.poly_inv.knot_scale, out.variant,
                       (hyst_wide_t)HYST_INV_KNOTS / range);
    fill_knots(&out, range);
    *inv = out;
    return HYST_OK;
}
