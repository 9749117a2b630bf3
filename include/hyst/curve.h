/* SPDX-License-Identifier: MIT */
/**
 * @file curve.h
 * @brief The major ascending curve f0 and the branch shape g derived from it.
 *
 * A TCM needs one function of its curve: the branch shape
 * g(d) = f0(lo + d) - f0(lo), d in [0, hi - lo] (docs/theory.md).
 * hyst_curve_t holds it ready for per-sample use, as a tagged union of four
 * kinds:
 *  - polynomial: shifted to lo and scaled to u = d / (hi - lo) in [0, 1]
 *    once, at set-up, in hyst_wide_t precision; one Horner evaluation inline;
 *  - piecewise linear (breakpoints + values, or a PI loading curve, pi.h):
 *    binary search for the segment, exact at the breakpoints;
 *  - the inverses of both (hyst_curve_inverse()), for a compensator: the
 *    same engine on f0^-1 (inverse.h).
 *
 * A curve is prepared for one real variant (f32 or f64): its numbers have
 * that type. It may be const, live in flash and serve several instances; an
 * instance keeps a pointer to it (and a copy of what its per-sample path
 * needs), so it must outlive them, unchanged.
 */
#ifndef HYST_CURVE_H
#define HYST_CURVE_H

#include "hyst/status.h"
#include "hyst/types.h"

#ifdef __cplusplus
extern "C" {
#endif

/**
 * @brief A polynomial f0 on [lo, hi], as the user writes it.
 *
 * Coefficients are given HIGHEST POWER FIRST, as in the paper's Eq. 20 and as
 * numpy/MATLAB polyfit print them: f0(x) = coeffs[0] x^n + ... + coeffs[n].
 * Only the first degree + 1 entries are read. The same description serves
 * every variant. Example (paper, Eq. 20):
 * @code
 * static const hyst_poly_t f0 = { 3, 0.0, 40.0,
 *     { -6.1876e-6, 1.1949e-3, 8.6444e-2, 5.8517e-1 } };
 * @endcode
 */
typedef struct hyst_poly {
    unsigned degree;   /**< n, 1..HYST_MAX_DEGREE */
    hyst_wide_t lo;    /**< lower end of the identified input range */
    hyst_wide_t hi;    /**< upper end, hi > lo */
    hyst_wide_t coeffs[HYST_MAX_DEGREE + 1]; /**< c_n ... c_0, highest power first */
} hyst_poly_t;

/** @brief Kinds of curve the engine can run on. */
typedef enum hyst_curve_kind {
    HYST_CURVE_POLY = 1,     /**< polynomial f0, Horner's rule (inline) */
    HYST_CURVE_PWL = 2,      /**< piecewise-linear f0, binary search */
    HYST_CURVE_POLY_INV = 3, /**< f0^-1 of a polynomial: monotone bisection */
    HYST_CURVE_PWL_INV = 4,  /**< f0^-1 of a piecewise-linear f0: exact */
    HYST_CURVE_INV_TABLE = 5, /**< f0^-1 of a polynomial: cubic pieces on a uniform grid (inline) */
    HYST_CURVE_EVERETT = 6,  /**< asymmetric: a two-variable branch function E (inline) */
    HYST_CURVE_EVERETT_INV = 7, /**< the asymmetric kind's inverse: Newton per branch, bracketed */
    /** the asymmetric kind's inverse tabulated: rows of cubic pieces over
     *  the branch's start, blended per branch (inline) */
    HYST_CURVE_EVERETT_INV_TABLE = 8,
    /** asymmetric: E of a Preisach density constant on the cells of a grid
     *  (hyst_everett_grid_t); branches piecewise quadratic */
    HYST_CURVE_EVERETT_GRID = 9,
    /** its compensator: each branch's quadratic pieces solved in closed form */
    HYST_CURVE_EVERETT_GRID_INV = 10,
    /** f0 a monotone cubic spline on uniform knots (hyst_spline_t): cubic
     *  pieces in a table (inline) */
    HYST_CURVE_SPLINE = 11,
    /** its compensator: each sample's piece found by binary search, its
     *  cubic solved by Newton's iteration in its bracket */
    HYST_CURVE_SPLINE_INV = 12,
    /** its compensator tabulated: cubic pieces of f0^-1 on a uniform grid
     *  of the output, as HYST_CURVE_INV_TABLE's (inline) */
    HYST_CURVE_SPLINE_INV_TABLE = 13
} hyst_curve_kind_t;

/** Numbers of the table of an HYST_CURVE_INV_TABLE or
 *  HYST_CURVE_SPLINE_INV_TABLE curve with @p intervals intervals: four per
 *  interval, and four for the end of the range. */
#define HYST_INV_TABLE_LEN(intervals) (4u * ((intervals) + 1u))

/** Numbers of the table of an HYST_CURVE_EVERETT_INV_TABLE curve: both
 *  directions, @p rows + 1 rows each, HYST_INV_TABLE_LEN(@p intervals) per row. */
#define HYST_EVERETT_INV_TABLE_LEN(rows, intervals) (2u * ((rows) + 1u) * HYST_INV_TABLE_LEN(intervals))

/** Highest total degree of a branch function E (hyst_everett_t). */
#define HYST_EVERETT_MAX_DEGREE 4
/** Coefficients of E at that degree: w^i t^j, i >= 1, i + j <= degree. */
#define HYST_EVERETT_TERMS (HYST_EVERETT_MAX_DEGREE * (HYST_EVERETT_MAX_DEGREE + 1) / 2)

/**
 * @brief An asymmetric model (docs/theory.md, "Asymmetric hysteresis"): its
 *        branch function E, a polynomial in the loop's width and lower end.
 *
 * Rising from a turning point (b, y_b): y = y_b + E(x, b); falling from
 * (a, y_a): y = y_a - E(a, x), with, for lo <= b <= a <= hi,
 *   E(a, b) = sum of e[i - 1][j] w^i t^j over i >= 1, j >= 0, i + j <= degree,
 *   w = (a - b) / (hi - lo),  t = (b - lo) / (hi - lo).
 * E(b, b) = 0 by construction; E must increase in a and decrease in b on the
 * whole triangle (checked). A symmetric TCM is the case e[i - 1][j] = 0 for
 * j > 0 (E then depends on the width only).
 */
typedef struct hyst_everett {
    unsigned degree; /**< total degree in (w, t), 1..HYST_EVERETT_MAX_DEGREE */
    hyst_wide_t lo;  /**< domain */
    hyst_wide_t hi;  /**< upper end, hi > lo */
    hyst_wide_t y_lo; /**< output at lo after reset */
    /** e[i - 1][j]: coefficient of w^i t^j; entries with i + j > degree must be 0 */
    hyst_wide_t e[HYST_EVERETT_MAX_DEGREE][HYST_EVERETT_MAX_DEGREE];
} hyst_everett_t;

/** Most knot intervals of a grid branch function (hyst_everett_grid_t). */
#define HYST_EVERETT_GRID_MAX_INTERVALS 12
/** Cells of a grid of @p k knot intervals: k (k + 1) / 2. */
#define HYST_EVERETT_GRID_CELLS(k) ((k) * ((k) + 1u) / 2u)
/** Numbers of the table an HYST_CURVE_EVERETT_GRID curve of @p k knot
 *  intervals keeps (hyst_*_curve_from_everett_grid()): 2 k^2 + 1. */
#define HYST_EVERETT_GRID_TABLE_LEN(k) (2u * (k) * (k) + 1u)

/**
 * @brief An asymmetric model whose branch function E is the Preisach
 *        integral of a density constant on the cells of a grid
 *        (docs/theory.md, "Asymmetric hysteresis"): loops with near-steps
 *        and saturation (shape-memory alloys, magnetics) that a polynomial
 *        E cannot follow.
 *
 * The knots lo = knots[0] < ... < knots[K] = hi cut the triangle
 * lo <= b <= a <= hi into cells (i, j), j <= i: a in knot interval i, b in
 * interval j (the cells i = j are triangles). weight[i (i + 1) / 2 + j] >= 0
 * is the cell's mass: what the output gains when all of the cell switches
 * up. E(a, b) is the mass of the part of the triangle b <= b' <= a' <= a,
 * the density uniform in each cell; rising from a turning point (b, y_b)
 * y = y_b + E(x, b), falling from (a, y_a) y = y_a - E(a, x), as for
 * hyst_everett_t. Non-negative weights make every branch increasing, and
 * every branch is piecewise quadratic in x with its knots at the grid's.
 * y_hi = y_lo + the sum of the weights.
 */
typedef struct hyst_everett_grid {
    unsigned intervals; /**< K, 1..HYST_EVERETT_GRID_MAX_INTERVALS */
    hyst_wide_t knots[HYST_EVERETT_GRID_MAX_INTERVALS + 1]; /**< K + 1, strictly increasing */
    hyst_wide_t y_lo;   /**< output at lo after reset */
    /** weight[i (i + 1) / 2 + j], j <= i < K: cell (i, j)'s mass, >= 0 */
    hyst_wide_t weight[HYST_EVERETT_GRID_CELLS(HYST_EVERETT_GRID_MAX_INTERVALS)];
} hyst_everett_grid_t;

/** Most knot intervals of a spline f0 (hyst_spline_t). */
#define HYST_SPLINE_MAX_INTERVALS 32
/** Numbers of the table of an HYST_CURVE_SPLINE curve of @p k knot
 *  intervals (hyst_*_curve_from_spline()): four per interval, four for hi. */
#define HYST_SPLINE_TABLE_LEN(k) (4u * ((k) + 1u))

/**
 * @brief A symmetric model whose f0 is a cubic spline on uniform knots:
 *        near-steps and saturation that a polynomial of low degree cannot
 *        follow, at the per-sample cost of one cubic.
 *
 * The knots are x_k = lo + k (hi - lo) / K, k = 0..K. Between two knots f0
 * is the cubic (Hermite) that takes value[k] and slope[k] at x_k and
 * value[k + 1], slope[k + 1] at x_(k + 1): continuous with its first
 * derivative. Slopes are in output units per input unit; MATLAB's pchip()
 * and SciPy's PchipInterpolator give monotone ones. The curve checks that
 * every piece increases (hyst_*_curve_from_spline()). Example, f0 = x^3 + x
 * on [0, 1] with two pieces:
 * @code
 * static const hyst_spline_t f0 = { 2, 0.0, 1.0,
 *     { 0.0, 0.625, 2.0 }, { 1.0, 1.75, 4.0 } };
 * @endcode
 */
typedef struct hyst_spline {
    unsigned intervals; /**< K, 1..HYST_SPLINE_MAX_INTERVALS */
    hyst_wide_t lo;     /**< lower end of the domain */
    hyst_wide_t hi;     /**< upper end, hi > lo */
    hyst_wide_t value[HYST_SPLINE_MAX_INTERVALS + 1]; /**< f0(x_k), k = 0..K */
    hyst_wide_t slope[HYST_SPLINE_MAX_INTERVALS + 1]; /**< f0'(x_k), >= 0 */
} hyst_spline_t;

/** @brief f0(x) of a spline (x clamped to [lo, hi]), in hyst_wide_t: for
 *         tools and tests. 0 for NULL. */
hyst_wide_t hyst_spline_eval(const hyst_spline_t *f0, hyst_wide_t x);

/**
 * @brief Polynomial branch shape on u in [0, 1]:
 *        G(u) = f0(lo + u (hi - lo)) - f0(lo) = u (a[0] u^(n-1) + ... + a[n-1]).
 */
typedef struct hyst_curve_poly {
    unsigned degree;                 /**< n */
    hyst_num_t a[HYST_MAX_DEGREE];   /**< a[0] multiplies u^n */
} hyst_curve_poly_t;

/**
 * @brief A spline's pieces as a prepared curve keeps them (HYST_CURVE_SPLINE,
 *        its compensators).
 */
typedef struct hyst_curve_spline {
    /** the caller's table, HYST_SPLINE_TABLE_LEN(intervals) numbers:
     *  interval k holds c0..c3 of G(s) = c0 + t (c1 + t (c2 + t c3)),
     *  s = (x - lo) intervals / (hi - lo) of the forward curve,
     *  k = floor(s), t = s - k; the last four G(hi - lo), 0, 0, 0 */
    hyst_cptr_t table;
    size_t intervals;  /**< K */
    hyst_num_t span;   /**< the forward curve's hi - lo */
} hyst_curve_spline_t;

/**
 * @brief A prepared curve: its kind, its variant and the data of the kind.
 *
 * Filled by a constructor below; treat as read-only. The first three
 * members sit at the same offsets whatever the layout options, so a curve
 * built with other options is recognised and refused (HYST_ERR_LAYOUT).
 * lo, hi is the domain of THIS curve and y_lo, y_hi its values there: for an
 * inverse curve the domain is [f0(lo), f0(hi)] and the values lo, hi.
 */
typedef struct hyst_curve {
    unsigned kind;         /**< hyst_curve_kind_t */
    unsigned variant;      /**< HYST_VARIANT_F32 or HYST_VARIANT_F64: type of the numbers */
    unsigned long layout;  /**< HYST_LAYOUT of the library that prepared it */
    hyst_num_t lo, hi;     /**< domain */
    hyst_num_t y_lo, y_hi; /**< values at lo and hi */
    /** argument scale of g: 1 / (hi - lo) for POLY (g takes u), 1 for the
     *  other kinds (g takes d itself) */
    hyst_num_t unit;
    /** POLY: bound on |computed - exact| of one branch evaluation
     *  y_k +- g(x - x_k) in the variant's type (output units; the rounding
     *  of y_k itself adds one such bound per stored turning point below the
     *  current one); at most HYST_MAX_ROUNDING of the output range, else the
     *  constructor refuses the curve (HYST_ERR_ILL_CONDITIONED). 0 for the
     *  other kinds (not computed). */
    hyst_num_t rounding;
    union {
        hyst_curve_poly_t poly; /**< POLY */
        struct {
            hyst_curve_poly_t fwd;  /**< the forward polynomial's G */
            hyst_num_t span;        /**< input span of f0 (u -> d) */
            hyst_num_t knot_scale;  /**< HYST_INV_KNOTS / (f0(hi) - f0(lo)) */
            /** u where G(u) = k / knot_scale, k = 0..HYST_INV_KNOTS */
            hyst_num_t knot_u[HYST_INV_KNOTS + 1];
        } poly_inv; /**< POLY_INV */
        struct {
            unsigned degree; /**< n */
            /** per branch: the coefficient of w^i is a polynomial in the
             *  branch's anchor (rising: t of its LTP; falling: s = (a - lo) /
             *  (hi - lo) of its RTP); row i = n..1 (highest power of w first),
             *  anchor powers highest first, rows of n - i + 1 entries */
            hyst_num_t rise[HYST_EVERETT_TERMS];
            hyst_num_t fall[HYST_EVERETT_TERMS];
            /** EVERETT with every row at most linear in the anchor, on a
             *  domain with |lo| <= hi - lo (linear_x = 1): the same rows as
             *  functions of the turning point's input x itself, rising then
             *  falling, row i = n..1 a pair (slope in x, value at x = 0)
             *  after the top one's single entry; a slow sample then derives
             *  a branch without computing its anchor. 0 and unused else. */
            hyst_num_t lin_x[2][2 * HYST_EVERETT_MAX_DEGREE - 1];
            unsigned linear_x;
            hyst_num_t span;     /**< the drive's span hi - lo (of the forward curve) */
            hyst_num_t inv_span; /**< 1 / span */
            /** EVERETT_INV: Newton's last step, in w, at which the drive is
             *  taken (2^-20 in float, 2^-40 in double); 0 for EVERETT */
            hyst_num_t tol;
            hyst_num_t branch_rounding; /**< the forward curve's rounding bound */
            /** EVERETT_INV_TABLE: the caller's table, HYST_EVERETT_INV_TABLE_LEN(rows,
             *  intervals) numbers: direction (rising, falling), then row r of the
             *  branch's start a = r / rows (rising: t of its LTP; falling: s of its
             *  RTP), then as an INV_TABLE: interval k holds the drive step (drive
             *  units) at s = v intervals / V(a) as c0 + t (c1 + t (c2 + t c3)),
             *  v the output step, V(a) the branch's whole output step; c0 = -1 in
             *  every row marks an interval solved instead; NULL for the other kinds */
            hyst_cptr_t table;
            size_t rows;      /**< anchors - 1 (>= 3) */
            size_t intervals; /**< intervals per row (>= 1) */
            size_t exact;     /**< intervals (per direction, all rows) solved instead */
            hyst_wide_t max_err; /**< worst measured error / drive span (EVERETT_INV_TABLE) */
            /** V(a) per direction, a polynomial in the anchor, highest power first */
            hyst_num_t v_end[2][HYST_EVERETT_MAX_DEGREE + 1];
        } everett; /**< EVERETT, EVERETT_INV and EVERETT_INV_TABLE */
        struct {
            /** INV_TABLE: the forward polynomial's G (the exact intervals);
             *  degree 0 for SPLINE_INV_TABLE */
            hyst_curve_poly_t fwd;
            hyst_num_t span;        /**< input span of f0 (the drive range) */
            /** G's argument per drive step: 1 / span (INV_TABLE: G of u in
             *  [0, 1]); the forward spline's unit, intervals / span
             *  (SPLINE_INV_TABLE: G of s in knot intervals) */
            hyst_num_t u_per_d;
            /** the caller's table, HYST_INV_TABLE_LEN(intervals) numbers:
             *  interval k holds c0..c3 of d(s) = c0 + t (c1 + t (c2 + t c3)),
             *  s = e intervals / (f0(hi) - f0(lo)), k = floor(s), t = s - k;
             *  c0 = -1 marks an interval evaluated exactly */
            hyst_cptr_t table;
            size_t intervals;       /**< N */
            size_t exact;           /**< intervals evaluated exactly (flat points) */
            /** worst |table - exact inverse| / span measured at init over the
             *  table-evaluated intervals, rounding of the evaluation included */
            hyst_wide_t max_err;
            /** the q31 compensator's drive (q31.h): (code - drive_code_lo)
             *  2^drive_bits; 0 for the real variants */
            unsigned drive_bits;
            uint_least32_t drive_code_lo;
            /** SPLINE_INV_TABLE: the forward spline's pieces (the exact
             *  intervals), whose table must outlive this curve; unused for
             *  INV_TABLE */
            hyst_curve_spline_t fwd_spline;
        } inv_table; /**< INV_TABLE and SPLINE_INV_TABLE */
        struct {
            /** the caller's table, HYST_EVERETT_GRID_TABLE_LEN(intervals)
             *  numbers: the knots (K + 1), half of each diagonal cell's
             *  density (K), then for each cell (i, j), j < i, in the order
             *  i = 1..K-1, j = 0..i-1, four numbers: E(knot i, knot j + 1),
             *  the column's mass per unit of b between them, the row's per
             *  unit of a, and the cell's density (src/kind_everett_grid.h) */
            hyst_cptr_t table;
            unsigned intervals; /**< K */
        } everett_grid; /**< EVERETT_GRID and EVERETT_GRID_INV */
        hyst_curve_spline_t spline; /**< SPLINE and SPLINE_INV */
        struct {
            hyst_cptr_t x;  /**< the curve's breakpoints (caller's array) */
            hyst_cptr_t y;  /**< its values (caller's array) */
            size_t n;       /**< points, >= 2 */
        } pwl; /**< PWL and PWL_INV (for PWL_INV, x are f0's values) */
    } u;
} hyst_curve_t;

/**
 * @name Polynomial curve
 * @brief Validates a polynomial f0 and prepares its branch shape.
 *
 * Checks, in this order: NULL pointers, degree in 1..HYST_MAX_DEGREE, finite
 * lo < hi with a finite span hi - lo in the variant's type (HYST_ERR_DOMAIN),
 * finite coefficients and every per-sample quantity finite in the variant's
 * type: outputs, their span, Horner's partial sums (HYST_ERR_COEFF; a curve
 * that would make a sample overflow is refused here, not at the sample),
 * and that f0 is increasing on [lo, hi] (its slope is never
 * negative; isolated zeros such as x^2 at 0 are accepted). @p curve is
 * written only on success. Arguments: curve (out), f0 (highest power first).
 * @return HYST_OK, HYST_ERR_NULL, HYST_ERR_LAYOUT, HYST_ERR_DEGREE,
 *         HYST_ERR_DOMAIN, HYST_ERR_COEFF or HYST_ERR_NOT_INCREASING.
 */
/**@{*/
hyst_status_t hyst_f32_curve_from_poly_(hyst_curve_t *curve, const hyst_poly_t *f0,
                                        unsigned long layout);
#define hyst_f32_curve_from_poly(curve, f0) hyst_f32_curve_from_poly_((curve), (f0), HYST_LAYOUT)
#if HYST_ENABLE_F64
hyst_status_t hyst_f64_curve_from_poly_(hyst_curve_t *curve, const hyst_poly_t *f0,
                                        unsigned long layout);
#define hyst_f64_curve_from_poly(curve, f0) hyst_f64_curve_from_poly_((curve), (f0), HYST_LAYOUT)
#endif
/**@}*/

/**
 * @name A polynomial curve sealed ahead of time
 * @brief The polynomial kind's prepared numbers, made and checked where
 *        double costs nothing (the host: `hyst header --sealed`), and a
 *        CRC-32 over them, so that firmware takes them from flash with
 *        hyst_*_init_sealed() (tcm.h): integer work only, none of the
 *        curve's construction and no double arithmetic linked.
 *
 * hyst_*_seal_poly() runs every check of hyst_*_curve_from_poly() (its
 * statuses) and writes the numbers the instance runs on: the domain, the
 * outputs at its ends, G's argument scale 1 / (hi - lo), the rounding bound
 * and G's coefficients (hyst_curve_poly_t, a[0] of u^n). @p seal covers the
 * format, kind, variant, degree and every number as stored (its bit
 * pattern); a layout option changes none of them, and the layout is checked
 * by the init (the caller's HYST_LAYOUT). An instance initialised from the
 * sealed curve is, bit for bit, the one hyst_*_init() makes from @p f0 with
 * double set-up (HYST_NO_DOUBLE off). @p out is written only on success.
 */
/**@{*/
typedef struct hyst_f32_sealed_poly {
    unsigned long seal;       /**< CRC-32 of the format, kind, variant, degree, numbers */
    unsigned degree;          /**< n, 1..HYST_MAX_DEGREE */
    float lo, hi;             /**< domain */
    float y_lo, y_hi;         /**< f0(lo), f0(hi) */
    float unit;               /**< 1 / (hi - lo) */
    float rounding;           /**< the rounding bound (hyst_curve_t) */
    float a[HYST_MAX_DEGREE]; /**< G(u) = u (a[0] u^(n-1) + ... + a[n-1]) */
} hyst_f32_sealed_poly_t;
hyst_status_t hyst_f32_seal_poly_(hyst_f32_sealed_poly_t *out, const hyst_poly_t *f0,
                                  unsigned long layout);
#define hyst_f32_seal_poly(out, f0) hyst_f32_seal_poly_((out), (f0), HYST_LAYOUT)
#if HYST_ENABLE_F64
typedef struct hyst_f64_sealed_poly {
    unsigned long seal;        /**< CRC-32 of the format, kind, variant, degree, numbers */
    unsigned degree;           /**< n, 1..HYST_MAX_DEGREE */
    double lo, hi;             /**< domain */
    double y_lo, y_hi;         /**< f0(lo), f0(hi) */
    double unit;               /**< 1 / (hi - lo) */
    double rounding;           /**< the rounding bound (hyst_curve_t) */
    double a[HYST_MAX_DEGREE]; /**< G(u) = u (a[0] u^(n-1) + ... + a[n-1]) */
} hyst_f64_sealed_poly_t;
hyst_status_t hyst_f64_seal_poly_(hyst_f64_sealed_poly_t *out, const hyst_poly_t *f0,
                                  unsigned long layout);
#define hyst_f64_seal_poly(out, f0) hyst_f64_seal_poly_((out), (f0), HYST_LAYOUT)
#endif
/**@}*/

/**
 * @name Asymmetric curve
 * @brief Validates a branch function E (hyst_everett_t) and prepares its
 *        per-branch tables.
 *
 * Checks: NULL pointers, degree in 1..HYST_EVERETT_MAX_DEGREE (and at most
 * HYST_MAX_DEGREE), the domain
 * (HYST_ERR_DOMAIN), finite coefficients, zero above the degree
 * (HYST_ERR_COEFF), and, once, that dE/da >= 0 and dE/db <= 0 on the whole
 * triangle lo <= b <= a <= hi (Bernstein-Bezier coefficients on the
 * triangle, subdivided where needed; HYST_ERR_NOT_MONOTONE otherwise), and
 * the rounding bound in the variant's type (HYST_ERR_ILL_CONDITIONED). The
 * curve then runs on hyst_*_init_curve() (it must outlive the instance):
 * the fast path is the polynomial kind's, the branch's coefficients are
 * derived when the current turning point changes.
 * @return HYST_OK or the first failed check; @p curve written only on success.
 */
/**@{*/
hyst_status_t hyst_f32_curve_from_everett_(hyst_curve_t *curve, const hyst_everett_t *e,
                                           unsigned long layout);
#define hyst_f32_curve_from_everett(curve, e) \
    hyst_f32_curve_from_everett_((curve), (e), HYST_LAYOUT)
#if HYST_ENABLE_F64
hyst_status_t hyst_f64_curve_from_everett_(hyst_curve_t *curve, const hyst_everett_t *e,
                                           unsigned long layout);
#define hyst_f64_curve_from_everett(curve, e) \
    hyst_f64_curve_from_everett_((curve), (e), HYST_LAYOUT)
#endif
/**@}*/

/**
 * @name Asymmetric curve on a grid
 * @brief Validates a grid branch function (hyst_everett_grid_t) and
 *        prepares its table.
 *
 * Checks: NULL pointers, intervals in 1..HYST_EVERETT_GRID_MAX_INTERVALS
 * (HYST_ERR_DEGREE), finite and strictly increasing knots, also in the
 * variant's type (HYST_ERR_BREAKPOINTS), a finite y_lo and finite weights
 * (HYST_ERR_COEFF), weights >= 0 with a positive sum (HYST_ERR_NOT_MONOTONE),
 * @p table_len >= HYST_EVERETT_GRID_TABLE_LEN(intervals) (HYST_ERR_NOSPACE),
 * every tabulated number finite in the variant's type, and a normal number
 * of it where it carries more than a cell's share of a rounding of the
 * total mass (a density, a mass per unit of input) (HYST_ERR_COEFF) and
 * the rounding bound (HYST_ERR_ILL_CONDITIONED). The curve keeps a pointer
 * to @p table, which must outlive it, unchanged; it runs on
 * hyst_*_init_curve(). A sample on the fast path costs a compare and one
 * quadratic while it stays within a knot interval; a new interval's
 * coefficients come from the table in a few operations, and a branch's
 * from its turning point when it starts. Its compensator:
 * hyst_*_curve_everett_grid_inverse(); hyst_curve_inverse(), the tables'
 * builders and hyst_curve_check() answer HYST_ERR_ARG for the kind.
 * @return HYST_OK or the first failed check; @p curve and @p table written
 *         only on success (the table is filled, then the curve).
 */
/**@{*/
hyst_status_t hyst_f32_curve_from_everett_grid_(hyst_curve_t *curve, const hyst_everett_grid_t *g,
                                                float *table, size_t table_len,
                                                unsigned long layout);
#define hyst_f32_curve_from_everett_grid(curve, g, table, table_len) \
    hyst_f32_curve_from_everett_grid_((curve), (g), (table), (table_len), HYST_LAYOUT)
#if HYST_ENABLE_F64
hyst_status_t hyst_f64_curve_from_everett_grid_(hyst_curve_t *curve, const hyst_everett_grid_t *g,
                                                double *table, size_t table_len,
                                                unsigned long layout);
#define hyst_f64_curve_from_everett_grid(curve, g, table, table_len) \
    hyst_f64_curve_from_everett_grid_((curve), (g), (table), (table_len), HYST_LAYOUT)
#endif
/**@}*/

/**
 * @name Spline curve
 * @brief Validates a spline f0 (hyst_spline_t) and prepares its table of
 *        cubic pieces.
 *
 * Checks, in this order: NULL pointers, the layout, intervals in
 * 1..HYST_SPLINE_MAX_INTERVALS (HYST_ERR_DEGREE), finite lo < hi with a
 * finite span, also in the variant's type (HYST_ERR_DOMAIN), finite values
 * and slopes (HYST_ERR_COEFF), that f0 increases: every slope >= 0, every
 * piece's slope >= 0 between its knots (exact for a cubic, within 64
 * roundings of the piece's scale) and value[K] > value[0]
 * (HYST_ERR_NOT_INCREASING), @p table_len >=
 * HYST_SPLINE_TABLE_LEN(intervals) (HYST_ERR_NOSPACE), and every tabulated
 * number finite in the variant's type (HYST_ERR_COEFF). The curve keeps a
 * pointer to @p table, which must outlive it, unchanged; it runs on
 * hyst_*_init_curve(): a sample on the fast path costs one cubic, its
 * piece found by one multiplication. Its compensators:
 * hyst_curve_spline_inverse() and, tabulated,
 * hyst_*_curve_spline_inverse_table(); hyst_curve_check(),
 * hyst_curve_inverse() and the polynomial's and asymmetric kind's table
 * builders answer HYST_ERR_ARG for the kind.
 * @return HYST_OK or the first failed check; @p curve and @p table written
 *         only on success (the table, then the curve).
 */
/**@{*/
hyst_status_t hyst_f32_curve_from_spline_(hyst_curve_t *curve, const hyst_spline_t *f0,
                                          float *table, size_t table_len, unsigned long layout);
#define hyst_f32_curve_from_spline(curve, f0, table, table_len) \
    hyst_f32_curve_from_spline_((curve), (f0), (table), (table_len), HYST_LAYOUT)
#if HYST_ENABLE_F64
hyst_status_t hyst_f64_curve_from_spline_(hyst_curve_t *curve, const hyst_spline_t *f0,
                                          double *table, size_t table_len, unsigned long layout);
#define hyst_f64_curve_from_spline(curve, f0, table, table_len) \
    hyst_f64_curve_from_spline_((curve), (f0), (table), (table_len), HYST_LAYOUT)
#endif
/**@}*/

/**
 * @brief The compensator of a spline curve (hyst_*_curve_from_spline()):
 *        its input the desired output on [f0(lo), f0(hi)], its output the
 *        drive; of a compensator, solved or tabulated, the spline again.
 *
 * The same table: per sample, the last knot below the desired output
 * (a binary search) and its piece's cubic solved by bisection, every
 * sample out of line; monotone, exact at the knots. A flat piece has no
 * inverse (HYST_ERR_NOT_INVERTIBLE). hyst_curve_inverse() answers
 * HYST_ERR_ARG for this kind, so that a firmware inverting a polynomial
 * links none of it. The tabulated compensator, an index and one cubic
 * per sample: hyst_*_curve_spline_inverse_table().
 * @param[out] inv prepared inverse curve (may be the same object as @p fwd).
 * @param[in]  fwd a spline curve or one of its compensators.
 * @return HYST_OK, HYST_ERR_NULL, HYST_ERR_LAYOUT, HYST_ERR_ARG (not a
 *         prepared spline curve) or HYST_ERR_NOT_INVERTIBLE; @p inv
 *         written only on success.
 */
hyst_status_t hyst_curve_spline_inverse(hyst_curve_t *inv, const hyst_curve_t *fwd);

/**
 * @name Tabulated compensator of a spline curve
 * @brief Prepares the compensator of a spline curve
 *        (hyst_*_curve_from_spline()) with f0^-1 tabulated as
 *        hyst_*_curve_inverse_table() tabulates a polynomial's: a sample
 *        costs an index and one cubic, inline, where
 *        hyst_curve_spline_inverse()'s solves every sample out of line.
 *
 * The drive step d(e) for an output step e is tabulated on @p intervals
 * intervals uniform in e: the exact inverse of the spline's pieces at the
 * knots (solved in hyst_wide_t on the pieces as stored), its slope there
 * limited as Fritsch and Carlson do, cubic Hermite pieces between. Init
 * measures every interval against the exact inverse (15 points each); an
 * interval that misses HYST_INV_TABLE_TOL of the drive range (around a
 * knot, whose change of curvature bends d beyond a cubic, and next to a
 * knot of slope 0, where d has an infinite slope) is solved per sample
 * instead, out of line, as hyst_curve_spline_inverse()'s compensator
 * solves every sample: a spline needs more intervals than a polynomial for
 * as few of those. hyst_curve_inverse_error() reports the worst
 * measured error plus the drive's last rounding. The curve keeps pointers
 * to @p table and to the forward curve's table, both of which must outlive
 * it, unchanged (the forward curve itself need not). Its inverse,
 * hyst_curve_spline_inverse(), is the spline again; hyst_curve_inverse(),
 * hyst_curve_check() and the seals answer HYST_ERR_ARG for the kind.
 * @param[out] inv prepared inverse curve.
 * @param[in]  fwd a spline curve (hyst_*_curve_from_spline()) of the same variant.
 * @param[out] table HYST_INV_TABLE_LEN(intervals) numbers.
 * @param[in]  intervals 1 .. 2^20, as for a polynomial (HYST_INV_TABLE by default).
 * @return HYST_OK, HYST_ERR_NULL, HYST_ERR_LAYOUT (a curve of another
 *         variant), HYST_ERR_ARG (not a spline curve, or intervals out of
 *         range), HYST_ERR_NOT_INVERTIBLE (a flat piece, as
 *         hyst_curve_spline_inverse() refuses it) or
 *         HYST_ERR_ILL_CONDITIONED (the output range so small, subnormal,
 *         that intervals over it overflows the variant's type); @p inv and
 *         @p table written only on success.
 */
/**@{*/
hyst_status_t hyst_f32_curve_spline_inverse_table(hyst_curve_t *inv, const hyst_curve_t *fwd,
                                                  float *table, size_t intervals);
#if HYST_ENABLE_F64
hyst_status_t hyst_f64_curve_spline_inverse_table(hyst_curve_t *inv, const hyst_curve_t *fwd,
                                                  double *table, size_t intervals);
#endif
/**@}*/

/**
 * @name The compensator of an asymmetric curve on a grid
 * @brief Prepares the inverse of a grid curve (hyst_*_curve_from_everett_grid()):
 *        its input the desired output on [y_lo, y_hi], its output the drive.
 *
 * The forward branch from a turning point is increasing and quadratic on
 * each knot interval, so the compensator solves it in closed form on the
 * piece whose output steps hold the desired one (a square root and a few
 * operations); the current piece is kept, so a sample in it costs no
 * search. Stored turning points are (desired output, drive); the drive is
 * monotone along a branch (the engine's guard). Deadband and bounded memory
 * state the drive range as their bound. The curve keeps the forward curve's
 * table (which must outlive it) and runs on hyst_*_init_curve(). Its rounding
 * (hyst_rounding_bound()) is the solve's, 16 eps of the drive span; where a
 * branch starts flat (its slope 0 at its turning point) a rounding of the
 * desired output is magnified in the drive.
 * @return HYST_OK, HYST_ERR_NULL, HYST_ERR_LAYOUT (a curve of another variant),
 *         HYST_ERR_ARG (not a grid curve); @p inv written only on success.
 */
/**@{*/
hyst_status_t hyst_f32_curve_everett_grid_inverse(hyst_curve_t *inv, const hyst_curve_t *fwd);
#if HYST_ENABLE_F64
hyst_status_t hyst_f64_curve_everett_grid_inverse(hyst_curve_t *inv, const hyst_curve_t *fwd);
#endif
/**@}*/

/**
 * @name Piecewise-linear curve
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
 */
/**@{*/
hyst_status_t hyst_f32_curve_from_pwl_(hyst_curve_t *curve, const float *x, const float *y,
                                       size_t n, unsigned long layout);
#define hyst_f32_curve_from_pwl(curve, x, y, n) \
    hyst_f32_curve_from_pwl_((curve), (x), (y), (n), HYST_LAYOUT)
#if HYST_ENABLE_F64
hyst_status_t hyst_f64_curve_from_pwl_(hyst_curve_t *curve, const double *x, const double *y,
                                       size_t n, unsigned long layout);
#define hyst_f64_curve_from_pwl(curve, x, y, n) \
    hyst_f64_curve_from_pwl_((curve), (x), (y), (n), HYST_LAYOUT)
#endif
/**@}*/

/**
 * @brief Prepares the inverse curve f0^-1, for a compensator (inverse.h).
 *
 * A TCM initialised with the result (hyst_*_init_curve()) is the inverse
 * model: its input is the desired output on [f0(lo), f0(hi)], its output the
 * input that produces it. The engine clamps desired outputs outside that
 * range and reports HYST_WARN_CLAMPED.
 *  - polynomial: g^-1 by bisection, <= 2 HYST_INV_MAX_ITER steps, monotone;
 *  - piecewise linear: exact (the same points with the axes swapped; the
 *    inverse keeps pointing at the caller's arrays);
 *  - asymmetric (HYST_CURVE_EVERETT): HYST_CURVE_EVERETT_INV, stored turning
 *    points (desired output, drive) and, per branch, the drive step whose
 *    output step on the forward branch p(w) = E(...) is the desired one:
 *    Newton's iteration from the last drive, bracketed by the branch's ends
 *    (bisection where a step would leave the bracket); monotone, error in
 *    the drive about tol (curve.h) of its span, restores bit for bit.
 *    Deadband and bounded memory on it state the drive range as their bound
 *    (docs/pi_and_inverse.md). Real variants and integer codes, not q31;
 *  - an inverse curve: gives back the forward curve.
 * The forward curve must be strictly increasing: a PWL f0 with a flat piece,
 * or a polynomial with a flat stretch wider than rounding, is refused.
 * The inverse has the variant of @p fwd.
 *
 * @param[out] inv prepared inverse curve (may be the same object as @p fwd).
 * @param[in]  fwd curve prepared by a constructor.
 * @return HYST_OK, HYST_ERR_NULL, HYST_ERR_ARG (not a prepared curve),
 *         HYST_ERR_LAYOUT or HYST_ERR_NOT_INVERTIBLE.
 */
hyst_status_t hyst_curve_inverse(hyst_curve_t *inv, const hyst_curve_t *fwd);

/**
 * @name Tabulated inverse of a polynomial curve
 * @brief Prepares f0^-1 as a table of cubic pieces, for a compensator whose
 *        per-sample cost does not depend on the precision: an index and one
 *        cubic, inline on the fast path like a forward polynomial.
 *
 * The inverse branch function d(e) (drive step for an output step e) is
 * tabulated on @p intervals intervals uniform in e: the exact inverse at the
 * knots (bisection in hyst_wide_t), its slope there limited as Fritsch and
 * Carlson do (the pieces are monotone in exact arithmetic), cubic Hermite
 * pieces between. Init measures every interval against the exact inverse
 * (15 points each); an interval that misses HYST_INV_TABLE_TOL of the drive
 * range (next to a flat point of f0, where d has an infinite slope) is
 * evaluated exactly per sample instead (bisection in the interval's
 * bracket, out of line). hyst_curve_inverse_error() reports the worst
 * measured error plus the drive's last rounding (the drive step added to
 * the turning point's drive, eps |drive|: most of it on a domain far from 0
 * relative to its span). The table is caller storage of
 * HYST_INV_TABLE_LEN(@p intervals) numbers of the variant's type that must
 * outlive the curve, unchanged; @p inv keeps a pointer to it.
 * @param[out] inv prepared inverse curve.
 * @param[in]  fwd a polynomial curve (hyst_*_curve_from_poly()) of the same variant.
 * @param[out] table HYST_INV_TABLE_LEN(intervals) numbers.
 * @param[in]  intervals 1 .. 2^20 (HYST_INV_TABLE by default: docs/pi_and_inverse.md
 *             gives the size/error trade-off).
 * @return HYST_OK, HYST_ERR_NULL, HYST_ERR_LAYOUT (a curve of another variant),
 *         HYST_ERR_ARG (not a polynomial curve, or intervals out of range),
 *         HYST_ERR_NOT_INVERTIBLE or HYST_ERR_ILL_CONDITIONED (the output
 *         range so small, subnormal, that intervals over it overflows the
 *         variant's type; hyst_curve_inverse() takes such a curve).
 */
/**@{*/
hyst_status_t hyst_f32_curve_inverse_table(hyst_curve_t *inv, const hyst_curve_t *fwd,
                                           float *table, size_t intervals);
#if HYST_ENABLE_F64
hyst_status_t hyst_f64_curve_inverse_table(hyst_curve_t *inv, const hyst_curve_t *fwd,
                                           double *table, size_t intervals);
#endif
/**@}*/

/**
 * @name Tabulated inverse of an asymmetric curve
 * @brief Prepares the asymmetric kind's compensator (HYST_CURVE_EVERETT_INV,
 *        hyst_curve_inverse()) with its branches tabulated: a sample costs an
 *        index and one cubic, inline, whatever the branch.
 *
 * The inverse of a branch depends on where it starts (its anchor a: the
 * drive of its turning point over the drive range). For @p rows + 1 anchors
 * a = r / rows per direction, the drive step is tabulated as in
 * hyst_*_curve_inverse_table() on @p intervals intervals uniform in the
 * output step (cubic Hermite pieces with slopes limited as Fritsch and
 * Carlson do). A branch blends four rows around its anchor with cubic
 * Lagrange weights (its slow sample derives them); the blended cubic of the
 * interval a sample falls in is kept, so the next sample in it costs one
 * cubic. Init measures every interval between every two rows against the
 * exact inverse (4 anchors, 8 points); an interval that misses
 * HYST_INV_TABLE_TOL of the drive range anywhere is solved instead, in every
 * row, as hyst_curve_inverse()'s compensator does (Newton's iteration,
 * bracketed, out of line). hyst_curve_inverse_error() reports the worst
 * measured error plus the drive's last rounding. The drive is monotone along a branch (the engine's guard).
 * The table is caller storage of HYST_EVERETT_INV_TABLE_LEN(@p rows,
 * @p intervals) numbers that must outlive the curve, unchanged.
 * @param[out] inv prepared inverse curve.
 * @param[in]  fwd an asymmetric curve (hyst_*_curve_from_everett()) of the same variant.
 * @param[out] table HYST_EVERETT_INV_TABLE_LEN(rows, intervals) numbers.
 * @param[in]  rows 3 .. 4096 (HYST_EVERETT_INV_ROWS by default).
 * @param[in]  intervals 1 .. 2^20 (HYST_EVERETT_INV_INTERVALS by default).
 * @return HYST_OK, HYST_ERR_NULL, HYST_ERR_LAYOUT (a curve of another variant),
 *         HYST_ERR_ARG (not an asymmetric curve, or rows or intervals out of
 *         range), HYST_ERR_NOT_INVERTIBLE or HYST_ERR_ILL_CONDITIONED (the
 *         output range so small, about 1e-299 in double, 1e-29 in float, that
 *         a branch's interval index, intervals over 2^-30 of it, overflows the
 *         variant's type; hyst_curve_inverse() solves such a curve).
 */
/**@{*/
hyst_status_t hyst_f32_curve_everett_inverse_table(hyst_curve_t *inv, const hyst_curve_t *fwd,
                                                   float *table, size_t rows, size_t intervals);
#if HYST_ENABLE_F64
hyst_status_t hyst_f64_curve_everett_inverse_table(hyst_curve_t *inv, const hyst_curve_t *fwd,
                                                   double *table, size_t rows, size_t intervals);
#endif
/**@}*/

/**
 * @brief The seal of a tabulated inverse built ahead of time: a checksum of
 *        the table as stored (with its kind, variant, shape and this error)
 *        and the error its build measured.
 *
 * Building a table takes a while on a target (the asymmetric compensator's
 * default table: about a second on a Cortex-M4F). A table built on the host
 * (`hyst header --compensator`, or hyst_curve_table_seal() after a build)
 * goes into flash with its seal; firmware then prepares the curve with
 * hyst_*_curve_inverse_table_const() or
 * hyst_*_curve_everett_inverse_table_const() in milliseconds. The table
 * must be built in the variant that uses it (float or double).
 */
typedef struct hyst_table_seal {
    unsigned long crc;   /**< hyst_crc32 of the table's kind, variant, shape, error and numbers */
    hyst_wide_t max_err; /**< hyst_curve_inverse_error() of the build (rounded up to a float) */
} hyst_table_seal_t;

/**
 * @brief Seals a tabulated inverse (HYST_CURVE_INV_TABLE or
 *        HYST_CURVE_EVERETT_INV_TABLE of a real variant) for use from
 *        flash.
 * @return HYST_OK, HYST_ERR_NULL, HYST_ERR_LAYOUT or HYST_ERR_ARG (another
 *         kind or variant).
 */
hyst_status_t hyst_curve_table_seal(const hyst_curve_t *inv, hyst_table_seal_t *seal);

/**
 * @name A tabulated inverse built ahead of time
 * @brief Prepares the curve of a table built before (held in flash) without
 *        building it again: the same curve, bit for bit, as the build that
 *        made the table, and so the same outputs.
 *
 * Checks the seal (the table as stored, its shape, its error:
 * HYST_ERR_CRC when they differ, e.g. a damaged flash image or the wrong
 * rows or intervals), then that the table is this model's, and then what
 * the seal claims. A symmetric curve's table: at seven knots the model at
 * the stored drive step gives the knot's output step back within 8 units
 * of rounding (of its terms, of the drive step and the solver's width), the
 * end is the drive span, and every piece the table evaluates is measured
 * as the build measures it, within HYST_INV_TABLE_TOL and the error sealed.
 * The asymmetric kind's table: every knot of every row on the model's
 * branch as above, each row's end the branch's whole drive step, the
 * intervals evaluated exactly marked alike in every row, every piece the
 * build's (a cubic Hermite piece between two knots, its slope at each the
 * one the build computes from the model there, limited as Fritsch and
 * Carlson limit it, within their rounding), and every interval held as
 * pieces measured as the build measures it, at the same anchors and
 * points, within HYST_INV_TABLE_TOL (where the build would solve, a point
 * off its interval is bounded by two evaluations of the model instead):
 * an interval the build evaluates exactly given back its pieces is
 * refused. HYST_ERR_CURVE otherwise: a table of another model, or pieces
 * changed and sealed again (the table is in output steps relative to a
 * branch's whole step, so the model times a constant has the same table,
 * and is accepted). What is saved is the table's RAM, and for the
 * asymmetric kind the build's solving: its measurement is done again
 * (docs/results.md). The
 * table must hold the counts' numbers
 * (HYST_INV_TABLE_LEN(@p intervals), HYST_EVERETT_INV_TABLE_LEN(@p rows,
 * @p intervals)) and outlive the curve, unchanged.
 * @return what the build returns (HYST_ERR_NULL, HYST_ERR_LAYOUT,
 *         HYST_ERR_ARG, HYST_ERR_NOT_INVERTIBLE), or HYST_ERR_CRC,
 *         HYST_ERR_CURVE.
 */
/**@{*/
hyst_status_t hyst_f32_curve_inverse_table_const(hyst_curve_t *inv, const hyst_curve_t *fwd,
                                                 const float *table, size_t intervals,
                                                 const hyst_table_seal_t *seal);
hyst_status_t hyst_f32_curve_everett_inverse_table_const(hyst_curve_t *inv,
                                                         const hyst_curve_t *fwd,
                                                         const float *table, size_t rows,
                                                         size_t intervals,
                                                         const hyst_table_seal_t *seal);
#if HYST_ENABLE_F64
hyst_status_t hyst_f64_curve_inverse_table_const(hyst_curve_t *inv, const hyst_curve_t *fwd,
                                                 const double *table, size_t intervals,
                                                 const hyst_table_seal_t *seal);
hyst_status_t hyst_f64_curve_everett_inverse_table_const(hyst_curve_t *inv,
                                                         const hyst_curve_t *fwd,
                                                         const double *table, size_t rows,
                                                         size_t intervals,
                                                         const hyst_table_seal_t *seal);
#endif
/**@}*/

/**
 * @brief Worst error of a tabulated inverse (HYST_CURVE_INV_TABLE,
 *        HYST_CURVE_EVERETT_INV_TABLE, HYST_CURVE_SPLINE_INV_TABLE) measured
 *        at init, as a fraction of the drive range; 0 for the other kinds
 *        (exact) and for NULL.
 */
hyst_wide_t hyst_curve_inverse_error(const hyst_curve_t *curve);

/**
 * @brief Checks that a curve was prepared by a constructor of this library.
 *
 * A cheap structural check (layout, variant, kind, domain, pointers), not a
 * re-validation. It is what the functions that take any prepared curve
 * (hyst_curve_inverse(), the tables' builders and seals) require; a grid
 * curve (HYST_CURVE_EVERETT_GRID, _INV), which they have nothing for, is
 * HYST_ERR_ARG here and is checked by hyst_*_init_curve() alone (its
 * compensator: hyst_*_curve_everett_grid_inverse()).
 * @return HYST_OK, HYST_ERR_NULL, HYST_ERR_LAYOUT or HYST_ERR_ARG.
 */
hyst_status_t hyst_curve_check(const hyst_curve_t *curve);

/**
 * @name Evaluation
 * @brief The curve itself, f(x) = y_lo + g(x - lo), for tools and tests
 *        (x clamped to the domain; for an inverse curve, the input that f0
 *        maps to x). The curve must have the function's variant.
 */
/**@{*/
float hyst_f32_curve_eval(const hyst_curve_t *curve, float x);
#if HYST_ENABLE_F64
double hyst_f64_curve_eval(const hyst_curve_t *curve, double x);
#endif
/**@}*/

/**
 * @name Branch shape
 * @brief g(d) = f(lo + d) - f(lo) of a prepared curve f, 0 <= d <= hi - lo:
 *        what the engine evaluates (one Horner evaluation for a polynomial,
 *        a binary search for a piecewise-linear curve, the monotone
 *        bisection for an inverted polynomial); g(0) is exactly 0.
 */
/**@{*/
float hyst_f32_curve_g(const hyst_curve_t *curve, float d);
#if HYST_ENABLE_F64
double hyst_f64_curve_g(const hyst_curve_t *curve, double d);
#endif
/**@}*/

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

/**
 * @brief f0(x) by Horner's rule in user units, in hyst_wide_t (tools, tests).
 * @param[in] f0 polynomial, highest power first.
 * @param[in] x  input, any value.
 * @return f0(x).
 */
hyst_wide_t hyst_poly_eval(const hyst_poly_t *f0, hyst_wide_t x);

/** @name Default variant (f32, or f64 with HYST_USE_DOUBLE) */
/**@{*/
#define hyst_curve_from_poly HYST_DEFAULT_NAME_(curve_from_poly)
#define hyst_seal_poly HYST_DEFAULT_NAME_(seal_poly)
#define hyst_curve_from_everett HYST_DEFAULT_NAME_(curve_from_everett)
#define hyst_curve_from_everett_grid HYST_DEFAULT_NAME_(curve_from_everett_grid)
#define hyst_curve_everett_grid_inverse HYST_DEFAULT_NAME_(curve_everett_grid_inverse)
#define hyst_curve_from_spline HYST_DEFAULT_NAME_(curve_from_spline)
#define hyst_curve_spline_inverse_table HYST_DEFAULT_NAME_(curve_spline_inverse_table)
#define hyst_curve_from_pwl HYST_DEFAULT_NAME_(curve_from_pwl)
#define hyst_curve_eval HYST_DEFAULT_NAME_(curve_eval)
#define hyst_curve_g HYST_DEFAULT_NAME_(curve_g)
#define hyst_curve_inverse_table HYST_DEFAULT_NAME_(curve_inverse_table)
#define hyst_curve_everett_inverse_table HYST_DEFAULT_NAME_(curve_everett_inverse_table)
#define hyst_curve_inverse_table_const HYST_DEFAULT_NAME_(curve_inverse_table_const)
#define hyst_curve_everett_inverse_table_const HYST_DEFAULT_NAME_(curve_everett_inverse_table_const)
#ifdef HYST_USE_DOUBLE
typedef hyst_f64_sealed_poly_t hyst_sealed_poly_t;
#else
typedef hyst_f32_sealed_poly_t hyst_sealed_poly_t;
#endif
/**@}*/

#ifdef __cplusplus
}
#endif

#endif /* HYST_CURVE_H */
