/* SPDX-License-Identifier: MIT */
/* The model and its tabulated compensator, one axis, both from the curves
 * `hyst header --sealed --compensator` prepared, measured and sealed on the
 * host (no curve built, no table built or measured on the target). */
#include "eq20.h"
#include "hyst/hyst.h"
HYST_F32_DEFINE(axis, 4096);
HYST_F32_DEFINE(comp, 4096);
static hyst_curve_t comp_curve;
volatile float drive, out;
int main(void)
{
    if (HYST_F32_INIT_SEALED(axis, &eq20_sealed) != HYST_OK ||
        HYST_INIT_INVERSE_SEALED(comp, &comp_curve, &eq20_comp_sealed, eq20_table) != HYST_OK) {
        return 1;
    }
    for (;;) {
        out = hyst_f32_step(&axis, hyst_f32_step(&comp, drive));
    }
}
