/* SPDX-License-Identifier: MIT */
/* The q31 compensator (hyst_q31_inv_*, include/hyst/q31.h): desired outputs
 * in the q31 model's format in, the drive in fixed-point codes out. The
 * engine over hyst_q31_t inputs and outputs on the tabulated inverse of f0.
 * Set-up in hyst_wide_t (the table, measured against the exact inverse);
 * per sample integers only: one product for the interval, one cubic. */
#include <string.h>

#include "hyst/q31.h"

#include "hyst_util.h"

#define NUM_NAME(n) hyst_q31_inv_##n
#define NUM_VARIANT HYST_VARIANT_Q31_INV
#include "num_q31.h"
#include "num_ops.h"

/* The desired outputs' domain [-2^27, 2^27] (the model's output range). */
#define Q31_INV_HALF ((hyst_q31_t)1 << (HYST_Q31_SPAN_BITS - 1))

/* Out of line: the common path is one compare. */
static hyst_q31_t hyst_q31_inv_clamp_slow(hyst_tcm_t *S, hyst_q31_t y)
{
    S->status = HYST_WARN_CLAMPED;
    S->events |= HYST_EVENT_CLAMPED;
    return y < S->lo.q31 ? S->lo.q31 : S->hi.q31;
}

static int hyst_q31_inv_admit(hyst_tcm_t *S, hyst_q31_t y, hyst_q31_t *out)
{
    *out = y >= S->lo.q31 && y <= S->hi.q31 ? y : hyst_q31_inv_clamp_slow(S, y);
    return 1;
}

/* G^-1 at an output step u (q) off the inline path: the table (a piece's
 * truncations can dip below 0 next to a knot at drive 0), or on a marked
 * interval (next to a flat point of f0, where no cubic fits) the
 * model's own fixed-point G solved by bisection over the bracket of its
 * argument v (Q30) that the marker carries: the v of G(v) nearest to u, the
 * smallest of equals (G^-1(0) = 0 where f0 is flat at lo); then v's share of
 * the drive span, rounded. */
static hyst_q31_t hyst_q31_inv_other(const hyst_curve_t *c, hyst_q31_t u)
{
    const hyst_q31_t *tab = c->u.inv_table.table.q31;
    const hyst_q31_t d = hyst_q31_inv_table_g(tab, u);
    const hyst_curve_poly_t *p = &c->u.inv_table.fwd;
    const hyst_q31_t *marker = tab + 4u * hyst_q31_inv_table_interval(tab, u);
    hyst_q31_t a, b, ga, gb;
    if (marker[0] > -((hyst_q31_t)1 << 29)) { /* a piece: below 0 by truncation at most */
        return d < 0 ? 0 : d;
    }
    a = marker[1];
    b = marker[2];
    ga = hyst_q31_inv_horner(p->a, p->degree, a);
    gb = hyst_q31_inv_horner(p->a, p->degree, b);
    if (ga >= u) {
        b = a;
    }
    while (b - a > 1) { /* G(a) < u <= G(b) */
        const hyst_q31_t m = a + (b - a) / 2;
        const hyst_q31_t gm = hyst_q31_inv_horner(p->a, p->degree, m);
        if (gm < u) {
            a = m;
            ga = gm;
        } else {
            b = m;
            gb = gm;
        }
    }
    if (u - ga < gb - u) {
        b = a;
    }
    return (hyst_q31_t)(((int_least64_t)b * c->u.inv_table.span.q31 + ((int_least64_t)1 << 29)) >>
                        30);
}

#define TCM_NAME(n) hyst_q31_inv_##n
#define TCM_VARIANT HYST_VARIANT_Q31_INV
#define TCM_X hyst_q31_t
#define TCM_XF q31
#define TCM_Y hyst_q31_t
#define TCM_YF q31
#define TCM_ARG hyst_q31_t
#define TCM_IN hyst_q31_t
#define TCM_R(a) (a)
#define TCM_D(a, b) ((a) - (b))
#define TCM_MID(a, b) ((a) + ((b) - (a)) / 2)
#define TCM_NORM(a) (a)
#define TCM_ADMIT(S, x, out) hyst_q31_inv_admit((S), (x), (out))
#define TCM_G_OTHER(c, d) hyst_q31_inv_other((c), (d))
/* unit = 1: G's argument is the output step itself */
#define TCM_G_HALF(S, d) TCM_NAME(g)((S), (d) / 2)
#define TCM_ADD_BOUND(a, e) ((a) = hyst_q31_inv_add_bound((a), (e)))
#include "tcm_engine.h"
/* its kind: the tabulated inverse's (its exact intervals by TCM_G_OTHER) */
#define TCM_INV_TABLE_G(c, s) hyst_q31_inv_other((c), (s))
#include "kind_inv_table.h"

#define Q31_INV_SPAN ((uint_least32_t)1 << HYST_Q31_SPAN_BITS)

/* The table's forward curve: G's coefficients in hyst_wide_t, a[0]
 * multiplying u^n as in hyst_curve_poly_t, exact (hyst_poly_check_()), not
 * rounded to a real variant's numbers: the table is the same whether or not
 * the f64 variant exists. */
typedef struct {
    unsigned degree;
    hyst_wide_t a[HYST_MAX_DEGREE];
} wide_poly_t;

/* G(u) and G'(u) in the order of the real curves' unit_g() and unit_dg()
 * (src/hyst_curve_inv.c). */
static hyst_wide_t wide_g(const wide_poly_t *p, hyst_wide_t u)
{
    hyst_wide_t acc = p->a[0];
    unsigned i;
    for (i = 1u; i < p->degree; ++i) {
        acc = acc * u + p->a[i];
    }
    return acc * u;
}

static hyst_wide_t wide_dg(const wide_poly_t *p, hyst_wide_t u)
{
    hyst_wide_t acc = 0;
    unsigned i;
    for (i = 0u; i < p->degree; ++i) {
        acc = acc * u + (hyst_wide_t)(p->degree - i) * p->a[i];
    }
    return acc;
}

/* The builder (src/inv_table_build.h) on that G, and its pieces pass for
 * the q31 pieces: q31_table_pieces(). */
#define TB_NAME(n) wide_##n
#define TB_FWD_T wide_poly_t
#define TB_G(p, variant, u) ((void)(variant), wide_g((p), (u)))
#define TB_DG(p, variant, u) ((void)(variant), wide_dg((p), (u)))
#include "inv_table_build.h"
#define TP_NAME(n) q31_##n
#define TP_Q31 1
#define TP_GIVEN 0
#include "inv_table_pieces.h"

/* The table (q31.h): the inverse of G, f0's normalised coefficients g
 * (lowest power first, degree n), in `intervals` pieces uniform in the
 * output, drive span `drive_span` units, into table (its scale, then the
 * pieces); the count of exactly evaluated intervals into *exact and the
 * worst measured error / drive span into *max_err. */
static hyst_status_t q31_table(hyst_q31_t *table, size_t intervals, const hyst_wide_t *g,
                               unsigned n, hyst_q31_t drive_span, size_t *exact,
                               hyst_wide_t *max_err)
{
    hyst_curve_t out; /* the count of intervals marked exact */
    table_build_t b;
    wide_poly_t w;
    hyst_wide_t range;
    unsigned k;
    memset(&w, 0, sizeof w);
    w.degree = n;
    for (k = 0u; k < n; ++k) {
        w.a[k] = g[n - k]; /* a[0] multiplies u^n */
    }
    range = wide_g(&w, 1);
    if (!wide_table_size_ok((unsigned long)intervals)) {
        return HYST_ERR_ARG;
    }
    if (!(range > 0)) {
        return HYST_ERR_NOT_INVERTIBLE;
    }
    memset(&out, 0, sizeof out);
    memset(&b, 0, sizeof b);
    b.c = &out;
    b.fwd = &w;
    b.q31 = table + 1;
    b.span = (hyst_wide_t)drive_span;
    /* the samples' s = u N / 2^28 for an output step u in q: knot j at the
     * real output step j range / N */
    b.e_per_s = range / (hyst_wide_t)intervals;
    table[0] = (hyst_q31_t)(16u * (unsigned long)intervals); /* <= 2^24 */
    *max_err = q31_table_pieces(&b, intervals) / b.span;
    *exact = out.u.inv_table.exact;
    return HYST_OK;
}

hyst_status_t hyst_q31_init_inverse_table_(hyst_tcm_t *S, hyst_curve_t *inv,
                                           const hyst_poly_t *f0, uint_least32_t code_lo,
                                           uint_least32_t code_hi, hyst_q31_t *table,
                                           size_t intervals, hyst_q31_t *xltp,
                                           hyst_q31_t *yltp, hyst_q31_t *xrtp,
                                           hyst_q31_t *yrtp, size_t capacity,
                                           unsigned long layout)
{
    /* the curve's checks as the model's (hyst_q31_init_()), and its G in
     * hyst_wide_t, the table's forward curve */
    hyst_wide_t g[HYST_MAX_DEGREE + 1];
    hyst_curve_t q;
    hyst_wide_t max_err = 0;
    uint_least32_t codes = 0u;
    unsigned bits = 0u;
    size_t exact = 0u;
    hyst_status_t st =
        inv == NULL || table == NULL ? HYST_ERR_NULL : hyst_poly_check_(f0, g, layout);
    if (st == HYST_OK && (!(code_lo < code_hi) || code_hi > (uint_least32_t)HYST_CODE_MAX)) {
        st = HYST_ERR_DOMAIN;
    }
    if (st == HYST_OK) { /* the model's G in fixed point, for the marked intervals */
        hyst_wide_t range = 0;
        unsigned k;
        for (k = 1u; k <= f0->degree; ++k) {
            range += g[k];
        }
        memset(&q, 0, sizeof q);
        q.u.poly.degree = f0->degree;
        if (!(range > 0) || !hyst_q31_curve_(&q, g, f0->degree, range, 1)) {
            st = HYST_ERR_COEFF;
        }
    }
    /* 1..HYST_Q31_INV_MAX_INTERVALS in one unsigned compare (0 wraps) */
    if (st == HYST_OK &&
        (unsigned long)intervals - 1ul >= (unsigned long)HYST_Q31_INV_MAX_INTERVALS) {
        st = HYST_ERR_ARG;
    }
    if (st == HYST_OK) {
        st = hyst_check_memory(S, xltp, yltp, xrtp, yrtp, capacity, sizeof(hyst_q31_t),
                               sizeof(hyst_q31_t), layout);
    }
    if (st == HYST_OK) { /* the finest drive whose span stays within 2^28 */
        codes = code_hi - code_lo;
        while ((codes << (bits + 1u)) <= Q31_INV_SPAN) {
            ++bits;
        }
        st = q31_table(table, intervals, g, f0->degree, (hyst_q31_t)(codes << bits), &exact,
                       &max_err);
    }
    if (st != HYST_OK) {
        return st;
    }
    memset(inv, 0, sizeof *inv);
    inv->kind = HYST_CURVE_INV_TABLE;
    inv->variant = HYST_VARIANT_Q31_INV;
    inv->layout = HYST_LAYOUT;
    inv->lo.q31 = -Q31_INV_HALF;
    inv->hi.q31 = Q31_INV_HALF;
    inv->y_lo.q31 = 0;
    inv->y_hi.q31 = (hyst_q31_t)(codes << bits);
    inv->unit.q31 = 1;
    /* one branch evaluation, in drive units: the measured worst, rounded up */
    inv->rounding.q31 = (hyst_q31_t)(max_err * (hyst_wide_t)inv->y_hi.q31) + 1;
    inv->u.inv_table.fwd = q.u.poly;
    inv->u.inv_table.span.q31 = inv->y_hi.q31;
    inv->u.inv_table.table.q31 = table + 1;
    inv->u.inv_table.intervals = intervals;
    inv->u.inv_table.exact = exact;
    inv->u.inv_table.max_err = max_err;
    inv->u.inv_table.drive_bits = bits;
    inv->u.inv_table.drive_code_lo = code_lo;
    hyst_q31_inv_attach(S, inv, &hyst_q31_inv_ops_inv_table, inv->lo.q31, inv->hi.q31, inv->unit.q31, xltp, yltp, xrtp, yrtp,
                        capacity);
    return HYST_OK;
}

/* The deadband checks shared by the immediate call and the request. */
static hyst_status_t hyst_q31_inv_deadband_check(const hyst_tcm_t *S, hyst_q31_t width)
{
    if (S == NULL) {
        return HYST_ERR_NULL;
    }
    if (S->variant != (unsigned)HYST_VARIANT_Q31_INV || width < 0 ||
        width > S->hi.q31 - S->lo.q31) {
        return HYST_ERR_ARG;
    }
    return HYST_OK;
}

hyst_status_t hyst_q31_inv_set_deadband(hyst_tcm_t *S, hyst_q31_t width)
{
    const hyst_status_t st = hyst_q31_inv_deadband_check(S, width);
    if (st != HYST_OK) {
        return st;
    }
    hyst_q31_inv_bind_skip(S);
    S->deadband.q31 = width;
    hyst_q31_inv_set_detour(S);
    ++S->seq;
    return HYST_OK;
}

hyst_status_t hyst_q31_inv_request_deadband(hyst_tcm_t *S, hyst_q31_t width)
{
    const hyst_status_t st = hyst_q31_inv_deadband_check(S, width);
    if (st != HYST_OK) {
        return st;
    }
    hyst_q31_inv_bind_skip(S); /* before the counter, as the width */
    S->req_width.q31 = width; /* before the counter: the step reads it after */
    return hyst_post_request_(S, &S->req_deadband);
}

hyst_q31_t hyst_q31_inv_step(hyst_tcm_t *S, hyst_q31_t desired)
{
    return hyst_q31_inv_sample(S, desired);
}

hyst_status_t hyst_q31_inv_process(hyst_tcm_t *S, const hyst_q31_t *desired, hyst_q31_t *drive,
                                   size_t n)
{
    return hyst_q31_inv_block(S, desired, drive, n);
}

hyst_q31_t hyst_q31_inv_output(const hyst_tcm_t *S)
{
    return S != NULL ? hyst_q31_inv_view(S).y : 0;
}

hyst_q31_t hyst_q31_inv_input(const hyst_tcm_t *S)
{
    return S != NULL ? hyst_q31_inv_view(S).x : 0;
}

hyst_q31_t hyst_q31_inv_error_bound(const hyst_tcm_t *S)
{
    return S != NULL ? hyst_q31_inv_view(S).bound : 0;
}

unsigned hyst_q31_inv_drive_bits(const hyst_tcm_t *S)
{
    return S != NULL && S->variant == (unsigned)HYST_VARIANT_Q31_INV
               ? S->curve->u.inv_table.drive_bits
               : 0u;
}

uint_least32_t hyst_q31_inv_code(const hyst_tcm_t *S, hyst_q31_t drive)
{
    unsigned bits;
    if (S == NULL || S->variant != (unsigned)HYST_VARIANT_Q31_INV) {
        return 0u;
    }
    bits = S->curve->u.inv_table.drive_bits;
    drive = drive < 0 ? 0 : (drive > S->y_hi.q31 ? S->y_hi.q31 : drive);
    return S->curve->u.inv_table.drive_code_lo +
           (((uint_least32_t)drive + ((uint_least32_t)1 << bits >> 1)) >> bits);
}
