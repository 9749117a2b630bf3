/* SPDX-License-Identifier: MIT */
/* The asymmetric model (E of degree 3) and its tabulated compensator
 * (hyst_f32_curve_everett_inverse_table(), 8 rows of 64 intervals), one
 * axis, both kinds named at init: the firmware links those two kinds alone. */
#include "hyst/hyst.h"
static const hyst_everett_t e = {
    3, 0.0, 40.0, 0.58517, {{3.5, 1.0, 0.5, 0}, {1.2, 0.5, 0, 0}, {0.4, 0, 0, 0}, {0, 0, 0, 0}}};
static hyst_curve_t curve, inverse;
static float table[HYST_EVERETT_INV_TABLE_LEN(8, 64)];
HYST_F32_DEFINE(axis, 4096);
HYST_F32_DEFINE(comp, 4096);
volatile float drive, out;
int main(void)
{
    if (hyst_f32_curve_from_everett(&curve, &e) != HYST_OK ||
        hyst_f32_curve_everett_inverse_table(&inverse, &curve, table, 8, 64) != HYST_OK ||
        HYST_INIT_KIND(axis, &curve, hyst_f32_kind_everett) != HYST_OK ||
        HYST_INIT_KIND(comp, &inverse, hyst_f32_kind_everett_inverse_table) != HYST_OK) {
        return 1;
    }
    for (;;) {
        out = hyst_f32_step(&axis, hyst_f32_step(&comp, drive));
    }
}
