/* Inverse curves (METHOD.md section 8): f0^-1 for a compensator.
 *
 * Polynomial f0: g(d) = G(d / span) with G(u) = u (a[0] u^(n-1) + ... + a[n-1])
 * on u in [0, 1], G(0) = 0, G(1) = R = f0(hi) - f0(lo). g^-1(e) solves G(u) = e:
 *  1. start: G^-1 is tabulated at init at e_k = k R / K (K = HYST_INV_KNOTS),
 *     so e in [e_j, e_j+1] gives the bracket [u_j, u_j+1];
 *  2. at most 2 HYST_INV_MAX_ITER bisections of it, each one evaluation of
 *     G, fewer once a parabola fits to rounding;
 *  3. inverse quadratic interpolation in the last bracket.
 * Bisection, not Newton: its answer is monotone in e (proof at
 * hyst_poly_inv_g_), and a flat point of f0 (G' = 0) costs it nothing. */
#include "hyst_curve_impl.h"

/* G(u) in hyst_wide_t, from the coefficients the samples will use. */
static hyst_wide_t unit_g(const hyst_curve_t *c, hyst_wide_t u)
{
    hyst_wide_t acc = c->a[0];
    unsigned i;
    for (i = 1u; i < c->degree; ++i) {
        acc = acc * u + c->a[i];
    }
    return acc * u;
}

/* The start table: bisection in hyst_wide_t (init time, cost irrelevant). */
static void fill_knots(hyst_curve_t *c, hyst_wide_t range)
{
    hyst_wide_t from = 0;
    unsigned k, it;
    c->knot_u[0] = 0;
    c->knot_u[HYST_INV_KNOTS] = 1;
    for (k = 1u; k < HYST_INV_KNOTS; ++k) {
        /* k / K first: range * k overflows once range > DBL_MAX / K */
        const hyst_wide_t e = range * ((hyst_wide_t)k / (hyst_wide_t)HYST_INV_KNOTS);
        hyst_wide_t a = from, b = 1;
        for (it = 0u; it < 80u; ++it) {
            const hyst_wide_t m = (a + b) / 2;
            if (m <= a || m >= b) {
                break;
            }
            if (unit_g(c, m) < e) {
                a = m;
            } else {
                b = m;
            }
        }
        from = a;
        c->knot_u[k] = (hyst_real_t)a;
    }
}

hyst_status_t hyst_curve_inverse(hyst_curve_t *inv, const hyst_curve_t *fwd)
{
    hyst_curve_t out;
    hyst_wide_t range;
    hyst_status_t st = hyst_curve_check(fwd);
    if (inv == NULL) {
        return HYST_ERR_NULL;
    }
    if (st != HYST_OK) {
        return st;
    }
    if (fwd->kind == HYST_CURVE_PWL || fwd->kind == HYST_CURVE_PWL_INV) {
        return hyst_pwl_inverse_(inv, fwd);
    }
    out = *fwd; /* swap the axes; the polynomial stays the forward one */
    out.lo = fwd->y_lo;
    out.hi = fwd->y_hi;
    out.y_lo = fwd->lo;
    out.y_hi = fwd->hi;
    if (fwd->kind == HYST_CURVE_POLY_INV) { /* as hyst_curve_from_poly() set it */
        out.kind = HYST_CURVE_POLY;
        out.horner = out.degree;
        out.inv_span = (hyst_real_t)(1 / ((hyst_wide_t)out.hi - (hyst_wide_t)out.lo));
        *inv = out;
        return HYST_OK;
    }
    /* A non-constant polynomial accepted as increasing is strictly
     * increasing: its inverse exists. Refuse only a degenerate range. */
    range = unit_g(fwd, 1);
    if (!(range > 0) || !(fwd->y_hi > fwd->y_lo)) {
        return HYST_ERR_NOT_INVERTIBLE;
    }
    out.kind = HYST_CURVE_POLY_INV;
    out.horner = 0u; /* g^-1 is evaluated out of line */
    out.inv_span = 1; /* g^-1 takes the output difference itself */
    out.span = (hyst_real_t)((hyst_wide_t)fwd->hi - (hyst_wide_t)fwd->lo);
    out.knot_scale = (hyst_real_t)((hyst_wide_t)HYST_INV_KNOTS / range);
    fill_knots(&out, range);
    *inv = out;
    return HYST_OK;
}

/* Bisection levels per sample, at most: two per HYST_INV_MAX_ITER, each one
 * evaluation of G, as many multiply-adds as a Newton step's G and G'. */
#define LEVELS (2u * (unsigned)(HYST_INV_MAX_ITER))

/* Rounding unit of hyst_real_t: the early stop's target in u. */
#define REAL_EPS ((hyst_real_t)(sizeof(hyst_real_t) >= 8u ? 2.2e-16 : 1.2e-7))

/* G(u) in hyst_real_t, as the samples see it. */
static hyst_real_t real_g(const hyst_curve_t *c, hyst_real_t u)
{
    hyst_real_t acc = c->a[0];
    unsigned i;
    for (i = 1u; i < c->degree; ++i) {
        acc = acc * u + c->a[i];
    }
    return acc * u;
}

static hyst_real_t pos(hyst_real_t v) { return v > 0 ? v : 0; }

static hyst_real_t absr(hyst_real_t v) { return v < 0 ? -v : v; }

/* u(t) = u0 + side s (c1 + c2 s), s = max(0, side (t - t0)), c1, c2 >= 0:
 * every rounded operation is monotone, so u is non-decreasing in t. */
typedef struct {
    hyst_real_t u0, t0, c1, c2;
    int side; /* +1: from the left point, -1: from the right, 0: none */
} leaf_t;

/* The quadratic u(t) through three points, in the form above if its
 * coefficients allow (u' >= 0 at the end it is written from); else side 0.
 * Noise near a flat point or an overflow (NaN fails every test) give 0. */
static int fit_leaf(leaf_t *q, const hyst_real_t pu[3], const hyst_real_t pt[3])
{
    const hyst_real_t h1 = pt[1] - pt[0], h2 = pt[2] - pt[1];
    q->side = 0;
    if (h1 > 0 && h2 > 0) {
        const hyst_real_t d1 = (pu[1] - pu[0]) / h1, d2 = (pu[2] - pu[1]) / h2;
        const hyst_real_t cc = (d2 - d1) / (pt[2] - pt[0]);
        const hyst_real_t left = d1 - cc * h1, right = d2 + cc * h2; /* u' at t0, t2 */
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
static int cubic_small(hyst_real_t ta, hyst_real_t tm, hyst_real_t tb, int from, hyst_real_t to,
                       hyst_real_t width)
{
    const hyst_real_t guess = from > 0 ? (3 * ta + 6 * tb - to) * HYST_REAL_C(0.125)
                                       : (6 * ta + 3 * tb - to) * HYST_REAL_C(0.125);
    return absr(tm - guess) * width <= REAL_EPS * (tb - ta);
}

/* The early stop: the leaf's parabola u(t) predicts the parent's third
 * point (uo, to) to 16 REAL_EPS; in the child its error is ~1/60 of that.
 * q is left fitted if so, else side 0. */
static int leaf_predicts(leaf_t *q, const hyst_real_t pu[3], const hyst_real_t pt[3],
                         hyst_real_t uo, hyst_real_t to)
{
    if (fit_leaf(q, pu, pt) != 0) {
        const hyst_real_t sg = (hyst_real_t)q->side * (to - q->t0);
        const hyst_real_t far = q->u0 + (hyst_real_t)q->side * (sg * (q->c1 + q->c2 * sg));
        if (absr(uo - far) <= 16 * REAL_EPS) {
            return 1;
        }
    }
    q->side = 0;
    return 0;
}

/* The leaf's answer for t, in [ua, ub]: q if fitted (or fittable), else
 * linear between the ends (ta, ua), (tb, ub). Each branch is chosen by the
 * leaf alone and non-decreasing in t; NaN goes to ua. */
static hyst_real_t leaf_value(leaf_t *q, const hyst_real_t pu[3], const hyst_real_t pt[3],
                              hyst_real_t t, const hyst_real_t end[4])
{
    const hyst_real_t ua = end[0], ub = end[1], ta = end[2], tb = end[3];
    hyst_real_t r = ua;
    if (q->side != 0 || fit_leaf(q, pu, pt) != 0) {
        const hyst_real_t s = pos(q->side > 0 ? t - q->t0 : q->t0 - t);
        const hyst_real_t v = s * (q->c1 + q->c2 * s);
        r = q->side > 0 ? q->u0 + v : q->u0 - v;
    } else if (tb > ta) {
        r = ua + pos(t - ta) * ((ub - ua) / (tb - ta));
    }
    r = r > ua ? r : ua;
    return r < ub ? r : ub;
}

/* g^-1(e) is non-decreasing in e, for every e, however G rounds (finding 5:
 * Newton's answer was not; near a flat point it reversed by 1e-5 of the range).
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
hyst_real_t hyst_poly_inv_g_(const hyst_curve_t *c, hyst_real_t e)
{
    const hyst_real_t t = e * c->knot_scale;
    hyst_real_t ua, ub, ta, tb, uo = 0, to = 0, r, pu[3], pt[3], end[4];
    leaf_t q;
    unsigned j, lv, tries = 0u;
    int from = 0; /* side of the parent's third point (uo, to), 0: none */
    if (!(t > 0)) {
        return 0; /* g^-1(0) = 0 exactly; rounding below 0 clamped */
    }
    if (t >= (hyst_real_t)HYST_INV_KNOTS) {
        return c->span;
    }
    j = (unsigned)t;
    ua = c->knot_u[j];
    ub = c->knot_u[j + 1u];
    ta = (hyst_real_t)j; /* G K / R at the knots, by construction */
    tb = (hyst_real_t)(j + 1u);
    q.side = 0;
    for (lv = 0u; lv < LEVELS; ++lv) {
        const hyst_real_t m = (ua + ub) * HYST_REAL_C(0.5);
        hyst_real_t tm;
        int stop = 0;
        if (!(m > ua && m < ub)) {
            break; /* no real between: the leaf */
        }
        tm = real_g(c, m) * c->knot_scale;
        /* on odd levels (half the cost where it fails, near flat points)
         * and at most twice (the divisions stay bounded) */
        if ((lv & 1u) != 0u && tries < 2u && tb > ta && cubic_small(ta, tm, tb, from, to, ub - ua)) {
            pu[0] = ua;
            pu[1] = m;
            pu[2] = ub;
            pt[0] = ta;
            pt[1] = tm;
            pt[2] = tb;
            ++tries;
            stop = leaf_predicts(&q, pu, pt, uo, to);
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
    r = leaf_value(&q, pu, pt, t, end);
    return r * c->span;
}
