/* SPDX-License-Identifier: MIT */
/* The tabulated compensators run by the library alone, as firmware runs
 * them, for tests/cli/inv_table.sh: what 'hyst inv --intervals' must print.
 *   inv_table_run poly LO HI INTERVALS C_N ... C_0 < desired outputs
 *   inv_table_run everett LO HI Y_LO DEGREE ROWS INTERVALS TERM... < desired outputs
 * Kind poly: hyst_f64_init_inverse_table() (what HYST_INIT_INVERSE does);
 * kind everett: hyst_f64_curve_everett_inverse_table(), then
 * hyst_f64_init_curve(). E's terms in the model file's order; ROWS and
 * INTERVALS may be "default" (HYST_INV_TABLE, HYST_EVERETT_INV_ROWS,
 * HYST_EVERETT_INV_INTERVALS). One drive per input line (%.17g);
 * hyst_curve_inverse_error() on stderr (%.9g). */
#include "hyst/hyst.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define CAPACITY 4096u

/* A count, or the library's default for "default". */
static size_t count(const char *s, size_t dflt)
{
    return strcmp(s, "default") == 0 ? dflt : (size_t)strtoul(s, NULL, 10);
}

int main(int argc, char **argv)
{
    static double xltp[CAPACITY], yltp[CAPACITY], xrtp[CAPACITY], yrtp[CAPACITY];
    hyst_curve_t fwd, inv;
    hyst_tcm_t S;
    hyst_status_t st = HYST_ERR_ARG;
    double *table = NULL, y;
    int poly = argc > 1 && strcmp(argv[1], "poly") == 0, arg;
    if (argc < 6 || (!poly && (strcmp(argv[1], "everett") != 0 || argc < 9))) {
        (void)fputs("usage: inv_table_run poly LO HI INTERVALS C_N ... C_0 < outputs\n"
                    "       inv_table_run everett LO HI Y_LO DEGREE ROWS INTERVALS TERM..."
                    " < outputs\n",
                    stderr);
        return 2;
    }
    if (poly) {
        hyst_poly_t f0 = {0};
        const size_t intervals = count(argv[4], HYST_INV_TABLE);
        f0.lo = strtod(argv[2], NULL);
        f0.hi = strtod(argv[3], NULL);
        f0.degree = (unsigned)(argc - 6);
        for (arg = 5; arg < argc && arg - 5 <= HYST_MAX_DEGREE; ++arg) {
            f0.coeffs[arg - 5] = strtod(argv[arg], NULL);
        }
        table = (double *)malloc(HYST_INV_TABLE_LEN(intervals) * sizeof(double));
        if (table != NULL && arg == argc) {
            st = hyst_f64_init_inverse_table(&S, &inv, &f0, table, intervals, xltp, yltp, xrtp,
                                             yrtp, CAPACITY);
        }
    } else {
        hyst_everett_t e = {0};
        const size_t rows = count(argv[6], HYST_EVERETT_INV_ROWS);
        const size_t intervals = count(argv[7], HYST_EVERETT_INV_INTERVALS);
        unsigned i, j;
        e.lo = strtod(argv[2], NULL);
        e.hi = strtod(argv[3], NULL);
        e.y_lo = strtod(argv[4], NULL);
        e.degree = (unsigned)strtoul(argv[5], NULL, 10);
        arg = 8;
        for (i = 1u; i <= e.degree && i <= HYST_EVERETT_MAX_DEGREE; ++i) {
            for (j = 0u; i + j <= e.degree && arg < argc; ++j) {
                e.e[i - 1u][j] = strtod(argv[arg++], NULL);
            }
        }
        table = (double *)malloc(HYST_EVERETT_INV_TABLE_LEN(rows, intervals) * sizeof(double));
        if (table != NULL && arg == argc) {
            st = hyst_f64_curve_from_everett(&fwd, &e);
            if (st == HYST_OK) {
                st = hyst_f64_curve_everett_inverse_table(&inv, &fwd, table, rows, intervals);
            }
            if (st == HYST_OK) {
                st = hyst_f64_init_curve(&S, &inv, xltp, yltp, xrtp, yrtp, CAPACITY);
            }
        }
    }
    if (st != HYST_OK) {
        (void)fprintf(stderr, "inv_table_run: %s\n",
                      table == NULL ? "out of memory" : arg != argc ? "wrong number of arguments"
                                                                    : hyst_status_str(st));
        free(table);
        return 1;
    }
    (void)fprintf(stderr, "%.9g\n", (double)hyst_curve_inverse_error(&inv));
    while (scanf("%lf", &y) == 1) {
        (void)printf("%.17g\n", hyst_f64_step(&S, y));
    }
    free(table);
    return 0;
}
