/* SPDX-License-Identifier: MIT */
/* The models every benchmark runs: TCM on the paper's Eq. 20 over 12-bit
 * codes, and the paper's PI model of Table 1. */
#ifndef HYST_BENCH_MODELS_H
#define HYST_BENCH_MODELS_H

#include "hyst/hyst.h"

/** Input codes of a 12-bit DAC: Nu = 4096, x in 0 .. 4095. */
#define BENCH_NU 4096u

/** PI-10 of the paper's Table 1, domain [0, 1]. */
#define BENCH_PI_N 10u
extern const hyst_real_t bench_pi10_r[BENCH_PI_N];
extern const hyst_real_t bench_pi10_w[BENCH_PI_N];

/** Paper Eq. 20 (0..40 V, cubic) stretched over the codes 0 .. BENCH_NU - 1,
 *  then shifted by @p offset: domain offset .. offset + BENCH_NU - 1. */
void bench_f0_codes(hyst_poly_t *f0, double offset);

/** The asymmetric kind on the same codes: E(a, b) = g(a - b) of
 *  bench_f0_codes() plus a term growing with the loop's place (0.1 of the
 *  width term times t), of @p degree 3, or 4 with a w^4 term (linear in
 *  t still, as identified from major loops). */
void bench_everett_codes(hyst_everett_t *e, double offset, unsigned degree);
/* A grid branch function (hyst_everett_grid_t) on the same codes: 6 knot
 * intervals, the inner knots uneven, every cell's mass positive, one cell
 * ten times heavier (a near step). */
void bench_grid_codes(hyst_everett_grid_t *g, double offset);
/* The same grid with its weights scaled so that its outputs span the codes
 * from offset: the forward curve of the grid's compensator (BENCH_EVERETT
 * 5), built into fwd with table (len numbers). */
hyst_status_t bench_grid_inverse_codes(hyst_curve_t *fwd, hyst_everett_grid_t *g, double offset,
                                       hyst_real_t *table, size_t len);
/* A spline f0 (hyst_spline_t) on the same codes: 16 uniform intervals,
 * rises growing by a tenth each, one ten times larger (a near step), the
 * knots' slopes the smaller neighbouring secant; its outputs span
 * out_offset .. out_offset + out_span (the codes, for its compensator). */
void bench_spline_codes(hyst_spline_t *f, double offset, double out_offset, double out_span);
/** The same asymmetry on bench_f0_inverse_codes()'s f0: the outputs span
 *  the codes, the asymmetric compensator's desired outputs. */
void bench_everett_inverse_codes(hyst_everett_t *e, double offset);

/** Paper Eq. 20 over 0..40 V with its output scaled onto offset .. offset +
 *  BENCH_NU - 1: a compensator of it (inverse.h) takes the desired output
 *  as BENCH_NU codes, as the forward model takes the drive. */
void bench_f0_inverse_codes(hyst_poly_t *f0, double offset);

#endif
