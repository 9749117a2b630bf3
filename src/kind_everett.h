/* SPDX-License-Identifier: MIT */
/* The asymmetric kind (HYST_CURVE_EVERETT), a curve kind of the engine
 * (src/tcm_engine.h, TCM_NAME(kind_t)): each branch's coefficients derived
 * from the curve's tables at its turning point, on the slow sample that
 * starts it (its own copy of the slow sample derives them inline); the fast
 * path evaluates them as a polynomial's (S->horner: the degree in a bank of
 * Horner's cases of its own). Two tables, its rows as polynomials in the
 * anchor (kind_everett) or at most linear in it (kind_everett_lines: from
 * the TP's input itself). Included by src/kinds.h after the engine. */
#ifndef HYST_KIND_EVERETT_H
#define HYST_KIND_EVERETT_H

/* The order a branch's coefficients are written in: lowest power first
 * (the forward kind's S->coef, which the engine evaluates:
 * src/tcm_engine.h), or highest first (the compensators' own Newton
 * evaluation, src/kind_everett_inv.h). A constant at each call site. */
#define TCM_LOWEST_FIRST 1
#define TCM_HIGHEST_FIRST 0
#define TCM_COEF_AT_(n, i, lowest) ((lowest) ? (n) - 1u - (i) : (i))

/* The branch's G coefficients at `anchor` from a table of the curve
 * (curve.h): the coefficient of w^(n - i) is row i (i + 1 entries), a
 * polynomial in the anchor, by Horner's rule; written in the order
 * `lowest` (above). */
HYST_INLINE void TCM_NAME(table_coefs)(const hyst_num_t *row, unsigned n, TCM_Y anchor,
                                       hyst_num_t *coef, const int lowest)
{
    /* rows start at i (i + 1) / 2; unrolled (n <= HYST_EVERETT_MAX_DEGREE = 4,
     * the curve's check): a slow sample derives them */
    switch (n) {
    case 4u:
        YV(coef[TCM_COEF_AT_(n, 3u, lowest)]) = NUM_MULADD(
            NUM_MULADD(NUM_MULADD(YV(row[6]), anchor, YV(row[7])), anchor, YV(row[8])), anchor,
            YV(row[9]));
        /* fall through */
    case 3u:
        YV(coef[TCM_COEF_AT_(n, 2u, lowest)]) =
            NUM_MULADD(NUM_MULADD(YV(row[3]), anchor, YV(row[4])), anchor, YV(row[5]));
        /* fall through */
    case 2u:
        YV(coef[TCM_COEF_AT_(n, 1u, lowest)]) = NUM_MULADD(YV(row[1]), anchor, YV(row[2]));
        /* fall through */
    case 1u: YV(coef[TCM_COEF_AT_(n, 0u, lowest)]) = YV(row[0]); /* fall through */
    default: break;
    }
}

/* The branch's coefficients from the curve's rows as functions of the
 * TP's input itself (lin_x, curve.h: rows at most linear in the anchor):
 * no anchor to compute, one multiply-add each; lowest power first. */
HYST_INLINE void TCM_NAME(table_coefs_x)(const hyst_num_t *lin, unsigned n, TCM_Y x,
                                         hyst_num_t *coef)
{
    switch (n) {
    case 4u: YV(coef[n - 4u]) = NUM_MULADD(YV(lin[5]), x, YV(lin[6])); /* fall through */
    case 3u: YV(coef[n - 3u]) = NUM_MULADD(YV(lin[3]), x, YV(lin[4])); /* fall through */
    case 2u: YV(coef[n - 2u]) = NUM_MULADD(YV(lin[1]), x, YV(lin[2])); /* fall through */
    case 1u: YV(coef[n - 1u]) = YV(lin[0]); /* fall through */
    default: break;
    }
}

/* The forward asymmetric kind's anchor: the current TP's input, 0..1 over
 * the domain. */
HYST_INLINE TCM_Y TCM_NAME(input_anchor)(const hyst_tcm_t *S)
{
    return (YV(S->x_ctp) - TCM_R(XV(S->lo))) * YV(S->unit);
}


/* A skipped loop [b, a]'s error. Inside the window the full model differs
 * from the branch moved back along by the measure of relays in a rectangle
 * of area (x - b)(a - x) <= d^2 / 4 whose density is d^2 E / da db, which
 * may change sign and peaks anywhere in the window (not the loop's height
 * at its middle). In the scaled coordinates w = (a - b) unit and
 * t = (b' - b) unit of a relay (a', b') of the window, E = sum p_jk w^j t^k
 * (the rows Taylor-shifted to b's anchor) and the density times d^2 / 4 is
 * at most 1/4 sum j (j - 1 + k) |p_jk| W^(j + k), W = the window's w. */
static TCM_NOINLINE TCM_Y TCM_NAME(everett_loop_error)(const hyst_tcm_t *S, TCM_X b, TCM_X a)
{
    const unsigned n = S->curve->u.everett.degree;
    const TCM_Y W = TCM_D(a, b) * YV(S->unit);
    const TCM_Y anchor = (TCM_R(b) - TCM_R(XV(S->lo))) * YV(S->unit);
    const hyst_num_t *row = S->curve->u.everett.rise;
    TCM_Y sum = 0;
    unsigned i, k, l;
    for (i = 0u; i < n; ++i) { /* row i: w^(n - i), a polynomial of degree i in the anchor */
        const unsigned j = n - i;
        TCM_Y p[HYST_EVERETT_MAX_DEGREE];
        TCM_Y wpow = 1;
        for (k = 0u; k < HYST_EVERETT_MAX_DEGREE; ++k) { /* whole: GCC -O2 cannot see k <= i suffices */
            p[k] = k <= i ? YV(row[k]) : 0;
        }
        /* Taylor shift to the anchor: p[i - k] becomes the coefficient of t^k */
        for (k = 0u; k < i; ++k) {
            for (l = 1u; l <= i - k; ++l) {
                p[l] += p[l - 1u] * anchor;
            }
        }
        for (k = 0u; k < j; ++k) {
            wpow *= W;
        }
        for (k = 0u; k <= i; ++k) {
            sum += (TCM_Y)(j * (j - 1u + k)) * NUM_NAME(abs)(p[i - k]) * wpow;
            wpow *= W;
        }
        row += i + 1u;
    }
    return sum * NUM_C(0.2525); /* 1/4, rounded up by 1 % */
}

/* The current branch's coefficients, for the rare paths (settle()). */
static TCM_NOINLINE void TCM_NAME(everett_derive)(hyst_tcm_t *S)
{
    const hyst_curve_t *c = S->curve;
    if (c->u.everett.linear_x) { /* the per-sample cases' numbers */
        TCM_NAME(table_coefs_x)(c->u.everett.lin_x[S->moving_end == 0u ? 0 : 1],
                                c->u.everett.degree, YV(S->x_ctp), S->coef);
    } else {
        TCM_NAME(table_coefs)(S->moving_end == 0u ? c->u.everett.rise : c->u.everett.fall,
                              c->u.everett.degree, TCM_NAME(input_anchor)(S), S->coef,
                              TCM_LOWEST_FIRST);
    }
}

/* A case of the kind's slow-sample end for degree n, in its bank (base):
 * a slow sample's `derive` first derives the branch's coefficients, the
 * degree a constant, so that Horner's rule takes them from registers (the
 * worst sample, a wipe-out at Nu = 4096, within its budget); the fast path
 * evaluates the cached ones (emit()'s cases of the same bank). */
#define TCM_EVERETT_CASE_(base, n, derivation)    \
    case (base) + n##u:                           \
        if (TCM_DERIVES(derive)) {                \
            derivation(n##u);                     \
        }                                         \
        acc = TCM_HORNER##n##_(S->coef, u);       \
        break
#define TCM_EVERETT_CASES_(base, derivation)      \
    TCM_EVERETT_CASE_(base, 1, derivation);       \
    TCM_EVERETT_CASE_(base, 2, derivation);       \
    TCM_EVERETT_CASE_(base, 3, derivation);       \
    TCM_EVERETT_CASE_(base, 4, derivation)

/* The derivations: from the rows at the TP's anchor (bank 1), or from the
 * TP's input itself (bank 2: rows at most linear in the anchor,
 * table_coefs_x()). */
#define TCM_EVERETT_ROWS_(n)                                                                \
    TCM_NAME(table_coefs)(derive == TCM_DERIVE_RISE ? S->curve->u.everett.rise              \
                                                    : S->curve->u.everett.fall,             \
                          n, TCM_NAME(input_anchor)(S), S->coef, TCM_LOWEST_FIRST)
#define TCM_EVERETT_LINES_(n)                                                               \
    TCM_NAME(table_coefs_x)(S->curve->u.everett.lin_x[derive == TCM_DERIVE_RISE ? 0 : 1], n, \
                            YV(S->x_ctp), S->coef)

/* The end of the kind's slow sample: emit() with the new branch's
 * coefficients derived first. Any other value of S->horner is a pending
 * request. */
HYST_INLINE TCM_Y TCM_NAME(everett_emit)(hyst_tcm_t *S, TCM_X x, const int how, const int derive)
{
    const TCM_Y u = (TCM_R(x) - YV(S->x_ctp)) * YV(S->u_scale);
    TCM_Y acc, y;
    switch (S->horner) {
    TCM_EVERETT_CASES_(HYST_HORNER_BANK1_, TCM_EVERETT_ROWS_);
    TCM_EVERETT_CASES_(HYST_HORNER_BANK2_, TCM_EVERETT_LINES_);
    case 0u: /* never: a jump table from 0 needs no subtraction */
        return TCM_NAME(emit_rare)(S, x, how);
    default:
        if (TCM_DERIVES(derive)) {
            TCM_NAME(everett_derive)(S);
        }
        return TCM_NAME(emit_rare)(S, x, how);
    }
    y = TCM_NAME(held_guard)(S, NUM_MUL_G(acc, u), how);
    YV(S->y_prev) = y;
    return y;
}

/* The kind's numbers of the instance: its degree; the coefficients are
 * the branch's (derive()). */
static void TCM_NAME(everett_attach)(hyst_tcm_t *S, const hyst_curve_t *curve)
{
    S->degree = curve->u.everett.degree;
}

#define TCM_SLOW(n) TCM_NAME(everett_##n)
#define TCM_SLOW_EMIT(S, x, how, derive) TCM_NAME(everett_emit)((S), (x), (how), (derive))
#define TCM_SLOW_PER_BRANCH 1
#include "tcm_slow.h"

/* Its two tables: rows as polynomials in the anchor (bank 1), or at most
 * linear in it (bank 2; kind_of() chooses). */
static const TCM_NAME(kind_t) TCM_NAME(ops_everett) = {
    .derive = TCM_NAME(everett_derive),
    .slow = TCM_NAME(everett_step_slow),
    .loop_error = TCM_NAME(everett_loop_error),
    .attach = TCM_NAME(everett_attach),
    .bank = HYST_HORNER_BANK1_};

static const TCM_NAME(kind_t) TCM_NAME(ops_everett_lines) = {
    .derive = TCM_NAME(everett_derive),
    .slow = TCM_NAME(everett_step_slow),
    .loop_error = TCM_NAME(everett_loop_error),
    .attach = TCM_NAME(everett_attach),
    .bank = HYST_HORNER_BANK2_};

#undef TCM_EVERETT_CASE_
#undef TCM_EVERETT_CASES_
#undef TCM_EVERETT_ROWS_
#undef TCM_EVERETT_LINES_

#endif /* HYST_KIND_EVERETT_H */
