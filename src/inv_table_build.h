/* SPDX-License-Identifier: MIT */
/* The builder of a tabulated inverse (curve.h, HYST_INV_TABLE_LEN): cubic
 * Hermite pieces of G^-1 on intervals uniform in the output step, each
 * measured against the exact inverse and marked exact where it misses
 * HYST_INV_TABLE_TOL. Written once, instantiated per forward kind by the
 * file that prepares its tabulated inverse, so that each links the
 * forward kind's G alone and evaluates it inline:
 *   src/hyst_curve_inv.c: a polynomial's (HYST_CURVE_INV_TABLE), with one
 *     more instance of the pieces pass (src/inv_table_pieces.h): a table
 *     given ready-made, measured;
 *   src/hyst_q31_inv.c: the q31 compensator's, on G's exact coefficients,
 *     with the q31 pieces pass;
 *   src/hyst_spline.c: a spline's (HYST_CURVE_SPLINE_INV_TABLE).
 * The instance defines, before including it:
 *   TB_NAME(n)    its functions' names (one static name per object: the
 *                 symbols ctest);
 *   TB_FWD_T      what the forward kind's G is read from (the build's
 *                 b->fwd, given to table_start());
 *   TB_G(p, variant, u), TB_DG(p, variant, u)  G(u) and G'(u) in
 *                 hyst_wide_t, u in [0, 1] of the drive span, from the
 *                 numbers the samples use.
 * It gets table_build(), which builds a real table's pieces by
 * TB_NAME(table_pieces)(). */
#ifndef HYST_INV_TABLE_BUILD_H
#define HYST_INV_TABLE_BUILD_H

#if !defined(TB_NAME) || !defined(TB_FWD_T) || !defined(TB_G) || !defined(TB_DG)
#error "inv_table_build.h: define TB_NAME, TB_FWD_T, TB_G and TB_DG first"
#endif

#include <string.h>

#include "hyst_util.h"

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
    const TB_FWD_T *fwd; /* the forward kind's G, as TB_G() reads it */
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
    const TB_FWD_T *p = b->fwd;
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

/* The window moves on by one knot. Written out: GCC turns the loop over the
 * slots into three calls of memmove(), which a firmware would link for
 * this alone. */
static void TB_NAME(table_window_next)(table_build_t *b)
{
    b->u[0] = b->u[1];
    b->u[1] = b->u[2];
    b->u[2] = b->u[3];
    b->d[0] = b->d[1];
    b->d[1] = b->d[2];
    b->d[2] = b->d[3];
    b->m[0] = b->m[1];
    b->m[1] = b->m[2];
    b->m[2] = b->m[3];
}

/* Points per interval where init measures a piece against the exact inverse. */
#define TABLE_PROBES 16u

#define Q31_2_30 ((hyst_wide_t)((hyst_q31_t)1 << 30))
#define Q31_2_31 (2 * Q31_2_30)

/* The real variants' build: table_pieces() and the functions it calls. */
#define TP_NAME(n) TB_NAME(n)
#define TP_Q31 0
#define TP_GIVEN 0
#include "inv_table_pieces.h"

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
    hyst_curve_swap_axes_(out, fwd);
    out->kind = kind;
    (void)hyst_num_set(&out->rounding, variant, 0);
}

/* The end of a constructor's checks, once the curve has its axes swapped,
 * its forward G (fwd) and the table's drive span and G's argument per drive
 * step: the index scale, the build's state, the table's fields.
 * HYST_ERR_ILL_CONDITIONED where the scale overflows the variant's type. */
HYST_INLINE hyst_status_t TB_NAME(table_start)(hyst_curve_t *out, table_build_t *b,
                                               const TB_FWD_T *fwd, hyst_cptr_t table,
                                               size_t intervals, hyst_wide_t range,
                                               hyst_wide_t span, unsigned variant)
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
    b->fwd = fwd;
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

#endif /* HYST_INV_TABLE_BUILD_H */
