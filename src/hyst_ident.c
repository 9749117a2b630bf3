/* SPDX-License-Identifier: MIT */
/* Identification of f0: streaming least squares by Givens rotations on a
 * Chebyshev basis of the scaled input t = (x - mid) / half in [-1, 1]. */
#include "hyst/ident.h"

#include "hyst_util.h"

#include <math.h>
#include <string.h>



/* T_0(t) .. T_n(t) into b[0..n]. */
static void chebyshev(hyst_wide_t *b, unsigned n, hyst_wide_t t)
{
    unsigned k;
    b[0] = 1;
    b[1] = t;
    for (k = 2u; k <= n; ++k) {
        b[k] = 2 * t * b[k - 1u] - b[k - 2u];
    }
}

/* F(t) = sum a_k T_k(t) by Clenshaw's recurrence. */
static hyst_wide_t clenshaw(const hyst_wide_t *a, unsigned n, hyst_wide_t t)
{
    hyst_wide_t b1 = 0, b2 = 0;
    unsigned k;
    for (k = n; k >= 1u; --k) {
        const hyst_wide_t b0 = 2 * t * b1 - b2 + a[k];
        b2 = b1;
        b1 = b0;
    }
    return t * b1 - b2 + a[0];
}

/* Direction of travel of x: +1 rising, -1 falling, 0 not moved yet. */
/* G(u) = sum g[k] u^k over k >= 1 (g lowest power first), Horner's rule. */
static hyst_wide_t unit_horner(const hyst_wide_t *g, unsigned n, hyst_wide_t u)
{
    hyst_wide_t acc = 0;
    unsigned k;
    for (k = n; k >= 1u; --k) {
        acc = (acc + g[k]) * u;
    }
    return acc;
}

static int classify(hyst_ident_dir_t *d, hyst_wide_t x)
{
    if (d->started && x != d->x_prev) {
        d->dir = x > d->x_prev ? 1 : -1;
    }
    d->started = 1;
    d->x_prev = x;
    return d->dir;
}

static void dir_reset(hyst_ident_dir_t *d)
{
    d->x_prev = 0;
    d->started = 0;
    d->dir = 0;
}

/* Rotates the row v (m entries, destroyed) into the factor. */
static void givens_add(hyst_wide_t *restrict r, unsigned m, hyst_wide_t *restrict v)
{
    unsigned i, j;
    for (i = 0u; i < m; ++i) {
        hyst_wide_t *ri = r + hyst_packed_row_(i, m);
        hyst_wide_t a, rho, c, s;
        if (v[i] == 0) {
            continue;
        }
        a = ri[0];
        rho = HYST_WIDE_SQRT(a * a + v[i] * v[i]);
        c = a / rho;
        s = v[i] / rho;
        ri[0] = rho;
        for (j = i + 1u; j < m; ++j) {
            const hyst_wide_t rij = ri[j - i];
            ri[j - i] = c * rij + s * v[j];
            v[j] = c * v[j] - s * rij;
        }
    }
}

/* Checks the sample shared by add and check; 0 if usable. */
static hyst_status_t sample_status(const hyst_ident_t *id, hyst_wide_t x, hyst_wide_t y)
{
    if (!hyst_wide_is_finite(x) || !hyst_wide_is_finite(y)) {
        return HYST_ERR_NONFINITE;
    }
    if (x < id->lo || x > id->hi) {
        return HYST_ERR_DOMAIN;
    }
    return HYST_OK;
}

/* A sample ignored for its output (missing: NaN) still moves the drive:
 * the next sample's direction is taken from its input, not from the last
 * one used (a record's gap would otherwise put one sample on the wrong
 * branch, an error of the loop's width in the least squares). */
static void note_direction(hyst_ident_t *id, hyst_wide_t x)
{
    if (hyst_wide_is_finite(x) && x >= id->lo && x <= id->hi) {
        (void)classify(&id->dir, x);
    }
}

static int method_of(int method)
{
    return method == HYST_IDENT_DEFAULT ? HYST_IDENT_JOINT : method;
}

hyst_status_t hyst_ident_init_(hyst_ident_t *id, const hyst_ident_config_t *cfg,
                               unsigned long layout)
{
    size_t k;
    int method;
    if (id == NULL || cfg == NULL) {
        return HYST_ERR_NULL;
    }
    if (layout != HYST_LAYOUT) {
        return HYST_ERR_LAYOUT;
    }
    if (cfg->degree < 1u || cfg->degree > HYST_MAX_DEGREE) {
        return HYST_ERR_DEGREE;
    }
    if (!hyst_wide_is_finite(cfg->lo) || !hyst_wide_is_finite(cfg->hi) || !(cfg->lo < cfg->hi) ||
        !hyst_wide_is_finite(cfg->hi - cfg->lo)) {
        return HYST_ERR_DOMAIN;
    }
    method = method_of(cfg->method);
    if (method != HYST_IDENT_JOINT && method != HYST_IDENT_REFLECT) {
        return HYST_ERR_ARG;
    }
    id->degree = cfg->degree;
    id->method = method;
    id->phase = 0;
    id->lo = cfg->lo;
    id->hi = cfg->hi;
    id->mid = cfg->lo + (cfg->hi - cfg->lo) / 2;
    id->inv_half = 2 / (cfg->hi - cfg->lo);
    for (k = 0u; k < sizeof(id->r) / sizeof(id->r[0]); ++k) {
        id->r[k] = 0;
    }
    dir_reset(&id->dir);
    id->x_min = cfg->hi;
    id->x_max = cfg->lo;
    id->sy_min = id->sy_max = 0;
    id->n_min = id->n_max = 0u;
    id->rising = id->falling = id->ignored = 0u;
    for (k = 0u; k <= HYST_MAX_DEGREE; ++k) {
        id->unit_poly[k] = 0;
    }
    id->y_top = 0;
    id->ss = 0;
    id->max_abs = 0;
    id->checked = 0u;
    return HYST_OK;
}

/* Keeps the mean output at the extreme inputs (REFLECT's y(lo), y(hi)). */
static void track_extremes(hyst_ident_t *id, hyst_wide_t x, hyst_wide_t y)
{
    if (x < id->x_min || id->n_min == 0u) {
        id->x_min = x;
        id->sy_min = 0;
        id->n_min = 0u;
    }
    if (x == id->x_min) {
        id->sy_min += y;
        ++id->n_min;
    }
    if (x > id->x_max || id->n_max == 0u) {
        id->x_max = x;
        id->sy_max = 0;
        id->n_max = 0u;
    }
    if (x == id->x_max) {
        id->sy_max += y;
        ++id->n_max;
    }
}

hyst_status_t hyst_ident_add(hyst_ident_t *id, hyst_wide_t x, hyst_wide_t y)
{
    hyst_wide_t v[HYST_IDENT_COLS];
    const unsigned n = id->degree;
    hyst_status_t st;
    hyst_wide_t t;
    int dir;

    if (id->phase != 0) {
        return HYST_ERR_ARG;
    }
    st = sample_status(id, x, y);
    if (st != HYST_OK) {
        note_direction(id, x);
        ++id->ignored;
        return st;
    }
    track_extremes(id, x, y);
    dir = classify(&id->dir, x);
    if (dir == 0) {
        ++id->ignored;
        return HYST_OK;
    }
    t = (x - id->mid) * id->inv_half;
    chebyshev(v, n, t);
    v[n + 1u] = y;
    v[n + 2u] = 0;
    if (dir > 0) {
        ++id->rising;
    } else {
        unsigned k;
        ++id->falling;
        for (k = 0u; k <= n; ++k) {
            const hyst_wide_t odd = (k & 1u) ? -1 : 1; /* T_k(-t) = (-1)^k T_k(t) */
            if (id->method == HYST_IDENT_JOINT) {
                /* f0(lo) + f0(hi) - f0(lo + hi - x): T_k(-1) + T_k(1) - T_k(-t) */
                v[k] = odd + 1 - odd * v[k];
            } else {
                /* reflected: f0(-t) = y(lo) + y(hi) - y; y(lo) + y(hi) enters at solve */
                v[k] = odd * v[k];
            }
        }
        if (id->method == HYST_IDENT_REFLECT) {
            v[n + 1u] = -y;
            v[n + 2u] = 1;
        }
    }
    givens_add(id->r, n + 3u, v);
    return HYST_OK;
}

hyst_status_t hyst_ident_lower_degree(const hyst_ident_t *id, unsigned degree,
                                      hyst_ident_t *lower)
{
    hyst_ident_t out;
    unsigned n, m, big_m, i, j;
    if (id == NULL || lower == NULL) {
        return HYST_ERR_NULL;
    }
    if (id->phase != 0) {
        return HYST_ERR_ARG;
    }
    if (degree < 1u || degree > id->degree) {
        return HYST_ERR_DEGREE;
    }
    n = id->degree;
    big_m = n + 3u;
    m = degree + 3u;
    out = *id;
    out.degree = degree;
    for (i = 0u; i < sizeof(out.r) / sizeof(out.r[0]); ++i) {
        out.r[i] = 0;
    }
    /* T_0..T_degree are the first columns of both: their rows as they are,
     * each followed by its entries of the y and reflect columns */
    for (i = 0u; i <= degree; ++i) {
        const hyst_wide_t *from = id->r + hyst_packed_row_(i, big_m);
        hyst_wide_t *to = out.r + hyst_packed_row_(i, m);
        for (j = i; j <= degree; ++j) {
            to[j - i] = from[j - i];
        }
        to[degree + 1u - i] = from[n + 1u - i];
        to[degree + 2u - i] = from[n + 2u - i];
    }
    /* what no lower column reaches: the y and reflect entries of the higher
     * rows and the trailing triangle, rotated into the new trailing one */
    for (i = degree + 1u; i < big_m; ++i) {
        const hyst_wide_t *from = id->r + hyst_packed_row_(i, big_m);
        hyst_wide_t v[2];
        v[0] = i <= n + 1u ? from[n + 1u - i] : 0;
        v[1] = from[n + 2u - i];
        givens_add(out.r + hyst_packed_row_(degree + 1u, m), 2u, v);
    }
    *lower = out;
    return HYST_OK;
}

/* Power coefficients in x, highest first, of sum a_k T_k((x - mid) * inv_half). */
static void to_user_units(hyst_wide_t *out, const hyst_wide_t *a, unsigned n,
                          hyst_wide_t mid, hyst_wide_t inv_half)
{
    hyst_wide_t tk[HYST_MAX_DEGREE + 1], tk1[HYST_MAX_DEGREE + 1];
    hyst_wide_t p[HYST_MAX_DEGREE + 1], q[HYST_MAX_DEGREE + 1];
    unsigned k, j;
    /* p(t) = sum a_k T_k(t), power basis in t, lowest first */
    for (j = 0u; j <= n; ++j) {
        tk[j] = tk1[j] = p[j] = q[j] = 0;
    }
    tk1[0] = 1; /* T_0 */
    tk[1] = 1;  /* T_1 */
    p[0] = a[0];
    for (k = 1u; k <= n; ++k) {
        for (j = 0u; j <= k; ++j) {
            p[j] += a[k] * tk[j];
        }
        if (k < n) { /* T_{k+1} = 2 t T_k - T_{k-1}, stored in tk1 */
            for (j = k + 1u; j >= 1u; --j) {
                tk1[j] = 2 * tk[j - 1u] - tk1[j];
            }
            tk1[0] = -tk1[0];
            for (j = 0u; j <= k + 1u; ++j) {
                const hyst_wide_t swap = tk[j];
                tk[j] = tk1[j];
                tk1[j] = swap;
            }
        }
    }
    /* q(x) = p(inv_half x - mid inv_half) by Horner on polynomials */
    for (k = n + 1u; k-- > 0u;) {
        for (j = n; j >= 1u; --j) { /* q *= (b + c x) */
            q[j] = q[j] * (-mid * inv_half) + q[j - 1u] * inv_half;
        }
        q[0] = q[0] * (-mid * inv_half) + p[k];
    }
    for (j = 0u; j <= n; ++j) {
        out[j] = q[n - j];
    }
}

hyst_status_t hyst_ident_solve(hyst_ident_t *id, hyst_ident_result_t *res)
{
    const unsigned n = id == NULL ? 0u : id->degree;
    const unsigned m = n + 3u;
    hyst_wide_t z[HYST_MAX_DEGREE + 1];
    hyst_wide_t g[HYST_MAX_DEGREE + 1];
    hyst_wide_t s = 0, big = 0, top = 0, ra, rb, rc;
    hyst_ident_result_t out;
    unsigned i, j;

    if (id == NULL || res == NULL) {
        return HYST_ERR_NULL;
    }
    if (id->phase != 0) {
        return HYST_ERR_ARG;
    }
    for (i = 0u; i <= n; ++i) {
        const hyst_wide_t d = hyst_wide_abs(id->r[hyst_packed_row_(i, m)]);
        big = d > big ? d : big;
    }
    for (i = 0u; i <= n; ++i) {
        if (!(hyst_wide_abs(id->r[hyst_packed_row_(i, m)]) > big * HYST_WIDE_EPS * (hyst_wide_t)1000)) {
            return HYST_ERR_SINGULAR;
        }
    }
    out.y_lo_est = out.y_hi_est = 0;
    if (id->method == HYST_IDENT_REFLECT) {
        if (id->n_min > 0u) {
            out.y_lo_est = id->sy_min / (hyst_wide_t)id->n_min;
            out.y_hi_est = id->sy_max / (hyst_wide_t)id->n_max;
        }
        s = out.y_lo_est + out.y_hi_est;
    }
    /* back substitution with right-hand side b1 + s b2 */
    for (i = n + 1u; i-- > 0u;) {
        const hyst_wide_t *ri = id->r + hyst_packed_row_(i, m);
        hyst_wide_t acc = ri[n + 1u - i] + s * ri[n + 2u - i];
        for (j = i + 1u; j <= n; ++j) {
            acc -= ri[j - i] * z[j];
        }
        z[i] = acc / ri[0];
    }
    /* The coefficients in user units are what a curve runs on: refuse them
     * where expanding about 0 costs more than a curve accepts (a domain far
     * from 0 relative to its span), as hyst_*_curve_from_poly() would. */
    to_user_units(out.coeffs, z, n, id->mid, id->inv_half);
    hyst_unit_poly_(g, out.coeffs, n, id->lo, id->hi);
    for (i = 1u; i <= n; ++i) {
        top += g[i];
    }
    {
        const hyst_wide_t err = hyst_unit_poly_error_(out.coeffs, n, id->lo, id->hi);
        if (hyst_wide_is_finite(err) && hyst_wide_is_finite(top) && /* else: not finite, below */
            err > (hyst_wide_t)HYST_MAX_ROUNDING * hyst_wide_abs(top)) {
            return HYST_ERR_ILL_CONDITIONED;
        }
    }
    ra = id->r[hyst_packed_row_(n + 1u, m)];
    rb = id->r[hyst_packed_row_(n + 1u, m) + 1u];
    rc = id->r[hyst_packed_row_(n + 2u, m)];
    ra += s * rb;
    rc *= s;
    out.used = id->rising + id->falling;
    out.rms = out.used > 0u ? HYST_WIDE_SQRT((ra * ra + rc * rc) / (hyst_wide_t)out.used) : 0;
    out.max_abs = -1;
    out.degree = n;
    out.method = id->method;
    out.lo = id->lo;
    out.hi = id->hi;
    out.rising = id->rising;
    out.falling = id->falling;
    for (i = 0u; i <= HYST_MAX_DEGREE; ++i) {
        out.coeffs[i] = i <= n ? out.coeffs[i] : 0;
        id->unit_poly[i] = i <= n ? g[i] : 0;
    }
    id->y_top = g[0] + top;
    if (id->method != HYST_IDENT_REFLECT) {
        out.y_lo_est = clenshaw(z, n, -1);
        out.y_hi_est = clenshaw(z, n, 1);
    }
    out.turn = 0;
    out.increasing = hyst_poly_is_increasing(out.coeffs, n, id->lo, id->hi, &out.turn);
    if (out.increasing) {
        out.turn = 0;
    }
    id->phase = 1;
    dir_reset(&id->dir);
    id->ss = 0;
    id->max_abs = 0;
    id->checked = 0u;
    *res = out;
    return HYST_OK;
}

hyst_status_t hyst_ident_check(hyst_ident_t *id, hyst_wide_t x, hyst_wide_t y)
{
    hyst_status_t st;
    hyst_wide_t span, e;
    int dir;
    if (id->phase != 1) {
        return HYST_ERR_ARG;
    }
    st = sample_status(id, x, y);
    if (st != HYST_OK) {
        note_direction(id, x);
        return st;
    }
    dir = classify(&id->dir, x);
    if (dir == 0) {
        return HYST_OK;
    }
    /* against the returned coefficients as a curve runs them (the branches
     * from (lo, f0(lo)) and (hi, f0(hi))), not the fit's own basis: the
     * residual is that of the model the caller gets */
    span = id->hi - id->lo;
    if (dir > 0) {
        e = y - (id->unit_poly[0] + unit_horner(id->unit_poly, id->degree, (x - id->lo) / span));
    } else {
        e = y - (id->y_top - unit_horner(id->unit_poly, id->degree, (id->hi - x) / span));
    }
    id->ss += e * e;
    e = hyst_wide_abs(e);
    id->max_abs = e > id->max_abs ? e : id->max_abs;
    ++id->checked;
    return HYST_OK;
}

hyst_status_t hyst_ident_residuals(const hyst_ident_t *id, hyst_ident_result_t *res)
{
    if (id == NULL || res == NULL) {
        return HYST_ERR_NULL;
    }
    if (id->phase != 1 || id->checked == 0u) {
        return HYST_ERR_ARG;
    }
    res->rms = HYST_WIDE_SQRT(id->ss / (hyst_wide_t)id->checked);
    res->max_abs = id->max_abs;
    return HYST_OK;
}

hyst_status_t hyst_ident_domain(const hyst_wide_t *x, size_t n, hyst_wide_t *lo,
                                hyst_wide_t *hi)
{
    hyst_wide_t a = 0, b = 0;
    int any = 0;
    size_t i;
    if (x == NULL || lo == NULL || hi == NULL) {
        return HYST_ERR_NULL;
    }
    for (i = 0u; i < n; ++i) {
        if (!hyst_wide_is_finite(x[i])) {
            continue;
        }
        if (!any || x[i] < a) {
            a = x[i];
        }
        if (!any || x[i] > b) {
            b = x[i];
        }
        any = 1;
    }
    if (!(a < b)) {
        return HYST_ERR_DOMAIN;
    }
    *lo = a;
    *hi = b;
    return HYST_OK;
}

hyst_status_t hyst_ident_fit_(const hyst_ident_config_t *cfg, const hyst_wide_t *x,
                              const hyst_wide_t *y, size_t n, hyst_ident_t *work,
                              hyst_ident_result_t *res, unsigned long layout)
{
    hyst_ident_config_t c;
    hyst_status_t st;
    size_t i, count;
    if (cfg == NULL || x == NULL || y == NULL || work == NULL || res == NULL) {
        return HYST_ERR_NULL;
    }
    if (layout != HYST_LAYOUT) {
        return HYST_ERR_LAYOUT;
    }
    if (cfg->skip >= n || cfg->delay >= n - cfg->skip) {
        return HYST_ERR_ARG;
    }
    count = n - cfg->skip - cfg->delay;
    c = *cfg;
    if (c.lo == c.hi) {
        st = hyst_ident_domain(x + c.skip, count, &c.lo, &c.hi);
        if (st != HYST_OK) {
            return st;
        }
    }
    st = hyst_ident_init(work, &c);
    if (st != HYST_OK) {
        return st;
    }
    for (i = 0u; i < count; ++i) {
        (void)hyst_ident_add(work, x[c.skip + i], y[c.skip + c.delay + i]);
    }
    st = hyst_ident_solve(work, res);
    if (st != HYST_OK) {
        return st;
    }
    for (i = 0u; i < count; ++i) {
        (void)hyst_ident_check(work, x[c.skip + i], y[c.skip + c.delay + i]);
    }
    return hyst_ident_residuals(work, res);
}

hyst_status_t hyst_ident_poly(const hyst_ident_result_t *res, hyst_poly_t *f0)
{
    hyst_poly_t out;
    unsigned k;
    if (res == NULL || f0 == NULL) {
        return HYST_ERR_NULL;
    }
    if (res->degree < 1u || res->degree > HYST_MAX_DEGREE) {
        return HYST_ERR_DEGREE;
    }
    out.degree = res->degree;
    out.lo = res->lo;
    out.hi = res->hi;
    for (k = 0u; k <= HYST_MAX_DEGREE; ++k) {
        out.coeffs[k] = k <= res->degree ? res->coeffs[k] : 0;
        if (!hyst_wide_is_finite((hyst_wide_t)out.coeffs[k]) || !hyst_wide_is_finite((hyst_wide_t)out.lo) ||
            !hyst_wide_is_finite((hyst_wide_t)out.hi)) {
            return HYST_ERR_COEFF;
        }
    }
    *f0 = out;
    return HYST_OK;
}

/* ---- Prandtl-Ishlinskii weights by non-negative least squares ----
 *
 * The workspace (HYST_PI_FIT_WORK(n) entries) holds, n = operators:
 *   [0, n)      thresholds          [n, 2n)     operator states z
 *   [2n, 3n)    means of z          [3n, 4n)    co-moments of z with y
 *   [4n, 5n)    weights w           [5n, 6n)    the passive set's solution s
 *   [6n, 7n)    gradient of the LS objective    [7n, 8n)  set flags
 *   [8n, 9n)    right-hand side / solution of the passive set, compressed
 *   [9n, 9n+5)  mean of y, co-moment of y, smallest and largest x, x seen
 *   then the n x n co-moments of z (upper triangle) and the n x n Cholesky
 *   factor of the passive set (compressed, lower triangle).
 * Co-moments about the running means (Welford) keep the offset out of the
 * normal equations: it is the free intercept, recovered from the means. */

enum { PI_R, PI_Z, PI_MZ, PI_CY, PI_W, PI_S, PI_G, PI_SET, PI_B, PI_VECTORS };
enum { PI_MY, PI_SYY, PI_XMIN, PI_XMAX, PI_XSEEN, PI_SCALARS };


static hyst_wide_t *pi_vec(const hyst_pi_fit_t *f, unsigned which)
{
    return f->work + (size_t)which * f->n;
}

static hyst_wide_t *pi_scalar(const hyst_pi_fit_t *f, unsigned which)
{
    return f->work + (size_t)PI_VECTORS * f->n + which;
}

static hyst_wide_t *pi_gram(const hyst_pi_fit_t *f)
{
    return pi_scalar(f, 0u) + PI_SCALARS;
}

/* Co-moment of operators i and j (upper triangle stored). */
static hyst_wide_t pi_c(const hyst_pi_fit_t *f, size_t i, size_t j)
{
    return i <= j ? pi_gram(f)[i * f->n + j] : pi_gram(f)[j * f->n + i];
}

hyst_status_t hyst_pi_fit_thresholds(hyst_wide_t lo, hyst_wide_t hi, size_t n, hyst_wide_t *r)
{
    size_t i;
    if (r == NULL) {
        return HYST_ERR_NULL;
    }
    if (n < 1u || n > HYST_PI_FIT_MAX_OPERATORS) {
        return HYST_ERR_ARG;
    }
    if (!hyst_wide_is_finite(lo) || !hyst_wide_is_finite(hi) || !(lo < hi) ||
        !hyst_wide_is_finite(hi - lo)) {
        return HYST_ERR_DOMAIN;
    }
    for (i = 0u; i < n; ++i) {
        r[i] = (hi - lo) * (hyst_wide_t)i / (hyst_wide_t)n;
    }
    return HYST_OK;
}

hyst_status_t hyst_pi_fit_init(hyst_pi_fit_t *fit, const hyst_wide_t *r, size_t n,
                               hyst_wide_t *work, size_t work_len)
{
    size_t i;
    if (fit == NULL || r == NULL || work == NULL) {
        return HYST_ERR_NULL;
    }
    if (n < 1u || n > HYST_PI_FIT_MAX_OPERATORS) {
        return HYST_ERR_ARG;
    }
    if (work_len < HYST_PI_FIT_WORK(n)) {
        return HYST_ERR_NOSPACE;
    }
    if (r[0] != 0) {
        return HYST_ERR_BREAKPOINTS;
    }
    for (i = 1u; i < n; ++i) {
        if (!hyst_wide_is_finite(r[i]) || !(r[i] > r[i - 1u])) {
            return HYST_ERR_BREAKPOINTS;
        }
    }
    fit->n = n;
    fit->used = fit->ignored = 0u;
    fit->phase = 0;
    fit->work = work;
    for (i = 0u; i < HYST_PI_FIT_WORK(n); ++i) {
        work[i] = 0;
    }
    for (i = 0u; i < n; ++i) {
        pi_vec(fit, PI_R)[i] = r[i];
    }
    return HYST_OK;
}

/* One step of the play operators, as hyst_pi_step() computes it. */
static void pi_operators(const hyst_wide_t *r, hyst_wide_t *z, size_t n, hyst_wide_t x)
{
    size_t i;
    for (i = 0u; i < n; ++i) {
        const hyst_wide_t low = x < z[i] ? x : z[i];
        const hyst_wide_t up = x - r[i];
        z[i] = up > low ? up : low;
    }
}

hyst_status_t hyst_pi_fit_add(hyst_pi_fit_t *fit, hyst_wide_t x, hyst_wide_t y)
{
    hyst_wide_t *z, *mz, *cy, *dz, *c, *xs;
    hyst_wide_t dy, my_new, keep;
    size_t i, j, n;
    if (fit == NULL || fit->work == NULL) {
        return HYST_ERR_NULL;
    }
    if (fit->phase != 0) {
        return HYST_ERR_ARG;
    }
    n = fit->n;
    if (!hyst_wide_is_finite(x)) {
        ++fit->ignored;
        return HYST_ERR_NONFINITE;
    }
    z = pi_vec(fit, PI_Z);
    pi_operators(pi_vec(fit, PI_R), z, n, x);
    xs = pi_scalar(fit, PI_XMIN);
    if (*pi_scalar(fit, PI_XSEEN) == 0 || x < xs[0]) {
        xs[0] = x;
    }
    if (*pi_scalar(fit, PI_XSEEN) == 0 || x > xs[1]) {
        xs[1] = x;
    }
    *pi_scalar(fit, PI_XSEEN) = 1;
    if (!hyst_wide_is_finite(y)) {
        ++fit->ignored;
        return HYST_ERR_NONFINITE;
    }
    ++fit->used;
    /* Welford: deviations from the old means (kept in the solution area,
     * unused until solve), then co-moments scaled by (k - 1) / k. */
    mz = pi_vec(fit, PI_MZ);
    cy = pi_vec(fit, PI_CY);
    dz = pi_vec(fit, PI_S);
    c = pi_gram(fit);
    keep = (hyst_wide_t)(fit->used - 1u) / (hyst_wide_t)fit->used;
    dy = y - *pi_scalar(fit, PI_MY);
    my_new = *pi_scalar(fit, PI_MY) + dy / (hyst_wide_t)fit->used;
    for (i = 0u; i < n; ++i) {
        dz[i] = z[i] - mz[i];
        mz[i] += dz[i] / (hyst_wide_t)fit->used;
    }
    for (i = 0u; i < n; ++i) {
        const hyst_wide_t di = dz[i] * keep;
        for (j = i; j < n; ++j) {
            c[i * n + j] += di * dz[j];
        }
        cy[i] += di * dy;
    }
    *pi_scalar(fit, PI_SYY) += dy * (y - my_new);
    *pi_scalar(fit, PI_MY) = my_new;
    return HYST_OK;
}

/* ---- Non-negative least squares (hyst_util.h, hyst_nnls_t), shared by
 * the PI weights and the monotone E fit (src/hyst_everett_fit.c) ---- */

#define NNLS_PASSIVE ((hyst_wide_t)1)  /* weight free (positive) */
#define NNLS_REJECTED ((hyst_wide_t)-1) /* column dependent on the passive ones */

/* Solves H_PP s_P = c_P on the passive set (Cholesky, compressed) into s;
 * 0 if the set's matrix is numerically singular or holds more than `most`. */
static int nnls_passive_solve(const hyst_nnls_t *f)
{
    const size_t n = f->n, m = f->most;
    const hyst_wide_t *set = f->set, *cy = f->c;
    hyst_wide_t *s = f->s, *b = f->b, *l = f->l;
    size_t i, j, a, p = 0u;
    for (i = 0u; i < n; ++i) {
        size_t q = 0u;
        if (set[i] != NNLS_PASSIVE) {
            continue;
        }
        if (p == m) {
            return 0;
        }
        for (j = 0u; j <= i; ++j) {
            hyst_wide_t sum;
            if (set[j] != NNLS_PASSIVE) {
                continue;
            }
            sum = f->gram(f->ctx, i, j);
            for (a = 0u; a < q; ++a) {
                sum -= l[p * m + a] * l[q * m + a];
            }
            if (q < p) {
                l[p * m + q] = sum / l[q * m + q];
            } else {
                /* a pivot this small: column i lies in the span of the others */
                if (!(sum > f->gram(f->ctx, i, i) * HYST_WIDE_EPS * (hyst_wide_t)1e4)) {
                    return 0;
                }
                l[p * m + p] = HYST_WIDE_SQRT(sum);
            }
            ++q;
        }
        b[p++] = cy[i];
    }
    for (i = 0u; i < p; ++i) { /* L u = b */
        for (a = 0u; a < i; ++a) {
            b[i] -= l[i * m + a] * b[a];
        }
        b[i] /= l[i * m + i];
    }
    for (i = p; i-- > 0u;) { /* L' s = u */
        for (a = i + 1u; a < p; ++a) {
            b[i] -= l[a * m + i] * b[a];
        }
        b[i] /= l[i * m + i];
    }
    for (i = 0u, p = 0u; i < n; ++i) {
        s[i] = set[i] == NNLS_PASSIVE ? b[p++] : 0;
    }
    return 1;
}

/* Gradient of the objective's negative half: g = c - H w. */
static void nnls_gradient(const hyst_nnls_t *f)
{
    size_t i, j;
    for (i = 0u; i < f->n; ++i) {
        hyst_wide_t acc = f->c[i];
        for (j = 0u; j < f->n; ++j) {
            acc -= f->gram(f->ctx, i, j) * f->w[j];
        }
        f->g[i] = acc;
    }
}

/* The zero weight whose gradient is largest above tol, or n if none. */
static size_t nnls_entering(const hyst_nnls_t *f, hyst_wide_t tol)
{
    const hyst_wide_t *g = f->g, *set = f->set;
    size_t i, t = f->n;
    for (i = 0u; i < f->n; ++i) {
        if (set[i] == 0 && g[i] > tol && (t == f->n || g[i] > g[t])) {
            t = i;
        }
    }
    return t;
}

/* After a passive solve s: 1 if every passive entry is positive (w = s);
 * else moves w towards s until the first weight reaches 0, frees it (and
 * any other at 0) and returns 0. */
static int nnls_step_towards(const hyst_nnls_t *f)
{
    const size_t n = f->n;
    hyst_wide_t *w = f->w, *s = f->s, *set = f->set;
    hyst_wide_t alpha = 1;
    size_t i, out = n;
    for (i = 0u; i < n; ++i) {
        if (set[i] == NNLS_PASSIVE && !(s[i] > 0)) {
            const hyst_wide_t a = w[i] / (w[i] - s[i]);
            if (out == n || a < alpha) {
                alpha = a;
                out = i;
            }
        }
    }
    if (out == n) {
        for (i = 0u; i < n; ++i) {
            w[i] = s[i];
        }
        return 1;
    }
    for (i = 0u; i < n; ++i) {
        if (set[i] == NNLS_PASSIVE) {
            w[i] += alpha * (s[i] - w[i]);
            if (i == out || !(w[i] > 0)) {
                w[i] = 0;
                set[i] = 0;
            }
        } else if (set[i] == NNLS_REJECTED) {
            set[i] = 0; /* the set changed: worth another try */
        }
    }
    return 0;
}

/* The NNLS's stop: a gradient below n rounding units of its bound
 * sqrt(C_ii syy) is rounding, NNLS_MARGIN times over. 1000 leaves 1e-12 of
 * the bound in double; in float it would leave 3e-3, and the masses of
 * narrow columns out (a grid fitted to an exact record 6 % of its range
 * off), so none there. */
#define NNLS_MARGIN (sizeof(hyst_wide_t) >= 8u ? 1000u : 1u)

/* Lawson-Hanson: grow the passive set by the most promising zero weight;
 * when its unconstrained solution has a non-positive entry, step back
 * towards it until a weight reaches 0 and free that weight again. Both
 * loops are bounded (a rounding-level cycle ends with a feasible w). */
int hyst_nnls_(const hyst_nnls_t *f, hyst_wide_t tol)
{
    const size_t n = f->n;
    hyst_wide_t *s = f->s, *set = f->set;
    size_t iter, i;
    for (i = 0u; i < n; ++i) {
        f->w[i] = 0;
        set[i] = 0;
    }
    for (iter = 0u; iter < 3u * n + 3u; ++iter) {
        size_t t, inner;
        nnls_gradient(f);
        t = nnls_entering(f, tol);
        if (t == n) {
            return 1; /* KKT: no zero weight would lower the residual */
        }
        set[t] = NNLS_PASSIVE;
        for (inner = 0u; inner <= n; ++inner) {
            if (!nnls_passive_solve(f) || (inner == 0u && !(s[t] > 0))) {
                set[t] = NNLS_REJECTED; /* cannot help: w stays as it was */
                break;
            }
            if (nnls_step_towards(f)) {
                break;
            }
        }
    }
    return 0;
}

/* ---- The turning-point stack of E's identifications (hyst_util.h),
 * shared by the polynomial E's, the grid's and the spline's
 * (src/hyst_everett_fit.c, src/hyst_everett_grid_fit.c,
 * src/hyst_spline_fit.c) ---- */

void hyst_tp_start_(hyst_wide_t *tp_x, hyst_wide_t *tp_r, size_t cols, hyst_wide_t *r_prev,
                    hyst_wide_t lo)
{
    /* A0 = (lo, output y_lo): regressors (1, 0, ...) */
    memset(tp_r, 0, cols * sizeof *tp_r);
    memset(r_prev, 0, cols * sizeof *r_prev);
    tp_r[0] = 1;
    r_prev[0] = 1;
    tp_x[0] = lo;
}

int hyst_tp_step_(hyst_wide_t *tp_x, hyst_wide_t *tp_r, size_t *n_tp, size_t capacity,
                  size_t cols, hyst_wide_t *r_prev, hyst_wide_t x_prev, hyst_wide_t x,
                  hyst_wide_t *a, hyst_wide_t *b)
{
    const int up = x > x_prev;
    size_t n = *n_tp;
    if (up != ((n - 1u) % 2u == 0u)) { /* LTPs at even places, A0 first: x_prev turned */
        if (n == capacity) {
            return 0;
        }
        tp_x[n] = x_prev;
        memcpy(tp_r + n * cols, r_prev, cols * sizeof *r_prev);
        ++n;
    }
    /* wipe-out: passed the TP before the current one */
    while (n >= 3u && (up ? x >= tp_x[n - 2u] : x <= tp_x[n - 2u])) {
        n -= 2u;
    }
    if (!up && x <= tp_x[0]) {
        n = 1u; /* back at A0 */
    }
    memcpy(r_prev, tp_r + (n - 1u) * cols, cols * sizeof *r_prev);
    *n_tp = n;
    if ((n - 1u) % 2u == 0u) { /* rising from an LTP: E(x, LTP) */
        *a = x;
        *b = tp_x[n - 1u];
        return 1;
    }
    *a = tp_x[n - 1u]; /* falling from a UTP: -E(UTP, x) */
    *b = x;
    return -1;
}

/* ---- Fits along the record's branches with y_lo free and weights >= 0
 * (hyst_util.h, hyst_branch_fit_t), on that stack: the grid's and the
 * spline's (src/hyst_everett_grid_fit.c, src/hyst_spline_fit.c). Normal
 * equations in hyst_wide_t; the weights by hyst_nnls_ with y_lo
 * eliminated. ---- */

/* Samples per block of the normal equations. The residual is a difference
 * of sums that a near-exact record makes almost equal (syy + w'Hw - 2 w'c):
 * summed a sample at a time into sums of the record's size, their rounding
 * read a 12-interval grid's RMS 2 % low at noise 1e-6 of the range over 1e5
 * samples, and 0 at 1e-7. A block's sums stay a block's size and go into
 * compensated totals, one addition a block: 1e-4 at 1e-6 (its rounding in
 * double leaves about 1 % at 1e-7). The per-sample loop stays as it was. */
#define BRANCH_BLOCK 128u

/* A pivot of the centred Gram below this fraction of its diagonal entry (1e4
 * roundings) leaves a weight undetermined (hyst_branch_fit_determined_());
 * where one does, the solve adds a ridge of this fraction of the largest
 * diagonal entry: directions so weak get a ridge of their size, the others
 * shrink by far less than the fits' tolerances. */
#define BRANCH_RIDGE (HYST_WIDE_EPS * (hyst_wide_t)1e4)

/* *hi + *lo += v, *lo gathering *hi's rounding errors (Knuth's TwoSum) */
static void add_compensated(hyst_wide_t *hi, hyst_wide_t *lo, hyst_wide_t v)
{
    const hyst_wide_t sum = *hi + v, v_part = sum - *hi;
    *lo += (*hi - (sum - v_part)) + (v - v_part);
    *hi = sum;
}

/* The block's sums into the totals (their zeros skipped: the grid's rows
 * of cells no sample of the block reached), the block emptied. */
static void branch_flush(hyst_branch_fit_t *f)
{
    const size_t cols = f->cols, half = cols * (cols + 3u) / 2u;
    hyst_wide_t *hi = f->total, *lo = f->total + half, *block;
    size_t i, j, k = 0u;
    for (i = 0u; i < cols; ++i) {
        for (j = 0u; j <= i; ++j, ++k) {
            block = f->ata + i * cols + j;
            if (*block != 0) {
                add_compensated(hi + k, lo + k, *block);
                *block = 0;
            }
        }
    }
    for (i = 0u; i < cols; ++i, ++k) {
        if (f->aty[i] != 0) {
            add_compensated(hi + k, lo + k, f->aty[i]);
            f->aty[i] = 0;
        }
    }
    add_compensated(&f->yy_total[0], &f->yy_total[1], f->yy);
    f->yy = 0;
    f->in_block = 0u;
}

/* A'A's (i, j), j <= i, A'y's i and y'y over every sample: the blocks'
 * sums, their rounding errors and the block's. */
static hyst_wide_t branch_ata(const hyst_branch_fit_t *f, size_t i, size_t j)
{
    const size_t k = i * (i + 1u) / 2u + j, half = f->cols * (f->cols + 3u) / 2u;
    return f->total[k] + (f->total[half + k] + f->ata[i * f->cols + j]);
}

static hyst_wide_t branch_aty(const hyst_branch_fit_t *f, size_t i)
{
    const size_t k = f->cols * (f->cols + 1u) / 2u + i, half = f->cols * (f->cols + 3u) / 2u;
    return f->total[k] + (f->total[half + k] + f->aty[i]);
}

static hyst_wide_t branch_yy(const hyst_branch_fit_t *f)
{
    return f->yy_total[0] + (f->yy_total[1] + f->yy);
}

void hyst_branch_fit_start_(hyst_branch_fit_t *f, size_t cols, hyst_wide_t lo, hyst_wide_t hi,
                            hyst_wide_t *work, size_t work_len)
{
    memset(f, 0, sizeof *f);
    f->cols = cols;
    f->lo = lo;
    f->hi = hi;
    /* fixed parts first, the TPs in the rest */
    f->ata = work;
    f->solver = f->ata + cols * cols;
    f->aty = f->solver + 2u * cols * cols + 7u * cols;
    f->total = f->aty + cols;
    f->r_prev = f->total + cols * (cols + 3u);
    f->capacity = (work_len - (size_t)(f->r_prev + cols - work)) / (cols + 1u);
    f->tp_x = f->r_prev + cols;
    f->tp_r = f->tp_x + f->capacity;
    memset(work, 0, (size_t)(f->tp_x - work) * sizeof *work);
    hyst_tp_start_(f->tp_x, f->tp_r, cols, f->r_prev, lo);
    f->n_tp = 1u;
    f->x_prev = lo;
}

hyst_status_t hyst_branch_fit_add_(hyst_branch_fit_t *f, hyst_wide_t x, hyst_wide_t y,
                                   hyst_branch_terms_t terms, const void *ctx)
{
    const hyst_wide_t *r;
    size_t i, j, cols;
    if (!hyst_wide_is_finite(x)) {
        return HYST_ERR_NONFINITE;
    }
    if (x < f->lo || x > f->hi) {
        return HYST_ERR_DOMAIN;
    }
    if (x > f->x_prev || x < f->x_prev) {
        hyst_wide_t a, b;
        const int sign = hyst_tp_step_(f->tp_x, f->tp_r, &f->n_tp, f->capacity, f->cols,
                                       f->r_prev, f->x_prev, x, &a, &b);
        if (sign == 0) {
            return HYST_ERR_NOSPACE;
        }
        terms(ctx, a, b, (hyst_wide_t)sign, f->r_prev);
        f->x_prev = x;
    }
    if (!hyst_wide_is_finite(y)) {
        return HYST_ERR_NONFINITE;
    }
    if (f->used == 0u) {
        f->y_ref = y;
    }
    y -= f->y_ref;
    r = f->r_prev;
    cols = f->cols;
    for (i = 0u; i < cols; ++i) {
        const hyst_wide_t r_i = r[i]; /* read once: the row's stores may alias r */
        if (r_i != 0) { /* most grid cells are 0 on a branch: skip their rows */
            hyst_wide_t *row = f->ata + i * cols;
            for (j = 0u; j <= i; ++j) {
                row[j] += r_i * r[j];
            }
            f->aty[i] += r_i * y;
        }
    }
    f->yy += y * y;
    ++f->used;
    if (++f->in_block == BRANCH_BLOCK) {
        branch_flush(f);
    }
    return HYST_OK;
}

/* The weights' normal equations with y_lo eliminated into h (m x m, m the
 * weights) and c (m): H = A'A - s s' / n over the weights, s their sums;
 * the largest diagonal entry returned. */
static hyst_wide_t branch_centre(const hyst_branch_fit_t *f, hyst_wide_t *h, hyst_wide_t *c)
{
    const size_t cols = f->cols, m = cols - 1u;
    const hyst_wide_t n = (hyst_wide_t)f->used;
    hyst_wide_t big = 0;
    size_t i, j;
    for (i = 0u; i < m; ++i) {
        const hyst_wide_t si = branch_ata(f, i + 1u, 0u);
        for (j = 0u; j <= i; ++j) {
            const hyst_wide_t v =
                branch_ata(f, i + 1u, j + 1u) - si * branch_ata(f, j + 1u, 0u) / n;
            h[i * m + j] = v;
            h[j * m + i] = v;
        }
        c[i] = branch_aty(f, i + 1u) - si * branch_aty(f, 0u) / n;
        big = h[i * m + i] > big ? h[i * m + i] : big;
    }
    return big;
}

/* Whether the centred Gram h (m x m) determines every weight: h = L L' into
 * l (m x m), each pivot above BRANCH_RIDGE of its diagonal entry. */
static int branch_factors(const hyst_wide_t *h, size_t m, hyst_wide_t *l)
{
    size_t i, j, k;
    for (i = 0u; i < m; ++i) {
        for (j = 0u; j <= i; ++j) {
            hyst_wide_t sum = h[i * m + j];
            for (k = 0u; k < j; ++k) {
                sum -= l[i * m + k] * l[j * m + k];
            }
            if (i > j) {
                l[i * m + j] = sum / l[j * m + j];
            } else if (sum > h[i * m + i] * BRANCH_RIDGE) {
                l[i * m + i] = HYST_WIDE_SQRT(sum);
            } else {
                return 0; /* a weight's column in the span of the others' */
            }
        }
    }
    return 1;
}

int hyst_branch_fit_determined_(const hyst_branch_fit_t *f)
{
    size_t m;
    hyst_wide_t *h;
    if (f->used < 2u) {
        return 0;
    }
    m = f->cols - 1u;
    h = f->solver;
    (void)branch_centre(f, h, h + m * m);
    return branch_factors(h, m, h + m * m + m); /* the factor where the solve keeps its weights */
}

/* The centred Gram (the solver's first m^2 numbers) for the NNLS, with a
 * ridge on its diagonal. */
typedef struct {
    const hyst_wide_t *h;
    size_t m;
    hyst_wide_t ridge;
} branch_centred_t;

static hyst_wide_t branch_gram(const void *ctx, size_t i, size_t j)
{
    const branch_centred_t *c = (const branch_centred_t *)ctx;
    return c->h[i * c->m + j] + (i == j ? c->ridge : 0);
}

hyst_status_t hyst_branch_fit_solve_(const hyst_branch_fit_t *f, const hyst_wide_t **w_out,
                                     hyst_wide_t *y_lo, hyst_wide_t *rms)
{
    const size_t cols = f->cols, m = cols - 1u;
    hyst_wide_t *h, *c, *w, n, big, sum_y, syy, tol, rss, sum = 0, offset;
    branch_centred_t ctx;
    hyst_nnls_t p;
    size_t i, j;
    int undetermined;
    if (f->used < 2u) {
        return HYST_ERR_SINGULAR;
    }
    n = (hyst_wide_t)f->used;
    h = f->solver;
    c = h + m * m;
    w = c + m;
    big = branch_centre(f, h, c);
    /* A record that does not determine every weight leaves solutions that
     * fit it alike, and the NNLS's order of entry would pick one by rounding
     * (1e-12 of the outputs moved a grid's prediction of a measured record's
     * last third between 1.17 % and 1.00 % of its range): a ridge makes the
     * one returned that of least squared weights among them, whatever the
     * rounding. A determined fit is left as it is. The factor goes where the
     * NNLS then works. */
    undetermined = !branch_factors(h, m, w);
    sum_y = branch_aty(f, 0u);
    syy = branch_yy(f) - sum_y * sum_y / n;
    tol = HYST_WIDE_SQRT(big * (syy > 0 ? syy : 0)) * HYST_WIDE_EPS * (hyst_wide_t)(NNLS_MARGIN * m);
    ctx.h = h;
    ctx.m = m;
    ctx.ridge = undetermined ? big * BRANCH_RIDGE : 0;
    p.n = m;
    p.gram = branch_gram;
    p.ctx = &ctx;
    p.c = c;
    p.w = w;
    p.s = w + m;
    p.g = w + 2u * m;
    p.set = w + 3u * m;
    p.b = w + 4u * m;
    p.l = w + 5u * m; /* m x m: the rest of the solver's numbers */
    p.most = m;
    if (big > 0) {
        (void)hyst_nnls_(&p, tol);
    } else {
        memset(w, 0, m * sizeof *w);
    }
    rss = syy;
    offset = sum_y;
    for (i = 0u; i < m; ++i) {
        hyst_wide_t hw = 0;
        for (j = 0u; j < m; ++j) {
            hw += h[i * m + j] * w[j];
        }
        rss += w[i] * (hw - 2 * c[i]);
        offset -= w[i] * branch_ata(f, i + 1u, 0u);
        sum += w[i];
    }
    /* outputs so large that the normal equations overflow: no fit (a NaN
     * residual would read as 0 below) */
    if (!hyst_wide_is_finite(sum) || !hyst_wide_is_finite(rss) ||
        !hyst_wide_is_finite(f->y_ref + offset / n)) {
        return HYST_ERR_COEFF;
    }
    *w_out = w;
    *y_lo = f->y_ref + offset / n;
    *rms = HYST_WIDE_SQRT((rss > 0 ? rss : 0) / n);
    return sum > 0 ? HYST_OK : HYST_ERR_NOT_MONOTONE;
}

static hyst_wide_t pi_gram_at(const void *ctx, size_t i, size_t j)
{
    return pi_c((const hyst_pi_fit_t *)ctx, i, j);
}

/* The PI weights' problem in the fit's workspace (layout above). */
static void pi_nnls(const hyst_pi_fit_t *f, hyst_wide_t tol)
{
    hyst_nnls_t p;
    p.n = f->n;
    p.gram = pi_gram_at;
    p.ctx = f;
    p.c = pi_vec(f, PI_CY);
    p.w = pi_vec(f, PI_W);
    p.s = pi_vec(f, PI_S);
    p.g = pi_vec(f, PI_G);
    p.set = pi_vec(f, PI_SET);
    p.b = pi_vec(f, PI_B);
    p.l = pi_gram(f) + f->n * f->n;
    p.most = f->n;
    (void)hyst_nnls_(&p, tol);
}

hyst_status_t hyst_pi_fit_solve(hyst_pi_fit_t *fit, hyst_wide_t *w, hyst_pi_fit_result_t *res)
{
    hyst_wide_t big = 0, syy, tol, rss, offset;
    const hyst_wide_t *wk, *cy, *mz;
    size_t i, j, n;
    hyst_pi_fit_result_t out;
    if (fit == NULL || fit->work == NULL || w == NULL || res == NULL) {
        return HYST_ERR_NULL;
    }
    if (fit->phase != 0) {
        return HYST_ERR_ARG;
    }
    n = fit->n;
    if (fit->used < n + 1u) {
        return HYST_ERR_SINGULAR;
    }
    if (!(*pi_scalar(fit, PI_XMAX) > *pi_scalar(fit, PI_XMIN))) {
        return HYST_ERR_DOMAIN;
    }
    for (i = 0u; i < n; ++i) {
        big = pi_c(fit, i, i) > big ? pi_c(fit, i, i) : big;
    }
    if (!(big > 0)) {
        return HYST_ERR_DOMAIN; /* the inputs used never moved */
    }
    syy = *pi_scalar(fit, PI_SYY);
    /* |cy_i| <= sqrt(C_ii syy): a gradient below this share of the bound is rounding */
    tol = HYST_WIDE_SQRT(big * syy) * HYST_WIDE_EPS * (hyst_wide_t)(NNLS_MARGIN * n);
    pi_nnls(fit, tol);
    wk = pi_vec(fit, PI_W);
    cy = pi_vec(fit, PI_CY);
    mz = pi_vec(fit, PI_MZ);
    out.operators = n;
    out.positive = 0u;
    offset = *pi_scalar(fit, PI_MY);
    rss = syy;
    for (i = 0u; i < n; ++i) {
        hyst_wide_t cw = 0;
        for (j = 0u; j < n; ++j) {
            cw += pi_c(fit, i, j) * wk[j];
        }
        rss += wk[i] * (cw - 2 * cy[i]);
        offset -= wk[i] * mz[i];
        out.positive += wk[i] > 0 ? 1u : 0u;
        w[i] = wk[i];
    }
    out.offset = offset;
    out.rms = HYST_WIDE_SQRT((rss > 0 ? rss : 0) / (hyst_wide_t)fit->used);
    out.max_abs = -1;
    out.used = fit->used;
    out.invertible = wk[0] > 0;
    fit->phase = 1;
    *res = out;
    return HYST_OK;
}

hyst_status_t hyst_pi_fit_record(const hyst_pi_fit_config_t *cfg, const hyst_wide_t *x,
                                 const hyst_wide_t *y, size_t n, hyst_wide_t *work,
                                 size_t work_len, hyst_wide_t *r, hyst_wide_t *w,
                                 hyst_pi_fit_result_t *res)
{
    hyst_pi_fit_t fit;
    hyst_pi_fit_result_t out;
    hyst_status_t st;
    hyst_wide_t ss = 0, worst = 0;
    size_t i, k, count, ops;
    if (cfg == NULL || x == NULL || y == NULL || work == NULL || r == NULL || w == NULL ||
        res == NULL) {
        return HYST_ERR_NULL;
    }
    ops = cfg->operators;
    if (ops < 1u || ops > HYST_PI_FIT_MAX_OPERATORS) {
        return HYST_ERR_ARG;
    }
    if (cfg->skip >= n || cfg->delay >= n - cfg->skip) {
        return HYST_ERR_ARG;
    }
    count = n - cfg->skip - cfg->delay;
    for (i = 0u; i < count; ++i) {
        if (!hyst_wide_is_finite(x[cfg->skip + i]) ||
            !hyst_wide_is_finite(y[cfg->skip + cfg->delay + i])) {
            return HYST_ERR_NONFINITE;
        }
    }
    if (cfg->thresholds != NULL) {
        for (i = 0u; i < ops; ++i) {
            r[i] = cfg->thresholds[i];
        }
    } else {
        hyst_wide_t lo, hi;
        st = hyst_ident_domain(x + cfg->skip, count, &lo, &hi);
        if (st == HYST_OK) {
            st = hyst_pi_fit_thresholds(lo, hi, ops, r);
        }
        if (st != HYST_OK) {
            return st;
        }
    }
    st = hyst_pi_fit_init(&fit, r, ops, work, work_len);
    if (st != HYST_OK) {
        return st;
    }
    for (i = 0u; i < count; ++i) {
        (void)hyst_pi_fit_add(&fit, x[cfg->skip + i], y[cfg->skip + cfg->delay + i]);
    }
    st = hyst_pi_fit_solve(&fit, w, &out);
    if (st != HYST_OK) {
        return st;
    }
    /* second pass: the fitted model from reset, as hyst_pi_step() runs it */
    for (k = 0u; k < ops; ++k) {
        pi_vec(&fit, PI_Z)[k] = 0;
    }
    for (i = 0u; i < count; ++i) {
        hyst_wide_t e = y[cfg->skip + cfg->delay + i] - out.offset;
        pi_operators(r, pi_vec(&fit, PI_Z), ops, x[cfg->skip + i]);
        for (k = 0u; k < ops; ++k) {
            e -= w[k] * pi_vec(&fit, PI_Z)[k];
        }
        ss += e * e;
        e = hyst_wide_abs(e);
        worst = e > worst ? e : worst;
    }
    out.rms = HYST_WIDE_SQRT(ss / (hyst_wide_t)count);
    out.max_abs = worst;
    *res = out;
    return HYST_OK;
}
