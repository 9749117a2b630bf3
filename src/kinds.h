/* SPDX-License-Identifier: MIT */
/* The curve kinds of a variant, one file each, and the one place that binds
 * a prepared curve to its kind (kind_of()). Included after src/tcm_engine.h
 * by a variant with real outputs (src/variant_real.h, src/hyst_code.c),
 * which defines TCM_CURVE_G(c, u): g of the kinds evaluated out of line,
 * TCM_INV_TABLE_G(c, s): a tabulated inverse's, TCM_SPLINE_G(c, s): a
 * spline's or its solved compensator's, and
 * TCM_SPLINE_TABLE_G(c, s): its tabulated compensator's.
 * An init that binds one kind alone (hyst_*_init_: the polynomial) links
 * no other kind's code. */
#ifndef HYST_KINDS_H
#define HYST_KINDS_H

#if !defined(TCM_CURVE_G) || !defined(TCM_INV_TABLE_G) || !defined(TCM_SPLINE_G) || \
    !defined(TCM_SPLINE_TABLE_G)
#error "kinds.h: the variant must define TCM_CURVE_G, TCM_INV_TABLE_G, TCM_SPLINE_G and TCM_SPLINE_TABLE_G"
#endif

#include "kind_poly.h"
#include "kind_curve.h"
#include "kind_inv_table.h"
#include "kind_everett.h"
#include "kind_everett_inv.h"
#include "kind_everett_inv_table.h"
#include "kind_everett_grid.h"
#include "kind_everett_grid_inv.h"
#include "kind_spline.h"

/* The kinds a firmware names (hyst_*_init_kind()): each binds the curves
 * of its own kind, for an instance of this variant, and NULL any other
 * curve; each references its own kind alone, so a firmware links the kinds
 * it names and no other. */
static const void *TCM_NAME(bound)(unsigned variant, int of_kind, const void *ops)
{
    return variant == (unsigned)TCM_VARIANT && of_kind ? ops : NULL;
}

static const void *TCM_NAME(bind_poly)(const hyst_curve_t *c, unsigned variant)
{
    return TCM_NAME(bound)(variant, c->kind == (unsigned)HYST_CURVE_POLY, &TCM_NAME(ops_poly));
}

static const void *TCM_NAME(bind_pwl)(const hyst_curve_t *c, unsigned variant)
{
    return TCM_NAME(bound)(variant, c->kind == (unsigned)HYST_CURVE_PWL ||
                                        c->kind == (unsigned)HYST_CURVE_PWL_INV,
                           &TCM_NAME(ops_curve));
}

static const void *TCM_NAME(bind_inverse)(const hyst_curve_t *c, unsigned variant)
{
    return TCM_NAME(bound)(variant, c->kind == (unsigned)HYST_CURVE_POLY_INV,
                           &TCM_NAME(ops_curve));
}

static const void *TCM_NAME(bind_inverse_table)(const hyst_curve_t *c, unsigned variant)
{
    return TCM_NAME(bound)(variant, c->kind == (unsigned)HYST_CURVE_INV_TABLE,
                           &TCM_NAME(ops_inv_table));
}

/* Its two tables: rows polynomial in the anchor, or at most linear in it. */
static const void *TCM_NAME(bind_everett)(const hyst_curve_t *c, unsigned variant)
{
    const int everett = c->kind == (unsigned)HYST_CURVE_EVERETT;
    return TCM_NAME(bound)(variant, everett,
                           everett && c->u.everett.linear_x ? &TCM_NAME(ops_everett_lines)
                                                            : &TCM_NAME(ops_everett));
}

static const void *TCM_NAME(bind_everett_inverse)(const hyst_curve_t *c, unsigned variant)
{
    return TCM_NAME(bound)(variant, c->kind == (unsigned)HYST_CURVE_EVERETT_INV,
                           &TCM_NAME(ops_everett_inv));
}

static const void *TCM_NAME(bind_everett_inverse_table)(const hyst_curve_t *c, unsigned variant)
{
    return TCM_NAME(bound)(variant, c->kind == (unsigned)HYST_CURVE_EVERETT_INV_TABLE,
                           &TCM_NAME(ops_everett_inv_table));
}

static const void *TCM_NAME(bind_everett_grid)(const hyst_curve_t *c, unsigned variant)
{
    return TCM_NAME(bound)(variant, c->kind == (unsigned)HYST_CURVE_EVERETT_GRID,
                           &TCM_NAME(ops_everett_grid));
}

static const void *TCM_NAME(bind_everett_grid_inverse)(const hyst_curve_t *c, unsigned variant)
{
    return TCM_NAME(bound)(variant, c->kind == (unsigned)HYST_CURVE_EVERETT_GRID_INV,
                           &TCM_NAME(ops_everett_grid_inv));
}

static const void *TCM_NAME(bind_spline)(const hyst_curve_t *c, unsigned variant)
{
    return TCM_NAME(bound)(variant, c->kind == (unsigned)HYST_CURVE_SPLINE ||
                                        c->kind == (unsigned)HYST_CURVE_SPLINE_INV,
                           &TCM_NAME(ops_spline));
}

static const void *TCM_NAME(bind_spline_inverse_table)(const hyst_curve_t *c, unsigned variant)
{
    return TCM_NAME(bound)(variant, c->kind == (unsigned)HYST_CURVE_SPLINE_INV_TABLE,
                           &TCM_NAME(ops_spline_inv_table));
}

/* The operations of the kind a caller named (hyst_*_init_kind()) for a
 * checked curve: HYST_ERR_NULL without a kind, HYST_ERR_CURVE for a kind
 * that is not the curve's or not this variant's. */
static hyst_status_t TCM_NAME(named_kind)(hyst_kind_t kind, const hyst_curve_t *curve,
                                          const TCM_NAME(kind_t) **ops)
{
    if (kind == NULL) {
        return HYST_ERR_NULL;
    }
    *ops = (const TCM_NAME(kind_t) *)kind(curve, (unsigned)TCM_VARIANT);
    return *ops != NULL ? HYST_OK : HYST_ERR_CURVE;
}

/* The kind of a prepared curve (checked: hyst_curve_check()), whichever it
 * is: hyst_*_init_curve(), which links every kind. */
static const TCM_NAME(kind_t) *TCM_NAME(kind_of)(const hyst_curve_t *curve)
{
    static const hyst_kind_t every[] = {
        TCM_NAME(bind_poly),           TCM_NAME(bind_pwl),            TCM_NAME(bind_inverse),
        TCM_NAME(bind_inverse_table),  TCM_NAME(bind_everett),
        TCM_NAME(bind_everett_inverse), TCM_NAME(bind_everett_inverse_table),
        TCM_NAME(bind_everett_grid),   TCM_NAME(bind_everett_grid_inverse),
        TCM_NAME(bind_spline),         TCM_NAME(bind_spline_inverse_table)};
    const void *kind = NULL;
    size_t i;
    for (i = 0u; kind == NULL && i < sizeof every / sizeof every[0]; ++i) {
        kind = every[i](curve, (unsigned)TCM_VARIANT);
    }
    return (const TCM_NAME(kind_t) *)kind; /* a checked curve has a kind */
}

#endif /* HYST_KINDS_H */
