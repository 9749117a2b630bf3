/* SPDX-License-Identifier: MIT */
/* Creep (creep.h): the checks, accessors and identification written once;
 * the per-sample functions of each real variant from src/creep_model.h. */
#include "hyst/creep.h"

#include "hyst_util.h"

#include <float.h>
#include <math.h>
#include <string.h>

/* A time constant both the model and its fit accept. */
static int tau_ok(hyst_wide_t tau) { return hyst_wide_is_finite(tau) && tau >= 1; }

/* a = 1 / tau in the variant's type into *alpha; 0 if tau is refused or a
 * is not a normal number there (a subnormal a loses its precision, and
 * cores that flush subnormals would freeze the lag). */
static int lag_rate(hyst_wide_t tau, unsigned variant, hyst_num_t *alpha)
{
    const hyst_wide_t least =
        variant == (unsigned)HYST_VARIANT_F32 ? (hyst_wide_t)FLT_MIN : HYST_WIDE_MIN;
    if (!tau_ok(tau)) {
        return 0;
    }
    (void)hyst_num_set(alpha, variant, 1 / tau);
    return hyst_num_get(alpha, variant) >= least;
}

/* The init of every real variant: the instance is built aside and copied
 * whole, so an error writes nothing. */
static hyst_status_t init_any(hyst_creep_t *C, size_t n_terms, const hyst_wide_t *tau,
                              const hyst_wide_t *weight, hyst_wide_t x_rest, unsigned variant,
                              unsigned long layout)
{
    hyst_creep_t out;
    size_t k;
    if (C == NULL || tau == NULL || weight == NULL) {
        return HYST_ERR_NULL;
    }
    if (layout != HYST_LAYOUT) {
        return HYST_ERR_LAYOUT;
    }
    if (n_terms < 1u || n_terms > HYST_CREEP_MAX_TERMS) {
        return HYST_ERR_ARG;
    }
    memset(&out, 0, sizeof out);
    for (k = 0u; k < n_terms; ++k) {
        if (!lag_rate(tau[k], variant, &out.alpha[k])) {
            return HYST_ERR_ARG;
        }
        if (!hyst_num_set(&out.weight[k], variant, weight[k])) { /* NaN fails too */
            return HYST_ERR_WEIGHTS;
        }
        if (!hyst_num_set(&out.state[k], variant, x_rest)) {
            return HYST_ERR_NONFINITE;
        }
    }
    {
        /* the drive limit: |s| <= L keeps x - s, the lags and c = sum w s finite */
        hyst_wide_t sum = 0;
        const hyst_wide_t top = variant == (unsigned)HYST_VARIANT_F32 ? (hyst_wide_t)FLT_MAX
                                                                      : HYST_WIDE_MAX;
        for (k = 0u; k < n_terms; ++k) {
            sum += hyst_wide_abs(hyst_num_get(&out.weight[k], variant));
        }
        (void)hyst_num_set(&out.x_limit, variant, top / (4 * (sum > 1 ? sum : 1)));
        if (!(hyst_wide_abs(x_rest) <= hyst_num_get(&out.x_limit, variant))) {
            return HYST_ERR_NONFINITE;
        }
    }
    out.variant = variant;
    out.n = n_terms;
    out.status = HYST_OK;
    *C = out;
    return HYST_OK;
}

#define NUM_T float
#define NUM_F f32
#define NUM_NAME(n) hyst_f32_##n
#define NUM_VARIANT HYST_VARIANT_F32
#define NUM_MULADD(a, b, c) HYST_F32_MULADD(a, b, c)
#include "creep_model.h"
#undef NUM_T
#undef NUM_F
#undef NUM_NAME
#undef NUM_VARIANT
#undef NUM_MULADD

hyst_status_t hyst_f32_creep_init_(hyst_creep_t *C, size_t n_terms, const hyst_wide_t *tau,
                                   const hyst_wide_t *weight, hyst_wide_t x_rest,
                                   unsigned long layout)
{
    return init_any(C, n_terms, tau, weight, x_rest, HYST_VARIANT_F32, layout);
}

hyst_status_t hyst_f32_creep_reset(hyst_creep_t *C, float x_rest)
{
    return hyst_f32_creep_reset_impl(C, x_rest);
}

float hyst_f32_creep_output(const hyst_creep_t *C)
{
    return hyst_f32_creep_output_impl(C);
}

float hyst_f32_creep_step(hyst_creep_t *C, float x)
{
    return hyst_f32_creep_step_impl(C, x);
}

#if HYST_ENABLE_F64
#define NUM_T double
#define NUM_F f64
#define NUM_NAME(n) hyst_f64_##n
#define NUM_VARIANT HYST_VARIANT_F64
#define NUM_MULADD(a, b, c) ((a) * (b) + (c))
#include "creep_model.h"
#undef NUM_T
#undef NUM_F
#undef NUM_NAME
#undef NUM_VARIANT
#undef NUM_MULADD

hyst_status_t hyst_f64_creep_init_(hyst_creep_t *C, size_t n_terms, const hyst_wide_t *tau,
                                   const hyst_wide_t *weight, hyst_wide_t x_rest,
                                   unsigned long layout)
{
    return init_any(C, n_terms, tau, weight, x_rest, HYST_VARIANT_F64, layout);
}

hyst_status_t hyst_f64_creep_reset(hyst_creep_t *C, double x_rest)
{
    return hyst_f64_creep_reset_impl(C, x_rest);
}

double hyst_f64_creep_output(const hyst_creep_t *C)
{
    return hyst_f64_creep_output_impl(C);
}

double hyst_f64_creep_step(hyst_creep_t *C, double x)
{
    return hyst_f64_creep_step_impl(C, x);
}
#endif

int hyst_creep_status(const hyst_creep_t *C) { return C != NULL ? C->status : HYST_ERR_NULL; }

unsigned hyst_creep_events(const hyst_creep_t *C) { return C != NULL ? C->events : 0u; }

void hyst_creep_clear_events(hyst_creep_t *C)
{
    if (C != NULL) {
        ++C->seq;
        C->events = 0u;
    }
}

size_t hyst_creep_size(const hyst_creep_t *C) { return C != NULL ? C->n : 0u; }

/* ---- Identification ---- */

hyst_status_t hyst_creep_fit_init(hyst_creep_fit_t *F, size_t n_terms, const hyst_wide_t *tau,
                                  hyst_wide_t x_rest)
{
    hyst_creep_fit_t out;
    size_t k;
    if (F == NULL || tau == NULL) {
        return HYST_ERR_NULL;
    }
    memset(&out, 0, sizeof out);
    if (n_terms < 1u || n_terms > HYST_CREEP_MAX_TERMS) {
        return HYST_ERR_ARG;
    }
    for (k = 0u; k < n_terms; ++k) {
        if (!tau_ok(tau[k])) {
            return HYST_ERR_ARG;
        }
        out.alpha[k] = 1 / tau[k];
        out.state[k] = x_rest;
    }
    if (!hyst_wide_is_finite(x_rest)) {
        return HYST_ERR_NONFINITE;
    }
    out.n = n_terms;
    *F = out;
    return HYST_OK;
}

/* The lags take the drive x in, as hyst_*_creep_step() does. */
static void fit_advance(hyst_creep_fit_t *F, hyst_wide_t x)
{
    size_t k;
    for (k = 0u; k < F->n; ++k) {
        F->state[k] += F->alpha[k] * (x - F->state[k]);
    }
}

hyst_status_t hyst_creep_fit_feed(hyst_creep_fit_t *F, hyst_wide_t x)
{
    if (F == NULL) {
        return HYST_ERR_NULL;
    }
    if (!hyst_wide_is_finite(x)) {
        return HYST_ERR_NONFINITE;
    }
    fit_advance(F, x);
    return HYST_OK;
}

hyst_status_t hyst_creep_fit_add(hyst_creep_fit_t *F, hyst_wide_t x, hyst_wide_t residual)
{
    hyst_wide_t dev[HYST_CREEP_MAX_TERMS], dr, share, keep;
    size_t i, j;
    if (F == NULL) {
        return HYST_ERR_NULL;
    }
    if (!hyst_wide_is_finite(x) || !hyst_wide_is_finite(residual)) {
        return HYST_ERR_NONFINITE;
    }
    /* Welford: deviations from the means before this equation; the
     * co-moments grow by (k - 1) / k of their products. */
    ++F->used;
    share = 1 / (hyst_wide_t)F->used;
    keep = (hyst_wide_t)(F->used - 1u) * share;
    for (i = 0u; i < F->n; ++i) {
        dev[i] = F->state[i] - F->mean[i];
        F->mean[i] += dev[i] * share;
    }
    dr = residual - F->mean_r;
    F->mean_r += dr * share;
    for (i = 0u; i < F->n; ++i) {
        const hyst_wide_t di = dev[i] * keep;
        for (j = i; j < F->n; ++j) {
            F->css[i * HYST_CREEP_MAX_TERMS + j] += di * dev[j];
        }
        F->csr[i] += di * dr;
    }
    F->crr += dr * dr * keep;
    fit_advance(F, x);
    return HYST_OK;
}

hyst_status_t hyst_creep_fit_solve(const hyst_creep_fit_t *F, hyst_wide_t *weight,
                                   hyst_wide_t *offset, hyst_wide_t *rms)
{
    enum { M = HYST_CREEP_MAX_TERMS };
    hyst_wide_t scale[M], l[M * M], u[M], w[M], ss, off;
    size_t n, i, j, k;
    if (F == NULL || weight == NULL || offset == NULL) {
        return HYST_ERR_NULL;
    }
    n = F->n;
    if (n < 1u || n > (size_t)M || F->used <= n) {
        return HYST_ERR_SINGULAR;
    }
    for (i = 0u; i < n; ++i) {
        const hyst_wide_t cii = F->css[i * M + i];
        if (!(cii > 0) || !hyst_wide_is_finite(cii)) {
            return HYST_ERR_SINGULAR; /* a lag that never moved */
        }
        scale[i] = 1 / HYST_WIDE_SQRT(cii);
    }
    /* R = D C D (unit diagonal) = L L' */
    for (i = 0u; i < n; ++i) {
        for (j = 0u; j <= i; ++j) {
            hyst_wide_t sum = F->css[j * M + i] * scale[i] * scale[j];
            for (k = 0u; k < j; ++k) {
                sum -= l[i * M + k] * l[j * M + k];
            }
            if (j < i) {
                l[i * M + j] = sum / l[j * M + j];
                continue;
            }
            /* The pivot is the share of the lag's variance the earlier
             * lags leave; refused at 1e4 rounding units of its uncentred
             * sum of squares (the constant column's share counted). */
            if (!(sum > HYST_WIDE_EPS * (hyst_wide_t)1e4 *
                            (1 + (hyst_wide_t)F->used * F->mean[i] * F->mean[i] *
                                     scale[i] * scale[i]))) {
                return HYST_ERR_SINGULAR;
            }
            l[i * M + i] = HYST_WIDE_SQRT(sum);
        }
    }
    ss = F->crr;
    for (i = 0u; i < n; ++i) { /* L u = D c */
        u[i] = F->csr[i] * scale[i];
        for (k = 0u; k < i; ++k) {
            u[i] -= l[i * M + k] * u[k];
        }
        u[i] /= l[i * M + i];
        ss -= u[i] * u[i];
    }
    off = F->mean_r;
    for (i = n; i-- > 0u;) { /* L' v = u, w = D v */
        w[i] = u[i];
        for (k = i + 1u; k < n; ++k) {
            w[i] -= l[k * M + i] * w[k];
        }
        w[i] /= l[i * M + i];
    }
    for (i = 0u; i < n; ++i) {
        w[i] *= scale[i];
        off -= w[i] * F->mean[i];
        if (!hyst_wide_is_finite(w[i])) {
            return HYST_ERR_SINGULAR;
        }
    }
    if (!hyst_wide_is_finite(off)) {
        return HYST_ERR_SINGULAR;
    }
    for (i = 0u; i < n; ++i) {
        weight[i] = w[i];
    }
    *offset = off;
    if (rms != NULL) {
        *rms = HYST_WIDE_SQRT((ss > 0 ? ss : 0) / (hyst_wide_t)F->used);
    }
    return HYST_OK;
}

/* The model the scores are of: the f64 creep where double is linked. */
#if HYST_ENABLE_F64
#define CREEP_SCORE_INIT hyst_f64_creep_init
#define CREEP_SCORE_STEP(C, x) (hyst_wide_t)hyst_f64_creep_step((C), (double)(x))
#else
#define CREEP_SCORE_INIT hyst_f32_creep_init
#define CREEP_SCORE_STEP(C, x) (hyst_wide_t)hyst_f32_creep_step((C), (float)(x))
#endif

hyst_status_t hyst_creep_fit_holdout(size_t n_terms, const hyst_wide_t *tau, hyst_wide_t x_rest,
                                     const hyst_wide_t *u, const hyst_wide_t *r, size_t len,
                                     size_t train, hyst_creep_holdout_t *out)
{
    hyst_creep_fit_t F;
    hyst_creep_holdout_t got;
    hyst_creep_t C;
    hyst_wide_t ss = 0;
    hyst_status_t st;
    size_t k;
    if (u == NULL || r == NULL || out == NULL) {
        return HYST_ERR_NULL;
    }
    if (train > len) {
        return HYST_ERR_ARG;
    }
    memset(&got, 0, sizeof got);
    st = hyst_creep_fit_init(&F, n_terms, tau, x_rest);
    for (k = 0u; st == HYST_OK && k < train; ++k) { /* a missing residual: the lags go on */
        st = hyst_wide_is_finite(r[k]) ? hyst_creep_fit_add(&F, u[k], r[k])
                                       : hyst_creep_fit_feed(&F, u[k]);
    }
    if (st == HYST_OK) {
        st = hyst_creep_fit_solve(&F, got.weight, &got.offset, &got.fit_rms);
    }
    if (st == HYST_OK) {
        st = CREEP_SCORE_INIT(&C, n_terms, tau, got.weight, x_rest);
    }
    for (k = 0u; st == HYST_OK && k < len; ++k) { /* from rest, as a user runs it */
        const hyst_wide_t e = r[k] - CREEP_SCORE_STEP(&C, u[k]) - got.offset;
        if (!hyst_wide_is_finite(u[k])) {
            st = HYST_ERR_NONFINITE;
        } else if (hyst_wide_is_finite(r[k])) {
            const hyst_wide_t a = e < 0 ? -e : e;
            got.max_abs = a > got.max_abs ? a : got.max_abs;
            if (k >= train) {
                ss += e * e;
                ++got.holdout_used;
            }
        }
    }
    if (st != HYST_OK) {
        return st;
    }
    got.holdout_rms =
        got.holdout_used > 0u ? HYST_WIDE_SQRT(ss / (hyst_wide_t)got.holdout_used) : 0;
    *out = got;
    return HYST_OK;
}
