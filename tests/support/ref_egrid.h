/* SPDX-License-Identifier: MIT */
/* A plain double reference of the asymmetric kind on a grid (curve.h,
 * hyst_everett_grid_t), sharing no code with the library: E as the sum over
 * the cells of each one's density times the area of its part of the
 * triangle, and Madelung's rules by the asymmetric kind's reference
 * (ref_everett.h, its fn). Used by the tests. */
#ifndef REF_EGRID_H
#define REF_EGRID_H

#include "ref_everett.h"

/* E(a, b), a >= b, of grid g. */
double ref_egrid_e(const hyst_everett_grid_t *g, double a, double b);

/* A reference on grid g (g must outlive it; one grid at a time): r runs
 * ref_everett_step() with E from g; *domain holds its lo, hi and y_lo. */
void ref_egrid_init(ref_everett_t *r, hyst_everett_t *domain, const hyst_everett_grid_t *g);

/* A random grid: 1..max_k knot intervals of random widths on a random
 * domain (ends exact in float), weights in [0, 1) scaled, about one in five
 * 0, one cell in eight sharp (ten times heavier). */
hyst_everett_grid_t ref_egrid_random(rng_t *rng, unsigned max_k);

#endif
