/* SPDX-License-Identifier: MIT */
/* A simulated piezo actuator that is NOT a TCM: the rate-independent
 * Bouc-Wen model (Low & Guo form), in double precision.
 *   y = d x - h + y0,   dh = alpha d dx - beta |dx| h - gamma dx |h|
 * Its minor loops do not close exactly and it has no wiping-out property,
 * so a TCM identified from its major loop can only approximate it: the
 * honest stand-in for a real stage. Integrated with Heun's method in input
 * steps of at most max_step; only the order of inputs matters. */
#ifndef PLANT_BW_H
#define PLANT_BW_H

typedef struct {
    double d, alpha, beta, gamma, y0, max_step;
    double x, h;
} plant_bw_t;

/* Parameters tuned to the paper's piezo stage: 0..40 V -> about 0.6..5.6 um,
 * loop width about 13 % of the range. Pre-cycled over 0..40 V, so it
 * starts at the bottom of its periodic major loop, at x = 0. */
void plant_bw_init_piezo(plant_bw_t *p);
double plant_bw_step(plant_bw_t *p, double x);

#endif
