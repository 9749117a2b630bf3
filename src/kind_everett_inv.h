/* SPDX-License-Identifier: MIT */
/* The asymmetric kind's compensator (HYST_CURVE_EVERETT_INV), a curve kind
 * of the engine (src/tcm_engine.h, TCM_NAME(kind_t)): each branch solved by
 * Newton's iteration, bracketed, on the forward branch it inverts. Included
 * by src/kinds.h after the engine, in a variant with real outputs. */
#ifndef HYST_KIND_EVERETT_INV_H
#define HYST_KIND_EVERETT_INV_H

#include "kind_everett.h"

/* Evaluations of a branch by the asymmetric compensator's solve(), at most. */
#define TCM_SOLVE_STEPS 48u

/* p(w) = w q(w) and p'(w) on the current branch, q of degree n - 1 <= 3
 * (HYST_EVERETT_MAX_DEGREE), by Horner's rule unrolled. */
#define TCM_HORNER_D_(c, n, w, p, dp)                                        \
    do {                                                                   \
        TCM_Y q_ = YV((c)[0]), dq_ = 0;                                    \
        switch (n) {                                                       \
        case 4u: dq_ = q_; q_ = NUM_MULADD(q_, (w), YV((c)[1]));           \
            dq_ = NUM_MULADD(dq_, (w), q_);                                \
            q_ = NUM_MULADD(q_, (w), YV((c)[2]));                          \
            dq_ = NUM_MULADD(dq_, (w), q_);                                \
            q_ = NUM_MULADD(q_, (w), YV((c)[3])); break;                   \
        case 3u: dq_ = q_; q_ = NUM_MULADD(q_, (w), YV((c)[1]));           \
            dq_ = NUM_MULADD(dq_, (w), q_);                                \
            q_ = NUM_MULADD(q_, (w), YV((c)[2])); break;                   \
        case 2u: dq_ = q_; q_ = NUM_MULADD(q_, (w), YV((c)[1])); break;    \
        default: break;                                                    \
        }                                                                  \
        (p) = q_ * (w);                                                    \
        (dp) = NUM_MULADD((w), dq_, q_);                                   \
    } while (0)

/* The asymmetric compensator's G (HYST_CURVE_EVERETT_INV): the drive step
 * span w whose output step on the current forward branch, p(w) = w q(w)
 * (q's coefficients: derive()), is v. Newton's iteration from the last
 * output's w (a function of what a snapshot keeps, so a restore continues
 * bit for bit), bracketed: each evaluation's sign narrows [0, w_end] (p
 * increases), and a step that would leave it (or a zero slope) bisects
 * instead. A step s from w is taken as the answer once Taylor's bound on
 * its error, curv s^2 / (2 (p'(w) - 2 curv s)) with curv >= |p''| on the
 * branch, is at most tol: one evaluation for a sample that moves a little
 * along its branch. Also once s <= tol (s then estimates the error, or
 * bounds it where Newton converges fast) or the bracket is that narrow, and
 * at once on an exact root: at a branch's start p'(0) = 0 (and p''(0) may
 * be 0 too), where Newton's iteration only creeps towards the root and the
 * evaluations would run out far from it. */
HYST_INLINE TCM_Y TCM_NAME(solve_with)(const hyst_curve_t *c, const hyst_num_t *coef, TCM_Y curv,
                                       TCM_Y w_end, TCM_Y v, TCM_Y w)
{
    const unsigned n = c->u.everett.degree;
    const TCM_Y tol = YV(c->u.everett.tol);
    TCM_Y a = 0, b = w_end;
    unsigned k;
    w = w > 0 ? (w < b ? w : b) : 0; /* NaN: 0 */
    for (k = 0u; k < TCM_SOLVE_STEPS; ++k) {
        TCM_Y p, dp, f, step, next;
        TCM_HORNER_D_(coef, n, w, p, dp);
        f = p - v;
        if (f > 0) {
            b = w;
        } else {
            a = w;
        }
        step = f / dp;
        next = w - step;
        if (!(next >= a && next <= b)) { /* NaN too */
            if (f == 0) { /* w is the root; p'(w) = 0 there (a branch's start) */
                break;
            }
            next = NUM_MULADD(b - a, NUM_C(0.5), a);
            if (!(b - a > tol)) {
                w = next;
                break;
            }
        } else {
            const TCM_Y s = NUM_NAME(abs)(step);
            if (curv * s * s <= 2 * tol * NUM_MULADD(-(2 * curv), s, dp) || s <= tol) {
                w = next;
                break;
            }
        }
        w = next;
    }
    return w * YV(c->u.everett.span);
}

/* The same on the branch whose numbers derive() keeps in S. */
HYST_INLINE TCM_Y TCM_NAME(solve_inline)(const hyst_tcm_t *S, TCM_Y v, TCM_Y w)
{
    return TCM_NAME(solve_with)(S->curve, S->coef, YV(S->curv), YV(S->w_end), v, w);
}

/* The same from the secant's point, out of line, for the rare paths (g()
 * of a merge, resume_()): the kind's G. */
static TCM_NOINLINE TCM_Y TCM_NAME(solve)(const hyst_tcm_t *S, TCM_Y v)
{
    return TCM_NAME(solve_inline)(S, v, v * YV(S->secant));
}

/* The asymmetric compensator's anchor of a TP of drive y (the current
 * TP's: y_ctp): y, 0..1 over the drive range. */
HYST_INLINE TCM_Y TCM_NAME(drive_anchor)(const hyst_tcm_t *S, TCM_Y y)
{
    return (y - YV(S->y_lo)) * YV(S->curve->u.everett.inv_span);
}

/* The numbers solve_with() needs for the current branch of the asymmetric
 * compensator: its coefficients, a bound on |p''|, the bracket's end and the
 * secant to it. */
static void TCM_NAME(newton_state)(const hyst_tcm_t *S, hyst_num_t *coef, TCM_Y *curv,
                                   TCM_Y *w_end, TCM_Y *secant)
{
    const hyst_curve_t *c = S->curve;
    const unsigned n = c->u.everett.degree;
    /* the branch ends at its parent TP (loop closure): a bracket, and the
     * secant from the TP to it, solve()'s start on a slow sample */
    const int up = S->moving_end == 0u;
    const size_t at = up ? S->n_rtp : S->n_ltp;
    const TCM_X x_end = !up ? XV(S->xltp)[at - 1u] : at > 0u ? XV(S->xrtp)[at - 1u] : XV(S->hi);
    const TCM_Y y_end = !up ? YV(S->yltp)[at - 1u] : at > 0u ? YV(S->yrtp)[at - 1u] : YV(S->y_hi);
    const TCM_Y v_end = NUM_NAME(abs)(TCM_R(x_end) - YV(S->x_ctp)) * YV(S->unit);
    unsigned i;
    TCM_NAME(table_coefs)(up ? c->u.everett.rise : c->u.everett.fall, n,
                          TCM_NAME(drive_anchor)(S, YV(S->y_ctp)), coef, TCM_HIGHEST_FIRST);
    *w_end = NUM_NAME(abs)(y_end - YV(S->y_ctp)) * YV(c->u.everett.inv_span);
    *secant = v_end > 0 ? *w_end / v_end : 0;
    *curv = 0; /* |p''| <= sum k (k - 1) |a_k| on w in [0, 1] */
    for (i = 0u; i + 2u <= n; ++i) {
        const unsigned k = n - i; /* coef[i] multiplies w^k in p */
        *curv += (TCM_Y)(k * (k - 1u)) * NUM_NAME(abs)(YV(coef[i]));
    }
}

/* The end of a sample of the asymmetric compensator (how: as emit()). Its
 * solve() starts from y_prev, so the monotone guard holds y, not G (and no
 * window closes: a restore re-derives nothing but what a snapshot keeps). */
HYST_INLINE TCM_Y TCM_NAME(solved_end)(hyst_tcm_t *S, TCM_X x, const int how)
{
    const int up = how == TCM_FAST ? S->moving_end == 0u : how == TCM_ROSE;
    const TCM_Y v = (TCM_R(x) - YV(S->x_ctp)) * YV(S->u_scale);
    TCM_Y y, w = v * YV(S->secant); /* a slow sample: from the secant */
    if (how == TCM_FAST) { /* from the last output (on this branch) */
        w = (YV(S->y_prev) - YV(S->y_ctp)) * YV(S->curve->u.everett.inv_span);
        w = S->moving_end == 0u ? w : -w;
    }
    YV(S->g_prev) = TCM_NAME(solve_inline)(S, v, w);
    y = TCM_NAME(on_branch)(S, YV(S->g_prev));
    if (up ? y < YV(S->y_prev) : y > YV(S->y_prev)) {
        y = YV(S->y_prev);
    }
    if (how == TCM_FAST) {
        XV(S->window[S->moving_end]) = x;
    }
    YV(S->y_prev) = y;
    return y;
}

static TCM_NOINLINE TCM_Y TCM_NAME(emit_solved)(hyst_tcm_t *S, TCM_X x, const int how)
{
    return TCM_NAME(solved_end)(S, x, how);
}

/* The fast path's sample: its own copy, how a constant. */
static TCM_NOINLINE TCM_Y TCM_NAME(solved_fast)(hyst_tcm_t *S, TCM_X x)
{
    return TCM_NAME(solved_end)(S, x, TCM_FAST);
}

/* The kind's sample: a new branch's numbers first (derive: src/tcm_engine.h,
 * TCM_DERIVE_RISE...), then the solved end. */
static TCM_NOINLINE TCM_Y TCM_NAME(solved_emit)(hyst_tcm_t *S, TCM_X x, int how, int derive)
{
    if (TCM_DERIVES(derive)) {
        TCM_NAME(newton_state)(S, S->coef, &YV(S->curv), &YV(S->w_end), &YV(S->secant));
    }
    return TCM_NAME(emit_solved)(S, x, how);
}

static TCM_NOINLINE void TCM_NAME(solved_derive)(hyst_tcm_t *S)
{
    TCM_NAME(newton_state)(S, S->coef, &YV(S->curv), &YV(S->w_end), &YV(S->secant));
}

/* No E of the desired output: a skipped loop's error is the drive range. */
static TCM_Y TCM_NAME(drive_range)(const hyst_tcm_t *S, TCM_X b, TCM_X a)
{
    (void)b;
    (void)a;
    return YV(S->y_hi) - YV(S->y_lo);
}

/* The end of the kind's slow sample; any other value of S->horner is a
 * pending request. */
HYST_INLINE TCM_Y TCM_NAME(solved_slow_emit)(hyst_tcm_t *S, TCM_X x, const int how,
                                             const int derive)
{
    if (TCM_DERIVES(derive)) {
        TCM_NAME(solved_derive)(S);
    }
    return S->horner == HYST_HORNER_OWN_ ? TCM_NAME(emit_solved)(S, x, how)
                                           : TCM_NAME(emit_rare)(S, x, how);
}

/* Every sample is the kind's own (emit()'s HYST_HORNER_OWN_ case). */
static void TCM_NAME(solved_attach)(hyst_tcm_t *S, const hyst_curve_t *curve)
{
    (void)curve;
    S->degree = HYST_HORNER_OWN_;
}

#define TCM_SLOW(n) TCM_NAME(solved_##n)
#define TCM_SLOW_EMIT(S, x, how, derive) TCM_NAME(solved_slow_emit)((S), (x), (how), (derive))
#define TCM_SLOW_PER_BRANCH 1
#include "tcm_slow.h"

static const TCM_NAME(kind_t) TCM_NAME(ops_everett_inv) = {
    .g = TCM_NAME(solve),
    .emit = TCM_NAME(solved_emit),
    .derive = TCM_NAME(solved_derive),
    .slow = TCM_NAME(solved_step_slow),
    .loop_error = TCM_NAME(drive_range),
    .attach = TCM_NAME(solved_attach),
    .fast = TCM_NAME(solved_fast)};

#endif /* HYST_KIND_EVERETT_INV_H */
