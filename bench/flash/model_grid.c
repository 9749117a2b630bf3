/* SPDX-License-Identifier: MIT */
/* The asymmetric model on a grid (hyst_everett_grid_t, 3 intervals), one
 * axis, its kind named at init: the firmware links that kind alone. */
#include "hyst/hyst.h"
static const hyst_everett_grid_t grid = {3, {0.0, 10.0, 25.0, 40.0}, 0.5, {1, 2, 1, 0.5, 3, 1}};
static float table[HYST_EVERETT_GRID_TABLE_LEN(3)];
static hyst_curve_t curve;
HYST_F32_DEFINE(axis, 4096);
volatile float drive, out;
int main(void)
{
    if (hyst_f32_curve_from_everett_grid(&curve, &grid, table, HYST_EVERETT_GRID_TABLE_LEN(3)) !=
            HYST_OK ||
        HYST_INIT_KIND(axis, &curve, hyst_f32_kind_everett_grid) != HYST_OK) {
        return 1;
    }
    for (;;) {
        out = hyst_f32_step(&axis, drive);
    }
}
