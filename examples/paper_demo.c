/* The paper's test signal (Sec. 3.2: a triangle whose amplitude shrinks
 * around the centre, then grows back) through the TCM with f0 of Eq. 20,
 * computed on the target. Prints one CSV row per sample:
 * index, input (V), output (um), turning points (LTP + RTP). */
#include "hyst/hyst.h"
#include "hyst_port.h"
#include "support.h"

#include <stdio.h>

#define NU 4096u /* 12-bit DAC: the paper's sizing */

HYST_DEFINE(piezo, NU);

int main(void)
{
    static hyst_real_t x[8192];
    double levels[32];
    const int n_levels = paper_levels(0.0, 40.0, levels);
    const long n = ramp_path(0.0, levels, n_levels, 0.1, x, 8192);
    size_t max_tp = 0u;
    long i;
    hyst_port_init();
    if (HYST_INIT(piezo, &paper_eq20) != HYST_OK) {
        printf("init failed\n");
        return 1;
    }
    printf("# hyst paper demo: f0 = Eq. 20 on [0, 40] V, Nu = %u, %ld samples\n", NU, n);
    printf("i,x_V,y_um,tp\n");
    for (i = 0; i < n; ++i) {
        const hyst_real_t y = hyst_step(&piezo, x[i]);
        const size_t tp = hyst_tp_count(&piezo);
        max_tp = tp > max_tp ? tp : max_tp;
        printf("%ld,%.4f,%.6f,%u\n", i, (double)x[i], (double)y, (unsigned)tp);
    }
    printf("# max turning points %u (paper: 14 = 7 LTP + 7 RTP)\n", (unsigned)max_tp);
    return max_tp == 14u ? 0 : 2;
}
