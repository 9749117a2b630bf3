/* SPDX-License-Identifier: MIT */
/* The asymmetric kind on a grid (HYST_CURVE_EVERETT_GRID), a curve kind of
 * the engine (src/tcm_engine.h, TCM_NAME(kind_t)): E of a Preisach density
 * constant on the cells of a grid (curve.h, hyst_everett_grid_t). Along a
 * branch, G is a quadratic in u (the input's distance from the TP) on each
 * knot interval: rising from b in interval m, r = knot m+1 - b, on interval
 * i > m (t = u - (knot i - b))
 *   G = E(k_i, k_m+1) + r col + q_m r^2 + (row + d r) t + q_i t^2,
 * and falling from a in interval m, s = a - knot m, on interval j < m the
 * same with the column's and the row's parts swapped (the table's cell
 * (m, j)); on the TP's own interval G = q_m u^2. The branch's numbers are
 * derived when it starts (m, r, q_m r^2), a piece's when a sample first
 * falls in it (a few operations from the table); the fast path is a compare
 * and one quadratic (HYST_HORNER_OWN_: the kind's fast()). The instance's
 * fields it keeps them in (tcm.h):
 *   cached_k   m, the knot interval of the branch's TP
 *   curv       the TP's input in the curve's units (the knots')
 *   v_scale    r (rising) or s (falling)
 *   secant     q_m r^2: G where the TP's interval ends
 *   blend[0..2] the current piece's coefficients (of t^0, t^1, t^2)
 *   blend[3], w_end  the piece's start and end in u (the end excluded)
 * The guard holds the output, not G (as the solved compensator's), so that
 * G at the last input, all a restore re-derives, is the run's. Included by
 * src/kinds.h after the engine. */
#ifndef HYST_KIND_EVERETT_GRID_H
#define HYST_KIND_EVERETT_GRID_H

/* The curve's table (curve.h): knots, half diagonal densities, cells. */
#define TCM_EG_TABLE_(S) ((S)->curve->u.everett_grid.table.TCM_YF)

typedef struct {
    TCM_Y c0, c1, c2, start, end;
} TCM_NAME(eg_piece_t);

/* Further than any input step: the last piece's end. */
HYST_INLINE TCM_Y TCM_NAME(eg_far)(const hyst_tcm_t *S)
{
    const TCM_Y *tab = TCM_EG_TABLE_(S);
    return 2 * (tab[S->curve->u.everett_grid.intervals] - tab[0]) + 1;
}

/* An input of the instance in the curve's units (the knots'): itself in a
 * real variant (its domain is the curve's, its unit 1), a code mapped onto
 * the curve's domain. */
HYST_INLINE TCM_Y TCM_NAME(eg_user)(const hyst_tcm_t *S, TCM_Y x)
{
#if TCM_REAL_INPUT
    (void)S;
    return x;
#else
    return NUM_MULADD(x - TCM_R(XV(S->lo)), YV(S->unit), YV(S->curve->lo));
#endif
}

/* Piece i of the current branch (knot interval i: m, m + 1, ... rising;
 * m, m - 1, ... falling), from the branch's numbers and the table. */
static TCM_NAME(eg_piece_t) TCM_NAME(eg_piece_at)(const hyst_tcm_t *S, unsigned i)
{
    const TCM_Y *tab = TCM_EG_TABLE_(S);
    const unsigned k = S->curve->u.everett_grid.intervals;
    const unsigned m = (unsigned)S->cached_k;
    const TCM_Y x0 = YV(S->curv), far = TCM_NAME(eg_far)(S);
    const TCM_Y *rec;
    TCM_NAME(eg_piece_t) p;
    p.c0 = 0;
    p.c1 = 0;
    p.c2 = tab[k + 1u + i];
    if (S->moving_end == 0u) { /* rising */
        p.start = i == m ? 0 : tab[i] - x0;
        p.end = i + 1u < k ? tab[i + 1u] - x0 : far;
        if (i != m) {
            rec = tab + 2u * k + 1u + 4u * (i * (i - 1u) / 2u + m);
            p.c0 = NUM_MULADD(YV(S->v_scale), rec[1], rec[0]) + YV(S->secant);
            p.c1 = NUM_MULADD(rec[3], YV(S->v_scale), rec[2]);
        }
    } else { /* falling */
        p.start = i == m ? 0 : x0 - tab[i + 1u];
        p.end = i > 0u ? x0 - tab[i] : far;
        if (i != m) {
            rec = tab + 2u * k + 1u + 4u * (m * (m - 1u) / 2u + i);
            p.c0 = NUM_MULADD(YV(S->v_scale), rec[2], rec[0]) + YV(S->secant);
            p.c1 = NUM_MULADD(rec[3], YV(S->v_scale), rec[1]);
        }
    }
    return p;
}

/* The piece of the current branch that holds u (>= 0). */
static TCM_NAME(eg_piece_t) TCM_NAME(eg_piece)(const hyst_tcm_t *S, TCM_Y u)
{
    const TCM_Y *tab = TCM_EG_TABLE_(S);
    const unsigned k = S->curve->u.everett_grid.intervals;
    const TCM_Y x0 = YV(S->curv);
    unsigned i = (unsigned)S->cached_k;
    if (S->moving_end == 0u) {
        while (i + 1u < k && u >= tab[i + 1u] - x0) {
            ++i;
        }
    } else {
        while (i > 0u && u >= x0 - tab[i]) {
            --i;
        }
    }
    return TCM_NAME(eg_piece_at)(S, i);
}

/* G at u on the current branch, out of line (rare paths: merges, the
 * deadband, a restore): the kind's g. */
static TCM_NOINLINE TCM_Y TCM_NAME(eg_g)(const hyst_tcm_t *S, TCM_Y u)
{
    const TCM_NAME(eg_piece_t) p = TCM_NAME(eg_piece)(S, u);
    const TCM_Y t = u - p.start;
    return NUM_MULADD(NUM_MULADD(p.c2, t, p.c1), t, p.c0);
}

/* The piece holding u made the current one. */
static TCM_NOINLINE void TCM_NAME(eg_cache)(hyst_tcm_t *S, TCM_Y u)
{
    const TCM_NAME(eg_piece_t) p = TCM_NAME(eg_piece)(S, u);
    YV(S->blend[0]) = p.c0;
    YV(S->blend[1]) = p.c1;
    YV(S->blend[2]) = p.c2;
    YV(S->blend[3]) = p.start;
    YV(S->w_end) = p.end;
}

/* A new branch's numbers from its TP's drive x0 (the curve's units). */
static void TCM_NAME(eg_derive_at)(hyst_tcm_t *S, TCM_Y x0)
{
    const TCM_Y *tab = TCM_EG_TABLE_(S);
    const unsigned k = S->curve->u.everett_grid.intervals;
    unsigned m = 0u;
    TCM_Y r;
    if (S->moving_end == 0u) { /* knot m <= b < knot m + 1 (the last interval holds hi) */
        while (m + 1u < k && tab[m + 1u] <= x0) {
            ++m;
        }
        r = tab[m + 1u] - x0;
    } else { /* knot m < a <= knot m + 1 (the first holds lo) */
        while (m + 1u < k && tab[m + 1u] < x0) {
            ++m;
        }
        r = x0 - tab[m];
    }
    YV(S->curv) = x0;
    S->cached_k = m;
    YV(S->v_scale) = r;
    YV(S->secant) = tab[k + 1u + m] * r * r;
}

/* A new branch's numbers, from its TP (x_ctp), and its first piece. */
static TCM_NOINLINE void TCM_NAME(eg_derive)(hyst_tcm_t *S)
{
    TCM_NAME(eg_derive_at)(S, TCM_NAME(eg_user)(S, YV(S->x_ctp)));
    TCM_NAME(eg_cache)(S, 0);
}

/* A sample's end once G (its g_prev) is known, how as emit(): the output
 * guarded against the last one in the input's direction (this kind's and
 * its compensator's). */
HYST_INLINE TCM_Y TCM_NAME(eg_guarded)(hyst_tcm_t *S, TCM_X x, const int how)
{
    const int up = how == TCM_FAST ? S->moving_end == 0u : how == TCM_ROSE;
    TCM_Y y = TCM_NAME(on_branch)(S, YV(S->g_prev));
    if (up ? y < YV(S->y_prev) : y > YV(S->y_prev)) {
        y = YV(S->y_prev);
    }
    if (how == TCM_FAST) {
        XV(S->window[S->moving_end]) = x;
    }
    YV(S->y_prev) = y;
    return y;
}

/* The end of a sample on the current branch (how: as emit()): G from the
 * current piece (another's made current first), then eg_guarded(). */
HYST_INLINE TCM_Y TCM_NAME(eg_end)(hyst_tcm_t *S, TCM_X x, const int how)
{
    const TCM_Y u = (TCM_R(x) - YV(S->x_ctp)) * YV(S->u_scale);
    TCM_Y t;
    if (!(u >= YV(S->blend[3]) && u < YV(S->w_end))) {
        TCM_NAME(eg_cache)(S, u);
    }
    t = u - YV(S->blend[3]);
    YV(S->g_prev) = NUM_MULADD(NUM_MULADD(YV(S->blend[2]), t, YV(S->blend[1])), t,
                               YV(S->blend[0]));
    return TCM_NAME(eg_guarded)(S, x, how);
}

/* The fast path's sample: its own copy, how a constant. */
static TCM_NOINLINE TCM_Y TCM_NAME(eg_fast)(hyst_tcm_t *S, TCM_X x)
{
    return TCM_NAME(eg_end)(S, x, TCM_FAST);
}

/* The kind's sample for emit()'s other callers: a new branch's numbers
 * first (derive: TCM_DERIVE_RISE...), then the end. */
static TCM_NOINLINE TCM_Y TCM_NAME(eg_emit)(hyst_tcm_t *S, TCM_X x, int how, int derive)
{
    if (TCM_DERIVES(derive)) {
        TCM_NAME(eg_derive)(S);
    }
    return TCM_NAME(eg_end)(S, x, how);
}

/* The end of the kind's slow sample; any other value of S->horner is a
 * pending request. */
HYST_INLINE TCM_Y TCM_NAME(eg_slow_emit)(hyst_tcm_t *S, TCM_X x, const int how, const int derive)
{
    if (TCM_DERIVES(derive)) {
        TCM_NAME(eg_derive)(S);
    }
    return S->horner == HYST_HORNER_OWN_ ? TCM_NAME(eg_end)(S, x, how)
                                         : TCM_NAME(emit_rare)(S, x, how);
}

/* A skipped loop [b, a]'s error: the full model differs from the branch
 * moved back along by the mass of a rectangle of area (x - b)(a - x) <=
 * (a - b)^2 / 4 inside the window's cells, at most their highest density
 * times that area. */
static TCM_NOINLINE TCM_Y TCM_NAME(eg_loop_error)(const hyst_tcm_t *S, TCM_X b, TCM_X a)
{
    const TCM_Y *tab = TCM_EG_TABLE_(S);
    const unsigned k = S->curve->u.everett_grid.intervals;
    const TCM_Y d = TCM_D(a, b) * YV(S->unit);
    const TCM_Y ub = TCM_NAME(eg_user)(S, TCM_R(b)), ua = TCM_NAME(eg_user)(S, TCM_R(a));
    TCM_Y most = 0;
    unsigned first = 0u, last = 0u, i, j;
    while (first + 1u < k && tab[first + 1u] <= ub) {
        ++first;
    }
    last = first;
    while (last + 1u < k && tab[last + 1u] < ua) {
        ++last;
    }
    for (i = first; i <= last; ++i) {
        const TCM_Y diag = 2 * tab[k + 1u + i];
        most = diag > most ? diag : most;
        for (j = first; j < i; ++j) {
            const TCM_Y dens = tab[2u * k + 1u + 4u * (i * (i - 1u) / 2u + j) + 3u];
            most = dens > most ? dens : most;
        }
    }
    return most * d * d * NUM_C(0.2525); /* 1/4, rounded up by 1 % */
}

/* Every sample is the kind's own (emit()'s HYST_HORNER_OWN_ case); no
 * coefficients (a snapshot's curve identity covers the table: curve_id in
 * src/hyst_snapshot.c). */
static void TCM_NAME(eg_attach)(hyst_tcm_t *S, const hyst_curve_t *curve)
{
    (void)curve;
    S->degree = HYST_HORNER_OWN_;
}

#define TCM_SLOW(n) TCM_NAME(eg_##n)
#define TCM_SLOW_EMIT(S, x, how, derive) TCM_NAME(eg_slow_emit)((S), (x), (how), (derive))
#define TCM_SLOW_PER_BRANCH 1
#include "tcm_slow.h"

static const TCM_NAME(kind_t) TCM_NAME(ops_everett_grid) = {
    .g = TCM_NAME(eg_g),
    .emit = TCM_NAME(eg_emit),
    .derive = TCM_NAME(eg_derive),
    .slow = TCM_NAME(eg_step_slow),
    .loop_error = TCM_NAME(eg_loop_error),
    .attach = TCM_NAME(eg_attach),
    .fast = TCM_NAME(eg_fast)};

#undef TCM_EG_TABLE_

#endif /* HYST_KIND_EVERETT_GRID_H */
