/* SPDX-License-Identifier: MIT */
/* Identification of the asymmetric kind's E (ident.h, hyst_everett_fit_*):
 * Madelung's rules run on the recorded inputs; each stacked turning point
 * keeps the regressors of its output, as the model keeps the output, so a
 * sample's row is the current TP's plus or minus the terms of E between
 * them. Normal equations in hyst_wide_t, solved by Cholesky's method. */
#include "hyst/ident.h"

#include "hyst_util.h"

#include <math.h>
#include <string.h>

#if defined(HYST_NO_DOUBLE)
#define WIDE_SQRT(v) sqrtf(v) /* no double math linked */
#else
#define WIDE_SQRT(v) sqrt(v)
#endif

/* Regressors of E(a, b): w^i t^j for i = 1..n, j = 0..n - i (column 1 on;
 * column 0 is the output at lo), scaled by `sign`, added to r. */
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
        for (j = 0u; i + j <= f->degree; ++j) {
            r[col++] += wi * tj;
            tj *= t;
        }
    }
}

hyst_status_t hyst_everett_fit_init(hyst_everett_fit_t *fit, unsigned degree, hyst_wide_t lo,
                                    hyst_wide_t hi, hyst_wide_t *work, size_t work_len)
{
    if (fit == NULL || work == NULL) {
        return HYST_ERR_NULL;
    }
    if (degree < 1u || degree > (unsigned)HYST_EVERETT_MAX_DEGREE) {
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
    fit->cols = 1u + (size_t)degree * (degree + 1u) / 2u;
    fit->lo = lo;
    fit->hi = hi;
    fit->capacity = work_len / (HYST_EVERETT_FIT_COLS + 1u);
    fit->tp_x = work;
    fit->tp_r = work + fit->capacity;
    /* A0 = (lo, output y_lo): regressors (1, 0, ...) */
    memset(fit->tp_r, 0, fit->cols * sizeof fit->tp_r[0]);
    fit->tp_r[0] = 1;
    fit->tp_x[0] = lo;
    fit->n_tp = 1u;
    fit->x_prev = lo;
    fit->r_prev[0] = 1;
    return HYST_OK;
}

/* Pushes the last sample as a turning point. */
static int push(hyst_everett_fit_t *f)
{
    if (f->n_tp == f->capacity) {
        return 0;
    }
    f->tp_x[f->n_tp] = f->x_prev;
    memcpy(f->tp_r + f->n_tp * f->cols, f->r_prev, f->cols * sizeof f->r_prev[0]);
    ++f->n_tp;
    return 1;
}

hyst_status_t hyst_everett_fit_add(hyst_everett_fit_t *fit, hyst_wide_t x, hyst_wide_t y)
{
    int rising;
    size_t i, j;
    if (fit == NULL) {
        return HYST_ERR_NULL;
    }
    if (!hyst_wide_is_finite(x)) {
        return HYST_ERR_NONFINITE;
    }
    if (x < fit->lo || x > fit->hi) {
        return HYST_ERR_DOMAIN;
    }
    rising = (fit->n_tp - 1u) % 2u == 0u; /* LTPs at even places, A0 first */
    if (x > fit->x_prev || x < fit->x_prev) {
        const int up = x > fit->x_prev;
        if (up != rising && !push(fit)) {
            return HYST_ERR_NOSPACE;
        }
        /* wipe-out: passed the TP before the current one */
        while (fit->n_tp >= 3u &&
               (up ? x >= fit->tp_x[fit->n_tp - 2u] : x <= fit->tp_x[fit->n_tp - 2u])) {
            fit->n_tp -= 2u;
        }
        if (!up && x <= fit->lo) {
            fit->n_tp = 1u; /* back at A0 */
        }
        {
            const hyst_wide_t ctp = fit->tp_x[fit->n_tp - 1u];
            memcpy(fit->r_prev, fit->tp_r + (fit->n_tp - 1u) * fit->cols,
                   fit->cols * sizeof fit->r_prev[0]);
            if ((fit->n_tp - 1u) % 2u == 0u) {
                add_terms(fit, x, ctp, 1, fit->r_prev);
            } else {
                add_terms(fit, ctp, x, -1, fit->r_prev);
            }
        }
        fit->x_prev = x;
    }
    if (!hyst_wide_is_finite(y)) {
        return HYST_ERR_NONFINITE;
    }
    for (i = 0u; i < fit->cols; ++i) {
        for (j = 0u; j <= i; ++j) {
            fit->ata[i * HYST_EVERETT_FIT_COLS + j] += fit->r_prev[i] * fit->r_prev[j];
        }
        fit->aty[i] += fit->r_prev[i] * y;
    }
    fit->yy += y * y;
    ++fit->used;
    return HYST_OK;
}

hyst_status_t hyst_everett_fit_solve(const hyst_everett_fit_t *fit, hyst_everett_t *e,
                                     hyst_wide_t *rms)
{
    hyst_wide_t l[HYST_EVERETT_FIT_COLS * HYST_EVERETT_FIT_COLS];
    hyst_wide_t s[HYST_EVERETT_FIT_COLS];
    hyst_wide_t ss;
    size_t n, i, j, k, col;
    unsigned a, b;
    if (fit == NULL || e == NULL) {
        return HYST_ERR_NULL;
    }
    n = fit->cols;
    memset(s, 0, sizeof s);
    if (n < 2u || n > HYST_EVERETT_FIT_COLS || fit->used <= n) {
        return HYST_ERR_SINGULAR;
    }
    for (i = 0u; i < n; ++i) { /* A = L L' */
        for (j = 0u; j <= i; ++j) {
            hyst_wide_t sum = fit->ata[i * HYST_EVERETT_FIT_COLS + j];
            for (k = 0u; k < j; ++k) {
                sum -= l[i * HYST_EVERETT_FIT_COLS + k] * l[j * HYST_EVERETT_FIT_COLS + k];
            }
            if (i > j) {
                l[i * HYST_EVERETT_FIT_COLS + j] = sum / l[j * HYST_EVERETT_FIT_COLS + j];
            } else if (sum > fit->ata[i * HYST_EVERETT_FIT_COLS + i] * HYST_WIDE_EPS * (hyst_wide_t)1e4) {
                l[i * HYST_EVERETT_FIT_COLS + i] = WIDE_SQRT(sum);
            } else {
                return HYST_ERR_SINGULAR; /* a column in the span of the others */
            }
        }
    }
    for (i = 0u; i < n; ++i) { /* L u = A'y */
        s[i] = fit->aty[i];
        for (k = 0u; k < i; ++k) {
            s[i] -= l[i * HYST_EVERETT_FIT_COLS + k] * s[k];
        }
        s[i] /= l[i * HYST_EVERETT_FIT_COLS + i];
    }
    for (i = n; i-- > 0u;) { /* L' s = u */
        for (k = i + 1u; k < n; ++k) {
            s[i] -= l[k * HYST_EVERETT_FIT_COLS + i] * s[k];
        }
        s[i] /= l[i * HYST_EVERETT_FIT_COLS + i];
    }
    /* residual: y'y - 2 s'A'y + s'A s */
    ss = fit->yy;
    for (i = 0u; i < n; ++i) {
        hyst_wide_t as = 0;
        for (j = 0u; j < n; ++j) {
            as += (i >= j ? fit->ata[i * HYST_EVERETT_FIT_COLS + j]
                          : fit->ata[j * HYST_EVERETT_FIT_COLS + i]) *
                  s[j];
        }
        ss += s[i] * (as - 2 * fit->aty[i]);
    }
    memset(e, 0, sizeof *e);
    e->degree = fit->degree;
    e->lo = fit->lo;
    e->hi = fit->hi;
    e->y_lo = s[0];
    for (a = 1u, col = 1u; a <= fit->degree; ++a) {
        for (b = 0u; a + b <= fit->degree; ++b) {
            e->e[a - 1u][b] = s[col++];
        }
    }
    if (rms != NULL) {
        *rms = WIDE_SQRT((ss > 0 ? ss : 0) / (hyst_wide_t)fit->used);
    }
    return HYST_OK;
}
