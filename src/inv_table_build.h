/* SPDX-License-Identifier: MIT */
/* The builder of a tabulated inverse (curve.h, HYST_INV_TABLE_LEN): cubic
 * Hermite pieces of G^-1 on intervals uniform in the output step, each
 * measured against the exact inverse and marked exact where it misses
 * HYST_INV_TABLE_TOL. Written once, instantiated per forward kind by the
 * file that prepares its tabulated inverse, so that each links the
 * forward kind's G alone and evaluates it inline:
 *   src/hyst_curve_inv.c: a polynomial's (HYST_CURVE_INV_TABLE), also the
 *     q31 compensator's pieces and a table given ready-made, measured;
 *   src/hyst_spline.c: a spline's (HYST_CURVE_SPLINE_INV_TABLE).
 * The instance defines, before including it:
 *   TB_NAME(n)    its functions' names (one static name per object: the
 *                 symbols ctest);
 *   TB_FWD_T      what the forward kind's G is read from, and TB_FWD(c)
 *                 that of the curve c being built;
 *   TB_G(p, variant, u), TB_DG(p, variant, u)  G(u) and G'(u) in
 *                 hyst_wide_t, u in [0, 1] of the drive span, from the
 *                 numbers the samples use;
 *   TB_REAL_ONLY  1: real tables built alone (no q31 pieces, no table given
 *                 ready-made: their branches compile out); 0 by default. */
#ifndef HYST_INV_TABLE_BUILD_H
#define HYST_INV_TABLE_BUILD_H

#if !defined(TB_NAME) || !defined(TB_FWD_T) || !defined(TB_FWD) || !defined(TB_G) || !defined(TB_DG)
#error "inv_table_build.h: define TB_NAME, TB_FWD_T, TB_FWD, TB_G and TB_DG first"
#endif

#include <string.h>

#include "hyst_util.h"

#ifndef TB_REAL_ONLY
#define TB_REAL_ONLY 0
#endif
#if TB_REAL_ONLY
#define TB_Q31_(b) 0
#define TB_GIVEN_(b) 0
#else
#define TB_Q31_(b) ((b)->q31 != NULL)
#define TB_GIVEN_(b) ((b)->given.f32 != NULL)
#endif

/* The u in [a, b] where G crosses e (G(a) <= e <= G(b)), from a guess u:
 * Newton steps, each narrowing the bracket by the sign of G(u) - e, and a
 * bisection instead of a step that would leave it; stops once a step is
 * at the rounding level. A good guess (the table's own cubic) needs 2 or 3
 * evaluations instead of bisection's ~45. */
static hyst_wide_t TB_NAME(solve_g_near)(const TB_FWD_T *p, unsigned variant, hyst_wide_t e,
                                         hyst_wide_t a, hyst_wide_t b, hyst_wide_t u)
{
    unsigned it;
    for (it = 0u; it < 200u; ++it) {
        const hyst_wide_t r = TB_G(p, variant, u) - e;
        const hyst_wide_t dg = TB_DG(p, variant, u);
        hyst_wide_t next;
        if (r < 0) {
            a = u;
        } else {
            b = u;
        }
        next = dg > 0 ? u - r / dg : a;
        if (!(next > a && next < b)) {
            next = (a + b) / 2;
            if (!(next > a && next < b)) {
                break; /* adjacent numbers */
            }
        } else if (hyst_wide_abs(next - u) <= 4 * HYST_WIDE_EPS * hyst_wide_abs(u)) {
            return next;
        }
        u = next;
    }
    return u;
}

/* Building an inverse table: the curve being built, and a window of four
 * knots k-1 .. k+2 (the drive d at s = k, and its raw slope dd/ds). */
typedef struct {
    hyst_curve_t *c;
    hyst_ptr_t table;
    hyst_q31_t *q31; /* the q31 compensator's pieces (q31.h), else NULL */
    /* a table given ready-made: its pieces measured, not built (NULL: build) */
    hyst_cptr_t given;
    int beyond; /* a given piece misses HYST_INV_TABLE_TOL (a build would solve it) */
    hyst_wide_t span, e_per_s, eps;
    hyst_wide_t u[4], d[4], m[4];
} table_build_t;

/* Knot j (0..N) into window slot w: exact u by bisection from the previous
 * knot's, its drive and slope (infinite at a flat point of f0). */
static void TB_NAME(table_knot)(table_build_t *b, size_t j, unsigned w)
{
    const TB_FWD_T *p = TB_FWD(b->c);
    const hyst_wide_t from = j > 0u ? b->u[w - 1u] : 0;
    hyst_wide_t u =
        TB_NAME(solve_g_near)(p, b->c->variant, (hyst_wide_t)j * b->e_per_s, from, 1, from);
    b->u[w] = u;
    b->d[w] = u * b->span;
    u = TB_DG(p, b->c->variant, u);
    b->m[w] = u > 0 ? b->e_per_s * b->span / u : -1; /* -1: infinite */
}

/* Slope at window slot w (1 or 2), limited to three times the secants on
 * either side (Fritsch-Carlson: then each piece is monotone). */
static hyst_wide_t TB_NAME(table_slope)(const table_build_t *b, unsigned w, int has_left,
                                        int has_right)
{
    hyst_wide_t m = b->m[w];
    const hyst_wide_t left = has_left ? 3 * (b->d[w] - b->d[w - 1u]) : -1;
    const hyst_wide_t right = has_right ? 3 * (b->d[w + 1u] - b->d[w]) : -1;
    if (left >= 0 && (m < 0 || left < m)) {
        m = left;
    }
    if (right >= 0 && (m < 0 || right < m)) {
        m = right;
    }
    return m < 0 ? 0 : m;
}

/* Points per interval where init measures a piece against the exact inverse. */
#define TABLE_PROBES 16u

#define Q31_2_30 ((hyst_wide_t)((hyst_q31_t)1 << 30))
#define Q31_2_31 (2 * Q31_2_30)

/* The q31 compensator's piece from the cubic's coefficients c (drive
 * units, in t = 0..1): re-expanded about t = 1/2 (hyst_q31_cubic_()),
 * rounded and stored in b, b0 then moved so that the interval's start gives
 * its knot's drive exactly (G^-1(0) = 0; the truncations would leave it up
 * to 3 units off, possibly below 0); 0, nothing stored, if a coefficient or
 * a Horner partial sum could leave 32 bits (|t - 1/2| <= 1/2: each step
 * adds at most half the last sum, plus one for the truncation). */
static int TB_NAME(q31_piece)(hyst_q31_t *b, const hyst_wide_t *c)
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
static hyst_wide_t TB_NAME(piece_at)(const table_build_t *b, size_t k, const hyst_wide_t *c,
                                     unsigned probe)
{
    const hyst_wide_t t = (hyst_wide_t)probe / (hyst_wide_t)TABLE_PROBES;
    if (TB_Q31_(b)) { /* probe / TABLE_PROBES in Q32, exact (TABLE_PROBES = 2^4) */
        return (hyst_wide_t)hyst_q31_cubic_(b->q31 + 4u * k,
                                            HYST_Q31_MID_((uint_least32_t)probe << (32 - 4)));
    }
    return c[0] + t * (c[1] + t * (c[2] + t * c[3]));
}

/* Marks interval k for exact evaluation. The q31 marker carries the
 * bracket of G's argument (Q30) from the knots in window slots 1 and 2. */
static void TB_NAME(table_mark)(table_build_t *b, size_t k)
{
    if (TB_Q31_(b)) {
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
static hyst_wide_t TB_NAME(table_piece)(table_build_t *b, size_t k, int has_left, int has_right)
{
    const hyst_wide_t m0 = TB_NAME(table_slope)(b, 1u, has_left, 1);
    const hyst_wide_t m1 = TB_NAME(table_slope)(b, 2u, 1, has_right);
    const hyst_wide_t dd = b->d[2] - b->d[1];
    const TB_FWD_T *p = TB_FWD(b->c);
    hyst_wide_t c[4], worst = 0;
    unsigned i;
    c[0] = b->d[1];
    c[1] = m0;
    c[2] = 3 * dd - 2 * m0 - m1;
    c[3] = m0 + m1 - 2 * dd;
    if (TB_GIVEN_(b)) { /* measure the given piece itself */
        for (i = 0u; i < 4u; ++i) {
            c[i] = hyst_cptr_get(b->given, 4u * k + i, b->c->variant);
        }
        if (c[0] < 0) {
            return 0; /* solved instead (its marking is checked by table_matches()) */
        }
    } else if (TB_Q31_(b)) {
        if (!TB_NAME(q31_piece)(b->q31 + 4u * k, c)) {
            TB_NAME(table_mark)(b, k);
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
        const hyst_wide_t cubic = TB_NAME(piece_at)(b, k, c, i);
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
    worst += TB_Q31_(b) ? 8
                            : 4 * b->eps *
                                  (hyst_wide_abs(c[0]) + hyst_wide_abs(c[1]) + hyst_wide_abs(c[2]) +
                                   hyst_wide_abs(c[3]));
    if (!(worst <= (hyst_wide_t)HYST_INV_TABLE_TOL * b->span)) {
        if (TB_GIVEN_(b)) {
            b->beyond = 1;
            return worst;
        }
        TB_NAME(table_mark)(b, k);
        return 0;
    }
    return worst;
}

/* The pieces of every interval (knots in a window of four), then the end of
 * the range (s = N, and above it by rounding); returns the worst error. */
static hyst_wide_t TB_NAME(table_pieces)(table_build_t *b, size_t intervals)
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
        err = TB_NAME(table_piece)(b, k, k > 0u, k + 1u < intervals);
        worst = err > worst ? err : worst;
        for (w = 0u; w < 3u; ++w) {
            b->u[w] = b->u[w + 1u];
            b->d[w] = b->d[w + 1u];
            b->m[w] = b->m[w + 1u];
        }
    }
    for (w = 0u; w < 4u && !TB_GIVEN_(b); ++w) {
        const hyst_wide_t end = w == 0u ? b->span : 0;
        if (TB_Q31_(b)) {
            b->q31[4u * intervals + w] = (hyst_q31_t)end;
        } else {
            (void)hyst_table_put_(b->table, 4u * intervals + w, b->c->variant, end);
        }
    }
    return worst;
}

/* Largest interval count: s = e N / R keeps its integer part exact in float. */
#define TABLE_MAX_INTERVALS ((unsigned long)1 << 20)

/* n intervals within 1..TABLE_MAX_INTERVALS. A function, not an inline
 * compare: where size_t is 16 bits the upper test is always true, which
 * GCC would report (-Wtype-limits). */
static int TB_NAME(table_size_ok)(unsigned long n) { return n >= 1ul && n <= TABLE_MAX_INTERVALS; }

/* A curve from fwd, its inverse or its forward curve: its kind, the axes
 * swapped, no rounding bound (curve.h: the kinds but POLY's). */
HYST_INLINE void TB_NAME(table_axes)(hyst_curve_t *out, const hyst_curve_t *fwd, unsigned kind,
                                     unsigned variant)
{
    *out = *fwd;
    out->kind = kind;
    out->lo = fwd->y_lo;
    out->hi = fwd->y_hi;
    out->y_lo = fwd->lo;
    out->y_hi = fwd->hi;
    (void)hyst_num_set(&out->rounding, variant, 0);
}

/* The end of a constructor's checks, once the curve has its axes swapped,
 * its forward G and the table's drive span and G's argument per drive
 * step: the index scale, the build's state, the table's fields.
 * HYST_ERR_ILL_CONDITIONED where the scale overflows the variant's type. */
HYST_INLINE hyst_status_t TB_NAME(table_start)(hyst_curve_t *out, table_build_t *b,
                                               hyst_cptr_t table, size_t intervals,
                                               hyst_wide_t range, hyst_wide_t span,
                                               unsigned variant)
{
    /* s = e unit, as the samples compute it: the knots sit where they see them;
     * an output range so small (subnormal) that the scale overflows the
     * variant's type would put every sample in one interval */
    if (!hyst_num_set(&out->unit, variant, (hyst_wide_t)intervals / range)) {
        return HYST_ERR_ILL_CONDITIONED;
    }
    memset(b, 0, sizeof *b);
    b->span = span;
    b->e_per_s = 1 / hyst_num_get(&out->unit, variant);
    b->eps = hyst_real_eps(variant);
    out->u.inv_table.table = table;
    out->u.inv_table.intervals = intervals;
    out->u.inv_table.exact = 0u;
    out->u.inv_table.drive_bits = 0u;
    out->u.inv_table.drive_code_lo = 0u;
    b->c = out;
    return HYST_OK;
}

/* A constructor's end, once table_start() passed: the pieces built into
 * table, the table's error (the pieces' worst and the drive's last
 * rounding, of the drive span, rounded up to a float), the curve written. */
HYST_INLINE hyst_status_t TB_NAME(table_build)(hyst_curve_t *inv, hyst_curve_t *out,
                                               table_build_t *b, hyst_ptr_t table,
                                               size_t intervals)
{
    b->table = table;
    out->u.inv_table.max_err = hyst_table_err_(
        (TB_NAME(table_pieces)(b, intervals) + hyst_drive_rounding_(out)) / b->span);
    *inv = *out;
    return HYST_OK;
}

#undef TB_Q31_
#undef TB_GIVEN_
#endif /* HYST_INV_TABLE_BUILD_H */
