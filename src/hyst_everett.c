/* SPDX-License-Identifier: MIT */
/* The asymmetric curve kind (curve.h, hyst_everett_t), set up once in
 * hyst_wide_t for every real variant: validation, the monotonicity proof of
 * E on its triangle, the per-branch tables the engine derives a branch's
 * coefficients from (src/tcm_engine.h, derive()), and a rounding bound. */
#include "hyst_util.h"

#include <float.h>
#include <string.h>

#define EV_N HYST_EVERETT_MAX_DEGREE
#define EV_SIDE (EV_N + 1) /* bivariate polynomials: p[a][b] of u^a v^b, a + b <= EV_N */
#define EV_DEPTH 12u       /* subdivision depth of the proof */
#define EV_BUDGET 4096L    /* sub-triangles the proof may visit */

typedef struct {
    hyst_wide_t c[EV_SIDE][EV_SIDE]; /* c[a][b]: coefficient of u^a v^b */
} bipoly_t;

static hyst_wide_t factorial(unsigned k)
{
    hyst_wide_t f = 1;
    while (k > 1u) {
        f *= (hyst_wide_t)k--;
    }
    return f;
}

/* r = p * q, truncated at total degree EV_N (exact for the products here). */
static void bipoly_mul(bipoly_t *r, const bipoly_t *p, const bipoly_t *q)
{
    bipoly_t out;
    unsigned a, b, c, d;
    memset(&out, 0, sizeof out);
    for (a = 0u; a <= EV_N; ++a) {
        for (b = 0u; a + b <= EV_N; ++b) {
            for (c = 0u; a + c <= EV_N; ++c) {
                for (d = 0u; a + b + c + d <= EV_N; ++d) {
                    out.c[a + c][b + d] += p->c[a][b] * q->c[c][d];
                }
            }
        }
    }
    *r = out;
}

/* r(s, t) = p(P0 + s (P1 - P0) + t (P2 - P0)), vertices as (u, v) pairs. */
static void compose(bipoly_t *r, const bipoly_t *p, const hyst_wide_t *v0, const hyst_wide_t *v1,
                    const hyst_wide_t *v2)
{
    bipoly_t lu, lv, pu, pv, term;
    unsigned a, b, i, j;
    memset(&lu, 0, sizeof lu);
    memset(&lv, 0, sizeof lv);
    lu.c[0][0] = v0[0];
    lu.c[1][0] = v1[0] - v0[0];
    lu.c[0][1] = v2[0] - v0[0];
    lv.c[0][0] = v0[1];
    lv.c[1][0] = v1[1] - v0[1];
    lv.c[0][1] = v2[1] - v0[1];
    memset(r, 0, sizeof *r);
    memset(&pu, 0, sizeof pu);
    pu.c[0][0] = 1;
    for (a = 0u; a <= EV_N; ++a) { /* pu = lu^a */
        memset(&pv, 0, sizeof pv);
        pv.c[0][0] = 1;
        for (b = 0u; a + b <= EV_N; ++b) { /* pv = lv^b */
            if (p->c[a][b] != 0) {
                bipoly_mul(&term, &pu, &pv);
                for (i = 0u; i <= EV_N; ++i) {
                    for (j = 0u; i + j <= EV_N; ++j) {
                        r->c[i][j] += p->c[a][b] * term.c[i][j];
                    }
                }
            }
            bipoly_mul(&pv, &pv, &lv);
        }
        bipoly_mul(&pu, &pu, &lu);
    }
}

/* Bernstein-Bezier coefficient of s^i t^j (1 - s - t)^(n-i-j) of the
 * degree-n polynomial q on the unit triangle, from its monomials. */
static hyst_wide_t bernstein(const bipoly_t *q, unsigned n, unsigned i, unsigned j)
{
    hyst_wide_t c = 0;
    unsigned a, b;
    for (a = 0u; a <= i; ++a) {
        for (b = 0u; b <= j; ++b) {
            c += q->c[a][b] * factorial(n - a - b) * factorial(i) * factorial(j) /
                 (factorial(i - a) * factorial(j - b) * factorial(n));
        }
    }
    return c;
}

/* The signs of p's Bernstein-Bezier coefficients on the triangle P0 P1 P2:
 * 1 if all >= -tol (p >= -tol there), 0 if one at a vertex is below (p
 * is negative there), -1 if undecided. */
static int sign_on(const bipoly_t *p, unsigned n, const hyst_wide_t *v0, const hyst_wide_t *v1,
                   const hyst_wide_t *v2, hyst_wide_t tol)
{
    bipoly_t q;
    hyst_wide_t lowest = 0;
    unsigned i, j;
    compose(&q, p, v0, v1, v2);
    for (i = 0u; i <= n; ++i) {
        for (j = 0u; i + j <= n; ++j) {
            const hyst_wide_t c = bernstein(&q, n, i, j);
            if ((i == n || j == n || i + j == 0u) && c < -tol) {
                return 0; /* the value at a vertex: negative there */
            }
            lowest = c < lowest ? c : lowest;
        }
    }
    return lowest >= -tol ? 1 : -1;
}

/* A triangle of the subdivision: vertices in units of 2^-EV_DEPTH of the
 * unit triangle (exact midpoints), and the depth left. */
typedef struct {
    long v[6];
    unsigned depth;
} tri_t;

/* 1 if p >= -tol on the unit triangle u, v >= 0, u + v <= 1: proved by the
 * signs of its Bernstein-Bezier coefficients, subdividing in four where
 * undecided (depth first, an explicit stack: 3 per level); 0 if it is
 * negative at a vertex, or the proof runs out of depth or budget. */
static int nonneg_on_triangle(const bipoly_t *p, unsigned n, hyst_wide_t tol)
{
    tri_t stack[3u * EV_DEPTH + 1u];
    const long one = 1L << EV_DEPTH;
    const hyst_wide_t unit = 1 / (hyst_wide_t)one;
    unsigned top = 1u, k;
    long budget = EV_BUDGET;
    memset(&stack[0], 0, sizeof stack[0]);
    stack[0].v[2] = one; /* (0, 0), (1, 0), (0, 1) */
    stack[0].v[5] = one;
    stack[0].depth = EV_DEPTH;
    while (top > 0u) {
        const tri_t t = stack[--top];
        hyst_wide_t v[6];
        int verdict;
        for (k = 0u; k < 6u; ++k) {
            v[k] = (hyst_wide_t)t.v[k] * unit;
        }
        verdict = sign_on(p, n, &v[0], &v[2], &v[4], tol);
        if (verdict == 0) {
            return 0;
        }
        if (verdict < 0) {
            const long m01[2] = {(t.v[0] + t.v[2]) / 2, (t.v[1] + t.v[3]) / 2};
            const long m12[2] = {(t.v[2] + t.v[4]) / 2, (t.v[3] + t.v[5]) / 2};
            const long m02[2] = {(t.v[0] + t.v[4]) / 2, (t.v[1] + t.v[5]) / 2};
            const long child[4][6] = {{t.v[0], t.v[1], m01[0], m01[1], m02[0], m02[1]},
                                      {m01[0], m01[1], t.v[2], t.v[3], m12[0], m12[1]},
                                      {m02[0], m02[1], m12[0], m12[1], t.v[4], t.v[5]},
                                      {m01[0], m01[1], m12[0], m12[1], m02[0], m02[1]}};
            unsigned c;
            if (t.depth == 0u || --budget < 0) {
                return 0;
            }
            for (c = 0u; c < 4u; ++c) {
                memcpy(stack[top].v, child[c], sizeof stack[top].v);
                stack[top++].depth = t.depth - 1u;
            }
        }
    }
    return 1;
}

/* With R(w, t) = E(b + w span, b): dE/da = R_w and dE/db = R_t - R_w, so
 * E increases in a and decreases in b on lo <= b <= a <= hi iff rw = R_w
 * and diff = R_w - R_t are >= 0 on the triangle w, t >= 0, w + t <= 1.
 * Returns the sum of |e_ij| (i + j), the scale of their coefficients. */
static hyst_wide_t derivatives(const hyst_everett_t *e, bipoly_t *rw, bipoly_t *diff)
{
    hyst_wide_t scale = 0;
    unsigned i, j;
    memset(rw, 0, sizeof *rw);
    memset(diff, 0, sizeof *diff);
    for (i = 1u; i <= e->degree; ++i) {
        for (j = 0u; i + j <= e->degree; ++j) {
            const hyst_wide_t c = e->e[i - 1u][j];
            rw->c[i - 1u][j] += (hyst_wide_t)i * c;
            diff->c[i - 1u][j] += (hyst_wide_t)i * c;
            if (j > 0u) {
                diff->c[i][j - 1u] -= (hyst_wide_t)j * c;
            }
            scale += hyst_wide_abs(c) * (hyst_wide_t)(i + j);
        }
    }
    return scale;
}

hyst_wide_t hyst_everett_range_(const hyst_everett_t *e)
{
    hyst_wide_t range = 0;
    unsigned i;
    for (i = 0u; i < e->degree; ++i) {
        range += e->e[i][0];
    }
    return range;
}

int hyst_everett_monotone_(const hyst_everett_t *e)
{
    bipoly_t rw, diff;
    const hyst_wide_t tol = 64 * HYST_WIDE_EPS * derivatives(e, &rw, &diff);
    return nonneg_on_triangle(&rw, e->degree - 1u, tol) &&
           nonneg_on_triangle(&diff, e->degree - 1u, tol);
}

size_t hyst_everett_bernstein_(const hyst_everett_t *e, hyst_wide_t *c)
{
    bipoly_t rw, diff;
    const unsigned n = e->degree - 1u;
    size_t k = 0u;
    unsigned i, j;
    (void)derivatives(e, &rw, &diff);
    for (i = 0u; i <= n; ++i) {
        for (j = 0u; i + j <= n; ++j) {
            c[k++] = bernstein(&rw, n, i, j);
            c[k++] = bernstein(&diff, n, i, j);
        }
    }
    return k;
}

/* Binomial coefficient C(j, m), small arguments. */
static hyst_wide_t choose(unsigned j, unsigned m)
{
    return factorial(j) / (factorial(m) * factorial(j - m));
}

/* The falling branch from s = (a - lo) / span: E(a, a - w span) = sum over
 * k, p of f[k][p] w^k s^p, from t = s - w expanded binomially. */
static void falling(const hyst_everett_t *e, bipoly_t *f)
{
    unsigned i, j, m;
    memset(f, 0, sizeof *f);
    for (i = 1u; i <= e->degree; ++i) {
        for (j = 0u; i + j <= e->degree; ++j) {
            for (m = 0u; m <= j; ++m) { /* w^i (s - w)^j: s^(j-m) (-w)^m */
                const hyst_wide_t c = e->e[i - 1u][j] * choose(j, m);
                f->c[i + m][j - m] += (m % 2u == 0u) ? c : -c;
            }
        }
    }
}

/* Rows of a table (curve.h): power of w from n down to 1, each a polynomial
 * in the anchor, highest power first. Returns sum over the rows of
 * (power of w) * (sum of |entries|), for the rounding bound; 0 if an entry
 * is not finite in the variant's type. */
static hyst_wide_t fill_table(hyst_num_t *out, const bipoly_t *p, unsigned n, unsigned variant)
{
    hyst_wide_t weight = 0;
    unsigned i, k, at = 0u;
    for (i = n; i >= 1u; --i) {
        hyst_wide_t row = 0;
        for (k = 0u; k <= n - i; ++k) {
            const hyst_wide_t c = p->c[i][n - i - k];
            if (!hyst_num_set(&out[at++], variant, c)) {
                return 0;
            }
            row += hyst_wide_abs(c);
        }
        weight += (hyst_wide_t)i * row;
    }
    return weight > 0 ? weight : HYST_WIDE_MIN;
}

/* Whether every row of a table is at most linear in the anchor. */
static int linear_in_anchor(const bipoly_t *p, unsigned n)
{
    unsigned i, j;
    for (i = 1u; i <= n; ++i) {
        for (j = 2u; i + j <= n; ++j) {
            if (p->c[i][j] != 0) {
                return 0;
            }
        }
    }
    return 1;
}

/* lin_x (curve.h) of a table linear in the anchor t = (x - lo) / span:
 * c0 + c1 t = (c1 / span) x + (c0 - c1 lo / span), each rounded once.
 * Returns 0 if a number is not finite in the variant's type. */
static int fill_lines(hyst_num_t *out, const bipoly_t *p, unsigned n, hyst_wide_t lo,
                      hyst_wide_t span, unsigned variant)
{
    unsigned i, at = 1u;
    if (!hyst_num_set(&out[0], variant, p->c[n][0])) {
        return 0;
    }
    for (i = n - 1u; i >= 1u; --i) {
        const hyst_wide_t slope = p->c[i][1] / span;
        if (!hyst_num_set(&out[at++], variant, slope) ||
            !hyst_num_set(&out[at++], variant, p->c[i][0] - slope * lo)) {
            return 0;
        }
    }
    return 1;
}

hyst_status_t hyst_curve_everett_(hyst_curve_t *curve, const hyst_everett_t *e, unsigned variant,
                                  unsigned long layout)
{
    bipoly_t rise, fall;
    hyst_curve_t out;
    hyst_wide_t range, eps, bound, ymax, w_rise, w_fall;
    unsigned n, i, j;
    int finite = 1;
    if (curve == NULL || e == NULL) {
        return HYST_ERR_NULL;
    }
    if (layout != HYST_LAYOUT) {
        return HYST_ERR_LAYOUT;
    }
    n = e->degree;
    /* the branch's coefficients live in the instance's HYST_MAX_DEGREE */
    if (n < 1u || n > (unsigned)HYST_EVERETT_MAX_DEGREE || n > (unsigned)HYST_MAX_DEGREE) {
        return HYST_ERR_DEGREE;
    }
    if (!hyst_wide_is_finite(e->lo) || !hyst_wide_is_finite(e->hi) || !(e->lo < e->hi) ||
        !hyst_wide_is_finite(e->hi - e->lo)) {
        return HYST_ERR_DOMAIN;
    }
    if (!hyst_wide_is_finite(e->y_lo)) {
        return HYST_ERR_COEFF;
    }
    memset(&rise, 0, sizeof rise);
    for (i = 1u; i <= (unsigned)HYST_EVERETT_MAX_DEGREE; ++i) {
        for (j = 0u; j < (unsigned)HYST_EVERETT_MAX_DEGREE; ++j) {
            const hyst_wide_t c = e->e[i - 1u][j];
            if (!hyst_wide_is_finite(c) || (i + j > n && c != 0)) {
                return HYST_ERR_COEFF;
            }
            if (i + j <= n) {
                rise.c[i][j] = c;
            }
        }
    }
    range = hyst_everett_range_(e);
    falling(e, &fall);
    memset(&out, 0, sizeof out);
    out.kind = HYST_CURVE_EVERETT;
    out.variant = variant;
    out.layout = HYST_LAYOUT;
    out.u.everett.degree = n;
    finite &= hyst_num_set(&out.lo, variant, e->lo);
    finite &= hyst_num_set(&out.hi, variant, e->hi);
    finite &= hyst_num_set(&out.y_lo, variant, e->y_lo);
    finite &= hyst_num_set(&out.y_hi, variant, e->y_lo + range);
    finite &= hyst_num_set(&out.unit, variant, 1 / (e->hi - e->lo));
    if (!finite || !(hyst_num_get(&out.lo, variant) < hyst_num_get(&out.hi, variant))) {
        return HYST_ERR_DOMAIN;
    }
    w_rise = fill_table(out.u.everett.rise, &rise, n, variant);
    w_fall = fill_table(out.u.everett.fall, &fall, n, variant);
    if (w_rise == 0 || w_fall == 0) {
        return HYST_ERR_COEFF;
    }
    if (!hyst_everett_monotone_(e)) {
        return HYST_ERR_NOT_MONOTONE;
    }
    /* Within |lo| <= span, |x| <= 2 span: a coefficient from lin_x errs by
     * at most 4 eps of its row's |entries|, one more than from the anchor */
    if (linear_in_anchor(&rise, n) && linear_in_anchor(&fall, n) &&
        hyst_wide_abs(e->lo) <= e->hi - e->lo) {
        if (!fill_lines(out.u.everett.lin_x[0], &rise, n, e->lo, e->hi - e->lo, variant) ||
            !fill_lines(out.u.everett.lin_x[1], &fall, n, e->lo, e->hi - e->lo, variant)) {
            return HYST_ERR_COEFF;
        }
        out.u.everett.linear_x = 1u;
    }
    /* One branch evaluation y_k +- G: the anchor, each coefficient's Horner
     * in it and Horner in w with the final product err by at most
     * gamma(4n + 4) sum over the powers i of i sum |row i| (a-priori bounds,
     * the argument's rounding folded in by the factor i), the sum once more
     * by eps max |y|; 1 % for the bound's own rounding. */
    eps = variant == (unsigned)HYST_VARIANT_F64 ? (hyst_wide_t)DBL_EPSILON / 2
                                                : (hyst_wide_t)FLT_EPSILON / 2;
    ymax = hyst_wide_abs(e->y_lo) + hyst_wide_abs(range);
    bound = ((hyst_wide_t)(4u * n + 4u + out.u.everett.linear_x) * eps /
             (1 - (hyst_wide_t)(4u * n + 4u + out.u.everett.linear_x) * eps)) *
                (w_rise > w_fall ? w_rise : w_fall) +
            eps * ymax;
    bound *= (hyst_wide_t)1.01;
    {
        hyst_num_t probe; /* partial sums and outputs finite in the variant's type */
        if (!hyst_num_set(&probe, variant, 2 * ymax + w_rise + w_fall) ||
            !hyst_num_set(&out.rounding, variant, bound)) {
            return HYST_ERR_COEFF;
        }
        out.u.everett.branch_rounding = out.rounding;
        (void)hyst_num_set(&out.u.everett.span, variant, e->hi - e->lo);
        out.u.everett.inv_span = out.unit;
    }
    if (!(range > 0) || bound > (hyst_wide_t)HYST_MAX_ROUNDING * range) {
        return range > 0 ? HYST_ERR_ILL_CONDITIONED : HYST_ERR_NOT_MONOTONE;
    }
    *curve = out;
    return HYST_OK;
}

hyst_status_t hyst_f32_curve_from_everett_(hyst_curve_t *curve, const hyst_everett_t *e,
                                           unsigned long layout)
{
    return hyst_curve_everett_(curve, e, HYST_VARIANT_F32, layout);
}

#if HYST_ENABLE_F64
hyst_status_t hyst_f64_curve_from_everett_(hyst_curve_t *curve, const hyst_everett_t *e,
                                           unsigned long layout)
{
    return hyst_curve_everett_(curve, e, HYST_VARIANT_F64, layout);
}
#endif
