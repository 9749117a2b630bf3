/* SPDX-License-Identifier: MIT */
#include "plant_bw.h"

void plant_bw_init_piezo(plant_bw_t *p)
{
    p->d = 0.1872;    /* um/V */
    p->alpha = 0.42;
    p->beta = 0.028;  /* 1/V */
    p->gamma = 0.012; /* 1/V */
    p->y0 = -0.670;   /* um: the periodic major loop spans the paper's 0.585..5.559 um */
    p->max_step = 0.01;
    p->x = 0.0;
    p->h = 0.0;
    /* full cycles, as a real stage is exercised after power-up: the state
     * then sits at the bottom of the periodic major loop */
    {
        int c;
        for (c = 0; c < 4; ++c) { /* a few cycles: the loop is periodic to 1e-6 um */
            (void)plant_bw_step(p, 40.0);
            (void)plant_bw_step(p, 0.0);
        }
    }
}

static double slope(const plant_bw_t *p, double dir, double h)
{
    const double ah = h < 0.0 ? -h : h;
    return p->alpha * p->d - p->beta * dir * h - p->gamma * ah;
}

double plant_bw_step(plant_bw_t *p, double x)
{
    const double dist = x > p->x ? x - p->x : p->x - x;
    const double dir = x > p->x ? 1.0 : -1.0;
    long steps = (long)(dist / p->max_step) + 1;
    const double dx = (x - p->x) / (double)steps;
    long k;
    for (k = 0; k < steps && dist > 0.0; ++k) { /* Heun in the input */
        const double k1 = slope(p, dir, p->h);
        const double k2 = slope(p, dir, p->h + k1 * dx);
        p->h += 0.5 * (k1 + k2) * dx;
    }
    p->x = x;
    return p->d * x - p->h + p->y0;
}
