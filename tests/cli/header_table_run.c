/* SPDX-License-Identifier: MIT */
/* The firmware side of 'hyst header --compensator', for
 * tests/cli/header_table.sh: the generated comp.h's table taken as it is
 * (const, as from flash) by hyst_curve_everett_inverse_table_const() (the
 * header defines comp_ROWS) or hyst_curve_inverse_table_const(), then the
 * compensator run on one desired output per input line; one drive per line
 * (%.17g). A refused table: the library's reason on stderr, exit status 3. */
#include "comp.h"
#include "hyst/hyst.h"

#include <stdio.h>

#define CAPACITY 4096u

int main(void)
{
    static hyst_real_t xltp[CAPACITY], yltp[CAPACITY], xrtp[CAPACITY], yrtp[CAPACITY];
    hyst_curve_t fwd, inv;
    hyst_t S;
    hyst_status_t st;
    double y;
#ifdef comp_ROWS
    st = hyst_curve_from_everett(&fwd, &comp);
    if (st == HYST_OK) {
        st = hyst_curve_everett_inverse_table_const(&inv, &fwd, comp_table, comp_ROWS,
                                                    comp_INTERVALS, &comp_seal);
    }
#else
    st = hyst_curve_from_poly(&fwd, &comp);
    if (st == HYST_OK) {
        st = hyst_curve_inverse_table_const(&inv, &fwd, comp_table, comp_INTERVALS, &comp_seal);
    }
#endif
    if (st == HYST_OK) {
        st = hyst_init_curve(&S, &inv, xltp, yltp, xrtp, yrtp, CAPACITY);
    }
    if (st != HYST_OK) {
        (void)fprintf(stderr, "%s\n", hyst_status_str(st));
        return 3;
    }
    while (scanf("%lf", &y) == 1) {
        (void)printf("%.17g\n", (double)hyst_step(&S, (hyst_real_t)y));
    }
    return 0;
}
