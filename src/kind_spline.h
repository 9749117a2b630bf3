/* SPDX-License-Identifier: MIT */
/* The spline kind (HYST_CURVE_SPLINE, hyst_spline_t) and its compensators
 * (HYST_CURVE_SPLINE_INV, HYST_CURVE_SPLINE_INV_TABLE), curve kinds of
 * the engine (src/tcm_engine.h, TCM_NAME(kind_t)): the spline's pieces and
 * the tabulated compensator's are tables of cubics that emit()'s case 0
 * evaluates on the fast path, G off it the variant's TCM_SPLINE_G and
 * TCM_SPLINE_TABLE_G (src/curve_eval.h: the tabulated compensator's exact
 * intervals solved as the solved compensator solves every sample, out of
 * line: no table, every sample slow). Included by src/kinds.h after the
 * engine. */
#ifndef HYST_KIND_SPLINE_H
#define HYST_KIND_SPLINE_H

static TCM_NOINLINE TCM_Y TCM_NAME(spline_kind_g)(const hyst_tcm_t *S, TCM_Y u)
{
    return TCM_SPLINE_G(S->curve, u);
}

static void TCM_NAME(spline_attach)(hyst_tcm_t *S, const hyst_curve_t *curve)
{
    if (curve->kind == (unsigned)HYST_CURVE_SPLINE) {
        S->table.TCM_YF = curve->u.spline.table.TCM_YF;
    } else if (curve->kind == (unsigned)HYST_CURVE_SPLINE_INV_TABLE) {
        S->table.TCM_YF = curve->u.inv_table.table.TCM_YF;
    }
}

static const TCM_NAME(kind_t) TCM_NAME(ops_spline) = {.g = TCM_NAME(spline_kind_g),
                                                       .slow = TCM_NAME(step_slow),
                                                       .attach = TCM_NAME(spline_attach)};

/* The tabulated compensator's G: a kind of its own, so that the solved
 * compensator's every sample tests no more kinds. */
static TCM_NOINLINE TCM_Y TCM_NAME(spline_table_kind_g)(const hyst_tcm_t *S, TCM_Y u)
{
    return TCM_SPLINE_TABLE_G(S->curve, u);
}

static const TCM_NAME(kind_t) TCM_NAME(ops_spline_inv_table) = {
    .g = TCM_NAME(spline_table_kind_g),
    .slow = TCM_NAME(step_slow),
    .attach = TCM_NAME(spline_attach)};

#endif /* HYST_KIND_SPLINE_H */
