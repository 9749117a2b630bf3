/* SPDX-License-Identifier: MIT */
/* A simulated actuator with asymmetric hysteresis and a lagging sensor,
 * that is NOT a polynomial TCM: a Preisach-class model given by its branch
 * (Everett) function E, in double precision,
 *   rising from the turning point (b, y_b):  y = y_b + E(x, b)
 *   falling from the turning point (a, y_a): y = y_a - E(a, x)
 * with turning points recorded and wiped out by Madelung's rules (minor
 * loops close). E(a, b) = S h(w) m(c), w = (a - b) / span the loop width,
 * c = (a + b) / (2 span) - lo / span its centre, h(w) = 0.35 w +
 * 0.35 (e^(2w) - 1 - 2w) / (e^2 - 3) (convex: a reversible slope at each
 * reversal, then steeper; loops run counter-clockwise like a piezo's),
 * m(c) = 1 + kappa (c - 1/2): loops grow with their centre, so rising and
 * falling branches are not point reflections of each other (asymmetric);
 * E is no polynomial and no product f(a) g(b) (non-separable). The sensor
 * reads the output through a first-order lag of time constant `lag`
 * samples. */
#ifndef PLANT_EVERETT_H
#define PLANT_EVERETT_H

#define PLANT_EVERETT_TPS 256

typedef struct {
    double lo, hi, scale, kappa, lag_alpha;
    double x, y, sensor;
    double tx[PLANT_EVERETT_TPS], ty[PLANT_EVERETT_TPS]; /* [0] = (lo, 0): LTPs even, RTPs odd */
    int n;
    int started;
} plant_everett_t;

/* 0..40 V -> 0..about 4.9 um, kappa 0.5, sensor lag 3 samples. Starts at
 * x = lo on the rising major branch. */
void plant_everett_init_piezo(plant_everett_t *p);
/* The actuator's output at input x (and the sensor's update). */
double plant_everett_step(plant_everett_t *p, double x);
/* The sensor's reading after the last step. */
double plant_everett_sensor(const plant_everett_t *p);
/* E(a, b), a >= b. */
double plant_everett_e(const plant_everett_t *p, double a, double b);

#endif
