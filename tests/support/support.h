/* SPDX-License-Identifier: MIT */
/* Shared by the tests: a seeded PRNG, test signals and the paper's curve. */
#ifndef HYST_TEST_SUPPORT_H
#define HYST_TEST_SUPPORT_H

#include "hyst/hyst.h"
#include <math.h>
#include <stdint.h>

/* Tolerance of the build's real type, as a fraction of the output range. */
#ifdef HYST_USE_DOUBLE
#define TOL_OF_RANGE 1e-9
#else
#define TOL_OF_RANGE 1e-5
#endif

/* The build's real type: the next number from v towards `to` (math.h), and
 * a curve's number (hyst_num_t) of the default variant. */
#ifdef HYST_USE_DOUBLE
#define NEXT(v, to) nextafter((v), (to))
#define CURVE_NUM(n) ((n).f64)
#else
#define NEXT(v, to) nextafterf((v), (to))
#define CURVE_NUM(n) ((n).f32)
#endif

/* Curves set up in float (HYST_NO_DOUBLE): init refuses with
 * HYST_ERR_ILL_CONDITIONED some that double sets up, such as x^5 on [-1, 1]
 * or a domain far from 0 relative to its span, because their expansion's
 * bound in float exceeds HYST_MAX_ROUNDING. */
#define SETUP_IN_FLOAT (sizeof(hyst_wide_t) < 8u)

/* The build's real type's infinity. */
#ifdef HYST_USE_DOUBLE
#define REAL_INF ((hyst_real_t)HUGE_VAL)
#else
#define REAL_INF ((hyst_real_t)HUGE_VALF)
#endif

/* The call returns `code` and leaves *obj as its copy *copy (unity.h's
 * asserts: a refusal writes nothing). */
#define UNCHANGED(copy, obj, code, call)                          \
    do {                                                          \
        TEST_ASSERT_EQUAL_INT((code), (call));                    \
        TEST_ASSERT_EQUAL_MEMORY((copy), (obj), sizeof *(obj));   \
    } while (0)

/* Paper Eq. 20: piezo positioner, 0..40 V, output in um. */
extern const hyst_poly_t paper_eq20;
extern const double paper_eq20_coeffs[4];

typedef struct {
    uint32_t s;
} rng_t;

void rng_seed(rng_t *r, uint32_t seed);
uint32_t rng_u32(rng_t *r);
double rng_unit(rng_t *r);                  /* [0, 1) */
double rng_range(rng_t *r, double a, double b);
uint32_t rng_below(rng_t *r, uint32_t n);   /* [0, n) */
double rng_gauss(rng_t *r);                 /* standard normal (Box-Muller) */

/* A random walk on [lo, hi]: *x moved by a step uniform in +-2 % of the
 * span, kept inside; returns it in the build's real type. */
hyst_real_t rng_walk(rng_t *r, double *x, double lo, double hi);

/* |v|, and the build's real type's spacing at m >= 0. */
double dabs(double v);
double real_ulp(double m);

/* The paper's test signal: a triangle from lo whose amplitude shrinks around
 * the centre for 7 peaks and 7 valleys, then grows back to the full range and
 * returns to lo. Turning levels in *levels (caller array of 32); returns count. */
int paper_levels(double lo, double hi, double *levels);

/* Samples of a piecewise-linear path through levels, step at most `step`,
 * starting at `start`. Writes at most max samples; returns how many. */
long ramp_path(double start, const double *levels, int n_levels, double step,
               hyst_real_t *out, long max);

/* f0 = x^degree on [lo, hi]. */
hyst_poly_t poly_monomial(unsigned degree, double lo, double hi);

/* A random increasing polynomial of the degree: positive coefficients,
 * lo in [0, 5], hi - lo in [1, 4000], terms of comparable size at hi. */
hyst_poly_t poly_random_increasing(rng_t *r, unsigned degree);

/* A random increasing spline on a random domain: values rising by random
 * steps, one in five flat with `flat` (value[K] kept above value[0]), one
 * in six a near step (3..30) with `steep`; slopes within three times the
 * smaller secant beside them (Fritsch-Carlson's box: every piece
 * increases), one in four 0 with `zeros`. */
hyst_spline_t spline_random(rng_t *r, unsigned intervals, int flat, int steep, int zeros);

/* f0 with coefficients c (highest power first) at x, in double-double: the
 * exact value of those coefficients' polynomial to about 2^-100 of the
 * largest term, a reference where Horner's rule in double cancels. */
double poly_eval_exact(const hyst_wide_t *c, unsigned degree, double x);

#endif
