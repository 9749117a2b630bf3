/* SPDX-License-Identifier: MIT */
/* Identification of f0: streaming least squares by Givens rotations on a
 * Chebyshev basis of the scaled input t = (x - mid) / half in [-1, 1]. */
#include "hyst/ident.h"

#include "hyst_util.h"

#include <math.h>

#if defined(HYST_NO_DOUBLE)
#define WIDE_SQRT(v) sqrtf(v) /* no double math linked */
#else
#define WIDE_SQRT(v) sqrt(v)
#endif



/* Offset of row i of an m-column packed upper-triangular factor. */
static size_t row_at(unsigned i, unsigned m)
{
    return (size_t)i * m - (size_t)i * (i - 1u) / 2u;
}

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
static void givens_add(hyst_wide_t *r, unsigned m, hyst_wide_t *v)
{
    unsigned i, j;
    for (i = 0u; i < m; ++i) {
        hyst_wide_t *ri = r + row_at(i, m);
        hyst_wide_t a, rho, c, s;
        if (v[i] == 0) {
            continue;
        }
        a = ri[0];
        rho = WIDE_SQRT(a * a + v[i] * v[i]);
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
        id->cheb[k] = 0;
    }
    id->shift = 0;
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
    hyst_wide_t s = 0, big = 0, ra, rb, rc;
    hyst_ident_result_t out;
    unsigned i, j;

    if (id == NULL || res == NULL) {
        return HYST_ERR_NULL;
    }
    if (id->phase != 0) {
        return HYST_ERR_ARG;
    }
    for (i = 0u; i <= n; ++i) {
        const hyst_wide_t d = hyst_wide_abs(id->r[row_at(i, m)]);
        big = d > big ? d : big;
    }
    for (i = 0u; i <= n; ++i) {
        if (!(hyst_wide_abs(id->r[row_at(i, m)]) > big * HYST_WIDE_EPS * (hyst_wide_t)1000)) {
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
        const hyst_wide_t *ri = id->r + row_at(i, m);
        hyst_wide_t acc = ri[n + 1u - i] + s * ri[n + 2u - i];
        for (j = i + 1u; j <= n; ++j) {
            acc -= ri[j - i] * z[j];
        }
        z[i] = acc / ri[0];
    }
    ra = id->r[row_at(n + 1u, m)];
    rb = id->r[row_at(n + 1u, m) + 1u];
    rc = id->r[row_at(n + 2u, m)];
    ra += s * rb;
    rc *= s;
    out.used = id->rising + id->falling;
    out.rms = out.used > 0u ? WIDE_SQRT((ra * ra + rc * rc) / (hyst_wide_t)out.used) : 0;
    out.max_abs = -1;
    out.degree = n;
    out.method = id->method;
    out.lo = id->lo;
    out.hi = id->hi;
    out.rising = id->rising;
    out.falling = id->falling;
    for (i = 0u; i <= HYST_MAX_DEGREE; ++i) {
        out.coeffs[i] = 0;
        id->cheb[i] = i <= n ? z[i] : 0;
    }
    to_user_units(out.coeffs, z, n, id->mid, id->inv_half);
    id->shift = clenshaw(z, n, -1) + clenshaw(z, n, 1);
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
    hyst_wide_t t, e;
    int dir;
    if (id->phase != 1) {
        return HYST_ERR_ARG;
    }
    st = sample_status(id, x, y);
    if (st != HYST_OK) {
        return st;
    }
    dir = classify(&id->dir, x);
    if (dir == 0) {
        return HYST_OK;
    }
    t = (x - id->mid) * id->inv_half;
    if (dir > 0) {
        e = y - clenshaw(id->cheb, id->degree, t);
    } else {
        e = y - (id->shift - clenshaw(id->cheb, id->degree, -t));
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
    res->rms = WIDE_SQRT(id->ss / (hyst_wide_t)id->checked);
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
