/**
 * @file curve.h
 * @brief The major ascending curve f0 and the branch shape g derived from it.
 *
 * A TCM needs one function of its curve: the branch shape
 * g(d) = f0(lo + d) - f0(lo), d in [0, hi - lo] (METHOD.md section 3).
 * hyst_curve_t holds it ready for per-sample use, in one of four kinds:
 *  - polynomial: shifted to lo and scaled to u = d / (hi - lo) in [0, 1]
 *    once, at set-up, in hyst_wide_t precision; one Horner evaluation inline;
 *  - piecewise linear (breakpoints + values, or a PI loading curve, pi.h):
 *    binary search for the segment, exact at the breakpoints;
 *  - the inverses of both (hyst_curve_inverse()), for a compensator: the
 *    same engine on f0^-1 (METHOD.md section 8, inverse.h).
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

/**
 * @brief Work per sample of an inverted polynomial (bound).
 *
 * HYST_CURVE_POLY_INV evaluates g^-1 by at most 2 HYST_INV_MAX_ITER
 * bisections of a tabulated bracket, each one evaluation of f0 (together the
 * multiply-adds of HYST_INV_MAX_ITER evaluations of f0 and f0'), and at most
 * ten divisions. g^-1 is non-decreasing in its argument.
 * See docs/pi_and_inverse.md for the measured worst error.
 */
#ifndef HYST_INV_MAX_ITER
#define HYST_INV_MAX_ITER 12
#endif
#if HYST_INV_MAX_ITER < 1
#error "HYST_INV_MAX_ITER must be at least 1"
#endif

/**
 * @brief Intervals of the start table of an inverted polynomial.
 *
 * g^-1 is tabulated at init at HYST_INV_KNOTS + 1 equally spaced outputs;
 * each sample starts Newton inside the bracket of its table interval.
 */
#ifndef HYST_INV_KNOTS
#define HYST_INV_KNOTS 16
#endif
#if HYST_INV_KNOTS < 1
#error "HYST_INV_KNOTS must be at least 1"
#endif

/** @brief Kinds of curve the engine can run on. */
typedef enum hyst_curve_kind {
    HYST_CURVE_POLY = 1,     /**< polynomial f0, Horner's rule (inline) */
    HYST_CURVE_PWL = 2,      /**< piecewise-linear f0, binary search */
    HYST_CURVE_POLY_INV = 3, /**< f0^-1 of a polynomial: bracketed Newton */
    HYST_CURVE_PWL_INV = 4   /**< f0^-1 of a piecewise-linear f0: exact */
} hyst_curve_kind_t;

/**
 * @brief Branch shape g of a curve, ready for per-sample use.
 *
 * Filled by a hyst_curve_* constructor; treat as opaque. Polynomial kinds
 * are self-contained (no pointers): they may be copied or stored in flash.
 * Piecewise-linear kinds point at the caller's breakpoint and value arrays,
 * which must stay alive and unchanged as long as the curve (or an instance
 * initialised with it) is used.
 *
 * lo, hi is the domain of THIS curve and y_lo, y_hi its values there: for an
 * inverse curve the domain is [f0(lo), f0(hi)] and the values lo, hi.
 */
typedef struct hyst_curve {
    int kind;              /**< hyst_curve_kind_t */
    unsigned degree;       /**< polynomial degree n (polynomial kinds) */
    /** degree of the inline Horner path of hyst_curve_g_unit(): n for POLY,
     *  0 for the kinds evaluated out of line (the per-sample dispatch) */
    unsigned horner;
    hyst_real_t lo, hi;    /**< domain of the curve */
    hyst_real_t y_lo;      /**< curve value at lo */
    hyst_real_t y_hi;      /**< curve value at hi */
    /** argument scale of hyst_curve_g_unit(): 1 / (hi - lo) for POLY, 1 for
     *  the other kinds (their g takes d itself) */
    hyst_real_t inv_span;
    /** polynomial kinds: f0(lo + s u) - f0(lo) = u (a[0] u^(n-1) + ... + a[n-1]),
     *  s = input span of f0 */
    hyst_real_t a[HYST_MAX_DEGREE];
    hyst_real_t span;       /**< POLY_INV: input span s of f0 (u -> d) */
    hyst_real_t knot_scale; /**< POLY_INV: HYST_INV_KNOTS / (f0(hi) - f0(lo)) */
    /** POLY_INV: u where g(u span) = k / knot_scale, k = 0..HYST_INV_KNOTS */
    hyst_real_t knot_u[HYST_INV_KNOTS + 1];
    const hyst_real_t *px; /**< PWL: caller's breakpoints (PWL_INV: values) */
    const hyst_real_t *py; /**< PWL: caller's values (PWL_INV: breakpoints) */
    size_t n_points;       /**< PWL: entries of px and py, >= 2 */
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
 * @brief Prepares a piecewise-linear f0 through caller-owned points.
 *
 * f0 interpolates (x[i], y[i]), i = 0..n-1, linearly; the domain is
 * [x[0], x[n-1]]. The curve keeps the two pointers, not copies: the arrays
 * must outlive the curve and every instance initialised with it, unchanged.
 * Checks, in this order: NULL pointers, n >= 2 (else HYST_ERR_ARG), finite
 * and strictly increasing breakpoints with a finite span x[n-1] - x[0]
 * (HYST_ERR_BREAKPOINTS), finite values with a finite span y[n-1] - y[0]
 * (HYST_ERR_COEFF), values non-decreasing with y[n-1] > y[0]
 * (HYST_ERR_NOT_INCREASING; flat pieces are allowed here, but such a curve
 * has no inverse). @p curve is written only on success.
 *
 * @param[out] curve prepared curve.
 * @param[in]  x     n breakpoints, strictly increasing.
 * @param[in]  y     n values f0(x[i]), non-decreasing.
 * @param[in]  n     number of points, >= 2.
 * @return HYST_OK or the error named above.
 */
hyst_status_t hyst_curve_from_pwl(hyst_curve_t *curve, const hyst_real_t *x,
                                  const hyst_real_t *y, size_t n);

/**
 * @brief Prepares the inverse curve f0^-1, for a compensator (METHOD.md 8).
 *
 * A TCM initialised with the result (hyst_init_curve()) is the inverse model:
 * its input is the desired output on [f0(lo), f0(hi)], its output the input
 * that produces it. The engine clamps desired outputs outside that range and
 * reports HYST_WARN_CLAMPED.
 *  - polynomial: g^-1 by bisection, <= 2 HYST_INV_MAX_ITER steps, monotone;
 *  - piecewise linear: exact (the same points with the axes swapped; the
 *    inverse keeps pointing at the caller's arrays);
 *  - an inverse curve: gives back the forward curve.
 * The forward curve must be strictly increasing: a PWL f0 with a flat piece,
 * or a polynomial with a flat stretch wider than rounding, is refused.
 *
 * @param[out] inv prepared inverse curve (may be the same object as @p fwd).
 * @param[in]  fwd curve prepared by a hyst_curve_* constructor.
 * @return HYST_OK, HYST_ERR_NULL, HYST_ERR_ARG (not a prepared curve) or
 *         HYST_ERR_NOT_INVERTIBLE.
 */
hyst_status_t hyst_curve_inverse(hyst_curve_t *inv, const hyst_curve_t *fwd);

/**
 * @brief Checks that a curve was prepared by a hyst_curve_* constructor.
 *
 * A cheap structural check (kind, domain, pointers), not a re-validation.
 * @param[in] curve curve to check.
 * @return HYST_OK, HYST_ERR_NULL or HYST_ERR_ARG.
 */
hyst_status_t hyst_curve_check(const hyst_curve_t *curve);

/**
 * @brief The curve itself, f(x) = y_lo + g(x - lo), for tools and tests.
 * @param[in] curve prepared curve.
 * @param[in] x     point of the domain (clamped to it).
 * @return f(x); for an inverse curve, the input that f0 maps to x.
 */
hyst_real_t hyst_curve_eval(const hyst_curve_t *curve, hyst_real_t x);

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
 * @brief g of the kinds other than HYST_CURVE_POLY (out of line).
 *
 * These kinds have inv_span = 1: their argument is d itself, unscaled, so a
 * piecewise-linear curve stays exact at its breakpoints.
 * @param[in] curve prepared curve.
 * @param[in] d     distance from the turning point, 0 <= d <= hi - lo.
 * @return g(d).
 */
hyst_real_t hyst_curve_g_unit_other(const hyst_curve_t *curve, hyst_real_t d);

/**
 * @brief Polynomial branch shape at u = d / (hi - lo), u in [0, 1]: the
 *        per-sample path, for curves with curve->horner >= 1 only.
 *
 * Horner's rule unrolled by a switch on the degree: one multiply-add per
 * coefficient, no loop and no call.
 */
HYST_INLINE hyst_real_t hyst_curve_horner(const hyst_curve_t *curve, hyst_real_t u)
{
    const hyst_real_t *a = curve->a; /* a[0] multiplies u^n */
    hyst_real_t acc;
#define HYST_H_(acc_, k_) ((acc_) * u + a[k_])
    switch (curve->horner) { /* independent cases: no register merges */
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
        for (k = 1u; k < curve->horner; ++k) {
            acc = HYST_H_(acc, k);
        }
        break;
    }
    }
#undef HYST_H_
    return acc * u;
}

/**
 * @brief The branch shape at u = d * inv_span, any kind.
 *
 * HYST_CURVE_POLY: hyst_curve_horner(), inline. Other kinds (inv_span = 1,
 * u = d): one out-of-line call, see hyst_curve_g().
 */
HYST_INLINE hyst_real_t hyst_curve_g_unit(const hyst_curve_t *curve, hyst_real_t u)
{
    return curve->horner != 0u ? hyst_curve_horner(curve, u) : hyst_curve_g_unit_other(curve, u);
}

/**
 * @brief The branch shape g(d) = f(lo + d) - f(lo) of a prepared curve f.
 *
 * Polynomial: one Horner evaluation, inline. Piecewise linear (either
 * direction): one binary search over the points, O(log n_points), one
 * division. Inverted polynomial: at most 2 HYST_INV_MAX_ITER evaluations
 * of f0 and ten divisions. Arguments slightly outside
 * [0, hi - lo] (rounding) are clamped by the out-of-line kinds.
 *
 * @param[in] curve prepared by a hyst_curve_* constructor.
 * @param[in] d     distance from the turning point, 0 <= d <= hi - lo.
 * @return g(d); g(0) is exactly 0.
 */
static inline hyst_real_t hyst_curve_g(const hyst_curve_t *curve, hyst_real_t d)
{
    return hyst_curve_g_unit(curve, d * curve->inv_span);
}

#ifdef __cplusplus
}
#endif

#endif /* HYST_CURVE_H */
