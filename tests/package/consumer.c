/* SPDX-License-Identifier: MIT */
/* A firmware-like consumer of the installed or embedded library: a float, a
 * double and an integer-code instance in one program, next to each other. */
#include "hyst/hyst.h"

#include <stdio.h>

static const hyst_poly_t f0 = {3u, 0.0, 40.0, {-6.1876e-6, 1.1949e-3, 8.6444e-2, 5.8517e-1}};

HYST_F32_DEFINE(axis_f32, 4096);
HYST_F64_DEFINE(axis_f64, 4096);
HYST_CODE_DEFINE(axis_code, 4096);

int main(void)
{
    float y32;
    double y64;
    float yc;
    if (HYST_F32_INIT(axis_f32, &f0) != HYST_OK || HYST_F64_INIT(axis_f64, &f0) != HYST_OK ||
        HYST_CODE_INIT(axis_code, &f0, 0u, 4000u) != HYST_OK) {
        return 1;
    }
    (void)hyst_f32_step(&axis_f32, 30.0f);
    (void)hyst_f64_step(&axis_f64, 30.0);
    (void)hyst_code_step(&axis_code, 3000u);
    y32 = hyst_f32_step(&axis_f32, 10.0f);
    y64 = hyst_f64_step(&axis_f64, 10.0);
    yc = hyst_code_step(&axis_code, 1000u);
    printf("consumer: f32 %.6f, f64 %.9f, code %.6f, turning points %u %u %u\n", (double)y32, y64,
           (double)yc, (unsigned)hyst_tp_count(&axis_f32), (unsigned)hyst_tp_count(&axis_f64),
           (unsigned)hyst_tp_count(&axis_code));
    if (hyst_tp_count(&axis_f32) != 1u || hyst_tp_count(&axis_f64) != 1u ||
        hyst_tp_count(&axis_code) != 1u) {
        return 2;
    }
    /* the three variants agree to float precision */
    return (y64 - (double)y32 < 1e-5 && (double)y32 - y64 < 1e-5 && y64 - (double)yc < 1e-5 &&
            (double)yc - y64 < 1e-5)
               ? 0
               : 3;
}
