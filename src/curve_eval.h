/* SPDX-License-Identifier: MIT */
/* The curve kinds evaluated out of line, and the piecewise-linear
 * constructor, in one real type: needs a number type descriptor and
 * src/num_ops.h. Instantiated by src/variant_real.h (f32, f64); the code
 * variant calls the f32 copy.
 *
 * Inverted polynomial: g(d) = G(d / span), G(u) = u (a[0] u^(n-1) + ... +
 * a[n-1]) on u in [0, 1], G(0) = 0, G(1) = R = f0(hi) - f0(lo). g^-1(e)
 * solves G(u) = e:
 *  1. start: G^-1 is tabulated at init at e_k = k R / K (K = HYST_INV_KNOTS,
 *     src/hyst_curve.c), so e in [e_j, e_j+1] gives the bracket [u_j, u_j+1];
 *  2. at most 2 HYST_INV_MAX_ITER bisections of it, each one evaluation of
 *     G, fewer once a parabola fits to rounding;
 *  3. inverse quadratic interpolation in the last bracket.
 * Bisection, not Newton: its answer is monotone in e (proof at poly_inv_g),
 * and a flat point of f0 (G' = 0) costs it nothing. */
#ifndef HYST_CURVE_EVAL_H
#define HYST_CURVE_EVAL_H

#ifndef HYST_NUM_OPS_H
#error "curve_eval.h: include src/num_ops.h first"
#endif

#include <limits.h>
#include <string.h>

#include "hyst_util.h"

/* Finite and strictly increasing? */
static int NUM_NAME(strictly_increasing)(const NUM_T *v, size_t n)
{
    size_t i;
    for (i = 0u; i < n; ++i) {
        if (!NUM_NAME(is_finite)(v[i]) || (i > 0u && !(v[i] > v[i - 1u]))) {
            return 0;
        }
    }
    return 1;
}

/* b - a finite in NUM_T, where interpolation computes the differences. */
static int NUM_NAME(span_is_finite)(NUM_T a, NUM_T b)
{
    const NUM_T d = b - a;
    return NUM_NAME(is_finite)(d);
}

static hyst_status_t NUM_NAME(curve_from_pwl_impl)(hyst_curve_t *curve, const NUM_T *x, const NUM_T *y,
                                       size_t n, unsigned long layout)
{
    hyst_curve_t out;
    size_t i;
    memset(&out, 0, sizeof out);
    if (curve == NULL || x == NULL || y == NULL) {
        return HYST_ERR_NULL;
    }
    if (layout != HYST_LAYOUT) {
        return HYST_ERR_LAYOUT;
    }
    if (n < 2u) {
        return HYST_ERR_ARG;
    }
    if (!NUM_NAME(strictly_increasing)(x, n) || !NUM_NAME(span_is_finite)(x[0], x[n - 1u])) {
        return HYST_ERR_BREAKPOINTS;
    }
    for (i = 0u; i < n; ++i) {
        if (!NUM_NAME(is_finite)(y[i])) {
            return HYST_ERR_COEFF;
        }
    }
    /* The value span bounds every segment's rise, as the breakpoint span
     * its width: then interpolation cannot overflow (the inverse swaps them). */
    if (!NUM_NAME(span_is_finite)(y[0], y[n - 1u])) {
        return HYST_ERR_COEFF;
    }
    for (i = 1u; i < n; ++i) {
        if (y[i] < y[i - 1u]) {
            return HYST_ERR_NOT_INCREASING;
        }
    }
    if (!(y[n - 1u] > y[0])) {
        return HYST_ERR_NOT_INCREASING;
    }
    out.kind = HYST_CURVE_PWL;
    out.variant = NUM_VARIANT;
    out.layout = HYST_LAYOUT;
    out.lo.NUM_F = x[0];
    out.hi.NUM_F = x[n - 1u];
    out.y_lo.NUM_F = y[0];
    out.y_hi.NUM_F = y[n - 1u];
    out.unit.NUM_F = 1; /* g takes d itself: exact at the breakpoints */
    out.u.pwl.x.NUM_F = x;
    out.u.pwl.y.NUM_F = y;
    out.u.pwl.n = n;
    *curve = out;
    return HYST_OK;
}

/* Largest k in [0, n-2] with px[k] <= x (binary search over px[1..n-2]). */
static size_t NUM_NAME(segment_of)(const NUM_T *px, size_t n, NUM_T x)
{
    size_t first = 1u;
    size_t count = n - 2u;
    while (count > 0u) {
        const size_t half = count / 2u;
        if (px[first + half] <= x) {
            first += half + 1u;
            count -= half + 1u;
        } else {
            count = half;
        }
    }
    return first - 1u;
}

static NUM_T NUM_NAME(pwl_eval)(const hyst_curve_t *curve, NUM_T x)
{
    const NUM_T *px = curve->u.pwl.x.NUM_F;
    const NUM_T *py = curve->u.pwl.y.NUM_F;
    size_t k;
    x = x < curve->lo.NUM_F ? curve->lo.NUM_F : (x > curve->hi.NUM_F ? curve->hi.NUM_F : x);
    k = NUM_NAME(segment_of)(px, curve->u.pwl.n, x);
    /* The fraction first, t in [0, 1]: t * dy can neither overflow (dy is
     * finite, see the span checks) nor underflow where (x - x_k) dy would.
     * Exact at every breakpoint: there t is 0. */
    return py[k] + (x - px[k]) / (px[k + 1u] - px[k]) * (py[k + 1u] - py[k]);
}

/* Bisection levels per sample, at most: two per HYST_INV_MAX_ITER, each one
 * evaluation of G, as many multiply-adds as a Newton step's G and G'. */
#define LEVELS (2u * (unsigned)(HYST_INV_MAX_ITER))

/* Rounding unit of NUM_T: the early stop's target in u. */
#define REAL_EPS NUM_EPS

/* G(u) in NUM_T, as the samples see it. */
static NUM_T NUM_NAME(real_g)(const hyst_curve_t *c, NUM_T u)
{
    return NUM_NAME(horner)(c->u.poly_inv.fwd.a, c->u.poly_inv.fwd.degree, u);
}

static NUM_T NUM_NAME(pos)(NUM_T v) { return v > 0 ? v : 0; }

/* u(t) = u0 + side s (c1 + c2 s), s = max(0, side (t - t0)), c1, c2 >= 0:
 * every rounded operation is monotone, so u is non-decreasing in t. */
typedef struct {
    NUM_T u0, t0, c1, c2;
    int side; /* +1: from the left point, -1: from the right, 0: none */
} NUM_NAME(leaf_t);

/* The quadratic u(t) through three points, in the form above if its
 * coefficients allow (u' >= 0 at the end it is written from); else side 0.
 * Noise near a flat point or an overflow (NaN fails every test) give 0. */
static int NUM_NAME(fit_leaf)(NUM_NAME(leaf_t) *q, const NUM_T pu[3], const NUM_T pt[3])
{
    const NUM_T h1 = pt[1] - pt[0], h2 = pt[2] - pt[1];
    q->side = 0;
    if (h1 > 0 && h2 > 0) {
        const NUM_T d1 = (pu[1] - pu[0]) / h1, d2 = (pu[2] - pu[1]) / h2;
        const NUM_T cc = (d2 - d1) / (pt[2] - pt[0]);
        const NUM_T left = d1 - cc * h1, right = d2 + cc * h2; /* u' at t0, t2 */
        if (cc >= 0 && left >= 0) {
            q->u0 = pu[0];
            q->t0 = pt[0];
            q->c1 = left;
            q->c2 = cc;
            q->side = 1;
        } else if (cc < 0 && right >= 0) {
            q->u0 = pu[2];
            q->t0 = pt[2];
            q->c1 = right;
            q->c2 = -cc;
            q->side = -1;
        }
    }
    return q->side;
}

/* Division-free early-stop precheck: G's parabola through the parent's
 * points (0, 2h, 4h: the bracket's ta, tb and the third point to, on side
 * `from`) predicts the new point tm to REAL_EPS in u. */
static int NUM_NAME(cubic_small)(NUM_T ta, NUM_T tm, NUM_T tb, int from, NUM_T to,
                       NUM_T width)
{
    const NUM_T guess = from > 0 ? (3 * ta + 6 * tb - to) * NUM_C(0.125)
                                       : (6 * ta + 3 * tb - to) * NUM_C(0.125);
    return NUM_NAME(abs)(tm - guess) * width <= REAL_EPS * (tb - ta);
}

/* The early stop: the leaf's parabola u(t) predicts the parent's third
 * point (uo, to) to 16 REAL_EPS; in the child its error is ~1/60 of that.
 * q is left fitted if so, else side 0. */
static int NUM_NAME(leaf_predicts)(NUM_NAME(leaf_t) *q, const NUM_T pu[3], const NUM_T pt[3],
                         NUM_T uo, NUM_T to)
{
    if (NUM_NAME(fit_leaf)(q, pu, pt) != 0) {
        const NUM_T sg = (NUM_T)q->side * (to - q->t0);
        const NUM_T far = q->u0 + (NUM_T)q->side * (sg * (q->c1 + q->c2 * sg));
        if (NUM_NAME(abs)(uo - far) <= 16 * REAL_EPS) {
            return 1;
        }
    }
    q->side = 0;
    return 0;
}

/* The leaf's answer for t, in [ua, ub]: q if fitted (or fittable), else
 * linear between the ends (ta, ua), (tb, ub). Each branch is chosen by the
 * leaf alone and non-decreasing in t; NaN goes to ua. */
static NUM_T NUM_NAME(leaf_value)(NUM_NAME(leaf_t) *q, const NUM_T pu[3], const NUM_T pt[3],
                              NUM_T t, const NUM_T end[4])
{
    const NUM_T ua = end[0], ub = end[1], ta = end[2], tb = end[3];
    NUM_T r = ua;
    if (q->side != 0 || NUM_NAME(fit_leaf)(q, pu, pt) != 0) {
        const NUM_T s = NUM_NAME(pos)(q->side > 0 ? t - q->t0 : q->t0 - t);
        const NUM_T v = s * (q->c1 + q->c2 * s);
        r = q->side > 0 ? q->u0 + v : q->u0 - v;
    } else if (tb > ta) {
        r = ua + NUM_NAME(pos)(t - ta) * ((ub - ua) / (tb - ta));
    }
    r = r > ua ? r : ua;
    return r < ub ? r : ub;
}

/* g^-1(e) is non-decreasing in e, for every e, however G rounds (a Newton
 * iteration's is not: near a flat point it reversed by 1e-5 of the range).
 * Why: the answer comes from a decision tree. The knot cell j = floor(t),
 * t = e K / R, is non-decreasing in e and the cells are ordered (knot_u is).
 * In the cell every split point m = (a + b) / 2 depends on the path so far,
 * not on e, and each decision "tm < t" (tm = G(m) K / R) is monotone in e, as
 * rounding is. For e1 < e2 both paths agree up to the first split where they
 * differ; there e1 goes left and e2 right (the reverse needs tm < t1 and
 * t2 <= tm), and each answer stays in its own half: g^-1(e1) <= m <= g^-1(e2).
 * If they never differ, both end in the same leaf, whose function of t is
 * non-decreasing (leaf_t). Where the descent stops is also decided by the
 * path alone. (A Newton point depends on e itself: two e could stop on noisy
 * points on either side of each other.)
 * Accuracy: halvings of the knot cell, then inverse quadratic interpolation
 * through the last split's three points (error ~ width^3). The descent stops
 * early once that parabola predicts the parent's third point to 16 REAL_EPS
 * in u: in the leaf, at a quarter of the distance, it is ~60 times closer. */
static NUM_T NUM_NAME(poly_inv_g)(const hyst_curve_t *c, NUM_T e)
{
    const NUM_T t = e * c->u.poly_inv.knot_scale.NUM_F;
    NUM_T ua, ub, ta, tb, uo = 0, to = 0, r, pu[3], pt[3], end[4];
    NUM_NAME(leaf_t) q;
    unsigned j, lv, tries = 0u;
    int from = 0; /* side of the parent's third point (uo, to), 0: none */
    if (!(t > 0)) {
        return 0; /* g^-1(0) = 0 exactly; rounding below 0 clamped */
    }
    if (t >= (NUM_T)HYST_INV_KNOTS) {
        return c->u.poly_inv.span.NUM_F;
    }
    j = (unsigned)t;
    ua = c->u.poly_inv.knot_u[j].NUM_F;
    ub = c->u.poly_inv.knot_u[j + 1u].NUM_F;
    ta = (NUM_T)j; /* G K / R at the knots, by construction */
    tb = (NUM_T)(j + 1u);
    q.side = 0;
    for (lv = 0u; lv < LEVELS; ++lv) {
        const NUM_T m = (ua + ub) * NUM_C(0.5);
        NUM_T tm;
        int stop = 0;
        if (!(m > ua && m < ub)) {
            break; /* no real between: the leaf */
        }
        tm = NUM_NAME(real_g)(c, m) * c->u.poly_inv.knot_scale.NUM_F;
        /* on odd levels (half the cost where it fails, near flat points)
         * and at most twice (the divisions stay bounded) */
        if ((lv & 1u) != 0u && tries < 2u && tb > ta && NUM_NAME(cubic_small)(ta, tm, tb, from, to, ub - ua)) {
            pu[0] = ua;
            pu[1] = m;
            pu[2] = ub;
            pt[0] = ta;
            pt[1] = tm;
            pt[2] = tb;
            ++tries;
            stop = NUM_NAME(leaf_predicts)(&q, pu, pt, uo, to);
        }
        if (tm < t) {
            uo = ua;
            to = ta;
            from = -1; /* the third point is left of the new bracket */
            ua = m;
            ta = tm;
        } else {
            uo = ub;
            to = tb;
            from = 1;
            ub = m;
            tb = tm;
        }
        if (stop) {
            break;
        }
    }
    /* the last split's three points: the leaf's ends and the third one
     * (none if no split: h1 = 0 then, linear leaf) */
    pu[0] = from < 0 ? uo : ua;
    pu[1] = from < 0 ? ua : (from > 0 ? ub : ua);
    pu[2] = from > 0 ? uo : ub;
    pt[0] = from < 0 ? to : ta;
    pt[1] = from < 0 ? ta : (from > 0 ? tb : ta);
    pt[2] = from > 0 ? to : tb;
    end[0] = ua; /* in the leaf: monotone across leaves */
    end[1] = ub;
    end[2] = ta;
    end[3] = tb;
    r = NUM_NAME(leaf_value)(&q, pu, pt, t, end);
    return r * c->u.poly_inv.span.NUM_F;
}

/* An interval of a tabulated inverse marked exact (next to a flat point of
 * f0): bisection on G inside the bracket of the nearest knots the table
 * evaluates (the end of the range always does). Monotone in s, as
 * poly_inv_g: the bracket is the same for every s of a run of marked
 * intervals, each decision is monotone in s, and the answer is the
 * bracket's lower end. At most ~log2(span / ulp) evaluations of G.
 * floor(s) < N: the caller's table_g() read that interval, and interval N
 * (the end of the range) is never marked. G^-1(0) = 0 exactly, as
 * poly_inv_g (the last line): where G dips below 0 next to lo (within the
 * curve's rounding), the bisection moves a to where G is back at 0, and a
 * descent to y_lo would stop short of lo. */
static NUM_T NUM_NAME(table_exact)(const hyst_curve_t *c, NUM_T s)
{
    const NUM_T *tab = c->u.inv_table.table.NUM_F;
    const NUM_T u_per_d = c->u.inv_table.u_per_d.NUM_F, scale = c->unit.NUM_F;
    size_t lo = (size_t)(unsigned long)s, hi = lo + 1u;
    NUM_T a, b;
    unsigned it;
    while (lo > 0u && tab[4u * lo] < 0) {
        --lo;
    }
    while (hi < c->u.inv_table.intervals && tab[4u * hi] < 0) {
        ++hi;
    }
    a = lo > 0u ? tab[4u * lo] : 0; /* knot 0's drive: 0, marked or not */
    b = tab[4u * hi];
    for (it = 0u; it < 2u * (unsigned)(sizeof(NUM_T) * CHAR_BIT); ++it) {
        const NUM_T m = (a + b) * NUM_C(0.5);
        if (!(m > a && m < b)) {
            break;
        }
        if (NUM_NAME(horner)(c->u.inv_table.fwd.a, c->u.inv_table.fwd.degree, m * u_per_d) *
                scale < s) {
            a = m;
        } else {
            b = m;
        }
    }
    return s > 0 ? a : 0;
}

/* E(lo + w span, lo) of an asymmetric curve or its inverse: the branch
 * rising from A0. */
static NUM_T NUM_NAME(everett_from_lo)(const hyst_curve_t *curve, NUM_T w)
{
    const unsigned n = curve->u.everett.degree;
    NUM_T acc = 0;
    unsigned i, at = 0u;
    for (i = 0u; i < n; ++i) { /* row i ends with its anchor^0 entry */
        at += i + 1u;
        acc = acc * w + curve->u.everett.rise[at - 1u].NUM_F;
    }
    return acc * w;
}

/* G^-1 of a spline (its pieces sp: the curve's, or its tabulated
 * compensator's forward spline) at the output step e from lo: the lowest
 * input step where G reaches e. The last knot below e (the knots' G never
 * decrease), then the next knot if e is its G (a flat run starts there),
 * else its piece's cubic solved by Newton's iteration from the secant's
 * guess, kept inside the bracket that every evaluation narrows (its middle
 * where a step would leave it), until the cubic is within its rounding of
 * e: a few steps where the slope is not near 0, bisection's count at most.
 * G^-1(0) = 0 and G^-1(G(hi)) = hi - lo exactly, and the knots are exact. */
HYST_INLINE NUM_T NUM_NAME(spline_inv_g)(const hyst_curve_spline_t *sp, NUM_T e)
{
    const NUM_T *tab = sp->table.NUM_F;
    const size_t n = sp->intervals;
    const NUM_T h = sp->span.NUM_F / (NUM_T)n;
    const NUM_T *p;
    size_t k = 0u, top = n + 1u;
    NUM_T a = 0, b = 1, t, noise;
    unsigned it;
    if (!(e > 0)) {
        return 0;
    }
    while (top - k > 1u) { /* tab[4 k] < e <= tab[4 top] (top n + 1: beyond hi) */
        const size_t mid = k + (top - k) / 2u;
        if (tab[4u * mid] < e) {
            k = mid;
        } else {
            top = mid;
        }
    }
    if (k == n) {
        return sp->span.NUM_F;
    }
    p = tab + 4u * k;
    if (p[4] <= e) {
        return k + 1u == n ? sp->span.NUM_F : (NUM_T)(k + 1u) * h;
    }
    /* the cubic's evaluation errs by a few roundings of its terms: within
     * that of e, t is the answer (the iterates would wander about it) */
    noise = 4 * NUM_EPS *
            (p[4] + (p[1] < 0 ? -p[1] : p[1]) + (p[2] < 0 ? -p[2] : p[2]) + (p[3] < 0 ? -p[3] : p[3]));
    t = (e - p[0]) / (p[4] - p[0]); /* in (0, 1]: p[0] < e < p[4] */
    for (it = 0u; it < 2u * (unsigned)(sizeof(NUM_T) * CHAR_BIT); ++it) {
        const NUM_T f = NUM_CUBIC_(p[0], p[1], p[2], p[3], t) - e;
        NUM_T next;
        if (!(f > noise || f < -noise)) {
            break;
        }
        if (f < 0) {
            a = t;
        } else {
            b = t;
        }
        next = t - f / (p[1] + t * (2 * p[2] + 3 * p[3] * t)); /* NaN or off: bisect */
        if (!(next > a && next < b)) {
            next = (a + b) * NUM_C(0.5);
            if (!(next > a && next < b)) {
                t = a; /* the bracket is two neighbouring numbers */
                break;
            }
        }
        if (next == t) {
            break;
        }
        t = next;
    }
    return ((NUM_T)k + t) * h;
}

/* G of a spline's tabulated compensator at s (table intervals) off the
 * fast path: the table's cubic, or in an interval marked exact (next to a
 * knot of slope 0, or where the spline's change of curvature at a knot
 * bends G^-1 beyond a cubic) the solved compensator's G^-1 (spline_inv_g())
 * at the output step s / unit. */
NUM_T NUM_NAME(spline_table_g_)(const hyst_curve_t *curve, NUM_T s)
{
    const NUM_T v = NUM_NAME(table_g)(curve->u.inv_table.table.NUM_F, s);
    return v >= 0 ? v
                  : NUM_NAME(spline_inv_g)(&curve->u.inv_table.fwd_spline, s / curve->unit.NUM_F);
}

NUM_T NUM_NAME(spline_g_)(const hyst_curve_t *curve, NUM_T s)
{
    NUM_T v;
    if (curve->kind == (unsigned)HYST_CURVE_SPLINE_INV) {
        return NUM_NAME(spline_inv_g)(&curve->u.spline, s);
    }
    v = NUM_NAME(table_g)(curve->u.spline.table.NUM_F, s);
    return v > 0 ? v : 0; /* G >= 0: a piece rounded below its knot's 0 */
}

NUM_T NUM_NAME(inv_table_g_)(const hyst_curve_t *curve, NUM_T s)
{
    const NUM_T v = NUM_NAME(table_g)(curve->u.inv_table.table.NUM_F, s);
    return v >= 0 ? v : NUM_NAME(table_exact)(curve, s);
}

NUM_T NUM_NAME(curve_g_other_)(const hyst_curve_t *curve, NUM_T d)
{
    if (curve->kind == (unsigned)HYST_CURVE_POLY_INV) {
        return NUM_NAME(poly_inv_g)(curve, d);
    }
    if (curve->kind == (unsigned)HYST_CURVE_EVERETT) {
        return NUM_NAME(everett_from_lo)(curve, d * curve->unit.NUM_F);
    }
    if (curve->kind == (unsigned)HYST_CURVE_EVERETT_INV ||
        curve->kind == (unsigned)HYST_CURVE_EVERETT_INV_TABLE) { /* that branch's inverse, bisected */
        NUM_T a = 0, b = 1;
        unsigned it;
        for (it = 0u; it < 2u * (unsigned)(sizeof(NUM_T) * CHAR_BIT); ++it) {
            const NUM_T m = (a + b) * NUM_C(0.5);
            if (!(m > a && m < b)) {
                break;
            }
            if (NUM_NAME(everett_from_lo)(curve, m) < d) {
                a = m;
            } else {
                b = m;
            }
        }
        return a * curve->u.everett.span.NUM_F;
    }
    if (curve->kind == (unsigned)HYST_CURVE_INV_TABLE) { /* d is s here */
        return NUM_NAME(inv_table_g_)(curve, d);
    }
    /* PWL, PWL_INV: the difference of two interpolations; exactly 0 at d = 0 */
    return NUM_NAME(pwl_eval)(curve, curve->lo.NUM_F + d) - curve->y_lo.NUM_F;
}

/* E(lo + d, lo) of a grid curve (src/kind_everett_grid.h: the branch
 * rising from lo, its TP in interval 0). */
static NUM_T NUM_NAME(everett_grid_from_lo)(const hyst_curve_t *curve, NUM_T d)
{
    const NUM_T *tab = curve->u.everett_grid.table.NUM_F;
    const unsigned k = curve->u.everett_grid.intervals;
    const NUM_T x = tab[0] + d, r = tab[1] - tab[0]; /* tab[0]: lo, the inverse's too */
    const NUM_T *rec;
    NUM_T t;
    unsigned i = 0u;
    while (i + 1u < k && x >= tab[i + 1u]) {
        ++i;
    }
    if (i == 0u) {
        return tab[k + 1u] * d * d;
    }
    rec = tab + 2u * k + 1u + 4u * (i * (i - 1u) / 2u);
    t = x - tab[i];
    return NUM_MULADD(NUM_MULADD(tab[k + 1u + i], t, NUM_MULADD(rec[3], r, rec[2])), t,
                      NUM_MULADD(r, rec[1], rec[0]) + tab[k + 1u] * r * r);
}

static NUM_T NUM_NAME(curve_g_impl)(const hyst_curve_t *curve, NUM_T d)
{
    if (curve == NULL || curve->variant != (unsigned)NUM_VARIANT) {
        return 0;
    }
    if (curve->kind == (unsigned)HYST_CURVE_EVERETT_GRID) {
        return NUM_NAME(everett_grid_from_lo)(curve, d);
    }
    if (curve->kind == (unsigned)HYST_CURVE_EVERETT_GRID_INV) { /* that branch's inverse, bisected */
        const NUM_T *tab = curve->u.everett_grid.table.NUM_F;
        NUM_T a = 0, b = tab[curve->u.everett_grid.intervals] - tab[0];
        unsigned it;
        for (it = 0u; it < 2u * (unsigned)(sizeof(NUM_T) * CHAR_BIT); ++it) {
            const NUM_T m = (a + b) * NUM_C(0.5);
            if (!(m > a && m < b)) {
                break;
            }
            if (NUM_NAME(everett_grid_from_lo)(curve, m) < d) {
                a = m;
            } else {
                b = m;
            }
        }
        return a;
    }
    if (curve->kind == (unsigned)HYST_CURVE_SPLINE ||
        curve->kind == (unsigned)HYST_CURVE_SPLINE_INV) {
        return NUM_NAME(spline_g_)(curve, d * curve->unit.NUM_F);
    }
    if (curve->kind == (unsigned)HYST_CURVE_SPLINE_INV_TABLE) {
        return NUM_NAME(spline_table_g_)(curve, d * curve->unit.NUM_F);
    }
    return curve->kind == (unsigned)HYST_CURVE_POLY
               ? NUM_NAME(horner)(curve->u.poly.a, curve->u.poly.degree, d * curve->unit.NUM_F)
               : NUM_NAME(curve_g_other_)(curve, d * curve->unit.NUM_F); /* exact for unit 1 */
}

static hyst_status_t NUM_NAME(curve_inverse_table_impl)(hyst_curve_t *inv, const hyst_curve_t *fwd,
                                            NUM_T *table, size_t intervals)
{
    hyst_ptr_t t;
    t.NUM_F = table;
    return hyst_curve_inverse_table_(inv, fwd, t, intervals, NUM_VARIANT);
}

static hyst_status_t NUM_NAME(curve_everett_inverse_table_impl)(hyst_curve_t *inv, const hyst_curve_t *fwd,
                                                    NUM_T *table, size_t rows, size_t intervals)
{
    hyst_ptr_t t;
    t.NUM_F = table;
    return hyst_curve_everett_inverse_table_(inv, fwd, t, rows, intervals, NUM_VARIANT);
}

static hyst_status_t NUM_NAME(curve_inverse_table_const_impl)(hyst_curve_t *inv, const hyst_curve_t *fwd,
                                                  const NUM_T *table, size_t intervals,
                                                  const hyst_table_seal_t *seal)
{
    hyst_cptr_t t;
    t.NUM_F = table;
    return hyst_curve_inverse_table_const_(inv, fwd, t, intervals, seal, NUM_VARIANT);
}

static hyst_status_t NUM_NAME(curve_everett_inverse_table_const_impl)(hyst_curve_t *inv,
                                                          const hyst_curve_t *fwd,
                                                          const NUM_T *table, size_t rows,
                                                          size_t intervals,
                                                          const hyst_table_seal_t *seal)
{
    hyst_cptr_t t;
    t.NUM_F = table;
    return hyst_curve_everett_inverse_table_const_(inv, fwd, t, rows, intervals, seal,
                                                   NUM_VARIANT);
}

static NUM_T NUM_NAME(curve_eval_impl)(const hyst_curve_t *curve, NUM_T x)
{
    if (curve == NULL || curve->variant != (unsigned)NUM_VARIANT) {
        return 0;
    }
    x = x < curve->lo.NUM_F ? curve->lo.NUM_F : (x > curve->hi.NUM_F ? curve->hi.NUM_F : x);
    return curve->y_lo.NUM_F + NUM_NAME(curve_g_impl)(curve, x - curve->lo.NUM_F);
}

#undef REAL_EPS
#undef LEVELS
#endif /* HYST_CURVE_EVAL_H */
