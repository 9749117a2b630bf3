/* SPDX-License-Identifier: MIT */
/* The asymmetric kind run by the library alone, for tests/cli/everett.sh:
 * what 'hyst sim --model' must print for a model of kind everett.
 *   everett_run LO HI Y_LO DEGREE TERM... < inputs
 * E's terms in the model file's order; one output per input line (%.17g),
 * the model from rest, no delay. */
#include "hyst/hyst.h"

#include <stdio.h>
#include <stdlib.h>

#define CAPACITY 4096u

int main(int argc, char **argv)
{
    static double xltp[CAPACITY], yltp[CAPACITY], xrtp[CAPACITY], yrtp[CAPACITY];
    hyst_everett_t e = {0};
    hyst_curve_t curve;
    hyst_tcm_t S;
    hyst_status_t st;
    double x;
    unsigned i, j;
    int arg = 5;
    if (argc < 6) {
        (void)fputs("usage: everett_run LO HI Y_LO DEGREE TERM... < inputs\n", stderr);
        return 2;
    }
    e.lo = strtod(argv[1], NULL);
    e.hi = strtod(argv[2], NULL);
    e.y_lo = strtod(argv[3], NULL);
    e.degree = (unsigned)strtoul(argv[4], NULL, 10);
    for (i = 1u; i <= e.degree && i <= HYST_EVERETT_MAX_DEGREE; ++i) {
        for (j = 0u; i + j <= e.degree && arg < argc; ++j) {
            e.e[i - 1u][j] = strtod(argv[arg++], NULL);
        }
    }
    st = hyst_f64_curve_from_everett(&curve, &e);
    if (st == HYST_OK) {
        st = hyst_f64_init_curve(&S, &curve, xltp, yltp, xrtp, yrtp, CAPACITY);
    }
    if (st != HYST_OK || arg != argc) {
        (void)fprintf(stderr, "everett_run: %s\n",
                      st != HYST_OK ? hyst_status_str(st) : "terms do not match the degree");
        return 1;
    }
    while (scanf("%lf", &x) == 1) {
        (void)printf("%.17g\n", hyst_f64_step(&S, x));
    }
    return 0;
}
