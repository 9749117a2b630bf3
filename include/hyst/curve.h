/**
 * @file curve.h
 * @brief The major ascending curve f0 and the branch shape g derived from it.
 *
 * A TCM needs one function of its curve: the branch shape
 * g(d) = f0(lo + d) - f0(lo), d in [0, hi - lo] (METHOD.md section 3).
 * hyst_curve_t holds it in a form that costs one Horner evaluation per sample:
 * the polynomial is shifted to lo and scaled to u = d / (hi - lo) in [0, 1]
 * once, at set-up, in hyst_wide_t precision.
 */
#ifndef HYST_CURVE_H
#define HYST_CURVE_H

#include "hyst/config.h"
#include "hyst/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/**
 * @brief A polynomial f0 on [lo, hi], as the user writes it.
 *
 * Coefficients are given HIGHEST POWER FIRST, as in the paper's Eq. 20 and as
 * numpy/MATLAB polyfit print them: f0(x) = coeffs[0] x^n + ... + coeffs[n].
 * Only the first degree + 1 entries are read. Example (paper, Eq. 20):
 * @code
 * static const hyst_poly_t f0 = { 3, 0.0f, 40.0f,
 *     { -6.1876e-6f, 1.1949e-3f, 8.6444e-2f, 5.8517e-1f } };
 * @endcode
 */
typedef struct hyst_poly {
    unsigned degree;   /**< n, 1..HYST_MAX_DEGREE */
    hyst_real_t lo;    /**< lower end of the identified input range */
    hyst_real_t hi;    /**< upper end, hi > lo */
    hyst_real_t coeffs[HYST_MAX_DEGREE + 1]; /**< c_n ... c_0, highest power first */
} hyst_poly_t;

/** @brief Kinds of curve the engine can run on. */
typedef enum hyst_curve_kind {
    HYST_CURVE_POLY = 1 /**< polynomial, Horner's rule */
} hyst_curve_kind_t;

/**
 * @brief Branch shape g of a curve, ready for per-sample use.
 *
 * Filled by hyst_curve_from_poly(); treat as opaque. Self-contained (no
 * pointers), so it may be copied or stored in flash.
 */
typedef struct hyst_curve {
    int kind;              /**< hyst_curve_kind_t */
    unsigned degree;       /**< polynomial degree n */
    hyst_real_t lo, hi;    /**< input domain */
    hyst_real_t y_lo;      /**< f0(lo) */
    hyst_real_t y_hi;      /**< f0(hi) */
    hyst_real_t inv_span;  /**< 1 / (hi - lo) */
    /** g(d) = u (a[0] u^(n-1) + ... + a[n-1]), u = d * inv_span */
    hyst_real_t a[HYST_MAX_DEGREE];
} hyst_curve_t;

/**
 * @brief Validates a polynomial f0 and prepares its branch shape.
 *
 * Checks, in this order: NULL pointers, degree in 1..HYST_MAX_DEGREE, finite
 * lo < hi, finite coefficients (and a finite f0 over the domain), and that f0
 * is increasing on [lo, hi] (its slope is never negative; isolated zeros such
 * as x^2 at 0 are accepted). @p curve is written only on success.
 *
 * @param[out] curve  prepared curve.
 * @param[in]  f0     polynomial, highest power first.
 * @return HYST_OK, HYST_ERR_NULL, HYST_ERR_DEGREE, HYST_ERR_DOMAIN,
 *         HYST_ERR_COEFF or HYST_ERR_NOT_INCREASING.
 */
hyst_status_t hyst_curve_from_poly(hyst_curve_t *curve, const hyst_poly_t *f0);

/**
 * @brief Checks that a polynomial increases on [lo, hi].
 *
 * Exact in the Bernstein basis of f0' with dyadic subdivision down to
 * 2^-HYST_MONOTONE_DEPTH of the domain; a dip narrower than that is not seen.
 *
 * @param[in]  coeffs highest power first, degree + 1 entries, finite.
 * @param[in]  degree 1..HYST_MAX_DEGREE.
 * @param[in]  lo, hi domain, lo < hi.
 * @param[out] turn   if not NULL and f0 is not increasing: an x in [lo, hi]
 *                    where the slope is negative (the leftmost one found);
 *                    lo when f0 overflows hyst_wide_t on the domain.
 * @return 1 if increasing, 0 if not (or if f0 overflows hyst_wide_t there).
 */
int hyst_poly_is_increasing(const hyst_wide_t *coeffs, unsigned degree,
                            hyst_wide_t lo, hyst_wide_t hi, hyst_wide_t *turn);

/** Depth of the dyadic subdivision of hyst_poly_is_increasing(). */
#define HYST_MONOTONE_DEPTH 20

/**
 * @brief f0(x) by Horner's rule in user units (for tools and tests).
 * @param[in] f0 polynomial, highest power first.
 * @param[in] x  input, any value.
 * @return f0(x).
 */
hyst_real_t hyst_poly_eval(const hyst_poly_t *f0, hyst_real_t x);

/**
 * @brief The branch shape g(d) = f0(lo + d) - f0(lo) of a prepared curve.
 * @param[in] curve prepared by hyst_curve_from_poly().
 * @param[in] d     distance from the turning point, 0 <= d <= hi - lo.
 * @return g(d); g(0) is exactly 0.
 */
/**
 * @brief The branch shape at u = d / (hi - lo), u in [0, 1].
 *
 * Horner's rule unrolled by a switch on the degree: one multiply-add per
 * coefficient and no loop overhead on the per-sample path.
 */
HYST_INLINE hyst_real_t hyst_curve_g_unit(const hyst_curve_t *curve, hyst_real_t u)
{
    const hyst_real_t *a = curve->a; /* a[0] multiplies u^n */
    hyst_real_t acc;
#define HYST_H_(acc_, k_) ((acc_) * u + a[k_])
    switch (curve->degree) { /* independent cases: no register merges */
    case 1: acc = a[0]; break;
    case 2: acc = HYST_H_(a[0], 1); break;
    case 3: acc = HYST_H_(HYST_H_(a[0], 1), 2); break;
    case 4: acc = HYST_H_(HYST_H_(HYST_H_(a[0], 1), 2), 3); break;
    case 5: acc = HYST_H_(HYST_H_(HYST_H_(HYST_H_(a[0], 1), 2), 3), 4); break;
    case 6: acc = HYST_H_(HYST_H_(HYST_H_(HYST_H_(HYST_H_(a[0], 1), 2), 3), 4), 5); break;
    case 7: acc = HYST_H_(HYST_H_(HYST_H_(HYST_H_(HYST_H_(HYST_H_(a[0], 1), 2), 3), 4), 5), 6); break;
    case 8: acc = HYST_H_(HYST_H_(HYST_H_(HYST_H_(HYST_H_(HYST_H_(HYST_H_(a[0], 1), 2), 3), 4), 5), 6), 7); break;
    default: { /* 9 and above: Horner's loop */
        unsigned k;
        acc = a[0];
        for (k = 1u; k < curve->degree; ++k) {
            acc = HYST_H_(acc, k);
        }
        break;
    }
    }
#undef HYST_H_
    return acc * u;
}

static inline hyst_real_t hyst_curve_g(const hyst_curve_t *curve, hyst_real_t d)
{
    return hyst_curve_g_unit(curve, d * curve->inv_span);
}

#ifdef __cplusplus
}
#endif

#endif /* HYST_CURVE_H */
