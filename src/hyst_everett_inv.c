/* SPDX-License-Identifier: MIT */
/* The asymmetric kind's compensators: the solved one's curve (the forward
 * curve's axes swapped, hyst_curve_inverse()) and the tabulated one (curve.h,
 * hyst_*_curve_everett_inverse_table()): rows of cubic pieces of the drive
 * step over the branch's output step, one row per anchor (the start of the
 * branch), for both directions; init measures the blend a branch makes of
 * four rows against the exact inverse. All in hyst_wide_t; the table is
 * stored in the variant's type. */
#include <string.h>

#include "hyst/curve.h"
#include "hyst_util.h"

#define EV_N HYST_EVERETT_MAX_DEGREE

/* Anchors and output steps probed per interval between two rows. */
#define BLEND_ANCHORS 4u
#define BLEND_PROBES 8u

/* Largest row and interval counts: the index s keeps its integer part exact
 * in float, and rows * intervals stays far from size_t's end. */
#define MAX_ROWS 4096ul
#define MAX_INTERVALS ((unsigned long)1 << 20)

/* A branch of the forward model, in the drive step w (0..1 of the span):
 * p(w) = w q(w), q's coefficients (highest power first) from the curve's
 * rows at the anchor, as the engine derives them (tcm_engine.h). */
typedef struct {
    unsigned n;
    hyst_wide_t q[EV_N];
    hyst_wide_t width; /* W: the drive step to the end of the domain */
    hyst_wide_t range; /* V = p(W) */
} branch_t;

static void branch_at(branch_t *b, const hyst_curve_t *c, int fall, hyst_wide_t anchor)
{
    const hyst_num_t *row = fall ? c->u.everett.fall : c->u.everett.rise;
    unsigned i, k, at = 0u;
    hyst_wide_t w = 0;
    b->n = c->u.everett.degree;
    for (i = 0u; i < b->n; ++i) { /* row i: i + 1 entries, anchor powers highest first */
        hyst_wide_t acc = 0;
        for (k = 0u; k <= i; ++k) {
            acc = acc * anchor + hyst_num_get(&row[at + k], c->variant);
        }
        b->q[i] = acc;
        at += i + 1u;
    }
    b->width = fall ? anchor : 1 - anchor;
    for (i = 0u; i < b->n; ++i) {
        w = w * b->width + b->q[i];
    }
    b->range = w * b->width;
}

/* p(w) and p'(w). */
static hyst_wide_t branch_p(const branch_t *b, hyst_wide_t w, hyst_wide_t *dp)
{
    hyst_wide_t q = 0, dq = 0;
    unsigned i;
    for (i = 0u; i < b->n; ++i) {
        dq = dq * w + q;
        q = q * w + b->q[i];
    }
    *dp = q + w * dq;
    return q * w;
}

/* The w in [0, W] with p(w) = v: Newton's iteration from `guess`, bisection
 * where a step would leave the bracket (p increases on it). */
static hyst_wide_t branch_solve(const branch_t *b, hyst_wide_t v, hyst_wide_t guess)
{
    const hyst_wide_t tiny = 4 * HYST_WIDE_EPS * b->width;
    hyst_wide_t lo = 0, hi = b->width;
    hyst_wide_t w = guess > 0 && guess < hi ? guess : hi / 2;
    unsigned it;
    if (!(v > 0)) {
        return 0;
    }
    if (!(v < b->range)) {
        return b->width;
    }
    for (it = 0u; it < 200u; ++it) {
        hyst_wide_t dp, next;
        const hyst_wide_t f = branch_p(b, w, &dp) - v;
        if (f > 0) {
            hi = w;
        } else {
            lo = w;
        }
        next = dp > 0 ? w - f / dp : lo - 1;
        if (!(next > lo && next < hi)) {
            next = lo + (hi - lo) / 2;
        }
        if (hyst_wide_abs(next - w) <= tiny || !(hi - lo > tiny)) {
            return next;
        }
        w = next;
    }
    return w;
}

/* Whether the w a solve would give for output step v (p(w) = v on [0, W],
 * 0 below, W above) is within dw of w, without solving: p increases on
 * [0, W], so that root is at least w - dw iff w - dw <= 0 or
 * p(w - dw) <= v, at most w + dw iff w + dw >= W or p(w + dw) >= v. Each
 * p within 8 units of rounding of its terms (Horner's scheme on the
 * coefficients' magnitudes): a root beyond dw by at most that rounding
 * over p' passes. */
static int within_of_root(const branch_t *b, hyst_wide_t v, hyst_wide_t w, hyst_wide_t dw)
{
    const hyst_wide_t eps = (hyst_wide_t)8 * HYST_WIDE_EPS;
    int side;
    if (!(dw >= 0)) {
        return 0;
    }
    for (side = 0; side < 2; ++side) {
        const hyst_wide_t at = side ? w + dw : w - dw;
        hyst_wide_t p, dp, m = 0;
        unsigned i;
        if (side ? at >= b->width : at <= 0) {
            continue;
        }
        for (i = 0u; i < b->n; ++i) {
            m = m * hyst_wide_abs(at) + hyst_wide_abs(b->q[i]);
        }
        p = branch_p(b, at, &dp);
        m = eps * hyst_wide_abs(at) * m + 8 * HYST_WIDE_MIN; /* and subnormal numbers */
        if (side ? !(p + m >= v) : !(p - m <= v)) {
            return 0;
        }
    }
    return 1;
}

/* V(a) = p_a(W(a)) as a polynomial in the anchor (degree n, highest power
 * first, into v[0..n]): each row's polynomial times W^(n - i), W = 1 - a
 * rising, a falling. */
static void range_poly(const hyst_curve_t *c, int fall, hyst_wide_t *v)
{
    const hyst_num_t *row = fall ? c->u.everett.fall : c->u.everett.rise;
    const unsigned n = c->u.everett.degree;
    hyst_wide_t acc[EV_N + 1]; /* acc[m]: coefficient of a^m */
    unsigned i, k, m, at = 0u;
    memset(acc, 0, sizeof acc);
    for (i = 0u; i < n; ++i) {
        const unsigned power = n - i; /* of W */
        hyst_wide_t wp[EV_N + 1];     /* W^power in a */
        memset(wp, 0, sizeof wp);
        wp[0] = 1;
        for (k = 0u; k < power; ++k) { /* times (1 - a) or a */
            for (m = k + 1u; m > 0u; --m) {
                wp[m] = fall ? wp[m - 1u] : wp[m] - wp[m - 1u];
            }
            wp[0] = fall ? 0 : wp[0];
        }
        for (k = 0u; k <= i; ++k) { /* the row's entry of a^(i - k) */
            const hyst_wide_t r = hyst_num_get(&row[at + k], c->variant);
            for (m = 0u; m <= power; ++m) {
                acc[m + i - k] += r * wp[m];
            }
        }
        at += i + 1u;
    }
    for (m = 0u; m <= n; ++m) {
        v[m] = acc[n - m];
    }
}

/* The build: the curve, its table, one direction's rows. */
typedef struct {
    hyst_curve_t *c;
    hyst_ptr_t table; /* written by a build */
    hyst_cptr_t view; /* read: the same table */
    size_t rows, intervals, row_len;
    hyst_wide_t span, inv_span, eps, worst;
} build_t;

static size_t row_at(const build_t *b, int fall, size_t r)
{
    return ((size_t)(fall ? b->rows + 1u : 0u) + r) * b->row_len;
}

/* V(a) as the engine evaluates it: the stored polynomial. */
static hyst_wide_t range_at(const build_t *b, int fall, hyst_wide_t a)
{
    const hyst_num_t *v = b->c->u.everett.v_end[fall ? 1 : 0];
    hyst_wide_t acc = 0;
    unsigned m;
    for (m = 0u; m <= b->c->u.everett.degree; ++m) {
        acc = acc * a + hyst_num_get(&v[m], b->c->variant);
    }
    return acc;
}

/* Row r: the exact drive step at the knots s = k (output step k V / N),
 * slopes limited as Fritsch and Carlson do, cubic Hermite pieces; entry N
 * the end of the branch. A row whose branch is empty (W or V not above 0)
 * is all zeros: no drive step. */
static void fill_row(build_t *b, int fall, size_t r)
{
    const hyst_wide_t a = (hyst_wide_t)r / (hyst_wide_t)b->rows;
    const size_t base = row_at(b, fall, r), n = b->intervals;
    const hyst_wide_t range = range_at(b, fall, a);
    branch_t br;
    hyst_wide_t d_prev = 0, m_prev = 0, w = 0;
    size_t k;
    unsigned i;
    branch_at(&br, b->c, fall, a);
    if (!(br.width > 0) || !(range > 0)) {
        for (k = 0u; k < b->row_len; ++k) {
            (void)hyst_table_put_(b->table, base + k, b->c->variant, 0);
        }
        return;
    }
    for (k = 0u; k <= n; ++k) {
        const hyst_wide_t v = (hyst_wide_t)k * range / (hyst_wide_t)n;
        const hyst_wide_t w_prev = w;
        hyst_wide_t dp, d, m;
        w = branch_solve(&br, v, w);
        /* knots never fall (a table from flash is checked for it): where
         * p's rounding is coarser than the step between two knots' outputs,
         * p is flat there and the solver may stop anywhere on it */
        w = w < w_prev ? w_prev : w;
        (void)branch_p(&br, w, &dp);
        d = w * b->span;
        m = dp > 0 ? range / (hyst_wide_t)n * b->span / dp : -1; /* -1: infinite */
        if (k > 0u) {
            const hyst_wide_t sec = 3 * (d - d_prev);
            hyst_wide_t m0 = m_prev, m1 = m, c[4];
            /* Fritsch-Carlson on both ends of the piece (each slope also
             * limited by its other secant as the next piece takes it) */
            m0 = m0 < 0 || m0 > sec ? sec : m0;
            m1 = m1 < 0 || m1 > sec ? sec : m1;
            c[0] = d_prev;
            c[1] = m0;
            c[2] = 3 * (d - d_prev) - 2 * m0 - m1;
            c[3] = m0 + m1 - 2 * (d - d_prev);
            for (i = 0u; i < 4u; ++i) {
                (void)hyst_table_put_(b->table, base + 4u * (k - 1u) + i, b->c->variant, c[i]);
            }
        }
        d_prev = d;
        m_prev = m;
    }
    (void)hyst_table_put_(b->table, base + 4u * n, b->c->variant, br.width * b->span);
    for (i = 1u; i < 4u; ++i) {
        (void)hyst_table_put_(b->table, base + 4u * n + i, b->c->variant, 0);
    }
}

/* The four rows a branch at anchor a blends and their weights, as the
 * engine derives them (tcm_engine.h, derive_blend()): cubic Lagrange on the
 * rows base .. base + 3 around a rows. Returns base. */
static size_t blend_weights(size_t rows, hyst_wide_t x, hyst_wide_t *l)
{
    size_t j = (size_t)x, base;
    j = j > rows - 1u ? rows - 1u : j;
    base = j < 1u ? 0u : (j - 1u > rows - 3u ? rows - 3u : j - 1u);
    x -= (hyst_wide_t)base;
    l[0] = -(x - 1) * (x - 2) * (x - 3) / 6;
    l[1] = x * (x - 2) * (x - 3) / 2;
    l[2] = -x * (x - 1) * (x - 3) / 2;
    l[3] = x * (x - 1) * (x - 2) / 6;
    return base;
}

static hyst_wide_t entry(const build_t *b, size_t i)
{
#if HYST_ENABLE_F64
    if (b->c->variant == (unsigned)HYST_VARIANT_F64) {
        return (hyst_wide_t)b->view.f64[i];
    }
#endif
    return (hyst_wide_t)b->view.f32[i];
}

/* An anchor x (in rows) of a direction, as measure_at() takes it: its
 * branch and V, the four rows blended there and their weights. */
typedef struct {
    branch_t br;
    hyst_wide_t range, index_scale, l[4]; /* index_scale: intervals / V */
    size_t base;
} anchor_t;

static void anchor_at(anchor_t *an, const build_t *b, int fall, hyst_wide_t x)
{
    const hyst_wide_t a = x / (hyst_wide_t)b->rows;
    an->base = blend_weights(b->rows, x, an->l);
    branch_at(&an->br, b->c, fall, a);
    an->range = range_at(b, fall, a);
    an->index_scale = (hyst_wide_t)b->intervals / an->range;
}

/* Interval k at an anchor, against the exact inverse, at BLEND_PROBES
 * points: the blend's drive d at the point is taken as exact for its
 * output step v = p(d) (one evaluation of the branch, no solve), and the
 * blend evaluated where the sample would for v; where v falls outside the
 * interval (the blend is off by more than the interval is wide), the
 * blend's d against the branch solved at the point's own output step.
 * Skipping those instead hid the error when few rows were blended (3 rows,
 * 16 384 intervals: 94 times the error reported). Plus a bound on the
 * rounding of the sample's arithmetic in the variant's type: the weights
 * (5 eps of each product) and the blend's four products and three sums
 * (4 eps), the cubic's (4 eps of its terms), the anchor's and the index's
 * (2 eps of the span each). Returns the worst error (drive units), 0 at an
 * empty branch (no drive step). `solve` 0: no solve off the interval, the
 * point's error bounded instead (within_of_root()): 0 if within what the
 * build accepts, else HYST_WIDE_MAX. */
static hyst_wide_t measure_at(const build_t *b, int fall, const anchor_t *an, size_t k, int solve)
{
    const branch_t *br = &an->br;
    const hyst_wide_t range = an->range;
    hyst_wide_t c[4], mag = 0, terms = 0, worst = 0, end, allowance;
    unsigned ip, i, q;
    for (i = 0u; i < 4u; ++i) {
        c[i] = 0;
        for (q = 0u; q < 4u; ++q) {
            const hyst_wide_t e = entry(b, row_at(b, fall, an->base + q) + 4u * k + i);
            c[i] += an->l[q] * e;
            mag += hyst_wide_abs(an->l[q] * e);
        }
        terms += hyst_wide_abs(c[i]);
    }
    if (!(range > 0) || !(br->width > 0)) { /* an empty branch: no drive step */
        return 0;
    }
    end = br->width * b->span;
    allowance = b->eps * (9 * mag + 4 * terms + 4 * b->span);
    for (ip = 0u; ip < BLEND_PROBES; ++ip) {
        const hyst_wide_t t = ((hyst_wide_t)ip + (hyst_wide_t)0.5) / (hyst_wide_t)BLEND_PROBES;
        hyst_wide_t d = c[0] + t * (c[1] + t * (c[2] + t * c[3])), dp, s, err;
        d = d < 0 ? 0 : (d > end ? end : d);
        s = branch_p(br, d * b->inv_span, &dp) * an->index_scale;
        if (s >= (hyst_wide_t)k && s < (hyst_wide_t)k + 1) {
            /* d is exact for its output, which falls in this interval: the
             * blend where the sample evaluates it (one evaluation) */
            s -= (hyst_wide_t)k;
            err = hyst_wide_abs(c[0] + s * (c[1] + s * (c[2] + s * c[3])) - d);
        } else { /* off its interval: against the branch solved at this output step */
            const hyst_wide_t v = ((hyst_wide_t)k + t) * range / (hyst_wide_t)b->intervals;
            if (solve) {
                err = hyst_wide_abs(d - b->span * branch_solve(br, v, d / b->span));
            } else if (within_of_root(br, v, d / b->span,
                                      ((hyst_wide_t)HYST_INV_TABLE_TOL * b->span - allowance) /
                                          b->span)) {
                err = 0;
            } else {
                return HYST_WIDE_MAX;
            }
        }
        worst = err > worst ? err : worst;
    }
    return worst + allowance;
}

/* The anchor ia (0 .. BLEND_ANCHORS - 1) between rows r and r + 1. */
static hyst_wide_t anchor_x(size_t r, unsigned ia)
{
    return (hyst_wide_t)r + (hyst_wide_t)ia / (hyst_wide_t)BLEND_ANCHORS;
}

/* Interval k between rows r and r + 1 of a direction, at BLEND_ANCHORS
 * anchors, r itself among them: the worst error (measure_at()). */
static hyst_wide_t measure(const build_t *b, int fall, size_t r, size_t k)
{
    hyst_wide_t worst = 0;
    unsigned ia;
    for (ia = 0u; ia < BLEND_ANCHORS; ++ia) {
        anchor_t an;
        hyst_wide_t err;
        anchor_at(&an, b, fall, anchor_x(r, ia));
        err = measure_at(b, fall, &an, k, 1);
        worst = err > worst ? err : worst;
    }
    return worst;
}

/* Marks interval k of every row of a direction for Newton's iteration: the
 * blend of any four rows there is then -1 (the weights sum to 1). */
static void mark(build_t *b, int fall, size_t k)
{
    size_t r;
    unsigned i;
    for (r = 0u; r <= b->rows; ++r) {
        for (i = 0u; i < 4u; ++i) {
            (void)hyst_table_put_(b->table, row_at(b, fall, r) + 4u * k + i, b->c->variant,
                                  i == 0u ? -1 : 0);
        }
    }
    ++b->c->u.everett.exact;
}

static void fill_direction(build_t *b, int fall)
{
    size_t r, k;
    for (r = 0u; r <= b->rows; ++r) {
        fill_row(b, fall, r);
    }
    for (k = 0u; k < b->intervals; ++k) {
        hyst_wide_t worst = 0;
        for (r = 0u; r < b->rows; ++r) {
            const hyst_wide_t err = measure(b, fall, r, k);
            worst = err > worst ? err : worst;
        }
        if (!(worst <= (hyst_wide_t)HYST_INV_TABLE_TOL * b->span)) {
            mark(b, fall, k);
        } else if (worst > b->worst) {
            b->worst = worst;
        }
    }
}

/* Counts in range; functions, not inline compares: where size_t is 16 bits
 * the upper tests are always true (-Wtype-limits). */
static int rows_ok(unsigned long n) { return n >= 3ul && n <= MAX_ROWS; }
static int intervals_ok(unsigned long n) { return n >= 1ul && n <= MAX_INTERVALS; }

/* The engine's least output step of a branch, (y_hi - y_lo) intervals 2^-30
 * (kind_everett_inv_table.h, blend_attach()), and the index scale it bounds, intervals /
 * least: normal and finite in the variant's type (with a factor 2 for the
 * type's rounding), else a slow sample's interval index could overflow
 * (desired outputs spanning a few subnormal numbers). */
static int index_scale_ok(const hyst_curve_t *inv, size_t intervals)
{
    const unsigned variant = inv->variant;
    const hyst_wide_t n = (hyst_wide_t)intervals;
    const hyst_wide_t least =
        (hyst_num_get(&inv->hi, variant) - hyst_num_get(&inv->lo, variant)) *
        (n * (hyst_wide_t)HYST_BLEND_LEAST_STEP);
    const int f32 = variant == (unsigned)HYST_VARIANT_F32;
    const hyst_wide_t min = f32 ? (hyst_wide_t)FLT_MIN : HYST_WIDE_MIN;
    const hyst_wide_t max = f32 ? (hyst_wide_t)FLT_MAX : HYST_WIDE_MAX;
    return least >= 2 * min && n / least <= max / 2;
}

/* The asymmetric kind and its solved compensator, into each other: the
 * axes swapped, the tables stay (the compensator solves the forward
 * branches). Newton's tolerance: 2^-20 of the drive span in float, 2^-40 in
 * double, well above the rounding of a branch evaluation divided by a
 * moderate slope, so that steps reach it. */
hyst_status_t hyst_everett_inverse_(hyst_curve_t *inv, const hyst_curve_t *fwd)
{
    const int to_inverse = fwd->kind == (unsigned)HYST_CURVE_EVERETT;
    const unsigned v = fwd->variant;
    const hyst_wide_t tol = v == (unsigned)HYST_VARIANT_F32
                                ? (hyst_wide_t)9.5367431640625e-7
                                : (hyst_wide_t)9.094947017729282379150390625e-13;
    hyst_curve_t out;
    hyst_curve_swap_axes_(&out, fwd);
    out.u.everett.table.f32 = NULL; /* the forward curve and the solved inverse have none */
    if (!(hyst_num_get(&out.hi, v) > hyst_num_get(&out.lo, v))) {
        return HYST_ERR_NOT_INVERTIBLE;
    }
    out.kind = to_inverse ? HYST_CURVE_EVERETT_INV : HYST_CURVE_EVERETT;
    /* the inverse takes the desired output step itself; the forward w */
    (void)hyst_num_set(&out.unit, v, to_inverse ? 1 : hyst_num_get(&out.u.everett.inv_span, v));
    (void)hyst_num_set(&out.u.everett.tol, v, to_inverse ? tol : 0);
    /* one solve's error, in the drive: about tol of its span */
    out.rounding = out.u.everett.branch_rounding;
    if (to_inverse) {
        (void)hyst_num_set(&out.rounding, v, 2 * tol * hyst_num_get(&out.u.everett.span, v));
    }
    *inv = out;
    return HYST_OK;
}

/* Everything of the table's curve but its numbers, and the build's state:
 * the checks both constructors make, then the solved compensator's curve
 * (the solved intervals' numbers) with the table's kind, shape and V(a). */
static hyst_status_t prepare(hyst_curve_t *out, build_t *b, const hyst_curve_t *inv,
                             const hyst_curve_t *fwd, hyst_cptr_t table, size_t rows,
                             size_t intervals, unsigned variant)
{
    unsigned m;
    int dir;
    hyst_status_t st = hyst_curve_check(fwd);
    if (inv == NULL || table.f32 == NULL) {
        return HYST_ERR_NULL;
    }
    if (st != HYST_OK) {
        return st;
    }
    if (fwd->variant != variant) {
        return HYST_ERR_LAYOUT;
    }
    if (fwd->kind != (unsigned)HYST_CURVE_EVERETT || !rows_ok((unsigned long)rows) ||
        !intervals_ok((unsigned long)intervals)) {
        return HYST_ERR_ARG;
    }
    st = hyst_everett_inverse_(out, fwd); /* HYST_CURVE_EVERETT_INV: the solved intervals' */
    if (st != HYST_OK) {
        return st;
    }
    if (!index_scale_ok(out, intervals)) {
        return HYST_ERR_ILL_CONDITIONED;
    }
    out->kind = HYST_CURVE_EVERETT_INV_TABLE;
    out->u.everett.table = table;
    out->u.everett.rows = rows;
    out->u.everett.intervals = intervals;
    out->u.everett.exact = 0u;
    for (dir = 0; dir < 2; ++dir) {
        hyst_wide_t v[EV_N + 1];
        range_poly(fwd, dir, v);
        for (m = 0u; m <= (unsigned)EV_N; ++m) {
            (void)hyst_num_set(&out->u.everett.v_end[dir][m], variant,
                               m <= fwd->u.everett.degree ? v[m] : 0);
        }
    }
    memset(b, 0, sizeof *b);
    b->c = out;
    b->view = table;
    b->rows = rows;
    b->intervals = intervals;
    b->row_len = HYST_INV_TABLE_LEN(intervals);
    b->span = hyst_num_get(&out->u.everett.span, variant);
    b->inv_span = 1 / b->span;
    b->eps = hyst_real_eps(variant);
    return HYST_OK;
}

/* The measured error into the curve, as a seal keeps it (both constructors
 * give the same curve), and one evaluation's error in the drive: the
 * table's, or a solve's. */
static void finish(hyst_curve_t *out, hyst_wide_t max_err, hyst_wide_t span)
{
    out->u.everett.max_err = max_err;
    if (max_err * span > hyst_num_get(&out->rounding, out->variant)) {
        (void)hyst_num_set(&out->rounding, out->variant, max_err * span);
    }
}

hyst_status_t hyst_curve_everett_inverse_table_(hyst_curve_t *inv, const hyst_curve_t *fwd,
                                                hyst_ptr_t table, size_t rows, size_t intervals,
                                                unsigned variant)
{
    hyst_curve_t out;
    build_t b;
    const hyst_cptr_t view = hyst_cptr_of(table, variant);
    hyst_status_t st;
    st = prepare(&out, &b, inv, fwd, view, rows, intervals, variant);
    if (st != HYST_OK) {
        return st;
    }
    b.table = table;
    fill_direction(&b, 0);
    fill_direction(&b, 1);
    finish(&out, hyst_table_err_((b.worst + hyst_drive_rounding_(&out)) / b.span), b.span);
    *inv = out;
    return HYST_OK;
}

/* The model at a knot of a row as fill_row() takes it: the knot's drive
 * step d at output step v, within dw of the build's (in w), and what
 * fill_row() computes its slope from there, p'(w), known within dp[0] ..
 * dp[1]. 0 if d is off the branch: p(d) must give v back (at the branch's
 * end where v is beyond p(W), as the solver stops there) within 8 units of
 * rounding of p's terms and of the drive step plus the width, and of
 * subnormal numbers (a residual, not the root solved again: where the root
 * is ill-conditioned, two solvers stop at different numbers). p' is known
 * within dw times a bound on p'' and 8 units of rounding of its terms in
 * each of the two evaluations (the build's and this one). Horner's scheme
 * on p and p', and on the coefficients' magnitudes at |w| + dw (bounds on
 * the rounding, and on p'' anywhere within dw of w). */
static int knot_model(const build_t *b, const branch_t *br, hyst_wide_t d, hyst_wide_t v,
                      hyst_wide_t dw, hyst_wide_t inv_span, hyst_wide_t *dp)
{
    const hyst_wide_t w = d * inv_span, x = hyst_wide_abs(w) + dw;
    const hyst_wide_t tiny = hyst_real_tiny(b->c->variant);
    /* q and q' at w; the magnitudes' polynomial m, m', m''/2 at x */
    hyst_wide_t q = br->q[0], dq = 0, m = hyst_wide_abs(q), dm = 0, ddm = 0;
    hyst_wide_t p, p1, change;
    unsigned i;
    for (i = 1u; i < br->n; ++i) {
        ddm = ddm * x + dm;
        dm = dm * x + m;
        m = m * x + hyst_wide_abs(br->q[i]);
        dq = dq * w + q;
        q = q * w + br->q[i];
    }
    p = q * w; /* p = w q */
    p1 = q + w * dq;
    v = v < br->range ? v : br->range;
    if (!(hyst_wide_abs(p - v) <= 8 * b->eps * (m * x + (w + br->width) * hyst_wide_abs(p1)) +
                                      8 * tiny * (1 + hyst_wide_abs(p1) * inv_span))) {
        return 0;
    }
    /* the bound on p'' is 2 m' + 2 x m''/2, on p''s terms m + x m' */
    change = 2 * (dm + x * ddm) * dw + 16 * b->eps * (m + x * dm);
    dp[0] = p1 - change;
    dp[1] = p1 + change;
    return 1;
}

/* A piece of a row as stored: its knots' drive steps, its slopes at both
 * ends, the rounding of its knots (tol, 8 units of its terms and of
 * subnormal numbers) and of its slopes (the same plus 8 units of four
 * secants: c2 and c3 are formed from terms up to four secants), and the
 * bounds of three times its secant as the build computed it (within six
 * knots' tol). */
typedef struct {
    hyst_wide_t start, end, slope[2], tol, slope_tol, sec_lo, sec_hi;
} piece_t;

/* Piece k of the row at base; 0 if it is solved instead. */
static int piece_of(const build_t *b, size_t base, size_t k, piece_t *p)
{
    const size_t at = base + 4u * k;
    const hyst_wide_t c0 = entry(b, at), c1 = entry(b, at + 1u);
    const hyst_wide_t c2 = entry(b, at + 2u), c3 = entry(b, at + 3u);
    const hyst_wide_t end = c0 + c1 + c2 + c3, sec = 3 * (end - c0);
    if (c0 < 0) {
        return 0;
    }
    p->start = c0;
    p->end = end;
    p->slope[0] = c1;
    p->slope[1] = c1 + 2 * c2 + 3 * c3;
    p->tol = 8 * b->eps *
                 (hyst_wide_abs(c0) + hyst_wide_abs(c1) + 2 * hyst_wide_abs(c2) +
                  3 * hyst_wide_abs(c3) + hyst_wide_abs(end)) +
             8 * hyst_real_tiny(b->c->variant);
    p->slope_tol = p->tol + 32 * b->eps * hyst_wide_abs(sec);
    p->sec_lo = sec - 6 * p->tol;
    p->sec_hi = sec + 6 * p->tol;
    return 1;
}

/* The slope at end `side` of piece p as fill_row() computes it, within its
 * rounding: m = per_interval / p' (infinite where p' <= 0), p' within
 * dp[0] .. dp[1], per_interval within per[0] .. per[1] (4 units for the
 * division and the products here), limited by three times p's secant
 * (Fritsch and Carlson). Compared as products, not quotients: a quotient
 * costs several products on a core without double. */
static int slope_matches(const piece_t *p, int side, const hyst_wide_t *per, const hyst_wide_t *dp)
{
    const hyst_wide_t lo = p->slope[side] + p->slope_tol, hi = p->slope[side] - p->slope_tol;
    /* lo >= min(m_lo, sec_lo), m_lo = per / dp[1] (infinite if dp[1] <= 0) */
    const int above = lo >= p->sec_lo || (dp[1] > 0 && lo * dp[1] >= per[0]);
    /* hi <= min(m_hi, sec_hi), m_hi = per / dp[0] (infinite if dp[0] <= 0) */
    const int below = hi <= p->sec_hi && (!(dp[0] > 0) || hi * dp[0] <= per[1]);
    return above && below;
}

/* The pieces of a row as fill_row() writes them (the seal's claim: these
 * are the build's pieces, and the build measured them), one rule at every
 * knot k (output step k V / N) next to a piece not solved instead: the
 * knot on the branch and the slope of each piece there fill_row()'s, the
 * model's slope limited by that piece's secant (knot_model(),
 * slope_matches()); where pieces meet, the one before ends at the start of
 * the one after. The knot's drive step is the start of the piece after it,
 * where none is stored the end of the piece before. A piece changed and
 * sealed again breaks one of these, a slope changed alike on both sides of
 * a knot too. One evaluation of the model per knot: no piece measured
 * again. */
static int row_structured(const build_t *b, const branch_t *br, size_t base, hyst_wide_t range)
{
    const size_t n = b->intervals;
    const hyst_wide_t per_interval = range / (hyst_wide_t)n * b->span; /* as fill_row() */
    const hyst_wide_t per[2] = {per_interval * (1 - 4 * b->eps), per_interval * (1 + 4 * b->eps)};
    const hyst_wide_t inv_span = 1 / b->span, v_step = range / (hyst_wide_t)n;
    piece_t before, after;
    int has_before = 0;
    size_t k;
    memset(&before, 0, sizeof before);
    for (k = 0u; k <= n; ++k) {
        const int has_after = k < n && piece_of(b, base, k, &after);
        hyst_wide_t dp[2], d, tol;
        if (has_before && has_after) {
            d = after.start;
            tol = before.tol > after.tol ? before.tol : after.tol;
            if (!(hyst_wide_abs(before.end - d) <= before.tol)) {
                return 0;
            }
        } else if (has_after || has_before) {
            d = has_after ? after.start : before.end;
            tol = has_after ? after.tol : before.tol;
        } else {
            continue;
        }
        /* d within tol of the build's knot, w = d / span within 2 units more
         * (the product by inv_span); v within 2 units of fill_row()'s k V / N */
        if (!knot_model(b, br, d, (hyst_wide_t)k * v_step,
                        (tol + 2 * b->eps * hyst_wide_abs(d)) * inv_span, inv_span, dp) ||
            (has_before && !slope_matches(&before, 1, per, dp)) ||
            (has_after && !slope_matches(&after, 0, per, dp))) {
            return 0;
        }
        if (has_after) {
            before = after;
        }
        has_before = has_after;
    }
    return 1;
}

/* Every interval held as pieces measured as the build measures it, at
 * the same anchors and points (measure_at(), no solve): within
 * HYST_INV_TABLE_TOL of the drive range, as the build keeps an interval
 * only then. No fewer points will do: the build solves an interval where
 * any of them misses, and one point misses alone (most solved intervals of
 * random E miss only between rows). Each anchor derived once for all its
 * intervals. */
static int pieces_measured(const build_t *b, int fall)
{
    const hyst_wide_t tol = (hyst_wide_t)HYST_INV_TABLE_TOL * b->span;
    size_t r, k;
    unsigned ia;
    for (r = 0u; r < b->rows; ++r) {
        for (ia = 0u; ia < BLEND_ANCHORS; ++ia) {
            anchor_t an;
            anchor_at(&an, b, fall, anchor_x(r, ia));
            for (k = 0u; k < b->intervals; ++k) {
                if (entry(b, row_at(b, fall, 0u) + 4u * k) >= 0 && /* not solved */
                    !(measure_at(b, fall, &an, k, 0) <= tol)) {
                    return 0;
                }
            }
        }
    }
    return 1;
}

/* A direction of a table given ready-made, against the model: in every
 * row, numbers finite and knots rising to the end (the drive steps the
 * build stores: hyst_table_shape_ok_()); an interval solved instead in one
 * row is so in every row (counted as the build counts them); each row's
 * end is the branch's whole drive step (within 8 units of the variant's
 * rounding, of the span), and its pieces the build's (row_structured(); a
 * row whose branch is empty is all zeros). 0 if it is another model's
 * table, or pieces changed. */
static int direction_matches(build_t *b, int fall)
{
    const hyst_wide_t tol = 8 * b->eps * b->span;
    const size_t n = b->intervals;
    size_t r, k;
    for (r = 0u; r <= b->rows; ++r) {
        if (!hyst_table_shape_ok_(b->view, row_at(b, fall, r), n, b->c->variant)) {
            return 0;
        }
    }
    for (k = 0u; k < n; ++k) {
        const int solved = entry(b, row_at(b, fall, 0u) + 4u * k) < 0;
        for (r = 1u; r <= b->rows; ++r) {
            if ((entry(b, row_at(b, fall, r) + 4u * k) < 0) != solved) {
                return 0;
            }
        }
        b->c->u.everett.exact += solved ? 1u : 0u;
    }
    for (r = 0u; r <= b->rows; ++r) {
        const hyst_wide_t a = (hyst_wide_t)r / (hyst_wide_t)b->rows;
        const hyst_wide_t range = range_at(b, fall, a);
        const size_t base = row_at(b, fall, r);
        branch_t br;
        int empty;
        branch_at(&br, b->c, fall, a);
        empty = !(br.width > 0) || !(range > 0); /* all zeros (fill_row()) */
        if (!(hyst_wide_abs(entry(b, base + 4u * n) - (empty ? 0 : br.width * b->span)) <= tol)) {
            return 0;
        }
        for (k = 0u; empty && k < n; ++k) {
            if (!(entry(b, base + 4u * k) <= tol)) { /* or the mark */
                return 0;
            }
        }
        if (!empty && !row_structured(b, &br, base, range)) {
            return 0;
        }
    }
    return pieces_measured(b, fall);
}

hyst_status_t hyst_curve_everett_inverse_table_const_(hyst_curve_t *inv, const hyst_curve_t *fwd,
                                                      hyst_cptr_t table, size_t rows,
                                                      size_t intervals,
                                                      const hyst_table_seal_t *seal,
                                                      unsigned variant)
{
    hyst_curve_t out;
    build_t b;
    hyst_status_t st = seal == NULL ? HYST_ERR_NULL
                                    : prepare(&out, &b, inv, fwd, table, rows, intervals, variant);
    if (st == HYST_OK) {
        st = hyst_table_seal_check_((unsigned)HYST_CURVE_EVERETT_INV_TABLE, variant, table, rows,
                                    intervals, seal);
    }
    if (st != HYST_OK) {
        return st;
    }
    /* what the seal claims: the build's pieces of this model's branches,
     * which the build measured (the checksum covers every number) */
    if (!direction_matches(&b, 0) || !direction_matches(&b, 1)) {
        return HYST_ERR_CURVE;
    }
    finish(&out, seal->max_err, b.span);
    *inv = out;
    return HYST_OK;
}
