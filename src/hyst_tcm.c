/* The TCM engine: turning-point memory, wipe-out, branch output. */
#include "hyst/tcm.h"

hyst_status_t hyst_init_curve(hyst_t *S, const hyst_curve_t *curve,
                              hyst_real_t *xltp, hyst_real_t *yltp,
                              hyst_real_t *xrtp, hyst_real_t *yrtp,
                              size_t capacity)
{
    if (S == NULL || curve == NULL || xltp == NULL || yltp == NULL ||
        xrtp == NULL || yrtp == NULL) {
        return HYST_ERR_NULL;
    }
    if (capacity < 2u) {
        return HYST_ERR_CAPACITY;
    }
    if (curve->kind != HYST_CURVE_POLY) {
        return HYST_ERR_ARG;
    }
    S->curve = *curve;
    S->xltp = xltp;
    S->yltp = yltp;
    S->xrtp = xrtp;
    S->yrtp = yrtp;
    S->capacity = capacity;
    hyst_reset(S);
    return HYST_OK;
}

hyst_status_t hyst_init(hyst_t *S, const hyst_poly_t *f0, hyst_real_t *xltp,
                        hyst_real_t *yltp, hyst_real_t *xrtp, hyst_real_t *yrtp,
                        size_t capacity)
{
    hyst_curve_t curve;
    hyst_status_t st;
    if (S == NULL || xltp == NULL || yltp == NULL || xrtp == NULL || yrtp == NULL) {
        return HYST_ERR_NULL;
    }
    if (capacity < 2u) {
        return HYST_ERR_CAPACITY;
    }
    st = hyst_curve_from_poly(&curve, f0);
    if (st != HYST_OK) {
        return st;
    }
    return hyst_init_curve(S, &curve, xltp, yltp, xrtp, yrtp, capacity);
}

void hyst_reset(hyst_t *S)
{
    S->xltp[0] = S->curve.lo;
    S->yltp[0] = S->curve.y_lo;
    S->n_ltp = 1u;
    S->n_rtp = 0u;
    S->x_prev = S->curve.lo;
    S->y_prev = S->curve.y_lo;
    S->status = HYST_OK;
    S->events = 0u;
}

#ifdef HYST_USE_LINEAR_SEARCH
/* Benchmark variant: scans down from the newest TP, so a sample costs one
 * comparison per TP it wipes out (O(capacity) worst case). Same results as
 * the binary search below, since the arrays are sorted. */
static size_t ltp_below(const hyst_real_t *xltp, size_t n, hyst_real_t x)
{
    while (n > 0u && !(xltp[n - 1u] < x)) {
        --n;
    }
    return n;
}

static size_t rtp_above(const hyst_real_t *xrtp, size_t n, hyst_real_t x)
{
    while (n > 0u && !(xrtp[n - 1u] > x)) {
        --n;
    }
    return n;
}
#else
/* Count of xltp[0..n) below x (ascending array): LTPs that survive a fall to x. */
static size_t ltp_below(const hyst_real_t *xltp, size_t n, hyst_real_t x)
{
    size_t left = 0u;
    while (n > 0u) {
        const size_t half = n / 2u;
        if (xltp[left + half] < x) {
            left += half + 1u;
            n -= half + 1u;
        } else {
            n = half;
        }
    }
    return left;
}

/* Count of xrtp[0..n) above x (descending array): RTPs that survive a rise to x. */
static size_t rtp_above(const hyst_real_t *xrtp, size_t n, hyst_real_t x)
{
    size_t left = 0u;
    while (n > 0u) {
        const size_t half = n / 2u;
        if (xrtp[left + half] > x) {
            left += half + 1u;
            n -= half + 1u;
        } else {
            n = half;
        }
    }
    return left;
}
#endif /* HYST_USE_LINEAR_SEARCH */

/* Out-of-line so the common path stays short: NaN/Inf or outside [lo, hi].
 * Returns 0 if the sample must be ignored, else 1 with *x clamped. */
static int admit_slow(hyst_t *S, hyst_real_t *x)
{
    const hyst_real_t v = *x;
    const hyst_real_t z = v - v;
    if (z != z) {
        S->status = HYST_ERR_NONFINITE;
        S->events |= HYST_EVENT_NONFINITE;
        return 0;
    }
    *x = v < S->curve.lo ? S->curve.lo : S->curve.hi;
    S->status = HYST_WARN_CLAMPED;
    S->events |= HYST_EVENT_CLAMPED;
    return 1;
}

hyst_real_t hyst_step(hyst_t *S, hyst_real_t x)
{
    size_t nl, nr;
    hyst_real_t y;

    HYST_TIMING_BEGIN();
    S->status = HYST_OK;
    if (!(x >= S->curve.lo && x <= S->curve.hi) && !admit_slow(S, &x)) {
        HYST_TIMING_END();
        return S->y_prev;
    }
    if (x == S->x_prev) { /* rule: repeated samples create no TP */
        HYST_TIMING_END();
        return S->y_prev;
    }
    nl = S->n_ltp;
    nr = S->n_rtp;
    if (nl > nr) {
        /* rising branch from LTP nl-1; RTP nr-1 (if any) is the one below */
        if (x < S->x_prev) {
            /* reversal: (x_prev, y_prev) becomes RTP nr, falling from it */
            if (x <= S->xltp[nl - 1u]) { /* the new RTP and LTP nl-1 wiped at once */
                nl = ltp_below(S->xltp, nl - 1u, x);
                nr = nl;
                nl += (nl == 0u); /* fell to lo: back at A0 */
            } else { /* nr < nl <= capacity: the RTP array has room */
                S->xrtp[nr] = S->x_prev;
                S->yrtp[nr] = S->y_prev;
                ++nr;
            }
        } else if (nr > 0u && x >= S->xrtp[nr - 1u]) {
            nr = rtp_above(S->xrtp, nr - 1u, x);
            nl = nr + 1u;
        }
    } else {
        /* falling branch from RTP nr-1; LTP nl-1 is the one below */
        if (x > S->x_prev) {
            if (x >= S->xrtp[nr - 1u]) { /* the new LTP and RTP nr-1 wiped at once */
                nr = rtp_above(S->xrtp, nr - 1u, x);
                nl = nr + 1u;
            } else {
                /* Only the LTP array can fill (A0 takes one of its entries).
                 * Full: forget the innermost loop, LTP nl-1 and RTP nr-1. */
                if (nl == S->capacity) {
                    --nl;
                    --nr;
                    S->status = HYST_WARN_FULL;
                    S->events |= HYST_EVENT_FULL;
                }
                S->xltp[nl] = S->x_prev;
                S->yltp[nl] = S->y_prev;
                ++nl;
            }
        } else if (x <= S->xltp[nl - 1u]) {
            nl = ltp_below(S->xltp, nl - 1u, x);
            nr = nl;
            nl += (nl == 0u);
        }
    }
    S->n_ltp = nl;
    S->n_rtp = nr;
    if (nl > nr) {
        y = S->yltp[nl - 1u] + hyst_curve_g(&S->curve, x - S->xltp[nl - 1u]);
    } else {
        y = S->yrtp[nr - 1u] - hyst_curve_g(&S->curve, S->xrtp[nr - 1u] - x);
    }
    S->x_prev = x;
    S->y_prev = y;
    HYST_TIMING_END();
    return y;
}

hyst_status_t hyst_process(hyst_t *S, const hyst_real_t *x, hyst_real_t *y,
                           size_t n)
{
    int worst = HYST_OK; /* HYST_WARN_FULL > HYST_WARN_CLAMPED > HYST_OK */
    int failed = 0;
    size_t i;
    if (n > 0u && (S == NULL || x == NULL || y == NULL)) {
        return HYST_ERR_NULL;
    }
    for (i = 0u; i < n; ++i) {
        y[i] = hyst_step(S, x[i]);
        if (S->status < 0) {
            failed = 1;
        } else if (S->status > worst) {
            worst = S->status;
        }
    }
    return failed ? HYST_ERR_NONFINITE : (hyst_status_t)worst;
}
