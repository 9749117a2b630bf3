/* SPDX-License-Identifier: MIT */
/* The curve kinds of a variant, one file each, and the one place that binds
 * a prepared curve to its kind (kind_of()). Included after src/tcm_engine.h
 * by a variant with real outputs (src/variant_real.h, src/hyst_code.c),
 * which defines TCM_CURVE_G(c, u): g of the kinds evaluated out of line,
 * TCM_INV_TABLE_G(c, s): a tabulated inverse's, TCM_SPLINE_G(c, s): a spline's or its solved compensator's, and
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

/* The kind of a prepared curve (checked: hyst_curve_check()). */
static const TCM_NAME(kind_t) *TCM_NAME(kind_of)(const hyst_curve_t *curve)
{
    switch (curve->kind) {
    case HYST_CURVE_POLY: return &TCM_NAME(kind_poly);
    case HYST_CURVE_EVERETT:
        return curve->u.everett.linear_x ? &TCM_NAME(kind_everett_lines) : &TCM_NAME(kind_everett);
    case HYST_CURVE_EVERETT_INV: return &TCM_NAME(kind_everett_inv);
    case HYST_CURVE_EVERETT_INV_TABLE: return &TCM_NAME(kind_everett_inv_table);
    case HYST_CURVE_EVERETT_GRID: return &TCM_NAME(kind_everett_grid);
    case HYST_CURVE_EVERETT_GRID_INV: return &TCM_NAME(kind_everett_grid_inv);
    case HYST_CURVE_SPLINE:
    case HYST_CURVE_SPLINE_INV: return &TCM_NAME(kind_spline);
    case HYST_CURVE_SPLINE_INV_TABLE: return &TCM_NAME(kind_spline_inv_table);
    case HYST_CURVE_INV_TABLE: return &TCM_NAME(kind_inv_table);
    default: return &TCM_NAME(kind_curve); /* PWL, PWL_INV, POLY_INV */
    }
}

#endif /* HYST_KINDS_H */
