/* Inverse curves (METHOD.md section 8): f0^-1 for a compensator.
 *
 * Polynomial f0: g(d) = G(d / span) with G(u) = u (a[0] u^(n-1) + ... + a[n-1])
 * on u in [0, 1], G(0) = 0, G(1) = R = f0(hi) - f0(lo). g^-1(e) solves G(u) = e:
 *  1. start: G^-1 is tabulated at init at e_k = k R / K (K = HYST_INV_KNOTS),
 *     so e in [e_j, e_j+1] gives the bracket [u_j, u_j+1] and a linear start;
 *  2. at most HYST_INV_MAX_ITER steps, each one evaluation of G and G':
 *     Newton while it stays in the bracket and its step is less than half
 *     the step before last, else bisection (the rule of Numerical Recipes'
 *     rtsafe). The bracket shrinks around the root at every step; near a
 *     flat point of f0, where Newton crawls or cycles, bisection halves it. */
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

/* A Newton step is taken only if at most 1/NEWTON_RATIO of the step before last. */
#define NEWTON_RATIO 4

/* Relative step below which Newton has converged to rounding. */
#define STEP_EPS ((hyst_real_t)(sizeof(hyst_real_t) >= 8u ? 2.3e-16 : 1.2e-7))

static hyst_real_t absr(hyst_real_t v) { return v < 0 ? -v : v; }

hyst_real_t hyst_poly_inv_g_(const hyst_curve_t *c, hyst_real_t e)
{
    const hyst_real_t *a = c->a;
    const hyst_real_t t = e * c->knot_scale;
    hyst_real_t ua, ub, u, dx, dx_old, best_f, best_u;
    unsigned j, i, it;
    if (!(t > 0)) {
        return 0; /* g^-1(0) = 0 exactly; rounding below 0 clamped */
    }
    if (t >= (hyst_real_t)HYST_INV_KNOTS) {
        return c->span;
    }
    j = (unsigned)t;
    ua = c->knot_u[j];
    ub = c->knot_u[j + 1u];
    u = ua + (ub - ua) * (t - (hyst_real_t)j); /* secant of the table */
    dx = ub - ua;
    dx_old = dx;
    best_u = u;
    best_f = -1; /* none yet */
    for (it = 0u; it < HYST_INV_MAX_ITER; ++it) {
        hyst_real_t p = a[0], dp = 0, f, df, next;
        int newton;
        for (i = 1u; i < c->degree; ++i) {
            dp = dp * u + p;
            p = p * u + a[i];
        }
        f = p * u - e;   /* G(u) - e */
        df = p + u * dp; /* G'(u) */
        if (f < 0) {
            ua = u;
        } else {
            ub = u;
        }
        /* Newton if it stays in the bracket and its step is at most 1/4 of
         * the step before last (two steps beat two bisections); else bisect.
         * Near a flat point of order m Newton only crawls, by (m-1)/m per
         * step, while bisection shrinks the residual by about 2^m. */
        next = df > 0 ? u - f / df : u; /* no division by a zero slope */
        newton = df > 0 && next >= ua && next <= ub &&
                 absr(f) * (hyst_real_t)NEWTON_RATIO <= absr(dx_old) * df;
        if (best_f < 0 || absr(f) < best_f) { /* the answer: the best point */
            best_f = absr(f);                 /* evaluated, never a guess */
            best_u = u;
        }
        if (f == 0 || (newton && absr(f) <= STEP_EPS * absr(u) * df)) {
            break; /* converged to rounding */
        }
        dx_old = dx;
        if (newton) {
            dx = f / df;
        } else {
            dx = (ub - ua) * HYST_REAL_C(0.5);
            next = ua + dx;
        }
        if (next == u) {
            break;
        }
        u = next;
    }
    return best_u * c->span;
}
