/* SPDX-License-Identifier: MIT */
/* The Prandtl-Ishlinskii model in one real type: play operators, analytic
 * inverse, loading curve. Instantiated by src/variant_real.h. */
#ifndef HYST_PI_MODEL_H
#define HYST_PI_MODEL_H

#ifndef HYST_CURVE_EVAL_H
#error "pi_model.h: include src/curve_eval.h first"
#endif

static hyst_status_t NUM_NAME(pi_check_impl)(const NUM_T *r, const NUM_T *w, size_t n)
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
        if (!hyst_wide_is_finite((hyst_wide_t)r[i]) || !(r[i] > r[i - 1u])) {
            return HYST_ERR_BREAKPOINTS;
        }
    }
    for (i = 0u; i < n; ++i) {
        sum += (hyst_wide_t)w[i];
        if (!hyst_wide_is_finite((hyst_wide_t)w[i]) || !(sum > 0)) {
            return HYST_ERR_WEIGHTS;
        }
    }
    return HYST_OK;
}

static hyst_status_t NUM_NAME(pi_init_impl)(hyst_pi_t *P, const NUM_T *r, const NUM_T *w, NUM_T *z, size_t n,
                                 unsigned long layout)
{
    hyst_status_t st;
    if (P == NULL || z == NULL) {
        return HYST_ERR_NULL;
    }
    if (layout != HYST_LAYOUT) {
        return HYST_ERR_LAYOUT;
    }
    st = NUM_NAME(pi_check_impl)(r, w, n);
    if (st != HYST_OK) {
        return st;
    }
    P->variant = NUM_VARIANT;
    P->r.NUM_F = r;
    P->w.NUM_F = w;
    P->z.NUM_F = z;
    P->n = n;
    hyst_pi_reset(P);
    return HYST_OK;
}

HYST_INLINE NUM_T NUM_NAME(pi_step_impl)(hyst_pi_t *P, NUM_T x)
{
    const NUM_T *r, *w;
    NUM_T *z;
    NUM_T y = 0;
    size_t i;
    if (P == NULL) {
        return 0;
    }
    r = P->r.NUM_F;
    w = P->w.NUM_F;
    z = P->z.NUM_F;
    if (!NUM_NAME(is_finite)(x)) {
        P->status = HYST_ERR_NONFINITE;
        P->events |= HYST_EVENT_NONFINITE;
        return P->y_prev.NUM_F;
    }
    for (i = 0u; i < P->n; ++i) {
        const NUM_T low = x < z[i] ? x : z[i];
        const NUM_T up = x - r[i];
        const NUM_T zi = up > low ? up : low;
        z[i] = zi;
        y = NUM_MULADD(w[i], zi, y);
    }
    P->status = HYST_OK;
    P->x_prev.NUM_F = x;
    P->y_prev.NUM_F = y;
    return y;
}

HYST_INLINE hyst_status_t NUM_NAME(pi_process_impl)(hyst_pi_t *P, const NUM_T *x, NUM_T *y,
                              size_t n)
{
    int failed = 0;
    size_t i;
    if (n > 0u && (P == NULL || x == NULL || y == NULL)) {
        return HYST_ERR_NULL;
    }
    if (hyst_block_overlap(x, sizeof *x, y, sizeof *y, n)) {
        return HYST_ERR_OVERLAP;
    }
    for (i = 0u; i < n; ++i) {
        y[i] = NUM_NAME(pi_step_impl)(P, x[i]);
        failed |= P->status < 0;
    }
    return failed ? HYST_ERR_NONFINITE : HYST_OK;
}

/* r'_i = f_PI(r_i), accumulated: r'_(i+1) = r'_i + W_i (r_(i+1) - r_i). */
static hyst_wide_t NUM_NAME(next_inverse_threshold)(hyst_wide_t prev, hyst_wide_t slope,
                                          const NUM_T *r, size_t i)
{
    return prev + slope * ((hyst_wide_t)r[i] - (hyst_wide_t)r[i - 1u]);
}

/* w'_i rounded to NUM_T; slope = W_i, prev_slope = W_(i-1), i >= 1. */
static NUM_T NUM_NAME(inverse_weight)(const NUM_T *w, size_t i, hyst_wide_t slope,
                                  hyst_wide_t prev_slope)
{
    return (NUM_T)(-(hyst_wide_t)w[i] / (slope * prev_slope));
}

static hyst_status_t NUM_NAME(pi_inverse_params_impl)(const NUM_T *r, const NUM_T *w,
                                     size_t n, NUM_T *r_inv, NUM_T *w_inv)
{
    hyst_wide_t slope, thr, sum;
    size_t i;
    hyst_status_t st = NUM_NAME(pi_check_impl)(r, w, n);
    if (st != HYST_OK) {
        return st;
    }
    if (r_inv == NULL || w_inv == NULL) {
        return HYST_ERR_NULL;
    }
    /* Pass 1: the rounded inverse thresholds must still increase strictly,
     * and the rounded inverse weights pass NUM_NAME(pi_check)() (same sums): 1/w_1
     * can overflow, and the partial sums 1/W_i can cancel to 0 once W_i/W_1
     * exceeds 1/eps. */
    slope = (hyst_wide_t)w[0];
    thr = 0;
    sum = (hyst_wide_t)(NUM_T)(1 / slope);
    if (!hyst_wide_is_finite(sum) || !(sum > 0)) {
        return HYST_ERR_WEIGHTS;
    }
    for (i = 1u; i < n; ++i) {
        const hyst_wide_t next = NUM_NAME(next_inverse_threshold)(thr, slope, r, i);
        const hyst_wide_t prev_slope = slope;
        NUM_T wi;
        if (!hyst_wide_is_finite(next) || !((NUM_T)next > (NUM_T)thr)) {
            return HYST_ERR_BREAKPOINTS;
        }
        thr = next;
        slope += (hyst_wide_t)w[i];
        wi = NUM_NAME(inverse_weight)(w, i, slope, prev_slope);
        sum += (hyst_wide_t)wi;
        if (!hyst_wide_is_finite((hyst_wide_t)wi) || !(sum > 0)) {
            return HYST_ERR_WEIGHTS;
        }
    }
    /* Pass 2: write. */
    slope = (hyst_wide_t)w[0];
    thr = 0;
    r_inv[0] = 0;
    w_inv[0] = (NUM_T)(1 / slope);
    for (i = 1u; i < n; ++i) {
        const hyst_wide_t prev_slope = slope;
        thr = NUM_NAME(next_inverse_threshold)(thr, slope, r, i);
        slope += (hyst_wide_t)w[i];
        r_inv[i] = (NUM_T)thr;
        w_inv[i] = NUM_NAME(inverse_weight)(w, i, slope, prev_slope);
    }
    return HYST_OK;
}

static hyst_status_t NUM_NAME(pi_init_inverse_impl)(hyst_pi_t *inv, const hyst_pi_t *fwd, NUM_T *r_inv,
                                         NUM_T *w_inv, NUM_T *z_inv, unsigned long layout)
{
    hyst_status_t st;
    if (inv == NULL || fwd == NULL || z_inv == NULL) {
        return HYST_ERR_NULL;
    }
    if (layout != HYST_LAYOUT) {
        return HYST_ERR_LAYOUT;
    }
    if (fwd->variant != (unsigned)NUM_VARIANT) {
        return HYST_ERR_ARG;
    }
    st = NUM_NAME(pi_inverse_params_impl)(fwd->r.NUM_F, fwd->w.NUM_F, fwd->n, r_inv, w_inv);
    if (st != HYST_OK) {
        return st;
    }
    return NUM_NAME(pi_init_impl)(inv, r_inv, w_inv, z_inv, fwd->n, layout);
}

static hyst_status_t NUM_NAME(pi_loading_curve_impl)(hyst_curve_t *curve, const NUM_T *r,
                                    const NUM_T *w, size_t n, NUM_T hi,
                                    NUM_T *bx, NUM_T *by)
{
    hyst_wide_t slope = 0, value = 0;
    size_t i;
    hyst_status_t st = NUM_NAME(pi_check_impl)(r, w, n);
    if (st != HYST_OK) {
        return st;
    }
    if (curve == NULL || bx == NULL || by == NULL) {
        return HYST_ERR_NULL;
    }
    if (!NUM_NAME(is_finite)(hi) || !(hi > r[n - 1u])) {
        return HYST_ERR_DOMAIN;
    }
    bx[0] = 0;
    by[0] = 0;
    for (i = 1u; i <= n; ++i) {
        const NUM_T x = i < n ? r[i] : hi;
        slope += (hyst_wide_t)w[i - 1u];
        value += slope * ((hyst_wide_t)x - (hyst_wide_t)bx[i - 1u]);
        bx[i] = x;
        by[i] = (NUM_T)value;
    }
    return NUM_NAME(curve_from_pwl_impl)(curve, bx, by, n + 1u, HYST_LAYOUT);
}

HYST_INLINE NUM_T NUM_NAME(pi_output_impl)(const hyst_pi_t *P) { return P != NULL ? P->y_prev.NUM_F : 0; }

#endif /* HYST_PI_MODEL_H */
