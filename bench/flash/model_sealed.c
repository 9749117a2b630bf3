/* SPDX-License-Identifier: MIT */
/* The float model of Eq. 20, one axis, from the curve `hyst header --sealed`
 * prepared and sealed on the host (no curve construction on the target). */
#include "eq20.h"
#include "hyst/hyst.h"
HYST_F32_DEFINE(axis, 4096);
volatile float drive, out;
int main(void)
{
    if (HYST_F32_INIT_SEALED(axis, &eq20_sealed) != HYST_OK) {
        return 1;
    }
    for (;;) {
        out = hyst_f32_step(&axis, drive);
    }
}
