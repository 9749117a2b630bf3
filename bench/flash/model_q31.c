/* SPDX-License-Identifier: MIT */
/* The fixed-point model (hyst/q31.h) on 12-bit codes, one axis. */
#include "hyst/hyst.h"
#include "hyst/q31.h"
static const hyst_poly_t f0 = {3, 0.0, 40.0, {-6.1876e-6, 1.1949e-3, 8.6444e-2, 5.8517e-1}};
HYST_Q31_DEFINE(axis, 4096);
volatile unsigned drive;
volatile hyst_q31_t out;
int main(void)
{
    if (HYST_Q31_INIT(axis, &f0, 0u, 4095u) != HYST_OK) {
        return 1;
    }
    for (;;) {
        out = hyst_q31_step(&axis, drive);
    }
}
