/* SPDX-License-Identifier: MIT */
/* The spline model (hyst_spline_t, 3 intervals), one axis, its kind named at
 * init: the firmware links that kind alone. */
#include "hyst/hyst.h"
static const hyst_spline_t f0 = {3, 0.0, 40.0, {0.0, 1.0, 4.0, 5.0}, {0.05, 0.2, 0.1, 0.02}};
static float table[HYST_SPLINE_TABLE_LEN(3)];
static hyst_curve_t curve;
HYST_F32_DEFINE(axis, 4096);
volatile float drive, out;
int main(void)
{
    if (hyst_f32_curve_from_spline(&curve, &f0, table, HYST_SPLINE_TABLE_LEN(3)) != HYST_OK ||
        HYST_INIT_KIND(axis, &curve, hyst_f32_kind_spline) != HYST_OK) {
        return 1;
    }
    for (;;) {
        out = hyst_f32_step(&axis, drive);
    }
}
