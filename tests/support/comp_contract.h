/* SPDX-License-Identifier: MIT */
/* What every compensator promises whatever its kind, checked the same way
 * for each (the asymmetric kind's solved and tabulated compensators). */
#ifndef HYST_TEST_COMP_CONTRACT_H
#define HYST_TEST_COMP_CONTRACT_H

#include <stddef.h>

#include "hyst/hyst.h"
#include "support.h"

/* An instance on a curve with its turning-point arrays: what re-initialises it. */
typedef struct {
    hyst_t *h;
    const hyst_curve_t *curve;
    hyst_real_t *xl, *yl, *xr, *yr;
    size_t capacity;
} comp_instance_t;

/* Sweeps the desired output of h (at any state) by adjacent values through
 * many turning points: from a random level in the middle 60 % of [lo, hi],
 * turning on average every 50 samples, and every 100 samples on average a
 * wider move of `jump` of the range. The drive never moves against the
 * desired output. */
void contract_drive_is_monotone(hyst_t *h, double lo, double hi, double jump, long samples,
                                rng_t *rng);

/* On the n desired outputs yd, with a fresh: its drives (into drive) equal
 * b's block call from reset (into drive2); a snapshot of a saved at every
 * 97th sample and restored into b continues bit for bit for 200 samples;
 * a snapshot of `other` (an instance on another curve) is refused by b. */
void contract_block_and_snapshots(const comp_instance_t *a, const comp_instance_t *b,
                                  hyst_t *other, const hyst_real_t *yd, hyst_real_t *drive,
                                  hyst_real_t *drive2, long n, unsigned char *snap, size_t size);

#endif
