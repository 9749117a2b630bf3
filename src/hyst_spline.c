/* SPDX-License-Identifier: MIT */
/* The spline kind's set-up (curve.h, hyst_spline_t): a cubic Hermite f0 on
 * uniform knots, proved increasing piece by piece and written as the table
 * of cubic pieces the engine's fast path evaluates (G in s, s the input in
 * knot intervals from lo), the same form as a tabulated inverse's; its
 * compensators, solved and tabulated. */
#include <string.h>

#include "hyst_util.h"

/* Piece k's cubic in t in [0, 1] from the knots' values and slopes, h the
 * knot spacing: c[0] + t (c[1] + t (c[2] + t c[3])) - value[k], every
 * number times `scale` (a power of two; 1 but where they would overflow,
 * and then h already scaled by it). */
static void piece(const hyst_spline_t *f0, unsigned k, hyst_wide_t h, hyst_wide_t scale,
                  hyst_wide_t *c)
{
    const hyst_wide_t rise = f0->value[k + 1u] * scale - f0->value[k] * scale;
    const hyst_wide_t m0 = h * f0->slope[k], m1 = h * f0->slope[k + 1u];
    c[0] = 0;
    c[1] = m0;
    c[2] = 3 * rise - 2 * m0 - m1;
    c[3] = m0 + m1 - 2 * rise;
}

hyst_wide_t hyst_spline_eval(const hyst_spline_t *f0, hyst_wide_t x)
{
    hyst_wide_t c[4], s, t;
    unsigned k;
    if (f0 == NULL || f0->intervals < 1u || f0->intervals > HYST_SPLINE_MAX_INTERVALS) {
        return 0;
    }
    x = x < f0->lo ? f0->lo : (x > f0->hi ? f0->hi : x);
    s = (x - f0->lo) / (f0->hi - f0->lo) * (hyst_wide_t)f0->intervals;
    k = (unsigned)s;
    if (k >= f0->intervals) {
        return f0->value[f0->intervals];
    }
    t = s - (hyst_wide_t)k;
    piece(f0, k, (f0->hi - f0->lo) / (hyst_wide_t)f0->intervals, 1, c);
    return f0->value[k] + t * (c[1] + t * (c[2] + t * c[3]));
}

/* Whether piece c (as piece() gives it) does not decrease on [0, 1]: its
 * slope c1 + 2 c2 t + 3 c3 t^2 at both ends (the knots' slopes, checked
 * >= 0 exactly by the caller) and, where the parabola opens upwards with
 * its vertex inside, at the vertex, within 64 roundings of the piece's
 * scale |rise| + both end slopes. Written so that nothing overflows: the
 * allowance term by term, and c2^2 / (3 c3) as -c2 t*. */
static int piece_increasing(const hyst_wide_t *c, hyst_wide_t rise, hyst_wide_t m1)
{
    const hyst_wide_t u = 64 * HYST_WIDE_EPS;
    if (c[3] > 0 && -c[2] > 0 && -c[2] < 3 * c[3]) { /* vertex t* = -c2 / (3 c3) in (0, 1) */
        return c[1] + c[2] * (-c[2] / c[3] / 3) >= -(hyst_wide_abs(rise) * u + c[1] * u + m1 * u);
    }
    return 1;
}

/* Piece k's shape (piece_increasing()) from its knots' numbers scaled by
 * 2^-8, for a piece whose own numbers overflow the type: scaling by a power
 * of two changes no decision. If they overflow still, a slope is more than
 * 41 times the rise (the rise is at most 2^-7 of the type's largest then):
 * outside the region of increasing pieces (both slopes at most 4 times the
 * rise). */
static int piece_scaled_increasing(const hyst_spline_t *f0, unsigned k, hyst_wide_t h)
{
    const hyst_wide_t s = 1 / (hyst_wide_t)256, hs = h * s;
    hyst_wide_t c[4];
    piece(f0, k, hs, s, c);
    if (!hyst_wide_is_finite(c[1]) || !hyst_wide_is_finite(c[2]) || !hyst_wide_is_finite(c[3])) {
        return 0;
    }
    return piece_increasing(c, f0->value[k + 1u] * s - f0->value[k] * s, hs * f0->slope[k + 1u]);
}

static hyst_status_t spline_check(const hyst_spline_t *f0, unsigned variant)
{
    const unsigned n = f0->intervals;
    hyst_wide_t h, c[4];
    hyst_num_t lo, hi, probe;
    unsigned k;
    if (n < 1u || n > HYST_SPLINE_MAX_INTERVALS) {
        return HYST_ERR_DEGREE;
    }
    if (!hyst_wide_is_finite(f0->lo) || !hyst_wide_is_finite(f0->hi) || !(f0->lo < f0->hi) ||
        !hyst_wide_is_finite(f0->hi - f0->lo) || !hyst_num_set(&lo, variant, f0->lo) ||
        !hyst_num_set(&hi, variant, f0->hi) || !hyst_num_set(&probe, variant, f0->hi - f0->lo) ||
        !hyst_num_set(&probe, variant, (hyst_wide_t)n / (f0->hi - f0->lo)) ||
        !(hyst_num_get(&lo, variant) < hyst_num_get(&hi, variant))) {
        return HYST_ERR_DOMAIN; /* the span overflows, or lo and hi round together */
    }
    for (k = 0u; k <= n; ++k) {
        if (!hyst_wide_is_finite(f0->value[k]) || !hyst_wide_is_finite(f0->slope[k])) {
            return HYST_ERR_COEFF;
        }
    }
    h = (f0->hi - f0->lo) / (hyst_wide_t)n;
    for (k = 0u; k <= n; ++k) {
        if (!(f0->slope[k] >= 0)) {
            return HYST_ERR_NOT_INCREASING;
        }
    }
    for (k = 0u; k < n; ++k) {
        int up;
        piece(f0, k, h, 1, c);
        /* 64 roundings of the piece's scale, as the polynomial kind's proof;
         * a piece whose numbers the table cannot hold is refused after
         * NOSPACE (curve.h's order), its shape checked here all the same */
        if (hyst_wide_is_finite(c[1]) && hyst_wide_is_finite(c[2]) && hyst_wide_is_finite(c[3])) {
            up = piece_increasing(c, f0->value[k + 1u] - f0->value[k], h * f0->slope[k + 1u]);
        } else {
            up = piece_scaled_increasing(f0, k, h);
        }
        if (!up) {
            return HYST_ERR_NOT_INCREASING;
        }
    }
    if (!(f0->value[n] > f0->value[0])) {
        return HYST_ERR_NOT_INCREASING; /* constant */
    }
    return HYST_OK;
}

static hyst_status_t curve_spline(hyst_curve_t *curve, const hyst_spline_t *f0, hyst_ptr_t table,
                                  size_t table_len, unsigned variant, unsigned long layout)
{
    hyst_curve_t out;
    hyst_wide_t h, c[4];
    hyst_status_t st;
    unsigned n, k, pass;
    int finite = 1;
    if (curve == NULL || f0 == NULL || table.f32 == NULL) {
        return HYST_ERR_NULL;
    }
    if (layout != HYST_LAYOUT) {
        return HYST_ERR_LAYOUT;
    }
    st = spline_check(f0, variant);
    if (st != HYST_OK) {
        return st;
    }
    n = f0->intervals;
    if (table_len < HYST_SPLINE_TABLE_LEN((size_t)n)) {
        return HYST_ERR_NOSPACE;
    }
    h = (f0->hi - f0->lo) / (hyst_wide_t)n;
    /* pass 0 checks every number in the variant's type, pass 1 writes them:
     * the table is written only when the curve will be */
    for (pass = 0u; pass < 2u; ++pass) {
        for (k = 0u; k <= n; ++k) {
            hyst_num_t v;
            unsigned j;
            if (k < n) {
                piece(f0, k, h, 1, c);
            } else {
                c[1] = c[2] = c[3] = 0;
            }
            c[0] = f0->value[k] - f0->value[0]; /* G at knot k */
            for (j = 0u; j < 4u; ++j) {
                if (pass == 0u) {
                    finite &= hyst_num_set(&v, variant, c[j]);
                } else {
                    (void)hyst_table_put_(table, (size_t)4u * k + j, variant, c[j]);
                }
            }
        }
        if (pass == 0u) { /* the ends' outputs too, before the table is written */
            hyst_num_t v;
            finite &= hyst_num_set(&v, variant, f0->value[0]);
            finite &= hyst_num_set(&v, variant, f0->value[n]);
        }
        if (!finite) {
            return HYST_ERR_COEFF;
        }
    }
    memset(&out, 0, sizeof out);
    out.kind = HYST_CURVE_SPLINE;
    out.variant = variant;
    out.layout = HYST_LAYOUT;
    (void)hyst_num_set(&out.lo, variant, f0->lo);
    (void)hyst_num_set(&out.hi, variant, f0->hi);
    (void)hyst_num_set(&out.y_lo, variant, f0->value[0]);
    (void)hyst_num_set(&out.y_hi, variant, f0->value[n]);
    (void)hyst_num_set(&out.unit, variant, (hyst_wide_t)n / (f0->hi - f0->lo));
    (void)hyst_num_set(&out.u.spline.span, variant, f0->hi - f0->lo);
    out.u.spline.table.f32 = table.f32;
    out.u.spline.intervals = n;
    *curve = out;
    return HYST_OK;
}

hyst_status_t hyst_f32_curve_from_spline_(hyst_curve_t *curve, const hyst_spline_t *f0,
                                          float *table, size_t table_len, unsigned long layout)
{
    hyst_ptr_t t;
    t.f32 = table;
    return curve_spline(curve, f0, t, table_len, HYST_VARIANT_F32, layout);
}

#if HYST_ENABLE_F64
hyst_status_t hyst_f64_curve_from_spline_(hyst_curve_t *curve, const hyst_spline_t *f0,
                                          double *table, size_t table_len, unsigned long layout)
{
    hyst_ptr_t t;
    t.f64 = table;
    return curve_spline(curve, f0, t, table_len, HYST_VARIANT_F64, layout);
}
#endif

/* Whether every piece of a spline curve or its solved compensator rises
 * (a flat piece has no inverse). */
static int pieces_rise(const hyst_curve_t *fwd)
{
    const hyst_cptr_t tab = fwd->u.spline.table;
    size_t k;
    for (k = 0u; k < fwd->u.spline.intervals; ++k) {
        if (!(hyst_cptr_get(tab, 4u * (k + 1u), fwd->variant) >
              hyst_cptr_get(tab, 4u * k, fwd->variant))) {
            return 0;
        }
    }
    return 1;
}

/* ---- The tabulated compensator (HYST_CURVE_SPLINE_INV_TABLE): the
 * builder of a polynomial's (src/inv_table_build.h) on the spline's G ---- */

/* The forward spline's piece at u in [0, 1] of its domain, as the samples
 * find it (knot interval floor(u K); the last one at u = 1, whose slope
 * there is the end's), into p, and t in it. */
static hyst_wide_t fwd_piece(const hyst_curve_t *c, unsigned variant, hyst_wide_t u,
                             hyst_wide_t *p)
{
    const size_t n = c->u.inv_table.fwd_spline.intervals;
    const hyst_wide_t s = u * (hyst_wide_t)n;
    size_t k = (size_t)(unsigned long)s;
    unsigned j;
    if (k >= n) {
        k = n - 1u;
    }
    for (j = 0u; j < 4u; ++j) {
        p[j] = hyst_cptr_get(c->u.inv_table.fwd_spline.table, 4u * k + j, variant);
    }
    return s - (hyst_wide_t)k;
}

/* G(u) from the pieces as stored, in hyst_wide_t. */
static hyst_wide_t pieces_g(const hyst_curve_t *c, unsigned variant, hyst_wide_t u)
{
    hyst_wide_t p[4];
    const hyst_wide_t t = fwd_piece(c, variant, u, p);
    return p[0] + t * (p[1] + t * (p[2] + t * p[3]));
}

/* G'(u): K times the piece's slope in t. */
static hyst_wide_t pieces_dg(const hyst_curve_t *c, unsigned variant, hyst_wide_t u)
{
    hyst_wide_t p[4];
    const hyst_wide_t t = fwd_piece(c, variant, u, p);
    const hyst_wide_t k = (hyst_wide_t)c->u.inv_table.fwd_spline.intervals;
    return k * (p[1] + t * (2 * p[2] + 3 * p[3] * t));
}

#define TB_NAME(n) spline_##n
#define TB_FWD_T hyst_curve_t
#define TB_G(p, variant, u) pieces_g((p), (variant), (u))
#define TB_DG(p, variant, u) pieces_dg((p), (variant), (u))
#include "inv_table_build.h"

/* The checks, in the polynomial's order (hyst_*_curve_inverse_table()),
 * and the curve but its numbers: the axes swapped, the forward spline's
 * pieces kept for the exact intervals, its unit their argument per drive
 * step. */
static hyst_status_t inv_table_prepare(hyst_curve_t *out, table_build_t *b, const hyst_curve_t *inv,
                                       const hyst_curve_t *fwd, hyst_cptr_t table, size_t intervals,
                                       unsigned variant)
{
    hyst_wide_t range, span;
    const hyst_status_t st = hyst_curve_check(fwd); /* the layout; ARG for a spline */
    if (inv == NULL || table.f32 == NULL) {
        return HYST_ERR_NULL;
    }
    if (st != HYST_OK && st != HYST_ERR_ARG) {
        return st;
    }
    if (fwd->variant != variant) {
        return HYST_ERR_LAYOUT;
    }
    if (fwd->kind != (unsigned)HYST_CURVE_SPLINE || hyst_spline_check_(fwd) != HYST_OK ||
        !spline_table_size_ok((unsigned long)intervals)) {
        return HYST_ERR_ARG;
    }
    if (!pieces_rise(fwd)) {
        return HYST_ERR_NOT_INVERTIBLE;
    }
    spline_table_axes(out, fwd, (unsigned)HYST_CURVE_SPLINE_INV_TABLE, variant);
    memset(&out->u, 0, sizeof out->u); /* no polynomial: its degree 0 */
    out->u.inv_table.fwd_spline = fwd->u.spline;
    out->u.inv_table.span = fwd->u.spline.span;
    out->u.inv_table.u_per_d = fwd->unit;
    range = pieces_g(out, variant, 1);
    span = hyst_num_get(&out->u.inv_table.span, variant);
    if (!(range > 0) || !(span > 0)) {
        return HYST_ERR_NOT_INVERTIBLE;
    }
    return spline_table_start(out, b, out, table, intervals, range, span, variant);
}

static hyst_status_t spline_inverse_table(hyst_curve_t *inv, const hyst_curve_t *fwd,
                                          hyst_ptr_t table, size_t intervals, unsigned variant)
{
    hyst_curve_t out;
    table_build_t b;
    const hyst_status_t st =
        inv_table_prepare(&out, &b, inv, fwd, hyst_cptr_of(table, variant), intervals, variant);
    return st != HYST_OK ? st : spline_table_build(inv, &out, &b, table, intervals);
}

hyst_status_t hyst_f32_curve_spline_inverse_table(hyst_curve_t *inv, const hyst_curve_t *fwd,
                                                  float *table, size_t intervals)
{
    hyst_ptr_t t;
    t.f32 = table;
    return spline_inverse_table(inv, fwd, t, intervals, HYST_VARIANT_F32);
}

#if HYST_ENABLE_F64
hyst_status_t hyst_f64_curve_spline_inverse_table(hyst_curve_t *inv, const hyst_curve_t *fwd,
                                                  double *table, size_t intervals)
{
    hyst_ptr_t t;
    t.f64 = table;
    return spline_inverse_table(inv, fwd, t, intervals, HYST_VARIANT_F64);
}
#endif

hyst_status_t hyst_spline_check_(const hyst_curve_t *curve)
{
    if (curve->kind == (unsigned)HYST_CURVE_SPLINE_INV_TABLE) { /* both tables */
        return curve->u.inv_table.table.f32 != NULL &&
                       spline_table_size_ok((unsigned long)curve->u.inv_table.intervals) &&
                       curve->u.inv_table.fwd_spline.table.f32 != NULL &&
                       curve->u.inv_table.fwd_spline.intervals >= 1u &&
                       curve->u.inv_table.fwd_spline.intervals <= HYST_SPLINE_MAX_INTERVALS
                   ? HYST_OK
                   : HYST_ERR_ARG;
    }
    return curve->u.spline.table.f32 != NULL && curve->u.spline.intervals >= 1u &&
                   curve->u.spline.intervals <= HYST_SPLINE_MAX_INTERVALS
               ? HYST_OK
               : HYST_ERR_ARG;
}

/* The spline of its tabulated compensator: its pieces and unit kept, the
 * axes swapped back. */
static hyst_status_t table_forward(hyst_curve_t *inv, const hyst_curve_t *fwd)
{
    hyst_curve_t out;
    spline_table_axes(&out, fwd, (unsigned)HYST_CURVE_SPLINE, fwd->variant);
    memset(&out.u, 0, sizeof out.u);
    out.unit = fwd->u.inv_table.u_per_d;
    out.u.spline = fwd->u.inv_table.fwd_spline;
    *inv = out;
    return HYST_OK;
}

hyst_status_t hyst_curve_spline_inverse(hyst_curve_t *inv, const hyst_curve_t *fwd)
{
    hyst_curve_t out;
    hyst_status_t st;
    int to_inverse;
    if (inv == NULL || fwd == NULL) {
        return HYST_ERR_NULL;
    }
    st = hyst_curve_check(fwd); /* the layout, variant and domain; ARG for this kind */
    if (st != HYST_ERR_ARG) {
        return st == HYST_OK ? HYST_ERR_ARG : st;
    }
    if ((fwd->kind != (unsigned)HYST_CURVE_SPLINE && fwd->kind != (unsigned)HYST_CURVE_SPLINE_INV &&
         fwd->kind != (unsigned)HYST_CURVE_SPLINE_INV_TABLE) ||
        hyst_spline_check_(fwd) != HYST_OK) {
        return HYST_ERR_ARG;
    }
    if (fwd->kind == (unsigned)HYST_CURVE_SPLINE_INV_TABLE) {
        return table_forward(inv, fwd);
    }
    if (!pieces_rise(fwd)) {
        return HYST_ERR_NOT_INVERTIBLE;
    }
    to_inverse = fwd->kind == (unsigned)HYST_CURVE_SPLINE;
    /* the same table: G^-1 takes the output step itself, G knot intervals */
    hyst_curve_swap_axes_(&out, fwd);
    out.kind = to_inverse ? HYST_CURVE_SPLINE_INV : HYST_CURVE_SPLINE;
    (void)hyst_num_set(&out.unit, out.variant,
                       to_inverse ? 1
                                  : (hyst_wide_t)fwd->u.spline.intervals /
                                        hyst_num_get(&fwd->u.spline.span, fwd->variant));
    *inv = out;
    return HYST_OK;
}
