/* The Prandtl-Ishlinskii model: play operators, analytic inverse, loading curve. */
#include "hyst/pi.h"

static int is_finite(hyst_wide_t v)
{
    hyst_wide_t z = v - v;
    return z == z;
}

hyst_status_t hyst_pi_check(const hyst_real_t *r, const hyst_real_t *w, size_t n)
{
    hyst_wide_t sum = 0;
    size_t i;
    if (r == NULL || w == NULL) {
        return HYST_ERR_NULL;
    }
    if (n == 0u) {
        return HYST_ERR_ARG;
    }
    if (r[0] != 0) {
        return HYST_ERR_BREAKPOINTS;
    }
    for (i = 1u; i < n; ++i) {
        if (!is_finite((hyst_wide_t)r[i]) || !(r[i] > r[i - 1u])) {
            return HYST_ERR_BREAKPOINTS;
        }
    }
    for (i = 0u; i < n; ++i) {
        sum += (hyst_wide_t)w[i];
        if (!is_finite((hyst_wide_t)w[i]) || !(sum > 0)) {
            return HYST_ERR_WEIGHTS;
        }
    }
    return HYST_OK;
}

hyst_status_t hyst_pi_init(hyst_pi_t *P, const hyst_real_t *r, const hyst_real_t *w,
                           hyst_real_t *z, size_t n)
{
    hyst_status_t st;
    if (P == NULL || z == NULL) {
        return HYST_ERR_NULL;
    }
    st = hyst_pi_check(r, w, n);
    if (st != HYST_OK) {
        return st;
    }
    P->r = r;
    P->w = w;
    P->z = z;
    P->n = n;
    hyst_pi_reset(P);
    return HYST_OK;
}

void hyst_pi_reset(hyst_pi_t *P)
{
    size_t i;
    for (i = 0u; i < P->n; ++i) {
        P->z[i] = 0; /* then sample 0 gives max(x - r_i, min(x, 0)) */
    }
    P->x_prev = 0;
    P->y_prev = 0;
    P->status = HYST_OK;
    P->events = 0u;
}

hyst_real_t hyst_pi_step(hyst_pi_t *P, hyst_real_t x)
{
    const hyst_real_t *r = P->r;
    const hyst_real_t *w = P->w;
    hyst_real_t *z = P->z;
    const hyst_real_t nan_test = x - x;
    hyst_real_t y = 0;
    size_t i;
    HYST_TIMING_BEGIN();
    if (nan_test != nan_test) {
        P->status = HYST_ERR_NONFINITE;
        P->events |= HYST_EVENT_NONFINITE;
        HYST_TIMING_END();
        return P->y_prev;
    }
    for (i = 0u; i < P->n; ++i) {
        const hyst_real_t low = x < z[i] ? x : z[i];
        const hyst_real_t up = x - r[i];
        const hyst_real_t zi = up > low ? up : low;
        z[i] = zi;
        y += w[i] * zi;
    }
    P->status = HYST_OK;
    P->x_prev = x;
    P->y_prev = y;
    HYST_TIMING_END();
    return y;
}

hyst_status_t hyst_pi_process(hyst_pi_t *P, const hyst_real_t *x, hyst_real_t *y,
                              size_t n)
{
    int failed = 0;
    size_t i;
    if (n > 0u && (P == NULL || x == NULL || y == NULL)) {
        return HYST_ERR_NULL;
    }
    for (i = 0u; i < n; ++i) {
        y[i] = hyst_pi_step(P, x[i]);
        failed |= P->status < 0;
    }
    return failed ? HYST_ERR_NONFINITE : HYST_OK;
}

/* r'_i = f_PI(r_i), accumulated: r'_(i+1) = r'_i + W_i (r_(i+1) - r_i). */
static hyst_wide_t next_inverse_threshold(hyst_wide_t prev, hyst_wide_t slope,
                                          const hyst_real_t *r, size_t i)
{
    return prev + slope * ((hyst_wide_t)r[i] - (hyst_wide_t)r[i - 1u]);
}

/* w'_i rounded to hyst_real_t; slope = W_i, prev_slope = W_(i-1), i >= 1. */
static hyst_real_t inverse_weight(const hyst_real_t *w, size_t i, hyst_wide_t slope,
                                  hyst_wide_t prev_slope)
{
    return (hyst_real_t)(-(hyst_wide_t)w[i] / (slope * prev_slope));
}

hyst_status_t hyst_pi_inverse_params(const hyst_real_t *r, const hyst_real_t *w,
                                     size_t n, hyst_real_t *r_inv, hyst_real_t *w_inv)
{
    hyst_wide_t slope, thr, sum;
    size_t i;
    hyst_status_t st = hyst_pi_check(r, w, n);
    if (st != HYST_OK) {
        return st;
    }
    if (r_inv == NULL || w_inv == NULL) {
        return HYST_ERR_NULL;
    }
    /* Pass 1: the rounded inverse thresholds must still increase strictly,
     * and the rounded inverse weights pass hyst_pi_check() (same sums): 1/w_1
     * can overflow, and the partial sums 1/W_i can cancel to 0 once W_i/W_1
     * exceeds 1/eps. */
    slope = w[0];
    thr = 0;
    sum = (hyst_wide_t)(hyst_real_t)(1 / slope);
    if (!is_finite(sum) || !(sum > 0)) {
        return HYST_ERR_WEIGHTS;
    }
    for (i = 1u; i < n; ++i) {
        const hyst_wide_t next = next_inverse_threshold(thr, slope, r, i);
        const hyst_wide_t prev_slope = slope;
        hyst_real_t wi;
        if (!is_finite(next) || !((hyst_real_t)next > (hyst_real_t)thr)) {
            return HYST_ERR_BREAKPOINTS;
        }
        thr = next;
        slope += (hyst_wide_t)w[i];
        wi = inverse_weight(w, i, slope, prev_slope);
        sum += (hyst_wide_t)wi;
        if (!is_finite((hyst_wide_t)wi) || !(sum > 0)) {
            return HYST_ERR_WEIGHTS;
        }
    }
    /* Pass 2: write. */
    slope = w[0];
    thr = 0;
    r_inv[0] = 0;
    w_inv[0] = (hyst_real_t)(1 / slope);
    for (i = 1u; i < n; ++i) {
        const hyst_wide_t prev_slope = slope;
        thr = next_inverse_threshold(thr, slope, r, i);
        slope += (hyst_wide_t)w[i];
        r_inv[i] = (hyst_real_t)thr;
        w_inv[i] = inverse_weight(w, i, slope, prev_slope);
    }
    return HYST_OK;
}

hyst_status_t hyst_pi_init_inverse(hyst_pi_t *inv, const hyst_pi_t *fwd,
                                   hyst_real_t *r_inv, hyst_real_t *w_inv,
                                   hyst_real_t *z_inv)
{
    hyst_status_t st;
    if (inv == NULL || fwd == NULL || z_inv == NULL) {
        return HYST_ERR_NULL;
    }
    st = hyst_pi_inverse_params(fwd->r, fwd->w, fwd->n, r_inv, w_inv);
    if (st != HYST_OK) {
        return st;
    }
    return hyst_pi_init(inv, r_inv, w_inv, z_inv, fwd->n);
}

hyst_status_t hyst_pi_loading_curve(hyst_curve_t *curve, const hyst_real_t *r,
                                    const hyst_real_t *w, size_t n, hyst_real_t hi,
                                    hyst_real_t *bx, hyst_real_t *by)
{
    hyst_wide_t slope = 0, value = 0;
    size_t i;
    hyst_status_t st = hyst_pi_check(r, w, n);
    if (st != HYST_OK) {
        return st;
    }
    if (curve == NULL || bx == NULL || by == NULL) {
        return HYST_ERR_NULL;
    }
    if (!is_finite((hyst_wide_t)hi) || !(hi > r[n - 1u])) {
        return HYST_ERR_DOMAIN;
    }
    bx[0] = 0;
    by[0] = 0;
    for (i = 1u; i <= n; ++i) {
        const hyst_real_t x = i < n ? r[i] : hi;
        slope += (hyst_wide_t)w[i - 1u];
        value += slope * ((hyst_wide_t)x - (hyst_wide_t)bx[i - 1u]);
        bx[i] = x;
        by[i] = (hyst_real_t)value;
    }
    return hyst_curve_from_pwl(curve, bx, by, n + 1u);
}
