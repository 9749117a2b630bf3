/* SPDX-License-Identifier: MIT */
/* The asymmetric model (E of degree 3), one axis, its kind named at init
 * (HYST_INIT_KIND): the firmware links that kind alone. With
 * -DANY_KIND=1 the same model by HYST_INIT_CURVE, which binds whatever kind
 * the curve has and so links every kind. */
#include "hyst/hyst.h"
static const hyst_everett_t e = {
    3, 0.0, 40.0, 0.58517, {{3.5, 1.0, 0.5, 0}, {1.2, 0.5, 0, 0}, {0.4, 0, 0, 0}, {0, 0, 0, 0}}};
static hyst_curve_t curve;
HYST_F32_DEFINE(axis, 4096);
volatile float drive, out;
int main(void)
{
    if (hyst_f32_curve_from_everett(&curve, &e) != HYST_OK) {
        return 1;
    }
#if ANY_KIND
    if (HYST_INIT_CURVE(axis, &curve) != HYST_OK) {
        return 1;
    }
#else
    if (HYST_INIT_KIND(axis, &curve, hyst_f32_kind_everett) != HYST_OK) {
        return 1;
    }
#endif
    for (;;) {
        out = hyst_f32_step(&axis, drive);
    }
}
