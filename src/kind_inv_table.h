/* SPDX-License-Identifier: MIT */
/* The tabulated inverse (a compensator of f0), a curve kind of the engine
 * (src/tcm_engine.h, TCM_NAME(kind_t)): its cubic pieces are evaluated by
 * emit()'s case 0 (S->degree 0, S->table); its intervals marked exact by G
 * out of line (TCM_INV_TABLE_G: src/curve_eval.h's inv_table_g_(), or the
 * q31 compensator's own). Included after the engine by src/kinds.h and by
 * src/hyst_q31_inv.c. */
#ifndef HYST_KIND_INV_TABLE_H
#define HYST_KIND_INV_TABLE_H

static TCM_NOINLINE TCM_Y TCM_NAME(inv_table_kind_g)(const hyst_tcm_t *S, TCM_Y u)
{
    return TCM_INV_TABLE_G(S->curve, u);
}

/* The pieces for the fast path. */
static void TCM_NAME(inv_table_attach)(hyst_tcm_t *S, const hyst_curve_t *curve)
{
    S->table.TCM_YF = curve->u.inv_table.table.TCM_YF;
}

static const TCM_NAME(kind_t) TCM_NAME(ops_inv_table) = {.g = TCM_NAME(inv_table_kind_g),
                                                          .slow = TCM_NAME(step_slow),
                                                          .attach = TCM_NAME(inv_table_attach)};

#endif /* HYST_KIND_INV_TABLE_H */
