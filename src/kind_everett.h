/* SPDX-License-Identifier: MIT */
/* The asymmetric kind (HYST_CURVE_EVERETT), a curve kind of the engine
 * (src/tcm_engine.h, TCM_NAME(kind_t)): each branch's coefficients derived
 * from the curve's tables at its turning point, on the slow sample that
 * starts it; the fast path evaluates them as a polynomial's (emit()'s
 * HYST_HORNER_ASYM_ cases derive them inline on the plain slow path).
 * Included by src/kinds.h after the engine. */
#ifndef HYST_KIND_EVERETT_H
#define HYST_KIND_EVERETT_H

/* E(a, b), a >= b: the asymmetric kind's from its rising table, anchored at b
 * (rare paths: the deadband). */
static TCM_NOINLINE TCM_Y TCM_NAME(e)(const hyst_tcm_t *S, TCM_X a, TCM_X b)
{
    {
        const unsigned n = S->curve->u.everett.degree;
        const TCM_Y w = TCM_D(a, b) * YV(S->unit);
        const TCM_Y anchor = (TCM_R(b) - TCM_R(XV(S->lo))) * YV(S->unit);
        const hyst_num_t *row = S->curve->u.everett.rise;
        TCM_Y acc = 0;
        unsigned i, k;
        /* Horner's rule in w over the coefficients, each by Horner's rule
         * in the anchor from its row (as derive() computes them) */
        for (i = 0u; i < n; ++i) {
            TCM_Y c = YV(row[0]);
            for (k = 1u; k <= i; ++k) {
                c = c * anchor + YV(row[k]);
            }
            acc = i == 0u ? c : NUM_MUL(acc, w) + c;
            row += i + 1u;
        }
        return NUM_MUL_G(acc, w);
    }
}

/* A skipped loop [b, a]'s error: its height at its middle. */
static TCM_Y TCM_NAME(everett_loop_error)(const hyst_tcm_t *S, TCM_X b, TCM_X a)
{
    const TCM_X m = TCM_MID(b, a);
    return NUM_NAME(abs)(TCM_NAME(e)(S, a, b) - TCM_NAME(e)(S, a, m) - TCM_NAME(e)(S, m, b));
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
                              c->u.everett.degree, TCM_NAME(input_anchor)(S), S->coef);
    }
}

/* The derivations of emit()'s cases for the kind (TCM_ASYM_CASE_): from the
 * rows at the TP's anchor, or from the TP's input itself (rows at most
 * linear in the anchor, table_coefs_x()). */
#define TCM_ASYM_ROWS_(n)                                                                   \
    TCM_NAME(table_coefs)(derive == TCM_DERIVE_RISE ? S->curve->u.everett.rise              \
                                                    : S->curve->u.everett.fall,             \
                          n, TCM_NAME(input_anchor)(S), S->coef)
#define TCM_ASYM_LINES_(n)                                                                  \
    TCM_NAME(table_coefs_x)(S->curve->u.everett.lin_x[derive == TCM_DERIVE_RISE ? 0 : 1], n, \
                            YV(S->x_ctp), S->coef)

/* The end of the kind's slow sample: emit() with the new branch's
 * coefficients derived first, the degree a constant per case, so that
 * Horner's rule takes them from registers (the worst sample, a wipe-out at
 * Nu = 4096, within its budget). Any other value of S->horner is a pending
 * request. */
HYST_INLINE TCM_Y TCM_NAME(everett_emit)(hyst_tcm_t *S, TCM_X x, const int how, const int derive)
{
    const TCM_Y u = (TCM_R(x) - YV(S->x_ctp)) * YV(S->u_scale);
    TCM_Y acc, y;
    switch (S->horner) {
    TCM_ASYM_CASES_(HYST_HORNER_ASYM_, TCM_ASYM_ROWS_);
    TCM_ASYM_CASES_(HYST_HORNER_ASYM_LINEAR_, TCM_ASYM_LINES_);
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

#define TCM_SLOW(n) TCM_NAME(everett_##n)
#define TCM_SLOW_EMIT(S, x, how, derive) TCM_NAME(everett_emit)((S), (x), (how), (derive))
#define TCM_SLOW_PER_BRANCH 1
#include "tcm_slow.h"

static const TCM_NAME(kind_t) TCM_NAME(kind_everett) = {
    NULL, NULL, TCM_NAME(everett_derive), TCM_NAME(everett_step_slow),
    TCM_NAME(everett_loop_error), NULL};

#endif /* HYST_KIND_EVERETT_H */
