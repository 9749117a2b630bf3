/* A firmware-like consumer of the installed or embedded library. */
#include "hyst/hyst.h"

#include <stdio.h>

HYST_DEFINE(axis, 4096);

int main(void)
{
    static const hyst_poly_t f0 = {3u, HYST_REAL_C(0.0), HYST_REAL_C(40.0),
                                   {HYST_REAL_C(-6.1876e-6), HYST_REAL_C(1.1949e-3),
                                    HYST_REAL_C(8.6444e-2), HYST_REAL_C(5.8517e-1)}};
    hyst_real_t y;
    if (HYST_INIT(axis, &f0) != HYST_OK) {
        return 1;
    }
    (void)hyst_step(&axis, HYST_REAL_C(30.0));
    y = hyst_step(&axis, HYST_REAL_C(10.0));
    printf("consumer: y = %.6f, turning points %u\n", (double)y, (unsigned)hyst_tp_count(&axis));
    return hyst_tp_count(&axis) == 1u ? 0 : 2;
}
