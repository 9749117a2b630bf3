/* SPDX-License-Identifier: MIT */
/* The pieces pass of the inverse-table builder (src/inv_table_build.h):
 * every interval's cubic measured against the exact inverse. One instance
 * per use, so that a firmware links the pass it calls and no other (the
 * real variants' build links no q31 piece and no table given ready-made).
 * No include guard: included once per instance, after inv_table_build.h,
 * which instantiates the real build itself. The instance defines:
 *   TP_NAME(n)  its functions' names;
 *   TP_Q31      1: the q31 compensator's pieces, built into b->q31;
 *   TP_GIVEN    1: the pieces of a table given ready-made (b->given)
 *               measured, not built;
 *               both 0: real pieces built into b->table.
 * The top function is TP_NAME(table_pieces)(b, intervals): the worst error. */
#if !defined(TP_NAME) || !defined(TP_Q31) || !defined(TP_GIVEN)
#error "inv_table_pieces.h: define TP_NAME, TP_Q31 and TP_GIVEN first"
#endif

/* The q31 compensator's piece from the cubic's coefficients c (drive
 * units, in t = 0..1): re-expanded about t = 1/2 (hyst_q31_cubic_()),
 * rounded and stored in b, b0 then moved so that the interval's start gives
 * its knot's drive exactly (G^-1(0) = 0; the truncations would leave it up
 * to 3 units off, possibly below 0); 0, nothing stored, if a coefficient or
 * a Horner partial sum could leave 32 bits (|t - 1/2| <= 1/2: each step
 * adds at most half the last sum, plus one for the truncation). */
static int TP_NAME(q31_piece)(hyst_q31_t *b, const hyst_wide_t *c)
{
    hyst_wide_t w[4], partial = 0;
    int j;
    w[3] = c[3];
    w[2] = c[2] + (hyst_wide_t)1.5 * c[3];
    w[1] = c[1] + c[2] + (hyst_wide_t)0.75 * c[3];
    w[0] = c[0] + (hyst_wide_t)0.5 * c[1] + (hyst_wide_t)0.25 * c[2] + (hyst_wide_t)0.125 * c[3];
    for (j = 3; j >= 0; --j) {
        partial = hyst_wide_abs(w[j]) + (hyst_wide_t)0.5 + partial / 2 + (j < 3 ? 1 : 0);
        if (!(partial < Q31_2_31 - 8)) { /* room for the move of b0 */
            return 0;
        }
    }
    for (j = 0; j < 4; ++j) { /* |w| < 2^31 - 8: rounds inside 32 bits */
        b[j] = (hyst_q31_t)(w[j] < 0 ? w[j] - (hyst_wide_t)0.5 : w[j] + (hyst_wide_t)0.5);
    }
    b[0] += (hyst_q31_t)(c[0] + (hyst_wide_t)0.5) - hyst_q31_cubic_(b, HYST_Q31_MID_(0u));
    return 1;
}

/* The cubic of piece k at probe t as the samples compute it. */
static hyst_wide_t TP_NAME(piece_at)(const table_build_t *b, size_t k, const hyst_wide_t *c,
                                     unsigned probe)
{
    const hyst_wide_t t = (hyst_wide_t)probe / (hyst_wide_t)TABLE_PROBES;
    if (TP_Q31) { /* probe / TABLE_PROBES in Q32, exact (TABLE_PROBES = 2^4) */
        return (hyst_wide_t)hyst_q31_cubic_(b->q31 + 4u * k,
                                            HYST_Q31_MID_((uint_least32_t)probe << (32 - 4)));
    }
    return c[0] + t * (c[1] + t * (c[2] + t * c[3]));
}

/* Marks interval k for exact evaluation. The q31 marker carries the
 * bracket of G's argument (Q30) from the knots in window slots 1 and 2. */
static void TP_NAME(table_mark)(table_build_t *b, size_t k)
{
    if (TP_Q31) {
        hyst_q31_t *q = b->q31 + 4u * k;
        const hyst_wide_t va = b->u[1] * Q31_2_30, vb = b->u[2] * Q31_2_30 + 1;
        q[0] = -((hyst_q31_t)1 << 30);
        q[1] = va > 0 ? (hyst_q31_t)va : 0; /* truncated: below the knot */
        q[2] = vb < Q31_2_30 ? (hyst_q31_t)vb : (hyst_q31_t)1 << 30;
        q[3] = 0;
    } else {
        (void)hyst_table_put_(b->table, 4u * k, b->c->variant, -1);
        (void)hyst_table_put_(b->table, 4u * k + 1u, b->c->variant, 0);
        (void)hyst_table_put_(b->table, 4u * k + 2u, b->c->variant, 0);
        (void)hyst_table_put_(b->table, 4u * k + 3u, b->c->variant, 0);
    }
    ++b->c->u.inv_table.exact;
}

/* Interval k from the knots in window slots 1 and 2: the cubic Hermite
 * piece, rounded as stored, measured against the exact inverse; stored, or
 * marked exact if it misses HYST_INV_TABLE_TOL (or, in q31, could overflow).
 * Returns its error (0 if marked). */
static hyst_wide_t TP_NAME(table_piece)(table_build_t *b, size_t k, int has_left, int has_right)
{
    const hyst_wide_t m0 = TB_NAME(table_slope)(b, 1u, has_left, 1);
    const hyst_wide_t m1 = TB_NAME(table_slope)(b, 2u, 1, has_right);
    const hyst_wide_t dd = b->d[2] - b->d[1];
    const TB_FWD_T *p = b->fwd;
    hyst_wide_t c[4], worst = 0;
    unsigned i;
    c[0] = b->d[1];
    c[1] = m0;
    c[2] = 3 * dd - 2 * m0 - m1;
    c[3] = m0 + m1 - 2 * dd;
    if (TP_GIVEN) { /* measure the given piece itself */
        for (i = 0u; i < 4u; ++i) {
            c[i] = hyst_cptr_get(b->given, 4u * k + i, b->c->variant);
        }
        if (c[0] < 0) {
            return 0; /* solved instead (its marking is checked by table_matches()) */
        }
    } else if (TP_Q31) {
        if (!TP_NAME(q31_piece)(b->q31 + 4u * k, c)) {
            TP_NAME(table_mark)(b, k);
            return 0;
        }
    } else {
        for (i = 0u; i < 4u; ++i) {
            c[i] = hyst_table_put_(b->table, 4u * k + i, b->c->variant, c[i]);
        }
    }
    for (i = 1u; i < TABLE_PROBES; ++i) {
        const hyst_wide_t t = (hyst_wide_t)i / (hyst_wide_t)TABLE_PROBES;
        const hyst_wide_t e = ((hyst_wide_t)k + t) * b->e_per_s;
        const hyst_wide_t cubic = TP_NAME(piece_at)(b, k, c, i);
        const hyst_wide_t guess = cubic / b->span;
        const hyst_wide_t exact =
            b->span * TB_NAME(solve_g_near)(p, b->c->variant, e, b->u[1], b->u[2],
                                            guess > b->u[1] && guess < b->u[2] ? guess : b->u[1]);
        const hyst_wide_t err = hyst_wide_abs(cubic - exact);
        worst = err > worst ? err : worst;
    }
    /* the evaluation's own rounding between the probes: in the variant's
     * real type, or the q31 truncations and roundings (hyst_q31_cubic_():
     * within (-2.7, 1.7) units, and b0's move) */
    worst += TP_Q31 ? 8
                            : 4 * b->eps *
                                  (hyst_wide_abs(c[0]) + hyst_wide_abs(c[1]) + hyst_wide_abs(c[2]) +
                                   hyst_wide_abs(c[3]));
    if (!(worst <= (hyst_wide_t)HYST_INV_TABLE_TOL * b->span)) {
        if (TP_GIVEN) {
            b->beyond = 1;
            return worst;
        }
        TP_NAME(table_mark)(b, k);
        return 0;
    }
    return worst;
}

/* The pieces of every interval (knots in a window of four), then the end of
 * the range (s = N, and above it by rounding); returns the worst error. */
static hyst_wide_t TP_NAME(table_pieces)(table_build_t *b, size_t intervals)
{
    hyst_wide_t worst = 0;
    size_t k;
    unsigned w;
    /* window slots 0..3 = knots k-1 .. k+2 */
    TB_NAME(table_knot)(b, 0u, 1u);
    TB_NAME(table_knot)(b, 1u, 2u);
    for (k = 0u; k < intervals; ++k) {
        hyst_wide_t err;
        if (k + 2u <= intervals) {
            TB_NAME(table_knot)(b, k + 2u, 3u);
        }
        err = TP_NAME(table_piece)(b, k, k > 0u, k + 1u < intervals);
        worst = err > worst ? err : worst;
        TB_NAME(table_window_next)(b);
    }
    for (w = 0u; w < 4u && !TP_GIVEN; ++w) {
        const hyst_wide_t end = w == 0u ? b->span : 0;
        if (TP_Q31) {
            b->q31[4u * intervals + w] = (hyst_q31_t)end;
        } else {
            (void)hyst_table_put_(b->table, 4u * intervals + w, b->c->variant, end);
        }
    }
    return worst;
}

#undef TP_NAME
#undef TP_Q31
#undef TP_GIVEN
