/* SPDX-License-Identifier: MIT */
/* The TCM engine, written once, instantiated explicitly by each variant's
 * translation unit (src/hyst_f32.c, src/hyst_f64.c, src/hyst_code.c). Every
 * name it generates is prefixed by TCM_NAME; everything is static but the
 * variant's internal entry points (reset_, resume_: src/hyst_util.h).
 *
 * Contract, checked below: before the #include the variant defines
 *   TCM_NAME(n)          prefixed name: hyst_f32_##n
 *   TCM_VARIANT          hyst_variant_t of its instances
 *   TCM_X, TCM_XF        stored input type and its hyst_num_t member
 *   TCM_Y, TCM_YF        output type and its member (src/num_ops.h included
 *                        for it: NUM_MULADD, NUM_NAME(abs))
 *   TCM_ARG, TCM_IN      per-sample input type (may be wider than TCM_X),
 *                        block input type
 *   TCM_R(a)             a as TCM_Y (exact for codes up to 24 bits)
 *   TCM_D(a, b)          a - b as TCM_Y, for a >= b (exact for codes)
 *   TCM_MID(a, b)        a point of [a, b], a or b once they are adjacent
 *   TCM_NORM(a)          a as stored in a TP array (reals: -0 becomes +0,
 *                        which the search by bit patterns needs)
 *   TCM_ADMIT(S, x, out) a function: 0 if the sample must be ignored, else
 *                        1 with *out inside the domain (clamped if needed)
 * and optionally TCM_G_OTHER(c, d): g of a fixed variant's kinds evaluated
 * out of line (the real variants bind theirs: TCM_NAME(kind_t) below);
 * TCM_KEY_T, TCM_UKEY_T: signed and unsigned integers of
 * TCM_X's size, to search reals by their bit patterns; and
 * TCM_LTP_BELOW(a, n, x), TCM_RTP_ABOVE(a, n, x): another search over the
 * sorted TP arrays than the binary search below (the benchmarks measure a
 * linear scan this way). Fixed-point outputs (src/hyst_q31.c) also define
 *   TCM_G_HALF(S, d)     g at d / 2 (default: g() of d * 0.5)
 *   TCM_ADD_BOUND(a, e)  a += e for an error bound (saturating in fixed point)
 * and the products of Horner's rule (src/num_ops.h: NUM_MUL, NUM_MUL_G).
 * TCM_REAL_INPUT 1 says TCM_X is TCM_Y (a TP's input may then be any real:
 * achieved_top()); default 0. TCM_POLY_ONLY 1 says the variant binds the
 * polynomial kind alone (src/hyst_q31.c): emit() then has Horner's cases
 * only, none of the other kinds' (a table, the banks, the kinds' own);
 * default 0. */
#ifndef HYST_TCM_ENGINE_H
#define HYST_TCM_ENGINE_H

#if !defined(TCM_NAME) || !defined(TCM_VARIANT) || !defined(TCM_X) || !defined(TCM_XF) ||   \
    !defined(TCM_Y) || !defined(TCM_YF) || !defined(TCM_ARG) || !defined(TCM_IN) ||          \
    !defined(TCM_R) || !defined(TCM_D) || !defined(TCM_MID) || !defined(TCM_NORM) ||         \
    !defined(TCM_ADMIT)
#error "tcm_engine.h: the variant must define every TCM_* macro of the contract"
#endif
#ifndef HYST_NUM_OPS_H
#error "tcm_engine.h: include src/num_ops.h for the output type first"
#endif

#include <limits.h>
#include <string.h>

#include "hyst_util.h"

#if defined(__GNUC__)
#define TCM_NOINLINE __attribute__((noinline))
#define TCM_RARELY(c) __builtin_expect((c) != 0, 0)
#else
#define TCM_NOINLINE
#define TCM_RARELY(c) (c)
#endif
/* c as likely as not: GCC then lays out the branch taken when c holds
 * right after the test (the NULL policy's exit: one cbnz on the other
 * path, where an unlikely exit goes to the end of the function, out of
 * cbz's reach: a compare and a branch). */
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 9
#define TCM_EVEN(c) __builtin_expect_with_probability((c) != 0, 1, 0.5)
#else
#define TCM_EVEN(c) (c)
#endif
/* v, usually c: GCC then lays case c of a switch on v out on the straight
 * path, and what follows the switch next to it. */
#if defined(__GNUC__)
#define TCM_USUALLY(v, c) ((unsigned)__builtin_expect((long)(v), (long)(c)))
#else
#define TCM_USUALLY(v, c) (v)
#endif

#ifndef TCM_G_HALF
#define TCM_G_HALF(S, d) TCM_NAME(g)((S), (d) * NUM_C(0.5))
#endif
#ifndef TCM_ADD_BOUND
#define TCM_ADD_BOUND(a, e) ((a) += (e))
#endif
#ifndef TCM_REAL_INPUT
#define TCM_REAL_INPUT 0
#endif
#ifndef TCM_POLY_ONLY
#define TCM_POLY_ONLY 0
#endif

/* Members of the variant's numbers: inputs and outputs. */
#define XV(v) ((v).TCM_XF)
#define YV(v) ((v).TCM_YF)

/* Bisection steps of a merge: enough for 24-bit codes and float inputs. */
#define TCM_ROOT_STEPS 24

/* "No merge alive": larger than any stack depth. */
#define TCM_NO_LEVEL ((size_t)-1)

/* Why a slow sample cannot take the plain path (S->detour, bit flags). */
#define TCM_SLOW_ONLY 1u /* no fast path: out-of-line curve, or a live merge */
#define TCM_BOOK 2u      /* bookkeeping when the stack changes: a live merge
                          * or an open deadband excursion */
#define TCM_DEADBAND 4u  /* reversals need the deadband test */
#define TCM_STALE 8u     /* the last sample's status is not OK: the next one
                          * resets it (off the plain path, which never sees it) */
#define TCM_PER_BRANCH 16u /* the branch's coefficients depend on its turning
                            * point (asymmetric kind): settle() derives them */
#define TCM_SETTLING 32u /* the input left the merged loops, but the output may
                          * still be held off the full model's branch by the
                          * monotone guard: the merges' error stays stated
                          * until it is back (finish_book()) */
#define TCM_KIND_SLOW 64u /* the kind has no fast path (no polynomial, no
                           * table): TCM_SLOW_ONLY always */
/* The flags of the instance's kind, set once by attach(): set_detour()
 * keeps them, so that it reads no kind or curve. */
#define TCM_OF_KIND (TCM_KIND_SLOW | TCM_PER_BRANCH)

/* A curve kind, as the engine sees it: the operations it binds at init
 * (src/kinds.h: one table per kind, in the kind's own file). The engine
 * calls them on slow and rare paths only; a kind the fast path's Horner
 * cases evaluate needs none of them on a sample that stays on its branch.
 * A kind never bound is never linked (--gc-sections). */
typedef struct TCM_NAME(kind) {
    /* G at u >= 0 on the current branch, out of line: the kinds that the
     * Horner cases of emit() do not evaluate (rare paths, exact intervals) */
    TCM_Y (*g)(const hyst_tcm_t *S, TCM_Y u);
    /* the end of a sample that emit()'s cases do not end (the kind's own
     * evaluation, derive: TCM_KEEP... below); NULL if none */
    TCM_Y (*emit)(hyst_tcm_t *S, TCM_X x, int how, int derive);
    /* the current branch's numbers, once it is settled (per-branch kinds:
     * TCM_PER_BRANCH); NULL if none */
    void (*derive)(hyst_tcm_t *S);
    /* the kind's slow sample: the engine's (step_slow()) or its own
     * (src/tcm_slow.h); named by every kind, so that a firmware links the
     * engine's only with a kind that runs it */
    TCM_Y (*slow)(hyst_tcm_t *S, TCM_ARG x);
    /* the deadband's error bound of a skipped loop [b, a]; NULL: the
     * engine's (skip(): a polynomial branch's bound by its coefficients,
     * else |g(a - b) - 2 g((a - b) / 2)|) */
    TCM_Y (*loop_error)(const hyst_tcm_t *S, TCM_X b, TCM_X a);
    /* the kind's numbers of the instance, set once at init (every kind has
     * one: init calls it unconditionally) */
    void (*attach)(hyst_tcm_t *S, const hyst_curve_t *curve);
    /* S->horner - S->degree with no request pending: 0, or the bank of
     * Horner's cases the kind's branches use (TCM_HORNER_BANK_) */
    unsigned bank;
    /* emit(S, x, TCM_FAST, TCM_KEEP): the fast path's call of a kind that
     * evaluates the sample itself (HYST_HORNER_OWN_, a blended interval
     * not cached), without the tests of how and derive; NULL if none */
    TCM_Y (*fast)(hyst_tcm_t *S, TCM_X x);
} TCM_NAME(kind_t);

#define TCM_KIND(S) ((const TCM_NAME(kind_t) *)(S)->kind)

static TCM_Y TCM_NAME(step_slow)(hyst_tcm_t *S, TCM_ARG x_in);

/* G of the kinds evaluated out of line: the variant's own (fixed point),
 * else the bound kind's. */
#ifdef TCM_G_OTHER
#define TCM_KIND_G(S, u) TCM_G_OTHER((S)->curve, (u))
#else
#define TCM_KIND_G(S, u) TCM_KIND(S)->g((S), (u))
#endif

/* The instance's polynomial branches (S->degree n = 1..HYST_MAX_DEGREE):
 * G(u) = u acc(u), acc = c[0] + c[1] u + ... + c[n-1] u^(n-1) with c =
 * S->coef, lowest power first. Horner's rule for degree n starts at c[n-1],
 * and every degree ends with the same multiply-adds on the same
 * coefficients (..., c[1], c[0]): a compiler optimising for size keeps one
 * copy of those tails for all the unrolled cases, where an array highest
 * power first ends each degree on a coefficient of its own. Cases above
 * HYST_MAX_DEGREE cannot run and read c[0], not past the array. */
#define TCM_C_(c, k) YV((c)[(k) < HYST_MAX_DEGREE ? (k) : 0])
#define TCM_H_(acc, c, u, k) NUM_MULADD(acc, u, TCM_C_(c, k)) /* acc u + c[k] */
#define TCM_HORNER1_(c, u) TCM_C_(c, 0)
#define TCM_HORNER2_(c, u) TCM_H_(TCM_C_(c, 1), c, u, 0)
#define TCM_HORNER3_(c, u) TCM_H_(TCM_H_(TCM_C_(c, 2), c, u, 1), c, u, 0)
#define TCM_HORNER4_(c, u) TCM_H_(TCM_H_(TCM_H_(TCM_C_(c, 3), c, u, 2), c, u, 1), c, u, 0)
#define TCM_HORNER5_(c, u) \
    TCM_H_(TCM_H_(TCM_H_(TCM_H_(TCM_C_(c, 4), c, u, 3), c, u, 2), c, u, 1), c, u, 0)
#define TCM_HORNER6_(c, u) \
    TCM_H_(TCM_H_(TCM_H_(TCM_H_(TCM_H_(TCM_C_(c, 5), c, u, 4), c, u, 3), c, u, 2), c, u, 1), c, u, 0)
#define TCM_HORNER7_(c, u)                                                                      \
    TCM_H_(TCM_H_(TCM_H_(TCM_H_(TCM_H_(TCM_H_(TCM_C_(c, 6), c, u, 5), c, u, 4), c, u, 3), c, u, 2), \
                  c, u, 1),                                                                     \
           c, u, 0)
#define TCM_HORNER8_(c, u)                                                                      \
    TCM_H_(TCM_H_(TCM_H_(TCM_H_(TCM_H_(TCM_H_(TCM_H_(TCM_C_(c, 7), c, u, 6), c, u, 5), c, u, 4), \
                                c, u, 3),                                                       \
                         c, u, 2),                                                              \
                  c, u, 1),                                                                     \
           c, u, 0)
/* What a case of Horner's rule yields (TCM_CASE_G_), and G from a
 * switch's result r (TCM_G_AFTER_). Where some case has G at once (a
 * table's cubic, a cached piece's), every case yields G = acc u: they all
 * join after their products, with no product by one. The variant of
 * polynomials alone (TCM_POLY_ONLY) yields acc and multiplies once after
 * the switch (its fixed-point product is a call on the Cortex-M0: one
 * copy, not one per case). */
#if TCM_POLY_ONLY
#define TCM_CASE_G_(acc, u) (acc)
#define TCM_G_AFTER_(r, u) NUM_MUL_G(r, u)
#else
#define TCM_CASE_G_(acc, u) NUM_MUL_G(acc, u)
#define TCM_G_AFTER_(r, u) (r)
#endif
/* The cases 1..8 of a switch on the degree, unrolled (the per-sample
 * paths: no loop, no call); the caller writes case 0 (the jump table
 * starts there) and the default (degree 9 and up). */
#define TCM_HORNER_CASES_(c, u, r)                          \
    case 1: r = TCM_CASE_G_(TCM_HORNER1_(c, u), u); break;  \
    case 2: r = TCM_CASE_G_(TCM_HORNER2_(c, u), u); break;  \
    case 3: r = TCM_CASE_G_(TCM_HORNER3_(c, u), u); break;  \
    case 4: r = TCM_CASE_G_(TCM_HORNER4_(c, u), u); break;  \
    case 5: r = TCM_CASE_G_(TCM_HORNER5_(c, u), u); break;  \
    case 6: r = TCM_CASE_G_(TCM_HORNER6_(c, u), u); break;  \
    case 7: r = TCM_CASE_G_(TCM_HORNER7_(c, u), u); break;  \
    case 8: r = TCM_CASE_G_(TCM_HORNER8_(c, u), u); break

/* Horner's loop over acc's n >= 1 coefficients: the degrees above 8. */
HYST_INLINE TCM_Y TCM_NAME(poly_loop)(const hyst_num_t *c, unsigned n, TCM_Y u)
{
    TCM_Y acc = YV(c[n - 1u]);
    unsigned k;
    for (k = 2u; k <= n; ++k) {
        acc = NUM_MULADD(acc, u, YV(c[n - k]));
    }
    return acc;
}

/* G(u) of a polynomial branch of n coefficients c. */
HYST_INLINE TCM_Y TCM_NAME(poly_g)(const hyst_num_t *c, unsigned n, TCM_Y u)
{
    TCM_Y r;
    switch (n) { /* independent cases: no register merges */
    case 0: r = 0; break; /* never called so */
    TCM_HORNER_CASES_(c, u, r);
    default: r = TCM_CASE_G_(TCM_NAME(poly_loop)(c, n, u), u); break;
    }
    return TCM_G_AFTER_(r, u);
}

/* G at u, any kind: Horner for polynomial branches, else the kind's. */
HYST_INLINE TCM_Y TCM_NAME(g_unit)(const hyst_tcm_t *S, TCM_Y u)
{
    return S->degree - 1u < (unsigned)HYST_MAX_DEGREE ? TCM_NAME(poly_g)(S->coef, S->degree, u)
                                                      : TCM_KIND_G(S, u);
}

/* G at u = d scale for the rare paths (merges, the deadband, requests,
 * degrees 9 and up, the clamped output of a live merge): one out-of-line
 * copy, not one inlined Horner switch per call site. */
static TCM_NOINLINE TCM_Y TCM_NAME(g_of)(const hyst_tcm_t *S, TCM_Y d, TCM_Y scale)
{
    return TCM_NAME(g_unit)(S, d * scale);
}

/* The same at an input difference d. */
HYST_INLINE TCM_Y TCM_NAME(g)(const hyst_tcm_t *S, TCM_Y d)
{
    return TCM_NAME(g_of)(S, d, YV(S->unit));
}

/* How a sample ends (emit()): on the fast path, or a slow sample whose
 * input rose or fell (its direction orients the monotone guard: against the
 * branch's own after a deadband skip), or a repeated input. */
#define TCM_FAST 1
#define TCM_ROSE 2
#define TCM_FELL 3
#define TCM_REPEAT 4

/* y_ctp +- g on the current branch: + rising, - falling. Adding g or
 * subtracting it rounds like y_ctp + sign g with sign = +-1. */
HYST_INLINE TCM_Y TCM_NAME(on_branch)(const hyst_tcm_t *S, TCM_Y g)
{
    return S->moving_end == 0u ? YV(S->y_ctp) + g : YV(S->y_ctp) - g;
}

/* G at the input x of the current branch, any kind. */
HYST_INLINE TCM_Y TCM_NAME(branch_g)(const hyst_tcm_t *S, TCM_X x)
{
    return TCM_NAME(g_unit)(S, (TCM_R(x) - YV(S->x_ctp)) * YV(S->u_scale));
}

/* The same out of line (g_of()): the rare paths'. */
HYST_INLINE TCM_Y TCM_NAME(branch_g_rare)(const hyst_tcm_t *S, TCM_X x)
{
    return TCM_NAME(g_of)(S, TCM_R(x) - YV(S->x_ctp), YV(S->u_scale));
}

/* Output on the current branch. One formula for both paths (the fast path
 * sees only polynomials, the same Horner code), so that a loop that closes
 * returns to its starting output bit for bit. */
HYST_INLINE TCM_Y TCM_NAME(branch_y)(const hyst_tcm_t *S, TCM_X x)
{
    return TCM_NAME(on_branch)(S, TCM_NAME(branch_g)(S, x));
}

static TCM_NOINLINE TCM_Y TCM_NAME(emit_rare)(hyst_tcm_t *S, TCM_X x, int how);
static void TCM_NAME(bind_skip)(hyst_tcm_t *S);
static void TCM_NAME(close_window)(hyst_tcm_t *S);

/* Float evaluation of an increasing G is not monotone at the rounding level
 * (src/hyst_curve.c bounds the error, not its sign), so the output of a
 * monotone input could step back. Guards, both off the arithmetic:
 * - slow sample: the output never behind y_prev in the input's direction;
 *   where it would be, y_prev is kept and the window closed, so the next
 *   sample is slow too. An open window thus always has
 *   y_prev == y_ctp +- g_prev (what a restore re-derives: resume_());
 * - fast path: the output never behind y_prev either. Rounding is
 *   monotone, so that is y_ctp +- G with G never below its value at the
 *   last input, g_prev, without reading or storing g_prev: the slow paths
 *   that read it (a merge's settling) run with the window closed. */
HYST_INLINE TCM_Y TCM_NAME(slow_guard)(hyst_tcm_t *S, TCM_Y g, const int how)
{
    TCM_Y y = TCM_NAME(on_branch)(S, g);
    YV(S->g_prev) = g;
    if (how == TCM_ROSE ? y < YV(S->y_prev) : y > YV(S->y_prev)) {
        y = YV(S->y_prev);
        TCM_NAME(close_window)(S);
    }
    return y;
}

/* The slow guard's rare end: the last output held, the window closed. Out
 * of line: a branch on the slow path, not the selects a compiler may write
 * into it otherwise (held_guard()). */
static TCM_NOINLINE TCM_Y TCM_NAME(held)(hyst_tcm_t *S)
{
    TCM_NAME(close_window)(S);
    return YV(S->y_prev);
}

/* slow_guard() with its rare end out of line (the asymmetric kind's slow
 * sample: GCC writes the inline end there as four conditional moves). */
HYST_INLINE TCM_Y TCM_NAME(held_guard)(hyst_tcm_t *S, TCM_Y g, const int how)
{
    const TCM_Y y = TCM_NAME(on_branch)(S, g);
    YV(S->g_prev) = g;
    if (TCM_RARELY(how == TCM_ROSE ? y < YV(S->y_prev) : y > YV(S->y_prev))) {
        return TCM_NAME(held)(S);
    }
    return y;
}

/* The fast path's end: the moving window end, the guarded output, stored
 * as y_prev. Each direction ends by itself (no shared tail to branch to). */
HYST_INLINE TCM_Y TCM_NAME(fast_end)(hyst_tcm_t *S, TCM_X x, TCM_Y g)
{
    const TCM_Y y_prev = YV(S->y_prev);
    TCM_Y y;
    if (S->moving_end == 0u) {
        XV(S->window[0]) = x;
        y = YV(S->y_ctp) + g;
        if (TCM_RARELY(y < y_prev)) {
            y = y_prev;
        }
        YV(S->y_prev) = y;
        return y;
    }
    XV(S->window[1]) = x;
    y = YV(S->y_ctp) - g;
    if (TCM_RARELY(y > y_prev)) {
        y = y_prev;
    }
    YV(S->y_prev) = y;
    return y;
}

#ifndef NUM_FIXED
/* A cubic piece at t in [0, 1]: c0 + t (c1 + t (c2 + t c3)). */
HYST_INLINE TCM_Y TCM_NAME(cubic_of)(TCM_Y c0, TCM_Y c1, TCM_Y c2, TCM_Y c3, TCM_Y t)
{
    return NUM_CUBIC_(c0, c1, c2, c3, t);
}
HYST_INLINE TCM_Y TCM_NAME(cubic)(const hyst_num_t *c, TCM_Y t)
{
    return TCM_NAME(cubic_of)(YV(c[0]), YV(c[1]), YV(c[2]), YV(c[3]), t);
}
#endif

/* What a kind's slow sample derives first at its end (a constant per call
 * site, src/tcm_slow.h): nothing (the branch is cached), or for the
 * asymmetric kinds the new branch's coefficients, rising or falling. */
#define TCM_KEEP 0
#define TCM_DERIVE_RISE 1
#define TCM_DERIVE_FALL 2
#define TCM_DERIVES(derive) ((derive) == TCM_DERIVE_RISE || (derive) == TCM_DERIVE_FALL)

/* Horner's cases of degrees 1..HYST_EVERETT_MAX_DEGREE at S->horner
 * base + n: a bank of a kind whose slow sample derives every branch's
 * coefficients inline in a case per degree (its own switch on S->horner:
 * TCM_NAME(kind_t), bank); the fast path evaluates them as a polynomial's.
 * Cases of their own, not labels of the polynomial's: GCC lays the fast
 * path out better so (one instruction less on a rising or a falling
 * sample of every kind). */
#define TCM_HORNER_BANK_(base, a, u, r)                                    \
    case (base) + 1u: r = TCM_CASE_G_(TCM_HORNER1_(a, u), u); break;       \
    case (base) + 2u: r = TCM_CASE_G_(TCM_HORNER2_(a, u), u); break;       \
    case (base) + 3u: r = TCM_CASE_G_(TCM_HORNER3_(a, u), u); break;       \
    case (base) + 4u: r = TCM_CASE_G_(TCM_HORNER4_(a, u), u); break

/* The fast path's usual case (TCM_USUALLY): the method's cubic f0, whose
 * branches are G of degree 3. GCC then runs that case straight into the
 * sample's end, with the end's two directions next to each other (a
 * compare-and-branch picks one): two instructions less on that sample. */
#define TCM_HORNER_USUAL 3u

/* emit()'s cases of the kinds without a slow sample of their own: a table
 * of cubic pieces (case 0: its cubic is G; its exact intervals by the tail
 * call) and polynomials of degree 1..8. */
#if TCM_POLY_ONLY /* case 0 never runs: the jump table starts there (one subtraction less) */
#define TCM_EMIT_CASES_(S, x, how, u, r)                        \
    case 0: r = 0; break;                                       \
        TCM_HORNER_CASES_((S)->coef, u, r)
#else
#define TCM_EMIT_CASES_(S, x, how, u, r)                        \
    case 0:                                                     \
        r = NUM_NAME(table_g)((S)->table.TCM_YF, u);            \
        if (!(r >= 0)) {                                        \
            return TCM_NAME(emit_rare)((S), (x), (how));        \
        }                                                       \
        break;                                                  \
        TCM_HORNER_CASES_((S)->coef, u, r)
#endif

/* The end of a sample on the current branch, as its kind set it up
 * (S->horner, hyst_util.h): its output, stored as y_prev (and as the moving
 * window end on the fast path). how: TCM_FAST, TCM_ROSE, TCM_FELL.
 * The fast path takes every kind's cases: polynomials of degree up to 8
 * and a table's cubic piece inline, the banks, a cached cubic piece
 * inline when it is the sample's, else the kind's own evaluation. A slow
 * sample ends here only for the kinds without a slow sample of their own
 * (src/tcm_slow.h's copy of the engine: polynomials, tables, the kinds
 * evaluated out of line): the kinds that derive their branches end theirs
 * themselves, so their cases are the fast path's only. Every other value
 * of S->horner (degree 9 and up, or a pending request:
 * HYST_HORNER_REQUEST_) leaves by a tail call, so a request costs the
 * per-sample paths nothing (the jump table's range check was there anyway)
 * and the fast path needs no stack frame. */
HYST_INLINE TCM_Y TCM_NAME(emit)(hyst_tcm_t *S, TCM_X x, const int how)
{
    const TCM_Y u = (TCM_R(x) - YV(S->x_ctp)) * YV(S->u_scale);
    TCM_Y r, y;
    if (how == TCM_FAST) {
        switch (TCM_USUALLY(S->horner, TCM_HORNER_USUAL)) {
        TCM_EMIT_CASES_(S, x, how, u, r);
#if !TCM_POLY_ONLY
        TCM_HORNER_BANK_(HYST_HORNER_BANK1_, S->coef, u, r);
        TCM_HORNER_BANK_(HYST_HORNER_BANK2_, S->coef, u, r);
        case HYST_HORNER_OWN_: /* the kind evaluates every sample */
            return TCM_KIND(S)->fast(S, x);
#endif
#ifndef NUM_FIXED
        case HYST_HORNER_PIECE_: { /* a cubic piece of the branch (S->coef), cached for
                                    * interval cached_k at v_scale intervals per unit of u:
                                    * a sample in it costs one cubic, inline; the others
                                    * are the kind's */
            const TCM_Y s = u * YV(S->v_scale);
            const unsigned long k = (unsigned long)s; /* s >= 0, below 2^31 */
            if (k != S->cached_k) {
                return TCM_KIND(S)->fast(S, x);
            }
            r = TCM_NAME(cubic)(S->coef, s - (TCM_Y)k); /* G */
            if (r < 0) { /* a solved interval; "< 0", not "!(>= 0)" as for the table of
                          * case 0 (r is a number: s and the blend are): GCC then
                          * does not share that case's tail, one branch less */
                return TCM_NAME(emit_rare)(S, x, how);
            }
            break;
        }
#endif
        default: /* a pending request, or degree 9 and up */
            return TCM_NAME(emit_rare)(S, x, how);
        }
        return TCM_NAME(fast_end)(S, x, TCM_G_AFTER_(r, u));
    }
    switch (S->horner) {
    TCM_EMIT_CASES_(S, x, how, u, r);
    default: /* a pending request, or degree 9 and up */
        return TCM_NAME(emit_rare)(S, x, how);
    }
    y = TCM_NAME(slow_guard)(S, TCM_G_AFTER_(r, u), how);
    YV(S->y_prev) = y;
    return y;
}

/* Derives S->detour from the state it summarises; called wherever that
 * state changes (all off the per-sample path), so that the plain slow path
 * tests one word. */
static void TCM_NAME(set_detour)(hyst_tcm_t *S)
{
    const unsigned kind = S->detour & TCM_OF_KIND;
    const unsigned merged = S->forgot_level != TCM_NO_LEVEL ? TCM_SLOW_ONLY | TCM_BOOK : 0u;
    S->detour = kind | merged | ((kind & TCM_KIND_SLOW) != 0u ? TCM_SLOW_ONLY : 0u) |
                (XV(S->db_reach) != 0 ? TCM_BOOK : 0u) |
                (XV(S->deadband) != 0 ? TCM_DEADBAND : 0u) |
                (S->status != HYST_OK ? TCM_STALE : 0u) |
                (S->forgot_level == TCM_NO_LEVEL && YV(S->forgot) != 0 ? TCM_SETTLING | TCM_BOOK
                                                                       : 0u);
}

/* A sample that leaves the plain path starts with the status OK. */
HYST_INLINE void TCM_NAME(fresh)(hyst_tcm_t *S)
{
    S->status = HYST_OK;
    S->detour &= ~TCM_STALE;
}

/* The fast-path cache of a rising branch from LTP `top` (n_ltp - 1), nr
 * RTPs stored, last input x. The callers pass the index they know: computing
 * n_ltp - 1 in size_t costs two instructions more per array on Thumb-2. */
HYST_INLINE void TCM_NAME(settle_rising)(hyst_tcm_t *S, TCM_X x, size_t top, size_t nr)
{
    YV(S->x_ctp) = TCM_R(XV(S->xltp)[top]);
    YV(S->y_ctp) = YV(S->yltp)[top];
    YV(S->u_scale) = YV(S->unit);
    XV(S->window[0]) = x;
    XV(S->window[1]) = nr > 0u ? (XV(S->xrtp) + nr)[-1] : XV(S->hi);
    S->moving_end = 0u;
}

/* The same for a falling branch from RTP `top` (n_rtp - 1); the LTP
 * below it has the same index (n_ltp == n_rtp on a falling branch). */
HYST_INLINE void TCM_NAME(settle_falling)(hyst_tcm_t *S, TCM_X x, size_t top)
{
    YV(S->x_ctp) = TCM_R(XV(S->xrtp)[top]);
    YV(S->y_ctp) = YV(S->yrtp)[top];
    YV(S->u_scale) = -YV(S->unit);
    XV(S->window[0]) = XV(S->xltp)[top];
    XV(S->window[1]) = x;
    S->moving_end = 1u;
}

/* Empties the fast-path window (its far end onto the last input), so the
 * next sample takes the slow path. Used when every sample must be slow, and
 * after a guarded sample (emit()). */
static void TCM_NAME(close_window)(hyst_tcm_t *S)
{
    XV(S->window[1u - S->moving_end]) = XV(S->window[S->moving_end]);
}

/* Ends a sample whose status is not OK: neither path stores an OK status
 * (the fast path stores none), so the next sample must be slow and leave
 * the plain path (TCM_STALE), where fresh() resets it. */
static void TCM_NAME(ended_not_ok)(hyst_tcm_t *S)
{
    if (S->status != HYST_OK) {
        TCM_NAME(close_window)(S);
        S->detour |= TCM_STALE;
    }
}

/* Derives the fast-path cache from the arrays and the last input, then
 * empties the window if every sample must be slow. */
HYST_INLINE void TCM_NAME(settle_as)(hyst_tcm_t *S, TCM_X x, const int per_branch)
{
    if (S->n_ltp > S->n_rtp) {
        TCM_NAME(settle_rising)(S, x, S->n_ltp - 1u, S->n_rtp);
    } else {
        TCM_NAME(settle_falling)(S, x, S->n_rtp - 1u);
    }
    if (per_branch && (S->detour & TCM_PER_BRANCH) != 0u) {
        TCM_KIND(S)->derive(S);
    }
    if ((S->detour & TCM_SLOW_ONLY) != 0u) {
        TCM_NAME(close_window)(S);
    }
}

/* The same for any kind (reset, restore). */
static void TCM_NAME(settle)(hyst_tcm_t *S, TCM_X x) { TCM_NAME(settle_as)(S, x, 1); }

void TCM_NAME(reset_)(hyst_tcm_t *S)
{
    ++S->seq;
    XV(S->xltp)[0] = XV(S->lo);
    YV(S->yltp)[0] = YV(S->y_lo);
    S->n_ltp = 1u;
    S->n_rtp = 0u;
    S->status = HYST_OK;
    S->events = 0u;
    YV(S->forgot) = 0;
    S->forgot_level = TCM_NO_LEVEL;
    XV(S->db_reach) = 0;
    YV(S->db_err) = 0;
    TCM_NAME(set_detour)(S);
    TCM_NAME(settle)(S, XV(S->lo));
    YV(S->y_prev) = YV(S->y_lo);
    YV(S->g_prev) = 0; /* G(0) */
}

void TCM_NAME(resume_)(hyst_tcm_t *S, const hyst_num_t *x, const hyst_num_t *y, int status,
                       const hyst_tcm_book_t *book)
{
    size_t i;
    ++S->seq;
    /* The keyed search needs +0 where a TP is zero. */
    for (i = 0u; i < S->n_ltp; ++i) {
        XV(S->xltp)[i] = TCM_NORM(XV(S->xltp)[i]);
    }
    for (i = 0u; i < S->n_rtp; ++i) {
        XV(S->xrtp)[i] = TCM_NORM(XV(S->xrtp)[i]);
    }
    TCM_NAME(bind_skip)(S); /* the run saved may have skipped a reversal (db_reach) */
    YV(S->forgot) = YV(book->forgot);
    S->forgot_level = book->forgot_level;
    XV(S->db_reach) = XV(book->db_reach);
    YV(S->db_err) = YV(book->db_err);
    S->status = status;
    S->tps_derived = S->n_ltp + S->n_rtp; /* stored as the run saved left them */
    TCM_NAME(set_detour)(S);
    TCM_NAME(settle)(S, TCM_NORM(XV(*x)));
    YV(S->y_prev) = YV(*y);
    YV(S->g_prev) = TCM_NAME(branch_g)(S, XV(S->window[S->moving_end]));
    /* as after the sample that left it; and where y is not the branch's
     * value at x (a guarded sample), the next one checks it again (not the
     * asymmetric compensator's: its guard holds y, and its next sample
     * must take the path it took in the run saved, emit_solved()) */
    if (status != HYST_OK || (S->degree != HYST_HORNER_OWN_ &&
                              TCM_NAME(on_branch)(S, YV(S->g_prev)) != YV(S->y_prev))) {
        TCM_NAME(close_window)(S);
    }
}

/* Validated set-up shared by every init: the curve's numbers, the arrays,
 * the identity, deadband off, reset. unit: G's argument per input step. */
static void TCM_NAME(attach)(hyst_tcm_t *S, const hyst_curve_t *curve,
                             const TCM_NAME(kind_t) *kind, TCM_X lo, TCM_X hi, TCM_Y unit,
                             TCM_X *xltp, TCM_Y *yltp, TCM_X *xrtp, TCM_Y *yrtp, size_t capacity)
{
    unsigned k;
    S->variant = (unsigned)TCM_VARIANT;
    S->layout = HYST_LAYOUT;
    S->curve = curve;
    S->kind = kind;
    S->slow = (void (*)(void))kind->slow;
    S->skip = NULL; /* no deadband yet (bind_skip()) */
    /* -0 made +0: the anchor A0 = lo is a stored TP, and a restore
     * normalises every stored TP (resume_): one bit pattern either way */
    XV(S->lo) = TCM_NORM(lo);
    XV(S->hi) = TCM_NORM(hi);
    YV(S->y_lo) = YV(curve->y_lo);
    YV(S->y_hi) = YV(curve->y_hi);
    YV(S->unit) = unit;
    YV(S->rounding) = YV(curve->rounding);
    S->degree = 0u; /* no polynomial, no table: every sample slow (set_detour()) */
    S->table.TCM_YF = NULL;
    for (k = 0u; k < HYST_MAX_DEGREE; ++k) {
        YV(S->coef[k]) = 0;
    }
    YV(S->curv) = 0; /* solved and blended branches: derive() */
    YV(S->w_end) = 0;
    YV(S->secant) = 0;
    YV(S->v_scale) = 0;
    for (k = 0u; k < 4u; ++k) {
        YV(S->blend[k]) = 0;
    }
    S->cached_k = ULONG_MAX;
    S->tps_derived = 0u;
    YV(S->table_rows) = YV(S->table_intervals) = YV(S->v_least) = 0;
    kind->attach(S, curve); /* S->degree, S->coef, S->table: what the fast path evaluates */
    S->horner = S->degree + kind->bank;
    S->detour = (S->degree == 0u && S->table.TCM_YF == NULL ? TCM_KIND_SLOW : 0u) |
                (kind->derive != NULL ? TCM_PER_BRANCH : 0u); /* set_detour() keeps them */
    S->seq = 0u;
    S->req_reset = S->done_reset = 0u;
    S->req_clear = S->done_clear = 0u;
    S->req_deadband = S->done_deadband = 0u;
    XV(S->req_width) = 0;
    XV(S->xltp) = xltp;
    YV(S->yltp) = yltp;
    XV(S->xrtp) = xrtp;
    YV(S->yrtp) = yrtp;
    S->capacity = capacity;
    XV(S->deadband) = 0;
    TCM_NAME(reset_)(S);
}

/* floor(log2 n), n > 0. */
static unsigned TCM_NAME(floor_log2)(size_t n)
{
#if defined(__GNUC__) || defined(__clang__) /* one clz instruction */
    return (unsigned)(sizeof(unsigned long) * CHAR_BIT - 1u) -
           (unsigned)__builtin_clzl((unsigned long)n);
#else
    unsigned lg = 0u;
    while (n > 1u) {
        n /= 2u;
        ++lg;
    }
    return lg;
#endif
}

/* Binary search without loop bookkeeping: the length of the prefix of
 * a[0..n) whose entries satisfy KEEP (the arrays are sorted so that it is a
 * prefix). One probe at p - 1 (p = 2^floor(log2 n)) leaves a window of p
 * entries; an unrolled ladder of probes p/2 .. 1 resolves it, each a load, a
 * compare and a conditional add: floor(log2 n) + 1 probes in all. Uses a, n,
 * lg = floor(log2 n) and advances b. */
#define TCM_PROBE_(step, KEEP)       \
    do {                             \
        if (KEEP(b + (step) - 1u)) { \
            b += (step);             \
        }                            \
    } while (0)

#define TCM_LADDER_(KEEP)                                                       \
    do {                                                                        \
        if (KEEP(a + ((size_t)1 << lg) - 1u)) {                                 \
            b += n - ((size_t)1 << lg) + 1u;                                    \
        }                                                                       \
        switch (lg) {                                                           \
        default: { /* capacities above 8192: the top of the ladder by a loop */ \
            size_t width = (size_t)1 << (lg - 1u);                              \
            for (; width > 2048u; width /= 2u) {                                \
                TCM_PROBE_(width, KEEP);                                        \
            }                                                                   \
        }                                                                       \
            /* fall through */                                                  \
        case 12u: TCM_PROBE_(2048u, KEEP); /* fall through */                   \
        case 11u: TCM_PROBE_(1024u, KEEP); /* fall through */                   \
        case 10u: TCM_PROBE_(512u, KEEP); /* fall through */                    \
        case 9u: TCM_PROBE_(256u, KEEP); /* fall through */                     \
        case 8u: TCM_PROBE_(128u, KEEP); /* fall through */                     \
        case 7u: TCM_PROBE_(64u, KEEP); /* fall through */                      \
        case 6u: TCM_PROBE_(32u, KEEP); /* fall through */                      \
        case 5u: TCM_PROBE_(16u, KEEP); /* fall through */                      \
        case 4u: TCM_PROBE_(8u, KEEP); /* fall through */                       \
        case 3u: TCM_PROBE_(4u, KEEP); /* fall through */                       \
        case 2u: TCM_PROBE_(2u, KEEP); /* fall through */                       \
        case 1u: TCM_PROBE_(1u, KEEP); /* fall through */                       \
        case 0u:                                                                \
            break;                                                              \
        }                                                                       \
    } while (0)

#ifdef TCM_KEY_T
/* Reals are searched by their bit patterns read as integers (TCM_KEY_T,
 * same size): an integer compare is one instruction fewer per probe than a
 * floating-point one on FPUs that move flags (Cortex-M4F, C28x). IEEE 754
 * patterns order like the values: as signed integers when the searched
 * value x is >= +0, as unsigned ones reversed when x < 0. Exact for finite
 * values but -0, which is why x and the stored TPs have -0 made +0
 * (TCM_NORM). */
HYST_INLINE TCM_KEY_T TCM_NAME(key)(const TCM_X *p)
{
    /* a union, not memcpy(): GCC calls memcpy() for each probe on the
     * Cortex-M0 (-Os), where a union read is one load */
    union {
        TCM_X x;
        TCM_KEY_T k;
    } v;
    v.x = *p;
    return v.k;
}
#define TCM_BELOW_S_(p) (TCM_NAME(key)(p) < kx)
#define TCM_BELOW_U_(p) ((TCM_UKEY_T)TCM_NAME(key)(p) > (TCM_UKEY_T)kx)
#define TCM_ABOVE_S_(p) (TCM_NAME(key)(p) > kx)
#define TCM_ABOVE_U_(p) ((TCM_UKEY_T)TCM_NAME(key)(p) < (TCM_UKEY_T)kx)
#define TCM_SEARCH_(SIGNED, UNSIGNED)               \
    do {                                            \
        const TCM_X xn = TCM_NORM(x);               \
        const TCM_KEY_T kx = TCM_NAME(key)(&xn);    \
        if (kx >= 0) {                              \
            TCM_LADDER_(SIGNED);                    \
        } else {                                    \
            TCM_LADDER_(UNSIGNED);                  \
        }                                           \
    } while (0)
#else
/* Values compared as they are; no unsigned ladder. */
#define TCM_BELOW_S_(p) (*(p) < x)
#define TCM_ABOVE_S_(p) (*(p) > x)
#define TCM_SEARCH_(KEEP, unused) TCM_LADDER_(KEEP)
#endif

/* Entries of a sorted TP array that survive the input's move to x: for a
 * fall (ascending xltp), the LTPs below x; for a rise (descending xrtp), the
 * RTPs above x. `falling` is a constant at each call site. */
HYST_INLINE size_t TCM_NAME(survivors)(const TCM_X *a, size_t n, TCM_X x, const int falling)
{
    const TCM_X *b = a;
    unsigned lg;
    if (n == 0u) {
        return 0u;
    }
    lg = TCM_NAME(floor_log2)(n);
    if (falling) {
        TCM_SEARCH_(TCM_BELOW_S_, TCM_BELOW_U_);
    } else {
        TCM_SEARCH_(TCM_ABOVE_S_, TCM_ABOVE_U_);
    }
    return (size_t)(b - a);
}

#ifndef TCM_LTP_BELOW
#define TCM_LTP_BELOW(a, n, x) TCM_NAME(survivors)((a), (n), (x), 1)
#define TCM_RTP_ABOVE(a, n, x) TCM_NAME(survivors)((a), (n), (x), 0)
#endif

/* A TP was pushed or wiped: no deadband excursion is open any more. */
static void TCM_NAME(window_closed)(hyst_tcm_t *S)
{
    XV(S->db_reach) = 0;
    YV(S->db_err) = 0;
    TCM_NAME(set_detour)(S);
}

/* The input left every merged loop: the state is the full model's again,
 * fast path back. The error bound stays until the output is on the full
 * model's branch too (TCM_SETTLING): the monotone guard may hold the last
 * output, which was within the bound. Out of line: off the worst path. */
static TCM_NOINLINE void TCM_NAME(merges_left)(hyst_tcm_t *S)
{
    S->forgot_level = TCM_NO_LEVEL;
    TCM_NAME(set_detour)(S);
}

/* After a wipe-out to stack depth `depth` (0: the input reached lo or hi,
 * which sets every past state): a merge whose outer TP is gone no longer
 * matters (the input left its loop), so the state is exact again once the
 * shallowest one is gone (and the error bound drops to 0 once the output
 * is, finish_book()). */
static void TCM_NAME(wiped)(hyst_tcm_t *S, size_t depth)
{
    if (depth <= S->forgot_level && S->forgot_level != TCM_NO_LEVEL) {
        TCM_NAME(merges_left)(S);
    }
    if (XV(S->db_reach) != 0) {
        TCM_NAME(window_closed)(S);
    }
}

/* A merge keeps the outer TP O = R2 = (xo, yo); the current point
 * P = (xp, yp) must lie on the rising branch of the new LTP V. */
typedef struct {
    TCM_X xo, xp;
    TCM_Y yo, yp;
} TCM_NAME(merge_t);

/* y at v of O's falling branch minus y at v of the branch that rises from v
 * through P: zero where V must be. */
static TCM_Y TCM_NAME(gap)(const hyst_tcm_t *S, const TCM_NAME(merge_t) *m, TCM_X v)
{
    return (m->yo - TCM_NAME(g)(S, TCM_D(m->xo, v))) - (m->yp - TCM_NAME(g)(S, TCM_D(m->xp, v)));
}

/* Root of gap on [a, b] = [x_L1, x_P] by bisection: the gap has opposite
 * signs at the ends when f0'' keeps one sign (docs/memory.md), else the
 * better end wins. *resid = the gap left at the returned point. */
static TCM_X TCM_NAME(root)(const hyst_tcm_t *S, const TCM_NAME(merge_t) *m, TCM_X a, TCM_X b,
                            TCM_Y *resid)
{
    TCM_Y fa = TCM_NAME(gap)(S, m, a);
    TCM_Y fb = TCM_NAME(gap)(S, m, b);
    if (fa != 0 && fb != 0 && (fa > 0) != (fb > 0)) {
        int k;
        for (k = 0; k < TCM_ROOT_STEPS; ++k) {
            const TCM_X mid = TCM_MID(a, b);
            TCM_Y fm;
            if (mid == a || mid == b) {
                break;
            }
            fm = TCM_NAME(gap)(S, m, mid);
            if ((fm > 0) == (fa > 0)) {
                a = mid;
                fa = fm;
            } else {
                b = mid;
                fb = fm;
            }
        }
    }
    if (NUM_NAME(abs)(fa) <= NUM_NAME(abs)(fb)) {
        *resid = NUM_NAME(abs)(fa);
        return a;
    }
    *resid = NUM_NAME(abs)(fb);
    return b;
}

/* Full LTP array at a reversal at P = (x_prev, y_prev), falling, so
 * nl == nr == capacity >= 2: the innermost loop (L1, R1) and P become one
 * LTP V on R2's falling branch whose rising branch passes through P (see
 * tcm.h, "Bounded memory"). Off the per-sample path. */
static TCM_NOINLINE void TCM_NAME(merge)(hyst_tcm_t *S, TCM_X x_prev, size_t *nr)
{
    const size_t l1 = S->capacity - 1u, r1 = *nr - 1u;
    TCM_NAME(merge_t) m;
    TCM_Y resid, miss, yv, height;
    TCM_X v;
    m.xp = x_prev;
    m.yp = YV(S->y_prev);
    m.xo = XV(S->xrtp)[r1 - 1u];
    m.yo = YV(S->yrtp)[r1 - 1u];
    v = TCM_NAME(root)(S, &m, XV(S->xltp)[l1], m.xp, &resid);
    yv = m.yp - TCM_NAME(g)(S, TCM_D(m.xp, v));
    miss = yv + TCM_NAME(g)(S, TCM_D(XV(S->xrtp)[r1], v)) - YV(S->yrtp)[r1]; /* at the lost R1 */
    XV(S->xltp)[l1] = TCM_NORM(v);
    YV(S->yltp)[l1] = yv;
    *nr = r1;
    TCM_ADD_BOUND(YV(S->forgot), NUM_NAME(abs)(miss) + resid);
    /* The full model and this one (clamped while a merge is alive,
     * slow_only()) both stay in the major loop's range: its height bounds
     * the error however many merges add up, and is the only bound of the
     * asymmetric kind, whose branches from V and from the lost L1 differ in
     * shape, not only in place. */
    height = YV(S->y_hi) - YV(S->y_lo);
    if ((S->detour & TCM_PER_BRANCH) != 0u || YV(S->forgot) > height) {
        YV(S->forgot) = height;
    }
    if (2u * r1 - 1u < S->forgot_level) { /* stack position of R2 */
        S->forgot_level = 2u * r1 - 1u;
    }
    TCM_NAME(set_detour)(S);
}

/* The height of a loop of width full (g's argument difference) at its
 * middle, |g(full) - 2 g(full / 2)|: the deadband's error bound where g''
 * keeps one sign (docs/memory.md). */
static TCM_Y TCM_NAME(loop_height)(const hyst_tcm_t *S, TCM_Y full)
{
    return NUM_NAME(abs)(TCM_NAME(g)(S, full) - 2 * TCM_G_HALF(S, full));
}

#ifndef NUM_FIXED
/* The deadband's error bound of a skipped loop of width full (g's argument
 * difference) on a polynomial branch (S->coef, S->degree; u in g's units).
 * Inside the window the full model differs from the branch moved back
 * along by the measure of relays in a rectangle (x - b) x (a - x) of
 * density g''(a' - b'), whose diagonal a' - b' = v is at most
 * min(v, u - v) long: the error is at most the integral of
 * |g''(v)| min(v, u - v) over [0, u], bounded term by term (g = sum a_k u^k:
 * |a_2| u^2 / 2 + the sum of |a_k| u^k, k >= 3, with min(v, u - v) <= u - v).
 * Where g'' is proven one-signed on [0, u] (its constant term wins), the
 * tighter loop_height(). */
static TCM_Y TCM_NAME(poly_loop_error)(const hyst_tcm_t *S, TCM_Y full)
{
    const unsigned n = S->degree;
    const TCM_Y u = full * YV(S->unit);
    TCM_Y rest = 0, sum = 0, pw = u; /* pw = u^(k-2) from k = 3 */
    unsigned k;
    for (k = 3u; k <= n; ++k) { /* coef[k - 1] multiplies u^k */
        const TCM_Y t = NUM_NAME(abs)(YV(S->coef[k - 1u])) * pw;
        rest += (TCM_Y)(k * (k - 1u)) * t;
        sum += t;
        pw *= u;
    }
    if (n >= 2u) {
        const TCM_Y a2 = NUM_NAME(abs)(YV(S->coef[1]));
        if (rest < 2 * a2) {
            return TCM_NAME(loop_height)(S, full);
        }
        sum += a2 * NUM_C(0.5);
    }
    return sum * u * u * NUM_C(1.01); /* rounded up by 1 % */
}
#endif

/* Deadband: the input reversed at x_prev within d < deadband of the
 * current TP. Nothing is stored: the trajectory moves back along the current
 * branch (reversibly), where the full model would run a minor loop of width
 * at most d inside it. Its error bound: the kind's loop_error, else on a
 * polynomial branch poly_loop_error(), else the loop's height (docs/memory.md),
 * kept for the widest d until the stack next changes (the full model has
 * then wiped that loop too). The bounds are here, not in a kind: a firmware
 * that sets no deadband links none of them (bind_skip()). */
static TCM_NOINLINE void TCM_NAME(skip)(hyst_tcm_t *S, TCM_X b, TCM_X a)
{
    const TCM_X d = (TCM_X)(a - b);
    if (d > XV(S->db_reach)) {
        const TCM_Y full = TCM_D(d, (TCM_X)0);
        XV(S->db_reach) = d;
        if (TCM_KIND(S)->loop_error != NULL) {
            YV(S->db_err) = TCM_KIND(S)->loop_error(S, b, a);
#ifndef NUM_FIXED
        } else if (S->degree - 1u < (unsigned)HYST_MAX_DEGREE) {
            YV(S->db_err) = TCM_NAME(poly_loop_error)(S, full);
#endif
        } else {
            YV(S->db_err) = TCM_NAME(loop_height)(S, full);
        }
        TCM_NAME(set_detour)(S);
    }
}

/* The deadband's skip, called through S->skip: bound by the calls that can
 * make a reversal skip (set_deadband, request_deadband, resume_), never by
 * an init, so a firmware that sets no deadband does not link skip(). Written
 * only while unbound: a request from another context never rewrites the
 * pointer a step may be reading. */
typedef void (*TCM_NAME(skip_fn))(hyst_tcm_t *S, TCM_X b, TCM_X a);
#define TCM_SKIP(S, b, a) ((TCM_NAME(skip_fn))(S)->skip)((S), (b), (a))
static void TCM_NAME(bind_skip)(hyst_tcm_t *S)
{
    if (S->skip == NULL) {
        S->skip = (void (*)(void))TCM_NAME(skip);
    }
}

/* Applies the requests another context posted (tcm.h, "Concurrency"), in
 * the stepping context, at the end of a sample: as if set_deadband(),
 * clear_events() and reset() were called, in this order, between that
 * sample and the next. Each request is a counter the other context
 * increments; done_* keeps the value applied, so a request posted twice
 * before a step applies once. */
static TCM_NOINLINE void TCM_NAME(serve)(hyst_tcm_t *S)
{
    S->horner = S->degree + TCM_KIND(S)->bank;
    if (S->req_deadband != S->done_deadband) {
        S->done_deadband = S->req_deadband;
        XV(S->deadband) = XV(S->req_width);
        TCM_NAME(set_detour)(S);
    }
    if (S->req_clear != S->done_clear) {
        S->done_clear = S->req_clear;
        S->events = 0u;
    }
    if (S->req_reset != S->done_reset) {
        S->done_reset = S->req_reset;
        TCM_NAME(reset_)(S);
    }
    ++S->seq;
}

/* A slow sample with TCM_SLOW_ONLY (its window left empty by settle(): the
 * next sample is slow too): while a merge is alive the output is clamped to
 * the major loop's range [y_lo, y_hi]. The merged LTP V's branches are not
 * the full model's and can leave that range (x^3's compensator: a drive of
 * 1.07 > hi). The full model's output always lies in the range, so clamping
 * never moves y away from it: |y - y_full| <= error_bound still holds. */
static TCM_NOINLINE TCM_Y TCM_NAME(slow_only)(hyst_tcm_t *S, TCM_X x, int how)
{
    TCM_Y y;
    YV(S->g_prev) = TCM_NAME(branch_g_rare)(S, x); /* for finish_book() */
    y = TCM_NAME(on_branch)(S, YV(S->g_prev));
    if (S->forgot_level != TCM_NO_LEVEL) {
        if (y > YV(S->y_hi)) {
            y = YV(S->y_hi);
        } else if (y < YV(S->y_lo)) {
            y = YV(S->y_lo);
        }
    }
    /* monotone as emit()'s slow guard; the window stays closed */
    if (how == TCM_ROSE ? y < YV(S->y_prev) : y > YV(S->y_prev)) {
        y = YV(S->y_prev);
    }
    return y;
}


/* TCM_SETTLING: the sample's output y back on the full model's branch ends
 * the merges' error bound; held off it by the monotone guard (the
 * deviation then at most the bound: the full model moved on in the input's
 * direction), the bound stays and the next sample is slow again. */
static TCM_NOINLINE void TCM_NAME(settle_bound)(hyst_tcm_t *S, TCM_Y y)
{
    if (y == TCM_NAME(on_branch)(S, YV(S->g_prev))) {
        YV(S->forgot) = 0;
        TCM_NAME(set_detour)(S);
    } else {
        TCM_NAME(close_window)(S);
    }
}

/* The end of a step_edge() sample that leaves the input where it was (a
 * NaN, or clamped to the end the input is at) while a request is pending:
 * the output stays, then the requests are applied, as every step's. Out of
 * line (a tail call): the clamped sample that moves keeps its registers. */
static TCM_NOINLINE TCM_Y TCM_NAME(serve_unmoved)(hyst_tcm_t *S)
{
    const TCM_Y y = YV(S->y_prev);
    TCM_NAME(serve)(S);
    return y;
}

/* A reversal while TCM_SETTLING (the merges left, the output held off the
 * full model's branch by the monotone guard): the TP it stores takes the
 * full model's output at x_prev, not the held one, so the state is the full
 * model's again; stored held, its offset would stay in every branch from
 * there while settle_bound(), measuring against that TP, declared the
 * error gone. The output moves to it in the new direction (the guard held
 * it against the old one), so it stays monotone. */
static void TCM_NAME(release_held)(hyst_tcm_t *S)
{
    if ((S->detour & TCM_SETTLING) != 0u) {
        YV(S->y_prev) = TCM_NAME(on_branch)(S, YV(S->g_prev));
    }
}

/* Is a reversal whose excursion from the current TP is d skipped? Below
 * the deadband, or inside the open window's widest skipped excursion: a
 * deadband narrowed while a window is open must not store a TP where the
 * output still carries the window's error (it stays on the branch it
 * moved back along until the input leaves the window's reach, where the
 * full model has wiped the skipped loops too). Without a change of the
 * deadband the reach is below it and the second test never decides. */
HYST_INLINE int TCM_NAME(skips)(const hyst_tcm_t *S, TCM_X d)
{
    return d < XV(S->deadband) || d < XV(S->db_reach);
}

/* The slow sample of the kinds emit() ends (src/tcm_slow.h). */
#define TCM_SLOW(n) TCM_NAME(n)
#define TCM_SLOW_EMIT(S, x, how, derive) TCM_NAME(emit)((S), (x), (how))
#define TCM_SLOW_PER_BRANCH 0
#include "tcm_slow.h"

/* The instance's slow sample: its kind's copy (attach()). */
typedef TCM_Y (*TCM_NAME(slow_fn))(hyst_tcm_t *S, TCM_ARG x);
#define TCM_STEP_SLOW(S, x) ((TCM_NAME(slow_fn))(S)->slow)((S), (x))

/* emit() for the other values of S->horner: the output by Horner's loop
 * or the kind's G (how: as emit(), or TCM_REPEAT for a repeated sample,
 * whose output stays), then the pending requests. */
static TCM_NOINLINE TCM_Y TCM_NAME(emit_rare)(hyst_tcm_t *S, TCM_X x, int how)
{
    TCM_Y y = YV(S->y_prev);
    if (how != TCM_REPEAT) {
        if (S->degree == HYST_HORNER_OWN_) { /* a request pending */
            y = TCM_KIND(S)->emit(S, x, how, TCM_KEEP);
        } else { /* one G for both ends */
            const TCM_Y g = TCM_NAME(branch_g_rare)(S, x);
            y = how == TCM_FAST ? TCM_NAME(fast_end)(S, x, g) : TCM_NAME(slow_guard)(S, g, how);
        }
    }
    YV(S->y_prev) = y;
    if (S->horner == HYST_HORNER_REQUEST_) {
        TCM_NAME(serve)(S);
    }
    return y;
}

/* The NULL policy's answer for a per-sample call: 0. Out of line, so that
 * the check costs the fast path one cbnz and nothing else (TCM_EVEN). */
static TCM_NOINLINE TCM_Y TCM_NAME(no_instance)(void) { return 0; }

/* The per-sample computation, inlined into the public step call. The fast path
 * does not store the status: every sample that ends with another status
 * closes the window, so the next one goes through step_slow(), which sets it. */
HYST_INLINE TCM_Y TCM_NAME(sample)(hyst_tcm_t *S, TCM_ARG x)
{
    if (TCM_EVEN(S == NULL)) {
        return TCM_NAME(no_instance)();
    }
    /* Fast path: the input moves on and reaches no stored TP. NaN fails the
     * comparisons, and the window lies inside [lo, hi]: no other check needed. */
    if (!(x > XV(S->window[0]) && x < XV(S->window[1]))) {
        return TCM_STEP_SLOW(S, x);
    }
    return TCM_NAME(emit)(S, (TCM_X)x, TCM_FAST); /* the window is empty for other curve kinds */
}

/* G at u, as emit() evaluates it. */
HYST_INLINE TCM_Y TCM_NAME(run_g)(const hyst_tcm_t *S, unsigned deg, TCM_Y u)
{
#if !TCM_POLY_ONLY
    if (deg == 0u) { /* a tabulated inverse: the same arithmetic as emit(), whose G * 1 is G */
        const TCM_Y v = NUM_NAME(table_g)(S->table.TCM_YF, u);
        return v >= 0 ? v : TCM_KIND_G(S, u);
    }
#endif
    return TCM_NAME(poly_g)(S->coef, deg, u);
}

/* The block call's inner loop: the samples from i on that stay inside the
 * fast-path window, with the window in registers and the branch in locals
 * (sample() keeps them in S: a store and a reload per sample). The same
 * arithmetic as step() (emit), so outputs are identical. Returns
 * the first sample that leaves the window, n if none. */
static size_t TCM_NAME(run)(hyst_tcm_t *S, const TCM_IN *x, TCM_Y *y, size_t i, size_t n)
{
    const size_t first = i;
    const TCM_Y x_ctp = YV(S->x_ctp), y_ctp = YV(S->y_ctp);
    const TCM_Y u_scale = YV(S->u_scale);
    const unsigned deg = S->degree;
    TCM_X w0 = XV(S->window[0]), w1 = XV(S->window[1]);
    TCM_Y y_last = YV(S->y_prev);
    if (S->horner == HYST_HORNER_REQUEST_ || deg == HYST_HORNER_OWN_ ||
        deg == HYST_HORNER_PIECE_) {
        return i; /* a pending request: step_slow() serves it; solved, blended: step by step */
    }
    /* One loop per direction: a selected update of w0 or w1 in one loop put
     * a select on the loop-carried compare (measured 0.41 vs 0.36 of
     * PI-10's time on the host). */
    if (S->moving_end == 0u) { /* rising: the lower end follows x */
        for (; i < n; ++i) {
            const TCM_X xi = x[i]; /* read before y[i]: y may be x */
            TCM_Y yi;
            if (!(xi > w0 && xi < w1)) {
                break;
            }
            yi = y_ctp + TCM_NAME(run_g)(S, deg, (TCM_R(xi) - x_ctp) * u_scale);
            if (yi < y_last) { /* guarded as fast_end() */
                yi = y_last;
            }
            y[i] = y_last = yi;
            w0 = xi;
        }
    } else {
        for (; i < n; ++i) {
            const TCM_X xi = x[i];
            TCM_Y yi;
            if (!(xi > w0 && xi < w1)) {
                break;
            }
            yi = y_ctp - TCM_NAME(run_g)(S, deg, (TCM_R(xi) - x_ctp) * u_scale);
            if (yi > y_last) {
                yi = y_last;
            }
            y[i] = y_last = yi;
            w1 = xi;
        }
    }
    if (i > first) {
        XV(S->window[0]) = w0;
        XV(S->window[1]) = w1;
        YV(S->y_prev) = y_last;
    }
    return i;
}

/* The block call; statuses folded as documented. Runs of samples on one
 * branch go through run(), the others through step_slow(). */
static hyst_status_t TCM_NAME(block)(hyst_tcm_t *S, const TCM_IN *x, TCM_Y *y, size_t n)
{
    int worst = HYST_OK; /* HYST_WARN_FULL > HYST_WARN_CLAMPED > HYST_OK */
    int failed = 0;
    size_t i = 0u;
    if (n > 0u && (S == NULL || x == NULL || y == NULL)) {
        return HYST_ERR_NULL;
    }
    if (hyst_block_overlap(x, sizeof *x, y, sizeof *y, n)) {
        return HYST_ERR_OVERLAP;
    }
    while (i < n) {
        i = TCM_NAME(run)(S, x, y, i, n);
        if (i == n) {
            break;
        }
        /* x[i] left the window, or the branch is solved (sample(): the
         * same arithmetic as step()) */
        y[i] = S->degree == HYST_HORNER_OWN_ || S->degree == HYST_HORNER_PIECE_
                   ? TCM_NAME(sample)(S, x[i])
                   : TCM_STEP_SLOW(S, x[i]);
        if (S->status < 0) {
            failed = 1;
        } else if (S->status > worst) {
            worst = S->status;
        }
        ++i;
    }
    return failed ? HYST_ERR_NONFINITE : (hyst_status_t)worst;
}

/* The last sample and the error bound as one consistent view, read from
 * any context (tcm.h, "Concurrency"). A fast-path sample changes x and y
 * without changing seq but moves x strictly: the same x and seq before and
 * after the reads prove that y and the bound belong to that x. */
typedef struct {
    TCM_X x;
    TCM_Y y, bound;
} TCM_NAME(view_t);

static TCM_NAME(view_t) TCM_NAME(view)(const hyst_tcm_t *S)
{
    const volatile hyst_tcm_t *V = S;
    TCM_NAME(view_t) v;
    unsigned attempt;
    for (attempt = 0u; attempt < HYST_READ_ATTEMPTS; ++attempt) {
        const unsigned long seq = V->seq;
        HYST_BARRIER();
        v.x = XV(V->window[V->moving_end]);
        v.y = YV(V->y_prev);
        v.bound = YV(V->forgot) + YV(V->db_err);
        HYST_BARRIER();
        if (v.x == XV(V->window[V->moving_end]) && seq == V->seq) {
            break;
        }
    }
    return v;
}

/* XV and YV stay defined: the kinds (src/kinds.h) read numbers through
 * them too. */
#endif /* HYST_TCM_ENGINE_H */
