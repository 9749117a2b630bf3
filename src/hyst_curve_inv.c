/* SPDX-License-Identifier: MIT */
/* Inverse curves f0^-1 for a compensator (docs/theory.md), written once for
 * every variant: the axes swapped, and for a polynomial the start table of
 * its monotone inversion (evaluated per sample by src/curve_eval.h), or the
 * table of cubic pieces of the tabulated inverse (built by
 * src/inv_table_build.h on the polynomial's G, evaluated inline by the
 * engine, src/tcm_engine.h). */
#include <string.h>

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

/* The u in [a, b] where G crosses e (G(a) <= e <= G(b)), by bisection in
 * hyst_wide_t down to adjacent numbers (init time, cost irrelevant). */
static hyst_wide_t solve_g(const hyst_curve_poly_t *p, unsigned variant, hyst_wide_t e,
                           hyst_wide_t a, hyst_wide_t b)
{
    unsigned it;
    for (it = 0u; it < 80u; ++it) {
        const hyst_wide_t m = (a + b) / 2;
        if (m <= a || m >= b) {
            break;
        }
        if (unit_g(p, variant, m) < e) {
            a = m;
        } else {
            b = m;
        }
    }
    return a;
}

/* The start table of POLY_INV. */
static void fill_knots(hyst_curve_t *c, hyst_wide_t range)
{
    hyst_wide_t from = 0;
    unsigned k;
    (void)hyst_num_set(&c->u.poly_inv.knot_u[0], c->variant, 0);
    (void)hyst_num_set(&c->u.poly_inv.knot_u[HYST_INV_KNOTS], c->variant, 1);
    for (k = 1u; k < HYST_INV_KNOTS; ++k) {
        /* k / K first: range * k overflows once range > DBL_MAX / K */
        const hyst_wide_t e = range * ((hyst_wide_t)k / (hyst_wide_t)HYST_INV_KNOTS);
        from = solve_g(&c->u.poly_inv.fwd, c->variant, e, from, 1);
        (void)hyst_num_set(&c->u.poly_inv.knot_u[k], c->variant, from);
    }
}

/* G'(u) from the coefficients the samples will use. */
static hyst_wide_t unit_dg(const hyst_curve_poly_t *p, unsigned variant, hyst_wide_t u)
{
    hyst_wide_t acc = 0;
    unsigned i;
    for (i = 0u; i < p->degree; ++i) {
        acc = acc * u + (hyst_wide_t)(p->degree - i) * hyst_num_get(&p->a[i], variant);
    }
    return acc;
}

/* The sum of G's terms' magnitudes at u in [0, 1]: what G(u)'s rounding,
 * and a change of its coefficients by rounding, scale with. */
static hyst_wide_t unit_g_scale(const hyst_curve_poly_t *p, unsigned variant, hyst_wide_t u)
{
    hyst_wide_t acc = 0;
    unsigned i;
    for (i = 0u; i < p->degree; ++i) {
        acc = acc * u + hyst_wide_abs(hyst_num_get(&p->a[i], variant));
    }
    return acc * u;
}

hyst_wide_t hyst_table_put_(hyst_ptr_t table, size_t i, unsigned variant, hyst_wide_t w)
{
#if HYST_ENABLE_F64
    if (variant == (unsigned)HYST_VARIANT_F64) {
        table.f64[i] = (double)w + 0.0; /* +0: the sign marks exact intervals */
        return (hyst_wide_t)table.f64[i];
    }
#else
    (void)variant;
#endif
    table.f32[i] = (float)w + 0.0f;
    return (hyst_wide_t)table.f32[i];
}

/* The builder (src/inv_table_build.h) on a polynomial's G. */
#define TB_NAME(n) n
#define TB_FWD_T hyst_curve_poly_t
#define TB_G(p, variant, u) unit_g((p), (variant), (u))
#define TB_DG(p, variant, u) unit_dg((p), (variant), (u))
#include "inv_table_build.h"
/* A table given ready-made, its pieces measured: given_table_pieces(). */
#define TP_NAME(n) given_##n
#define TP_Q31 0
#define TP_GIVEN 1
#include "inv_table_pieces.h"

/* Everything of the table's curve but its numbers, and the build's state:
 * the checks both constructors make, the axes swapped, the index scale. */
static hyst_status_t table_prepare(hyst_curve_t *out, table_build_t *b, const hyst_curve_t *inv,
                                   const hyst_curve_t *fwd, hyst_cptr_t table, size_t intervals,
                                   unsigned variant)
{
    hyst_wide_t range, span;
    hyst_status_t st = hyst_curve_check(fwd);
    if (inv == NULL || table.f32 == NULL) {
        return HYST_ERR_NULL;
    }
    if (st != HYST_OK) {
        return st;
    }
    if (fwd->variant != variant) {
        return HYST_ERR_LAYOUT;
    }
    if (fwd->kind != (unsigned)HYST_CURVE_POLY || !table_size_ok((unsigned long)intervals)) {
        return HYST_ERR_ARG;
    }
    table_axes(out, fwd, (unsigned)HYST_CURVE_INV_TABLE, variant);
    out->u.inv_table.fwd = fwd->u.poly;
    range = unit_g(&fwd->u.poly, variant, 1);
    span = hyst_num_get(&fwd->hi, variant) - hyst_num_get(&fwd->lo, variant);
    if (!(range > 0) || !(span > 0)) {
        return HYST_ERR_NOT_INVERTIBLE;
    }
    (void)hyst_num_set(&out->u.inv_table.span, variant, span);
    (void)hyst_num_set(&out->u.inv_table.u_per_d, variant, 1 / span);
    return table_start(out, b, &out->u.inv_table.fwd, table, intervals, range, span, variant);
}

/* The drive's last rounding: the sample adds the table's drive step to its
 * turning point's drive, in the variant's type, so the result rounds to
 * eps |drive| (unit roundoff, doubled for the turning point's own); on a
 * domain far from 0 relative to its span this is most of the error (f32 on
 * [500000, 500010]: 3e-3 of the span, 3 000 times the pieces'). */
hyst_wide_t hyst_drive_rounding_(const hyst_curve_t *inv)
{
    const hyst_wide_t lo = hyst_wide_abs(hyst_num_get(&inv->y_lo, inv->variant));
    const hyst_wide_t hi = hyst_wide_abs(hyst_num_get(&inv->y_hi, inv->variant));
    return hyst_real_eps(inv->variant) * (lo > hi ? lo : hi);
}

hyst_status_t hyst_curve_inverse_table_(hyst_curve_t *inv, const hyst_curve_t *fwd,
                                        hyst_ptr_t table, size_t intervals, unsigned variant)
{
    hyst_curve_t out;
    table_build_t b;
    const hyst_cptr_t view = hyst_cptr_of(table, variant);
    hyst_status_t st;
    st = table_prepare(&out, &b, inv, fwd, view, intervals, variant);
    return st != HYST_OK ? st : table_build(inv, &out, &b, table, intervals);
}

/* Knots checked against the model in a table given ready-made. */
#define CHECK_KNOTS 7u

/* A table given ready-made, against the model: its shape
 * (hyst_table_shape_ok_()), its end (the drive span, within 8 units of the
 * variant's rounding), the intervals evaluated exactly (counted as the
 * build counts them), and the drive step at CHECK_KNOTS knots: G there
 * gives the knot's output step back within 8 units of rounding of G's terms
 * and of the drive step plus the span, and of subnormal numbers (a
 * residual, not the root solved
 * again: where the root is ill-conditioned, two solvers stop at different
 * numbers). 0 if it is another model's table. */
static int table_matches(table_build_t *b, hyst_cptr_t table, size_t n)
{
    const unsigned variant = b->c->variant;
    const hyst_wide_t tol = 8 * b->eps * b->span;
    size_t k;
    unsigned j;
    if (!hyst_table_shape_ok_(table, 0u, n, variant)) {
        return 0;
    }
    for (k = 0u; k < n; ++k) {
        b->c->u.inv_table.exact += hyst_cptr_get(table, 4u * k, variant) < 0 ? 1u : 0u;
    }
    for (j = 0u; j < 4u; ++j) {
        const hyst_wide_t end = hyst_cptr_get(table, 4u * n + j, variant);
        if (!(hyst_wide_abs(end - (j == 0u ? b->span : 0)) <= tol)) {
            return 0;
        }
    }
    for (j = 1u; j <= CHECK_KNOTS; ++j) {
        const hyst_curve_poly_t *p = &b->c->u.inv_table.fwd;
        const size_t knot = j * n / (CHECK_KNOTS + 1u);
        const hyst_wide_t c0 = hyst_cptr_get(table, 4u * knot, variant);
        const hyst_wide_t u = c0 / b->span;
        const hyst_wide_t residual =
            hyst_wide_abs(unit_g(p, variant, u) - (hyst_wide_t)knot * b->e_per_s);
        const hyst_wide_t dg = hyst_wide_abs(unit_dg(p, variant, u));
        if (c0 >= 0 && /* else the mark */
            !(residual <= 8 * b->eps * (unit_g_scale(p, variant, u) + (u + 1) * dg) +
                              8 * hyst_real_tiny(variant) * (1 + dg / b->span))) {
            return 0;
        }
    }
    return 1;
}

hyst_status_t hyst_curve_inverse_table_const_(hyst_curve_t *inv, const hyst_curve_t *fwd,
                                              hyst_cptr_t table, size_t intervals,
                                              const hyst_table_seal_t *seal, unsigned variant)
{
    hyst_curve_t out;
    table_build_t b;
    hyst_wide_t err;
    hyst_status_t st = seal == NULL ? HYST_ERR_NULL
                                    : table_prepare(&out, &b, inv, fwd, table, intervals, variant);
    if (st == HYST_OK) {
        st = hyst_table_seal_check_((unsigned)HYST_CURVE_INV_TABLE, variant, table, 0u,
                                    intervals, seal);
    }
    if (st != HYST_OK) {
        return st;
    }
    if (!table_matches(&b, table, intervals)) {
        return HYST_ERR_CURVE;
    }
    /* what the seal claims: every piece measured as the build measures it,
     * within HYST_INV_TABLE_TOL and the error sealed (a table whose pieces
     * were changed and sealed again passed the knots' check) */
    b.given = table;
    err = hyst_table_err_((given_table_pieces(&b, intervals) + hyst_drive_rounding_(&out)) /
                          b.span);
    if (b.beyond || !(err <= seal->max_err)) {
        return HYST_ERR_CURVE;
    }
    out.u.inv_table.max_err = seal->max_err;
    *inv = out;
    return HYST_OK;
}

hyst_status_t hyst_inverse_table_measure_(const hyst_curve_t *inv)
{
    hyst_curve_t fwd, out;
    table_build_t b;
    hyst_wide_t err;
    const unsigned v = inv->variant;
    const size_t n = inv->u.inv_table.intervals;
    hyst_status_t st;
    hyst_curve_swap_axes_(&fwd, inv); /* the forward curve the table was built from */
    fwd.kind = HYST_CURVE_POLY;
    fwd.u.poly = inv->u.inv_table.fwd;
    st = table_prepare(&out, &b, inv, &fwd, inv->u.inv_table.table, n, v);
    if (st != HYST_OK) {
        return HYST_ERR_CURVE;
    }
    { /* the build's scales, bit for bit */
        const hyst_num_t *const have[5] = {&inv->unit, &inv->u.inv_table.span,
                                           &inv->u.inv_table.u_per_d, &inv->lo, &inv->hi};
        const hyst_num_t *const want[5] = {&out.unit, &out.u.inv_table.span,
                                           &out.u.inv_table.u_per_d, &out.lo, &out.hi};
        unsigned k;
        for (k = 0u; k < 5u; ++k) {
            if (!(hyst_num_get(have[k], v) == hyst_num_get(want[k], v))) {
                return HYST_ERR_CURVE;
            }
        }
    }
    if (!table_matches(&b, inv->u.inv_table.table, n) ||
        out.u.inv_table.exact != inv->u.inv_table.exact) {
        return HYST_ERR_CURVE;
    }
    /* every piece measured as the table from flash is (its const init) */
    b.given = inv->u.inv_table.table;
    err = hyst_table_err_((given_table_pieces(&b, n) + hyst_drive_rounding_(&out)) / b.span);
    return b.beyond || !(err <= hyst_table_err_(inv->u.inv_table.max_err)) ? HYST_ERR_CURVE
                                                                          : HYST_OK;
}

hyst_wide_t hyst_curve_inverse_error(const hyst_curve_t *curve)
{
    if (curve != NULL && curve->kind == (unsigned)HYST_CURVE_EVERETT_INV_TABLE) {
        return curve->u.everett.max_err;
    }
    return curve != NULL && (curve->kind == (unsigned)HYST_CURVE_INV_TABLE ||
                             curve->kind == (unsigned)HYST_CURVE_SPLINE_INV_TABLE)
               ? curve->u.inv_table.max_err
               : 0;
}

/* Inverse of a PWL or PWL_INV curve: the same points, axes swapped (exact). */
static hyst_status_t pwl_inverse(hyst_curve_t *inv, const hyst_curve_t *fwd)
{
    hyst_curve_t out;
    size_t i;
    for (i = 1u; i < fwd->u.pwl.n; ++i) { /* strictly increasing values */
        if (!(hyst_cptr_get(fwd->u.pwl.y, i, fwd->variant) >
              hyst_cptr_get(fwd->u.pwl.y, i - 1u, fwd->variant))) {
            return HYST_ERR_NOT_INVERTIBLE;
        }
    }
    hyst_curve_swap_axes_(&out, fwd);
    out.kind = fwd->kind == (unsigned)HYST_CURVE_PWL ? HYST_CURVE_PWL_INV : HYST_CURVE_PWL;
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
    if (fwd->kind == (unsigned)HYST_CURVE_EVERETT || fwd->kind == (unsigned)HYST_CURVE_EVERETT_INV ||
        fwd->kind == (unsigned)HYST_CURVE_EVERETT_INV_TABLE) {
        return hyst_everett_inverse_(inv, fwd);
    }
    hyst_curve_swap_axes_(&out, fwd); /* the polynomial stays the forward one */
    lo = hyst_num_get(&out.lo, out.variant);
    hi = hyst_num_get(&out.hi, out.variant);
    if (fwd->kind == (unsigned)HYST_CURVE_POLY_INV ||
        fwd->kind == (unsigned)HYST_CURVE_INV_TABLE) { /* as hyst_curve_poly_() set it */
        const hyst_curve_poly_t p = fwd->kind == (unsigned)HYST_CURVE_POLY_INV
                                        ? fwd->u.poly_inv.fwd
                                        : fwd->u.inv_table.fwd;
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
