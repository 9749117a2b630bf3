/* SPDX-License-Identifier: MIT */
/* The fixed-point model on 12-bit codes, one axis, from the q31 model
 * `hyst header --sealed --codes 0,4095` prepared and sealed on the host. */
#include "eq20.h"
#include "hyst/hyst.h"
#include "hyst/q31.h"
HYST_Q31_DEFINE(axis, 4096);
volatile unsigned drive;
volatile hyst_q31_t out;
int main(void)
{
    if (HYST_Q31_INIT_SEALED(axis, &eq20_q31_sealed) != HYST_OK) {
        return 1;
    }
    for (;;) {
        out = hyst_q31_step(&axis, drive);
    }
}
