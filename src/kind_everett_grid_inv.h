/* SPDX-License-Identifier: MIT */
/* The compensator of the asymmetric kind on a grid
 * (HYST_CURVE_EVERETT_GRID_INV), a curve kind of the engine
 * (src/tcm_engine.h, TCM_NAME(kind_t)): its input the desired output, its
 * output the drive. The forward branch from a TP's drive is increasing and
 * quadratic on each knot interval (src/kind_everett_grid.h), so its inverse
 * is solved in closed form on the piece whose output steps hold the desired
 * one: w = start + 2 d / (c1 + sqrt(c1^2 + 4 c2 d)), d = v - c0 (no
 * cancellation). The branch's numbers are derived from the TP's drive (the
 * instance's output, y_ctp) as the forward kind's; the current piece is
 * kept with the output step where it ends (v_least) and its end (w_end:
 * a drive step never beyond it), so a sample in it
 * costs a compare, a square root and a few operations. The guard holds the
 * drive; a skipped loop's error is the drive range (no E of the desired
 * output). Included by src/kinds.h after the forward kind. */
#ifndef HYST_KIND_EVERETT_GRID_INV_H
#define HYST_KIND_EVERETT_GRID_INV_H

#include <math.h>

#include "kind_everett_grid.h"
#include "kind_everett_inv.h"

/* The piece's output step at its end (far: beyond any). */
HYST_INLINE TCM_Y TCM_NAME(egi_g_end)(const TCM_NAME(eg_piece_t) *p)
{
    const TCM_Y l = p->end - p->start;
    return NUM_MULADD(NUM_MULADD(p->c2, l, p->c1), l, p->c0);
}

/* The drive step of the output step v >= c0 on piece p. */
HYST_INLINE TCM_Y TCM_NAME(egi_solve)(TCM_Y c0, TCM_Y c1, TCM_Y c2, TCM_Y start, TCM_Y v)
{
    const TCM_Y d = v > c0 ? v - c0 : 0;
    const TCM_Y den = c1 + NUM_SQRT(NUM_MULADD(4 * c2, d, c1 * c1));
    return den > 0 ? start + 2 * d / den : start;
}

/* The piece whose output steps hold v (the last if none ends above it,
 * *g_end then the branch's whole reach):
 * the first that reaches v, so that on a flat piece (no mass) the drive
 * stays nearest the TP. At the edge lo the engine starts the major rising
 * branch from A0 with v = 0: the drive must be lo itself, where the plant
 * forgets its memory too, not the end of a flat first piece. */
static TCM_NAME(eg_piece_t) TCM_NAME(egi_piece)(const hyst_tcm_t *S, TCM_Y v, TCM_Y *g_end)
{
    const unsigned k = S->curve->u.everett_grid.intervals;
    const TCM_Y *tab = S->curve->u.everett_grid.table.TCM_YF;
    unsigned i = (unsigned)S->cached_k;
    TCM_NAME(eg_piece_t) p = TCM_NAME(eg_piece_at)(S, i);
    int last = S->moving_end == 0u ? i + 1u == k : i == 0u;
    while (!last && v > TCM_NAME(egi_g_end)(&p)) {
        i = S->moving_end == 0u ? i + 1u : i - 1u;
        p = TCM_NAME(eg_piece_at)(S, i);
        last = S->moving_end == 0u ? i + 1u == k : i == 0u;
    }
    if (last) { /* the last piece ends at the domain's end: the branch's reach */
        p.end = S->moving_end == 0u ? tab[k] - YV(S->curv) : YV(S->curv) - tab[0];
    }
    *g_end = TCM_NAME(egi_g_end)(&p);
    return p;
}

/* The drive step from the TP to the drive of the stored TP the branch
 * would wipe out next (the current LTP's falling; the current RTP's, or
 * hi, rising): the drive never passes it before the desired output passes
 * that TP's. Else a desired output within a rounding of the TP's (a
 * setpoint come back to) could carry the drive across a flat stretch of
 * the branch, the plant forgetting that TP while the compensator keeps it. */
static TCM_Y TCM_NAME(egi_reach)(const hyst_tcm_t *S)
{
    const unsigned k = S->curve->u.everett_grid.intervals;
    if (S->moving_end == 0u) {
        return (S->n_rtp > 0u ? YV(S->yrtp)[S->n_rtp - 1u]
                              : S->curve->u.everett_grid.table.TCM_YF[k]) - YV(S->y_ctp);
    }
    return YV(S->y_ctp) - YV(S->yltp)[S->n_ltp - 1u];
}

/* The drive step of the output step v on the current branch, out of line
 * (rare paths: merges, a restore): the kind's g. */
static TCM_NOINLINE TCM_Y TCM_NAME(egi_g)(const hyst_tcm_t *S, TCM_Y v)
{
    TCM_Y g_end;
    const TCM_NAME(eg_piece_t) p = TCM_NAME(egi_piece)(S, v, &g_end);
    const TCM_Y w = TCM_NAME(egi_solve)(p.c0, p.c1, p.c2, p.start, v);
    const TCM_Y reach = TCM_NAME(egi_reach)(S), end = p.end < reach ? p.end : reach;
    return w < end ? w : end;
}

/* The piece holding v made the current one; its end, the drive step no
 * sample passes, at most the reach. */
static TCM_NOINLINE void TCM_NAME(egi_cache)(hyst_tcm_t *S, TCM_Y v)
{
    TCM_Y g_end;
    const TCM_NAME(eg_piece_t) p = TCM_NAME(egi_piece)(S, v, &g_end);
    const TCM_Y reach = TCM_NAME(egi_reach)(S);
    YV(S->blend[0]) = p.c0;
    YV(S->blend[1]) = p.c1;
    YV(S->blend[2]) = p.c2;
    YV(S->blend[3]) = p.start;
    YV(S->v_least) = g_end;
    YV(S->w_end) = p.end < reach ? p.end : reach;
}

/* A new branch's numbers from its TP's drive, and its first piece. */
static TCM_NOINLINE void TCM_NAME(egi_derive)(hyst_tcm_t *S)
{
    TCM_NAME(eg_derive_at)(S, YV(S->y_ctp));
    TCM_NAME(egi_cache)(S, 0);
}

/* The end of a sample (how: as emit()): the drive from the current piece
 * (another's made current first), guarded against the last drive in the
 * input's direction. */
HYST_INLINE TCM_Y TCM_NAME(egi_end)(hyst_tcm_t *S, TCM_X x, const int how)
{
    const TCM_Y v = (TCM_R(x) - YV(S->x_ctp)) * YV(S->u_scale);
    TCM_Y w;
    if (!(v >= YV(S->blend[0]) && v < YV(S->v_least))) {
        TCM_NAME(egi_cache)(S, v);
    }
    w = TCM_NAME(egi_solve)(YV(S->blend[0]), YV(S->blend[1]), YV(S->blend[2]), YV(S->blend[3]), v);
    /* at most the piece's end and the reach: beyond the branch's reach (a
     * desired output past it by rounding) the solve would extrapolate past
     * the domain, far past it on a nearly flat last piece */
    YV(S->g_prev) = w < YV(S->w_end) ? w : YV(S->w_end);
    return TCM_NAME(eg_guarded)(S, x, how);
}

static TCM_NOINLINE TCM_Y TCM_NAME(egi_fast)(hyst_tcm_t *S, TCM_X x)
{
    return TCM_NAME(egi_end)(S, x, TCM_FAST);
}

static TCM_NOINLINE TCM_Y TCM_NAME(egi_emit)(hyst_tcm_t *S, TCM_X x, int how, int derive)
{
    if (TCM_DERIVES(derive)) {
        TCM_NAME(egi_derive)(S);
    }
    return TCM_NAME(egi_end)(S, x, how);
}

HYST_INLINE TCM_Y TCM_NAME(egi_slow_emit)(hyst_tcm_t *S, TCM_X x, const int how, const int derive)
{
    if (TCM_DERIVES(derive)) {
        TCM_NAME(egi_derive)(S);
    }
    return S->horner == HYST_HORNER_OWN_ ? TCM_NAME(egi_end)(S, x, how)
                                         : TCM_NAME(emit_rare)(S, x, how);
}

#define TCM_SLOW(n) TCM_NAME(egi_##n)
#define TCM_SLOW_EMIT(S, x, how, derive) TCM_NAME(egi_slow_emit)((S), (x), (how), (derive))
#define TCM_SLOW_PER_BRANCH 1
#include "tcm_slow.h"

/* Its numbers at init: the forward kind's (the table's checksum). */
static const TCM_NAME(kind_t) TCM_NAME(ops_everett_grid_inv) = {
    .g = TCM_NAME(egi_g),
    .emit = TCM_NAME(egi_emit),
    .derive = TCM_NAME(egi_derive),
    .slow = TCM_NAME(egi_step_slow),
    .loop_error = TCM_NAME(drive_range), /* the drive range (src/kind_everett_inv.h) */
    .attach = TCM_NAME(eg_attach),
    .fast = TCM_NAME(egi_fast)};

#endif /* HYST_KIND_EVERETT_GRID_INV_H */
