/* SPDX-License-Identifier: MIT */
/* Identification of the asymmetric kind's E (ident.h, hyst_everett_fit_*):
 * Madelung's rules run on the recorded inputs; each stacked turning point
 * keeps the regressors of its output, as the model keeps the output, so a
 * sample's row is the current TP's plus or minus the terms of E between
 * them. Least squares in hyst_wide_t by square-root-free Givens rotations
 * (the normal equations would square the condition number of E's
 * monomials: float could not hold degree 3 or 4). */
#include "hyst/ident.h"

#include "hyst_util.h"

#include <math.h>
#include <string.h>

/* The highest power of t fitted with w^i: the fitted terms are i = 1..n,
 * j = 0..last_j(i), in this order (column 1 on; column 0 is the output at
 * lo). */
static unsigned last_j(const hyst_everett_fit_t *f, unsigned i)
{
    return f->degree - i < f->t_degree ? f->degree - i : f->t_degree;
}

/* Regressors of E(a, b): the fitted w^i t^j, scaled by `sign`, added to r. */
static void add_terms(const hyst_everett_fit_t *f, hyst_wide_t a, hyst_wide_t b,
                      hyst_wide_t sign, hyst_wide_t *r)
{
    const hyst_wide_t span = f->hi - f->lo, w = (a - b) / span, t = (b - f->lo) / span;
    hyst_wide_t wi = sign;
    size_t col = 1u;
    unsigned i, j;
    for (i = 1u; i <= f->degree; ++i) {
        hyst_wide_t tj = 1;
        wi *= w;
        for (j = 0u; j <= last_j(f, i); ++j) {
            r[col++] += wi * tj;
            tj *= t;
        }
    }
}

/* |v| (n entries) without squaring the entries themselves: outputs whose
 * squares overflow hyst_wide_t still have a finite norm. */
static hyst_wide_t norm_of(const hyst_wide_t *v, size_t n)
{
    hyst_wide_t big = 0, sum = 0;
    size_t k;
    for (k = 0u; k < n; ++k) {
        big = hyst_wide_abs(v[k]) > big ? hyst_wide_abs(v[k]) : big;
    }
    for (k = 0u; big > 0 && k < n; ++k) {
        sum += (v[k] / big) * (v[k] / big);
    }
    return big * HYST_WIDE_SQRT(sum);
}

/* Rotates the row v (m entries, destroyed) into the factor R = D^1/2 U
 * (U unit upper triangular, packed with D on its diagonal) by
 * square-root-free Givens rotations: R'R gains v v'. One division per
 * column and none of the square roots of plain rotations: a sample costs
 * about three times what the normal equations' update would. */
static void rotate_in(hyst_wide_t *restrict r, size_t m, hyst_wide_t *restrict v)
{
    hyst_wide_t w = 1; /* the row's weight, shrinking as it is rotated in */
    size_t i, j;
    for (i = 0u; i < m; ++i) {
        hyst_wide_t *ri = r + hyst_packed_row_(i, m);
        const hyst_wide_t vi = v[i];
        hyst_wide_t d, inv, c, s;
        if (vi == 0) {
            continue;
        }
        d = ri[0] + w * vi * vi;
        inv = 1 / d;
        c = ri[0] * inv;
        s = w * vi * inv;
        w *= c;
        ri[0] = d;
        for (j = i + 1u; j < m; ++j) {
            const hyst_wide_t vj = v[j];
            v[j] = vj - vi * ri[j - i];
            ri[j - i] = c * ri[j - i] + s * vj;
        }
        if (!(w > 0)) {
            break; /* the row is spent: every later column is in the span of the ones before */
        }
    }
}

hyst_status_t hyst_everett_fit_init(hyst_everett_fit_t *fit, unsigned degree, hyst_wide_t lo,
                                    hyst_wide_t hi, hyst_wide_t *work, size_t work_len)
{
    return hyst_everett_fit_init_terms(fit, degree, degree > 0u ? degree - 1u : 0u, lo, hi, work,
                                       work_len);
}

hyst_status_t hyst_everett_fit_init_terms(hyst_everett_fit_t *fit, unsigned degree,
                                          unsigned t_degree, hyst_wide_t lo, hyst_wide_t hi,
                                          hyst_wide_t *work, size_t work_len)
{
    unsigned i;
    if (fit == NULL || work == NULL) {
        return HYST_ERR_NULL;
    }
    if (degree < 1u || degree > (unsigned)HYST_EVERETT_MAX_DEGREE || t_degree >= degree) {
        return HYST_ERR_DEGREE;
    }
    if (!hyst_wide_is_finite(lo) || !hyst_wide_is_finite(hi) || !(lo < hi) ||
        !hyst_wide_is_finite(hi - lo)) {
        return HYST_ERR_DOMAIN;
    }
    if (work_len < HYST_EVERETT_FIT_WORK(2u)) {
        return HYST_ERR_NOSPACE;
    }
    memset(fit, 0, sizeof *fit);
    fit->degree = degree;
    fit->t_degree = t_degree;
    fit->cols = 1u;
    for (i = 1u; i <= degree; ++i) {
        fit->cols += last_j(fit, i) + 1u;
    }
    fit->lo = lo;
    fit->hi = hi;
    fit->capacity = work_len / (HYST_EVERETT_FIT_COLS + 1u);
    fit->tp_x = work;
    fit->tp_r = work + fit->capacity;
    hyst_tp_start_(fit->tp_x, fit->tp_r, fit->cols, fit->r_prev, lo);
    fit->n_tp = 1u;
    fit->x_prev = lo;
    return HYST_OK;
}

hyst_status_t hyst_everett_fit_add(hyst_everett_fit_t *fit, hyst_wide_t x, hyst_wide_t y)
{
    hyst_wide_t v[HYST_EVERETT_FIT_COLS + 1u];
    if (fit == NULL) {
        return HYST_ERR_NULL;
    }
    if (!hyst_wide_is_finite(x)) {
        return HYST_ERR_NONFINITE;
    }
    if (x < fit->lo || x > fit->hi) {
        return HYST_ERR_DOMAIN;
    }
    if (x > fit->x_prev || x < fit->x_prev) {
        hyst_wide_t a, b;
        const int sign = hyst_tp_step_(fit->tp_x, fit->tp_r, &fit->n_tp, fit->capacity,
                                       fit->cols, fit->r_prev, fit->x_prev, x, &a, &b);
        if (sign == 0) {
            return HYST_ERR_NOSPACE;
        }
        add_terms(fit, a, b, (hyst_wide_t)sign, fit->r_prev);
        fit->x_prev = x;
    }
    if (!hyst_wide_is_finite(y)) {
        return HYST_ERR_NONFINITE;
    }
    if (fit->used == 0u) {
        fit->y_ref = y;
    }
    memcpy(v, fit->r_prev, fit->cols * sizeof v[0]);
    v[fit->cols] = y - fit->y_ref; /* about the first output: y_lo's column
                                    * then need not carry an offset far above the range */
    rotate_in(fit->r, fit->cols + 1u, v);
    ++fit->used;
    return HYST_OK;
}

/* Constraint rows of the monotone fit, v_i = L^-1 c_i, each of
 * HYST_EVERETT_FIT_COLS numbers: the dual's Gram matrix is V'V. */
static hyst_wide_t dual_gram(const void *ctx, size_t i, size_t j)
{
    const hyst_wide_t *v = (const hyst_wide_t *)ctx;
    hyst_wide_t sum = 0;
    size_t k;
    for (k = 0u; k < HYST_EVERETT_FIT_COLS; ++k) {
        sum += v[i * HYST_EVERETT_FIT_COLS + k] * v[j * HYST_EVERETT_FIT_COLS + k];
    }
    return sum;
}

/* Least squares subject to C e >= 0, C the Bernstein-Bezier coefficients
 * of span dE/da and -span dE/db (linear in e), by its dual: with the
 * normal equations A'A = L L' and u = L^-1 A'y, the solution is
 * s = L'^-1 (u + V lambda), V = L^-1 C' (zero in the y_lo row), where
 * lambda >= 0 minimises |u + V lambda|^2: non-negative least squares, whose
 * normal equations V'V lambda = -V'u are hyst_nnls_t's. Returns 0 if that
 * ran out of iterations. */
static int monotone_solve(const hyst_everett_fit_t *fit, const hyst_wide_t *l,
                          const hyst_wide_t *u, hyst_wide_t *s)
{
    enum { M = HYST_EVERETT_BERNSTEIN_MAX, N = HYST_EVERETT_FIT_COLS };
    hyst_wide_t v[M * N], rhs[M], lambda[M], passive[M], grad[M], set[M], b[M];
    hyst_wide_t lp[(N - 1u) * (N - 1u)], coef[M];
    hyst_everett_t unit;
    hyst_nnls_t p;
    const size_t n = fit->cols;
    size_t m = 0u, i, k, col;
    unsigned a, c;
    int done;
    memset(v, 0, sizeof v);
    memset(&unit, 0, sizeof unit);
    unit.degree = fit->degree;
    for (a = 1u, col = 1u; a <= fit->degree; ++a) { /* C's column of each coefficient */
        for (c = 0u; c <= last_j(fit, a); ++c, ++col) {
            unit.e[a - 1u][c] = 1;
            m = hyst_everett_bernstein_(&unit, coef);
            unit.e[a - 1u][c] = 0;
            for (i = 0u; i < m; ++i) {
                v[i * N + col] = coef[i];
            }
        }
    }
    for (i = 0u; i < m; ++i) { /* v_i = L^-1 c_i, scaled to length 1 (same constraint) */
        hyst_wide_t *vi = v + i * N, len = 0;
        for (k = 0u; k < n; ++k) {
            size_t j;
            for (j = 0u; j < k; ++j) {
                vi[k] -= l[k * N + j] * vi[j];
            }
            vi[k] /= l[k * N + k];
            len += vi[k] * vi[k];
        }
        len = len > 0 ? HYST_WIDE_SQRT(len) : 1; /* a zero row constrains nothing */
        rhs[i] = 0;
        for (k = 0u; k < n; ++k) {
            vi[k] /= len;
            rhs[i] -= vi[k] * u[k];
        }
    }
    p.n = m;
    p.gram = dual_gram;
    p.ctx = v;
    p.c = rhs;
    p.w = lambda;
    p.s = passive;
    p.g = grad;
    p.set = set;
    p.b = b;
    p.l = lp;
    p.most = n - 1u; /* independent rows of V: at most its n - 1 non-zero entries */
    /* |rhs_i| <= |u|: a gradient below this share of it is rounding */
    done = hyst_nnls_(&p, norm_of(u, n) * HYST_WIDE_EPS * (hyst_wide_t)(1000u * m));
    for (k = 0u; k < n; ++k) { /* z = u + V lambda, into s */
        s[k] = u[k];
        for (i = 0u; i < m; ++i) {
            s[k] += v[i * N + k] * lambda[i];
        }
    }
    for (k = n; k-- > 0u;) { /* L' s = z */
        for (i = k + 1u; i < n; ++i) {
            s[k] -= l[i * N + k] * s[i];
        }
        s[k] /= l[k * N + k];
    }
    return done;
}

/* E's coefficients, y_lo and the domain from the solution s. */
static void to_everett(const hyst_everett_fit_t *fit, const hyst_wide_t *s, hyst_everett_t *e)
{
    unsigned a, b;
    size_t col;
    memset(e, 0, sizeof *e);
    e->degree = fit->degree;
    e->lo = fit->lo;
    e->hi = fit->hi;
    e->y_lo = s[0] + fit->y_ref; /* s[0] fits the outputs less y_ref */
    for (a = 1u, col = 1u; a <= fit->degree; ++a) {
        for (b = 0u; b <= last_j(fit, a); ++b) {
            e->e[a - 1u][b] = s[col++];
        }
    }
}

/* Least squares into e and rms; if `constrained` and the curve would
 * refuse that E, the least-squares E of the sufficient conditions. The
 * factor R (fit->r: R'R = A'A, its last column Q'y) gives L = R' and
 * u = L^-1 A'y as a Cholesky factorisation of the normal equations would,
 * at the condition number of A, not of A'A. */
static hyst_status_t solve(const hyst_everett_fit_t *fit, hyst_everett_t *e, hyst_wide_t *rms,
                           int constrained)
{
    enum { N = HYST_EVERETT_FIT_COLS };
    hyst_wide_t l[N * N];
    hyst_wide_t s[N], u[N], root[N + 1];
    hyst_wide_t ss;
    hyst_status_t st = HYST_OK;
    size_t n, m, i, k;
    if (fit == NULL || e == NULL) {
        return HYST_ERR_NULL;
    }
    n = fit->cols;
    memset(s, 0, sizeof s);
    memset(u, 0, sizeof u);
    if (n < 2u || n > N || fit->used <= n) {
        return HYST_ERR_SINGULAR;
    }
    m = n + 1u;
    for (k = 0u; k < m; ++k) {
        root[k] = HYST_WIDE_SQRT(fit->r[hyst_packed_row_(k, m)]); /* D^1/2 */
    }
    for (i = 0u; i < n; ++i) {
        hyst_wide_t column = 0; /* |A's column i|^2 */
        for (k = 0u; k < i; ++k) {
            l[i * N + k] = root[k] * fit->r[hyst_packed_row_(k, m) + (i - k)];
            column += l[i * N + k] * l[i * N + k];
        }
        l[i * N + i] = root[i];
        column += l[i * N + i] * l[i * N + i];
        /* a column in the span of the others: rotated to rounding */
        if (!(l[i * N + i] * l[i * N + i] >
              column * (HYST_WIDE_EPS * (hyst_wide_t)(1000u * n)) * (HYST_WIDE_EPS * (hyst_wide_t)(1000u * n)))) {
            return HYST_ERR_SINGULAR;
        }
        u[i] = root[i] * fit->r[hyst_packed_row_(i, m) + (n - i)];
        s[i] = u[i];
    }
    for (i = n; i-- > 0u;) { /* L' s = u */
        for (k = i + 1u; k < n; ++k) {
            s[i] -= l[k * N + i] * s[k];
        }
        s[i] /= l[i * N + i];
    }
    to_everett(fit, s, e);
    if (constrained && !hyst_everett_monotone_(e)) {
        /* the curve refuses the unconstrained E: the least-squares E the
         * sufficient conditions accept instead */
        const int done = monotone_solve(fit, l, u, s);
        to_everett(fit, s, e);
        if (!done || !hyst_everett_monotone_(e)) {
            st = HYST_ERR_NOT_MONOTONE;
        }
    }
    if (constrained && st == HYST_OK) {
        /* flat: an E that never rises, or by rounding of the outputs'
         * spread about y_ref (|Q'y| / used^1/2) only: the nearest monotone
         * E of outputs that rise and fall */
        const hyst_wide_t parts[2] = {root[n], norm_of(u, n)};
        hyst_wide_t spread = norm_of(parts, 2u) / HYST_WIDE_SQRT((hyst_wide_t)fit->used);
        if (!hyst_wide_is_finite(spread)) {
            spread = 0; /* the residual's own square overflowed: E only has to rise */
        }
        if (!(hyst_everett_range_(e) > spread * HYST_WIDE_EPS * (hyst_wide_t)(1000u * n))) {
            st = HYST_ERR_NOT_MONOTONE;
        }
    }
    if (constrained && st == HYST_OK) { /* what else the curve refuses: its rounding bound */
        hyst_curve_t curve;
#if HYST_ENABLE_F64
        st = hyst_curve_everett_(&curve, e, (unsigned)HYST_VARIANT_F64, HYST_LAYOUT);
#else
        st = hyst_curve_everett_(&curve, e, (unsigned)HYST_VARIANT_F32, HYST_LAYOUT);
#endif
    }
    /* residual: |Q'y - R s|^2, the rows of R and the part of y no column
     * reaches (R's last diagonal entry) */
    ss = fit->r[hyst_packed_row_(n, m)];
    for (i = 0u; i < n; ++i) {
        hyst_wide_t d = u[i];
        for (k = i; k < n; ++k) {
            d -= l[k * N + i] * s[k];
        }
        ss += d * d;
    }
    if (rms != NULL) {
        *rms = HYST_WIDE_SQRT(ss / (hyst_wide_t)fit->used);
    }
    return st;
}

hyst_status_t hyst_everett_fit_solve(const hyst_everett_fit_t *fit, hyst_everett_t *e,
                                     hyst_wide_t *rms)
{
    return solve(fit, e, rms, 1);
}

hyst_status_t hyst_everett_fit_solve_unconstrained(const hyst_everett_fit_t *fit,
                                                   hyst_everett_t *e, hyst_wide_t *rms)
{
    return solve(fit, e, rms, 0);
}
