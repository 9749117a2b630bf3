/* SPDX-License-Identifier: MIT */
/* RAM of one integer-code instance (struct + 4 arrays) for K = 8..128, as
 * the target's compiler lays it out: compile with -S, read the .word table. */
#include "hyst/code.h"

const unsigned long hyst_mem_ram[5] = {HYST_CODE_RAM(8), HYST_CODE_RAM(16), HYST_CODE_RAM(32),
                                       HYST_CODE_RAM(64), HYST_CODE_RAM(128)};
const unsigned long hyst_mem_struct = sizeof(hyst_tcm_t);
