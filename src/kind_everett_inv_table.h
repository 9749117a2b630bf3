/* SPDX-License-Identifier: MIT */
/* The asymmetric kind's tabulated compensator (HYST_CURVE_EVERETT_INV_TABLE),
 * a curve kind of the engine (src/tcm_engine.h, TCM_NAME(kind_t)): each
 * branch blended from four rows of the table around its anchor; the fast
 * path evaluates the cubic piece the last sample blended (emit()'s
 * HYST_HORNER_PIECE_ case), this file every other sample. Included by
 * src/kinds.h after the engine, in a variant with real outputs. */
#ifndef HYST_KIND_EVERETT_INV_TABLE_H
#define HYST_KIND_EVERETT_INV_TABLE_H

#include "kind_everett_inv.h"

/* The tabulated asymmetric compensator (HYST_CURVE_EVERETT_INV_TABLE,
 * S->degree HYST_HORNER_PIECE_): a branch's drive step at output step v is
 * the cubic of interval k = floor(s), s = v v_scale, blended from four rows
 * of the table (S->table: the first, S->blend: their weights; both set by
 * derive_blend() on the branch's slow sample). S->coef holds the blend of
 * interval S->cached_k: a sample in it costs one cubic. */

/* Interval k's coefficients blended from the branch's rows, into v (locals:
 * in registers, where S->coef would be stored and read back, the compiler
 * assuming that the table's reads alias it). */
HYST_INLINE void TCM_NAME(blend_coefs)(const hyst_tcm_t *S, unsigned long k, TCM_Y *v)
{
    const unsigned long row_len = HYST_INV_TABLE_LEN((unsigned long)S->curve->u.everett.intervals);
    const TCM_Y *r0 = S->table.TCM_YF + 4u * k;
    const TCM_Y *r1 = r0 + row_len;
    const TCM_Y *r2 = r1 + row_len;
    const TCM_Y *r3 = r2 + row_len;
    unsigned i;
    for (i = 0u; i < 4u; ++i) {
        v[i] = NUM_MULADD(YV(S->blend[3]), r3[i],
                          NUM_MULADD(YV(S->blend[2]), r2[i],
                                     NUM_MULADD(YV(S->blend[1]), r1[i], YV(S->blend[0]) * r0[i])));
    }
}

/* An interval every row marks (c0 = -1: the blend is then negative) is
 * solved as the exact compensator solves it, from the secant's point. */
static TCM_NOINLINE TCM_Y TCM_NAME(blend_exact)(const hyst_tcm_t *S, TCM_Y u)
{
    hyst_num_t coef[HYST_EVERETT_MAX_DEGREE];
    TCM_Y curv, w_end, secant;
    TCM_NAME(newton_state)(S, coef, &curv, &w_end, &secant);
    return TCM_NAME(solve_with)(S->curve, coef, curv, w_end, u, u * secant);
}

/* G at output step u >= 0 for the rare paths (merges, a restore, the tail
 * of a sample that refilled the blend): the same numbers as the inline path
 * (the cached blend, or the same blend computed here). */
static TCM_NOINLINE TCM_Y TCM_NAME(blend_g)(const hyst_tcm_t *S, TCM_Y u)
{
    const unsigned long n = (unsigned long)S->curve->u.everett.intervals;
    const TCM_Y s = u * YV(S->v_scale);
    unsigned long k = s < (TCM_Y)n ? (unsigned long)s : n; /* s >= 0 */
    TCM_Y g;
    if (k != S->cached_k) {
        TCM_Y v[4];
        TCM_NAME(blend_coefs)(S, k, v);
        g = TCM_NAME(cubic_of)(v[0], v[1], v[2], v[3], s - (TCM_Y)k);
    } else {
        g = TCM_NAME(cubic)(S->coef, s - (TCM_Y)k);
    }
    return g < 0 ? TCM_NAME(blend_exact)(S, u) : g;
}

/* Horner's rule over n = 1..HYST_EVERETT_MAX_DEGREE coefficients a[0]
 * (highest power) .. a[n - 1] at x, unrolled (a slow sample cannot afford
 * the loop): the numbers of the loop acc = acc x + a[i] from acc = 0, and
 * of NUM_NAME(horner) before its last product. */
HYST_INLINE TCM_Y TCM_NAME(poly_at)(const hyst_num_t *a, unsigned n, TCM_Y x)
{
    switch (n) {
    case 4u: return NUM_MULADD(NUM_MULADD(NUM_MULADD(YV(a[0]), x, YV(a[1])), x, YV(a[2])), x, YV(a[3]));
    case 3u: return NUM_MULADD(NUM_MULADD(YV(a[0]), x, YV(a[1])), x, YV(a[2]));
    case 2u: return NUM_MULADD(YV(a[0]), x, YV(a[1]));
    default: return YV(a[0]);
    }
}

#if TCM_REAL_INPUT
HYST_INLINE void TCM_NAME(table_coefs)(const hyst_num_t *row, unsigned n, TCM_Y anchor,
                                       hyst_num_t *coef, const int lowest);

/* p(w) = w q(w) on the branch that `row`'s table gives at `anchor`:
 * table_coefs(), then Horner's rule (NUM_NAME(horner)'s numbers), in one
 * switch on the degree n. */
HYST_INLINE TCM_Y TCM_NAME(branch_p)(const hyst_num_t *row, unsigned n, TCM_Y anchor, TCM_Y w)
{
    hyst_num_t c[HYST_EVERETT_MAX_DEGREE];
    TCM_Y q;
    switch (n) {
    case 4u:
        TCM_NAME(table_coefs)(row, 4u, anchor, c, TCM_HIGHEST_FIRST);
        q = TCM_NAME(poly_at)(c, 4u, w);
        break;
    case 3u:
        TCM_NAME(table_coefs)(row, 3u, anchor, c, TCM_HIGHEST_FIRST);
        q = TCM_NAME(poly_at)(c, 3u, w);
        break;
    case 2u:
        TCM_NAME(table_coefs)(row, 2u, anchor, c, TCM_HIGHEST_FIRST);
        q = TCM_NAME(poly_at)(c, 2u, w);
        break;
    default: q = YV(row[0]); break;
    }
    return NUM_MUL_G(q, w);
}

/* A TP pushed since the last derive (more TPs than then: pushes add one per
 * sample, wipe-outs and merges add none) is stored at the output the model
 * gives for its drive, not at the desired output: its drive is an earlier
 * output, one table evaluation off the exact inverse, and the branches that
 * start there then continue from where the model is, so the errors of
 * nested TPs do not add up. That output is the branch the TP ended, from
 * its parent TP, evaluated exactly (E's polynomial). Kept where it is not
 * strictly between the TP's neighbours in the input's order (rounding, or a
 * reversal smaller than the table's error). Integer inputs keep the desired
 * output (a code cannot hold it). */
HYST_INLINE void TCM_NAME(achieved_top)(hyst_tcm_t *S)
{
    const hyst_curve_t *c = S->curve;
    const size_t tps = S->n_ltp + S->n_rtp;
    const int fall = S->moving_end != 0u;
    const size_t t = fall ? S->n_rtp - 1u : S->n_ltp - 1u; /* the current TP */
    TCM_X *x_top;
    TCM_X x_parent, lower, upper, x_hat;
    TCM_Y y_parent, w;
    const int fresh = tps > S->tps_derived;
    S->tps_derived = tps;
    if (!fresh || (!fall && t == 0u)) { /* not new, or A0 */
        return;
    }
    /* an RTP t ended the rising branch from LTP t; an LTP t the falling one from RTP t - 1 */
    x_parent = fall ? XV(S->xltp)[t] : XV(S->xrtp)[t - 1u];
    y_parent = fall ? YV(S->yltp)[t] : YV(S->yrtp)[t - 1u];
    /* that branch's p(w) */
    w = NUM_NAME(abs)(YV(S->y_ctp) - y_parent) * YV(c->u.everett.inv_span);
    w = TCM_NAME(branch_p)(fall ? c->u.everett.rise : c->u.everett.fall, c->u.everett.degree,
                           TCM_NAME(drive_anchor)(S, y_parent), w) /
        YV(S->unit);
    x_hat = fall ? x_parent + w : x_parent - w;
    x_top = fall ? &XV(S->xrtp)[t] : &XV(S->xltp)[t];
    /* the input now is on the new branch: below an RTP, above an LTP */
    lower = fall ? XV(S->window[1]) : XV(S->xltp)[t - 1u];
    upper = fall ? (t > 0u ? XV(S->xrtp)[t - 1u] : XV(S->hi)) : XV(S->window[0]);
    if (x_hat > lower && x_hat < upper) { /* not -0: x_parent is stored normalised
                                          * (TCM_NORM), and x +- w is +0 when 0 */
        *x_top = x_hat;
        YV(S->x_ctp) = x_hat;
    }
}
#else
HYST_INLINE void TCM_NAME(achieved_top)(hyst_tcm_t *S) { (void)S; }
#endif

/* The kind's numbers of the instance: S->degree (emit()'s cached cubic
 * piece, HYST_HORNER_PIECE_) and derive_blend()'s constants table_rows,
 * table_intervals, v_least (out of line: init() stays small enough to stay
 * out of line itself). */
static TCM_NOINLINE void TCM_NAME(blend_attach)(hyst_tcm_t *S, const hyst_curve_t *curve)
{
    const TCM_Y n = (TCM_Y)curve->u.everett.intervals;
    S->degree = HYST_HORNER_PIECE_;
    YV(S->table_rows) = (TCM_Y)curve->u.everett.rows;
    YV(S->table_intervals) = n;
    YV(S->v_least) = TCM_D(XV(S->hi), XV(S->lo)) * (n * (TCM_Y)HYST_BLEND_LEAST_STEP);
}

/* The branch's rows, weights and index scale (derive()): cubic Lagrange
 * weights on the four rows around its anchor a (rows base .. base + 3 of
 * its direction, at x = a rows - base in 0..3), and v_scale = N / V(a), V
 * the branch's whole output step (V at least 2^-30 N of the desired
 * output range: s stays far below 2^32). */
HYST_INLINE void TCM_NAME(derive_blend)(hyst_tcm_t *S)
{
    const hyst_curve_t *c = S->curve;
    const unsigned fall = S->moving_end; /* 0 or 1 */
    const unsigned long rows = (unsigned long)c->u.everett.rows;
    const unsigned long n = (unsigned long)c->u.everett.intervals;
    const TCM_Y anchor = TCM_NAME(drive_anchor)(S, YV(S->y_ctp));
    const TCM_Y least = YV(S->v_least);
    TCM_Y x = anchor * YV(S->table_rows), range;
    unsigned long j = x > 0 ? (unsigned long)x : 0u, base;
    TCM_NAME(achieved_top)(S);
    j = j > rows - 1u ? rows - 1u : j;
    base = j < 1u ? 0u : (j - 1u > rows - 3u ? rows - 3u : j - 1u);
    x -= (TCM_Y)base;
    YV(S->blend[0]) = -(x - 1) * (x - 2) * (x - 3) / 6;
    YV(S->blend[1]) = x * (x - 2) * (x - 3) / 2;
    YV(S->blend[2]) = -x * (x - 1) * (x - 3) / 2;
    YV(S->blend[3]) = x * (x - 1) * (x - 2) / 6;
    S->table.TCM_YF = c->u.everett.table.TCM_YF +
                      ((fall != 0u ? rows + 1u : 0u) + base) * HYST_INV_TABLE_LEN(n);
    range = NUM_MULADD(TCM_NAME(poly_at)(c->u.everett.v_end[fall], c->u.everett.degree, anchor),
                       anchor, YV(c->u.everett.v_end[fall][c->u.everett.degree]));
    YV(S->v_scale) = YV(S->table_intervals) / (range > least ? range : least);
    S->cached_k = ULONG_MAX; /* no interval blended yet */
}

/* blended_sample()'s end in an interval every row marks solved: G from
 * blend_g() (which solves it), guarded as emit() guards it. emit_rare()'s
 * numbers without its serve(): no request is pending where a blended sample
 * runs (S->horner is the blend's), and the way back through serve() to
 * derive() would make the call graph a cycle (bench/analyse.py bounds the
 * stack). */
static TCM_NOINLINE TCM_Y TCM_NAME(blended_solved)(hyst_tcm_t *S, TCM_X x, const int how)
{
    const TCM_Y g = TCM_NAME(branch_g)(S, x);
    const TCM_Y y = how == TCM_FAST ? TCM_NAME(fast_end)(S, x, g) : TCM_NAME(slow_guard)(S, g, how);
    YV(S->y_prev) = y;
    return y;
}

/* A sample of the tabulated asymmetric compensator: one cubic where the
 * interval is the one blended last; else (and always after derive_blend())
 * the interval is blended first (the last one, N, past the branch's end by
 * rounding). Ends as emit() does, with the numbers blend_g() gives. */
HYST_INLINE TCM_Y TCM_NAME(blended_sample)(hyst_tcm_t *S, TCM_X x, const int how)
{
    const unsigned long n = (unsigned long)S->curve->u.everett.intervals;
    const TCM_Y u = (TCM_R(x) - YV(S->x_ctp)) * YV(S->u_scale);
    const TCM_Y s = u * YV(S->v_scale);
    unsigned long k = (unsigned long)s; /* s >= 0, below 2^31 (derive_blend()) */
    TCM_Y g, y;
    if (k != S->cached_k) {
        TCM_Y v[4];
        unsigned i;
        k = k < n ? k : n;
        TCM_NAME(blend_coefs)(S, k, v);
        for (i = 0u; i < 4u; ++i) {
            YV(S->coef[i]) = v[i];
        }
        S->cached_k = k;
        g = TCM_NAME(cubic_of)(v[0], v[1], v[2], v[3], s - (TCM_Y)k);
    } else {
        g = TCM_NAME(cubic)(S->coef, s - (TCM_Y)k);
    }
    if (g < 0) { /* a solved interval */
        return TCM_NAME(blended_solved)(S, x, how);
    }
    y = how == TCM_FAST ? TCM_NAME(fast_end)(S, x, g) : TCM_NAME(slow_guard)(S, g, how);
    YV(S->y_prev) = y;
    return y;
}
static TCM_NOINLINE TCM_Y TCM_NAME(emit_blended)(hyst_tcm_t *S, TCM_X x, const int how)
{
    return TCM_NAME(blended_sample)(S, x, how);
}

/* A slow sample of the tabulated asymmetric compensator that starts a
 * branch: derive_blend(), then the sample, in one frame (the weights and
 * the rows' address stay in registers). derive() keeps its own copy of
 * derive_blend() for the rare paths: calling this frame instead would save
 * about 1 KB of flash per variant, but cost the sample 6 instructions and
 * put serve()'s path on top of this one in the static call graph (the
 * stack bound, bench/analyse.py). */
static TCM_NOINLINE TCM_Y TCM_NAME(derive_emit_blended)(hyst_tcm_t *S, TCM_X x, const int how)
{
    TCM_NAME(derive_blend)(S);
    return TCM_NAME(blended_sample)(S, x, how);
}

/* The kind's sample (emit()'s HYST_HORNER_PIECE_ case, out of line): a new
 * branch's rows and weights first. */
static TCM_NOINLINE TCM_Y TCM_NAME(blended_emit)(hyst_tcm_t *S, TCM_X x, int how, int derive)
{
    return TCM_DERIVES(derive) ? TCM_NAME(derive_emit_blended)(S, x, how)
                               : TCM_NAME(emit_blended)(S, x, how);
}

/* The same on the fast path (an interval not cached). */
static TCM_NOINLINE TCM_Y TCM_NAME(blended_fast)(hyst_tcm_t *S, TCM_X x)
{
    return TCM_NAME(emit_blended)(S, x, TCM_FAST);
}

static TCM_NOINLINE void TCM_NAME(blended_derive)(hyst_tcm_t *S) { TCM_NAME(derive_blend)(S); }

/* The end of the kind's slow sample; any other value of S->horner is a
 * pending request. */
HYST_INLINE TCM_Y TCM_NAME(blended_slow_emit)(hyst_tcm_t *S, TCM_X x, const int how,
                                              const int derive)
{
    if (S->horner != HYST_HORNER_PIECE_) {
        if (TCM_DERIVES(derive)) {
            TCM_NAME(blended_derive)(S);
        }
        return TCM_NAME(emit_rare)(S, x, how);
    }
    return TCM_DERIVES(derive) ? TCM_NAME(derive_emit_blended)(S, x, how)
                               : TCM_NAME(emit_blended)(S, x, how);
}

#define TCM_SLOW(n) TCM_NAME(blended_##n)
#define TCM_SLOW_EMIT(S, x, how, derive) TCM_NAME(blended_slow_emit)((S), (x), (how), (derive))
#define TCM_SLOW_PER_BRANCH 1
#include "tcm_slow.h"

static const TCM_NAME(kind_t) TCM_NAME(ops_everett_inv_table) = {
    .g = TCM_NAME(blend_g),
    .emit = TCM_NAME(blended_emit),
    .derive = TCM_NAME(blended_derive),
    .slow = TCM_NAME(blended_step_slow),
    .loop_error = TCM_NAME(drive_range),
    .attach = TCM_NAME(blend_attach),
    .fast = TCM_NAME(blended_fast)};

#endif /* HYST_KIND_EVERETT_INV_TABLE_H */
