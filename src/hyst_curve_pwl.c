/* Piecewise-linear curves: validation and evaluation by binary search. */
#include "hyst_curve_impl.h"

/* Finite and strictly increasing? */
static int strictly_increasing(const hyst_real_t *v, size_t n)
{
    size_t i;
    for (i = 0u; i < n; ++i) {
        if (!hyst_wide_is_finite((hyst_wide_t)v[i]) || (i > 0u && !(v[i] > v[i - 1u]))) {
            return 0;
        }
    }
    return 1;
}

/* b - a finite in hyst_real_t, where interpolation computes the differences. */
static int span_is_finite(hyst_real_t a, hyst_real_t b)
{
    const hyst_real_t d = b - a;
    return hyst_wide_is_finite((hyst_wide_t)d);
}

hyst_status_t hyst_curve_from_pwl(hyst_curve_t *curve, const hyst_real_t *x,
                                  const hyst_real_t *y, size_t n)
{
    hyst_curve_t out = {0};
    size_t i;
    if (curve == NULL || x == NULL || y == NULL) {
        return HYST_ERR_NULL;
    }
    if (n < 2u) {
        return HYST_ERR_ARG;
    }
    if (!strictly_increasing(x, n) || !span_is_finite(x[0], x[n - 1u])) {
        return HYST_ERR_BREAKPOINTS;
    }
    for (i = 0u; i < n; ++i) {
        if (!hyst_wide_is_finite((hyst_wide_t)y[i])) {
            return HYST_ERR_COEFF;
        }
    }
    /* The value span bounds every segment's rise, as the breakpoint span
     * its width: then interpolation cannot overflow (the inverse swaps them). */
    if (!span_is_finite(y[0], y[n - 1u])) {
        return HYST_ERR_COEFF;
    }
    for (i = 1u; i < n; ++i) {
        if (y[i] < y[i - 1u]) {
            return HYST_ERR_NOT_INCREASING;
        }
    }
    if (!(y[n - 1u] > y[0])) {
        return HYST_ERR_NOT_INCREASING;
    }
    out.kind = HYST_CURVE_PWL;
    out.lo = x[0];
    out.hi = x[n - 1u];
    out.y_lo = y[0];
    out.y_hi = y[n - 1u];
    out.inv_span = 1; /* g takes d itself: exact at the breakpoints */
    out.px = x;
    out.py = y;
    out.n_points = n;
    *curve = out;
    return HYST_OK;
}

/* Largest k in [0, n-2] with px[k] <= x (binary search over px[1..n-2]). */
static size_t segment_of(const hyst_real_t *px, size_t n, hyst_real_t x)
{
    size_t first = 1u;
    size_t count = n - 2u;
    while (count > 0u) {
        const size_t half = count / 2u;
        if (px[first + half] <= x) {
            first += half + 1u;
            count -= half + 1u;
        } else {
            count = half;
        }
    }
    return first - 1u;
}

hyst_real_t hyst_pwl_eval_(const hyst_curve_t *curve, hyst_real_t x)
{
    const hyst_real_t *px = curve->px;
    const hyst_real_t *py = curve->py;
    size_t k;
    x = x < curve->lo ? curve->lo : (x > curve->hi ? curve->hi : x);
    k = segment_of(px, curve->n_points, x);
    /* The fraction first, t in [0, 1]: t * dy can neither overflow (dy is
     * finite, see the span checks) nor underflow where (x - x_k) dy would.
     * Exact at every breakpoint: there t is 0. */
    return py[k] + (x - px[k]) / (px[k + 1u] - px[k]) * (py[k + 1u] - py[k]);
}

/* Inverse of a PWL curve: the same points, axes swapped (exact). */
hyst_status_t hyst_pwl_inverse_(hyst_curve_t *inv, const hyst_curve_t *fwd)
{
    hyst_curve_t out = *fwd;
    if (!strictly_increasing(fwd->py, fwd->n_points)) {
        return HYST_ERR_NOT_INVERTIBLE;
    }
    out.kind = fwd->kind == HYST_CURVE_PWL ? HYST_CURVE_PWL_INV : HYST_CURVE_PWL;
    out.lo = fwd->y_lo;
    out.hi = fwd->y_hi;
    out.y_lo = fwd->lo;
    out.y_hi = fwd->hi;
    out.px = fwd->py;
    out.py = fwd->px;
    *inv = out;
    return HYST_OK;
}
