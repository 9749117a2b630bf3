/* SPDX-License-Identifier: MIT */
/* The model and its tabulated compensator (HYST_INIT_INVERSE), one axis. */
#include "hyst/hyst.h"
static const hyst_poly_t f0 = {3, 0.0, 40.0, {-6.1876e-6, 1.1949e-3, 8.6444e-2, 5.8517e-1}};
HYST_F32_DEFINE(axis, 4096);
HYST_DEFINE_INVERSE(comp, 4096);
volatile float drive, out;
int main(void)
{
    if (HYST_F32_INIT(axis, &f0) != HYST_OK || HYST_INIT_INVERSE(comp, &f0) != HYST_OK) {
        return 1;
    }
    for (;;) {
        out = hyst_f32_step(&axis, hyst_f32_step(&comp, drive));
    }
}
