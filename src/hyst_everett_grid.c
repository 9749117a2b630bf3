/* SPDX-License-Identifier: MIT */
/* The asymmetric kind on a grid (curve.h, hyst_everett_grid_t), set up once
 * in hyst_wide_t for every real variant: validation, and the table from
 * which the engine derives a branch's quadratic pieces
 * (src/kind_everett_grid.h). */
#include "hyst_util.h"

#include <float.h>
#include <string.h>

#define EG_MAX HYST_EVERETT_GRID_MAX_INTERVALS

/* The grid in wide numbers: knot interval widths, densities. */
typedef struct {
    unsigned k;
    hyst_wide_t h[EG_MAX];
} grid_t;

static hyst_wide_t weight(const hyst_everett_grid_t *g, unsigned i, unsigned j)
{
    return g->weight[i * (i + 1u) / 2u + j];
}

/* m / (a b): the product first, as it always was, unless it leaves the
 * normal numbers (widths below 1e-154 in double: a subnormal product has
 * lost digits); then one division after the other. */
static hyst_wide_t per_area(hyst_wide_t m, hyst_wide_t a, hyst_wide_t b)
{
    const hyst_wide_t ab = a * b;
    return ab >= HYST_WIDE_MIN && ab <= HYST_WIDE_MAX ? m / ab : m / a / b;
}

/* Table entry `at` (curve.h: knots, half diagonal densities, then four
 * numbers per cell (i, j), j < i); *mass: the mass a density or a mass per
 * unit of input carries (0 for the others). */
static hyst_wide_t entry(const hyst_everett_grid_t *g, const grid_t *w, size_t at, hyst_wide_t *mass)
{
    const size_t k = w->k;
    size_t r;
    unsigned i, j, l, p;
    hyst_wide_t sum = 0;
    *mass = 0;
    if (at <= k) {
        return g->knots[at];
    }
    if (at <= 2u * k) {
        i = (unsigned)(at - k - 1u);
        *mass = weight(g, i, i);
        return per_area(*mass, w->h[i], w->h[i]);
    }
    r = (at - 2u * k - 1u) / 4u;
    for (i = 1u; (size_t)i * (i + 1u) / 2u <= r; ++i) {
    }
    j = (unsigned)(r - (size_t)i * (i - 1u) / 2u);
    switch ((at - 2u * k - 1u) % 4u) {
    case 0u: /* E(knot i, knot j + 1): the cells inside */
        for (l = j + 1u; l < i; ++l) {
            for (p = j + 1u; p <= l; ++p) {
                sum += weight(g, l, p);
            }
        }
        return sum;
    case 1u: /* column j between them, per unit of b */
        for (l = j + 1u; l < i; ++l) {
            sum += weight(g, l, j);
        }
        *mass = sum;
        return sum / w->h[j];
    case 2u: /* row i between them, per unit of a */
        for (l = j + 1u; l < i; ++l) {
            sum += weight(g, i, l);
        }
        *mass = sum;
        return sum / w->h[i];
    default: /* the cell's density */
        *mass = weight(g, i, j);
        return per_area(*mass, w->h[i], w->h[j]);
    }
}

/* Knots finite, strictly increasing also in the variant's type, widths
 * finite (into w->h). */
static int knots_ok(const hyst_everett_grid_t *g, grid_t *w, unsigned variant)
{
    unsigned i;
    for (i = 0u; i <= w->k; ++i) {
        hyst_num_t v, prev;
        if (!hyst_wide_is_finite(g->knots[i]) || !hyst_num_set(&v, variant, g->knots[i])) {
            return 0;
        }
        if (i > 0u) {
            (void)hyst_num_set(&prev, variant, g->knots[i - 1u]);
            w->h[i - 1u] = g->knots[i] - g->knots[i - 1u];
            if (!(hyst_num_get(&v, variant) > hyst_num_get(&prev, variant)) ||
                !hyst_wide_is_finite(w->h[i - 1u])) {
                return 0;
            }
        }
    }
    return 1;
}

static hyst_status_t everett_grid(hyst_curve_t *curve, const hyst_everett_grid_t *g,
                           hyst_ptr_t table, size_t table_len, unsigned variant,
                           unsigned long layout)
{
    const hyst_wide_t least =
        variant == (unsigned)HYST_VARIANT_F32 ? (hyst_wide_t)FLT_MIN : HYST_WIDE_MIN;
    hyst_curve_t out;
    grid_t w;
    hyst_wide_t total = 0, eps, bound, slope = 0, reach, ymax;
    size_t len, at;
    unsigned k, i, j, cells;
    int finite = 1;
    if (curve == NULL || g == NULL || table.f32 == NULL) {
        return HYST_ERR_NULL;
    }
    if (layout != HYST_LAYOUT) {
        return HYST_ERR_LAYOUT;
    }
    k = g->intervals;
    if (k < 1u || k > (unsigned)EG_MAX) {
        return HYST_ERR_DEGREE;
    }
    w.k = k;
    if (!knots_ok(g, &w, variant)) {
        return HYST_ERR_BREAKPOINTS;
    }
    if (!hyst_wide_is_finite(g->y_lo)) {
        return HYST_ERR_COEFF;
    }
    for (i = 0u; i < HYST_EVERETT_GRID_CELLS(k); ++i) {
        if (!hyst_wide_is_finite(g->weight[i])) {
            return HYST_ERR_COEFF;
        }
    }
    for (i = 0u; i < HYST_EVERETT_GRID_CELLS(k); ++i) {
        if (g->weight[i] < 0) {
            return HYST_ERR_NOT_MONOTONE;
        }
        total += g->weight[i];
    }
    if (!(total > 0)) {
        return HYST_ERR_NOT_MONOTONE;
    }
    len = HYST_EVERETT_GRID_TABLE_LEN(k);
    cells = HYST_EVERETT_GRID_CELLS(k);
    if (table_len < len) {
        return HYST_ERR_NOSPACE;
    }
    for (at = 0u; at < len; ++at) { /* every entry finite before one is written */
        hyst_num_t v;
        hyst_wide_t mass;
        if (!hyst_num_set(&v, variant, entry(g, &w, at, &mass))) {
            return HYST_ERR_COEFF;
        }
        /* a mass whose density the type holds only as a subnormal or as 0
         * (a width's square overflowing): the model would lose it, more
         * than a rounding of the total if it is a cell's share of one */
        if (mass > total * hyst_real_eps(variant) / (hyst_wide_t)cells &&
            !(hyst_num_get(&v, variant) >= least)) {
            return HYST_ERR_COEFF;
        }
    }
    memset(&out, 0, sizeof out);
    out.kind = HYST_CURVE_EVERETT_GRID;
    out.variant = variant;
    out.layout = HYST_LAYOUT;
    finite &= hyst_num_set(&out.lo, variant, g->knots[0]);
    finite &= hyst_num_set(&out.hi, variant, g->knots[k]);
    finite &= hyst_num_set(&out.y_lo, variant, g->y_lo);
    finite &= hyst_num_set(&out.y_hi, variant, g->y_lo + total);
    finite &= hyst_num_set(&out.unit, variant, 1); /* G takes the input step itself */
    if (!finite) {
        return HYST_ERR_COEFF;
    }
    /* One branch evaluation y_k +- G: a piece's coefficients and the
     * quadratic, each of their terms a part of the total mass, err by a few
     * eps of it (16 with room); a piece's argument, the input's distance
     * from the TP less the knot's (each rounded once, then their
     * difference), by 3 eps of the span, times the steepest slope (a row's
     * or a column's mass per unit of input); the sum once more by eps
     * max |y|; 1 % for the bound's own rounding. */
    for (i = 0u; i < k; ++i) {
        hyst_wide_t row = 0, col = 0;
        for (j = 0u; j <= i; ++j) {
            row += weight(g, i, j);
        }
        for (j = i; j < k; ++j) {
            col += weight(g, j, i);
        }
        row /= w.h[i];
        col /= w.h[i];
        slope = row > slope ? row : slope;
        slope = col > slope ? col : slope;
    }
    eps = variant == (unsigned)HYST_VARIANT_F64 ? (hyst_wide_t)DBL_EPSILON / 2
                                                : (hyst_wide_t)FLT_EPSILON / 2;
    reach = g->knots[k] - g->knots[0];
    ymax = hyst_wide_abs(g->y_lo) + total;
    bound = (16 * eps * total + 4 * eps * reach * slope + eps * ymax) * (hyst_wide_t)1.01;
    if (!hyst_num_set(&out.rounding, variant, bound)) {
        return HYST_ERR_COEFF;
    }
    if (bound > (hyst_wide_t)HYST_MAX_ROUNDING * total) {
        return HYST_ERR_ILL_CONDITIONED;
    }
    for (at = 0u; at < len; ++at) {
        hyst_wide_t mass;
#if HYST_ENABLE_F64
        if (variant == (unsigned)HYST_VARIANT_F64) {
            table.f64[at] = (double)entry(g, &w, at, &mass);
            continue;
        }
#endif
        table.f32[at] = (float)entry(g, &w, at, &mass);
    }
    out.u.everett_grid.table = hyst_cptr_of(table, variant);
    out.u.everett_grid.intervals = k;
    *curve = out;
    return HYST_OK;
}

hyst_status_t hyst_f32_curve_from_everett_grid_(hyst_curve_t *curve, const hyst_everett_grid_t *g,
                                                float *table, size_t table_len,
                                                unsigned long layout)
{
    hyst_ptr_t t;
    t.f32 = table;
    return everett_grid(curve, g, t, table_len, HYST_VARIANT_F32, layout);
}

#if HYST_ENABLE_F64
hyst_status_t hyst_f64_curve_from_everett_grid_(hyst_curve_t *curve, const hyst_everett_grid_t *g,
                                                double *table, size_t table_len,
                                                unsigned long layout)
{
    hyst_ptr_t t;
    t.f64 = table;
    return everett_grid(curve, g, t, table_len, HYST_VARIANT_F64, layout);
}
#endif

/* The compensator's curve: the axes swapped, the table kept. */
static hyst_status_t grid_inverse(hyst_curve_t *inv, const hyst_curve_t *fwd, unsigned variant)
{
    hyst_curve_t out;
    hyst_wide_t span, eps;
    if (inv == NULL || fwd == NULL) {
        return HYST_ERR_NULL;
    }
    if (fwd->layout != HYST_LAYOUT || fwd->variant != variant) {
        return HYST_ERR_LAYOUT;
    }
    if (fwd->kind != (unsigned)HYST_CURVE_EVERETT_GRID || hyst_everett_grid_check_(fwd) != HYST_OK ||
        !(hyst_num_get(&fwd->y_lo, variant) < hyst_num_get(&fwd->y_hi, variant))) {
        return HYST_ERR_ARG;
    }
    hyst_curve_swap_axes_(&out, fwd);
    out.kind = HYST_CURVE_EVERETT_GRID_INV;
    (void)hyst_num_set(&out.unit, variant, 1); /* G^-1 takes the output step itself */
    span = hyst_num_get(&fwd->hi, variant) - hyst_num_get(&fwd->lo, variant);
    eps = variant == (unsigned)HYST_VARIANT_F64 ? (hyst_wide_t)DBL_EPSILON / 2
                                                : (hyst_wide_t)FLT_EPSILON / 2;
    (void)hyst_num_set(&out.rounding, variant, 16 * eps * span);
    *inv = out;
    return HYST_OK;
}

hyst_status_t hyst_f32_curve_everett_grid_inverse(hyst_curve_t *inv, const hyst_curve_t *fwd)
{
    return grid_inverse(inv, fwd, HYST_VARIANT_F32);
}

#if HYST_ENABLE_F64
hyst_status_t hyst_f64_curve_everett_grid_inverse(hyst_curve_t *inv, const hyst_curve_t *fwd)
{
    return grid_inverse(inv, fwd, HYST_VARIANT_F64);
}
#endif

hyst_status_t hyst_everett_grid_check_(const hyst_curve_t *curve)
{
    return curve->u.everett_grid.table.f32 != NULL && curve->u.everett_grid.intervals >= 1u &&
                   curve->u.everett_grid.intervals <= (unsigned)HYST_EVERETT_GRID_MAX_INTERVALS
               ? HYST_OK
               : HYST_ERR_ARG;
}
