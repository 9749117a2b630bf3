/* hyst sim: the TCM model over input samples, one output per line. */
#include "cli.h"
#include "hyst/hyst.h"

#include <stdio.h>
#include <stdlib.h>

static const char help[] =
    "usage: hyst sim --poly cN,...,c1,c0 --range LO,HI [--xcol I] [--tp] [FILE]\n"
    "\n"
    "Runs the hysteresis model (TCM) with major ascending curve\n"
    "f0(x) = cN x^N + ... + c1 x + c0 on [LO, HI] over the input samples of FILE\n"
    "(standard input if FILE is absent or '-'), starting from (LO, f0(LO)).\n"
    "Prints one output per line with 9 significant digits.\n"
    "\n"
    "  --poly cN,...,c0  coefficients, highest power first (degree 1..9)\n"
    "  --range LO,HI     domain of f0; inputs outside it are clamped (warned)\n"
    "  --xcol I          input column, 1-based (default 1); columns are separated\n"
    "                    by blanks, ',' or ';'; '#' lines and blank lines are skipped\n"
    "  --tp              add the turning-point count as a second column: y,tp\n"
    "  --help            this text\n"
    "\n"
    "Exit status: 0 success, 1 bad option or input (nothing is printed then).\n";

int cmd_sim(int argc, char **argv)
{
    cli_args_t a;
    const char *file = NULL, *pos = NULL, *v;
    double coeffs[HYST_MAX_DEGREE + 1], range[2];
    size_t ncoef = 0u, nrange = 0u, i, cap;
    unsigned long xcol = 1ul;
    int tp = 0, kind, rc;
    hyst_poly_t f0;
    hyst_status_t st;
    cli_table_t t;
    hyst_real_t *mem;
    hyst_t S;

    cli_args_init(&a, "sim", argc, argv);
    while ((kind = cli_args_next(&a, &pos)) != CLI_END) {
        if (kind < 0) {
            return 1;
        }
        if (kind == CLI_POS) {
            if (file != NULL) {
                return cli_fail(a.cmd, "more than one input file ('%s', '%s')", file, pos);
            }
            file = pos;
        } else if (cli_is(&a, "--help") || cli_is(&a, "-h")) {
            (void)fputs(help, stdout);
            return 0;
        } else if (cli_is(&a, "--tp")) {
            tp = 1;
        } else if (cli_is(&a, "--poly")) {
            if ((v = cli_value(&a)) == NULL ||
                !cli_opt_list(&a, v, coeffs, 2u, HYST_MAX_DEGREE + 1u, &ncoef)) {
                return 1;
            }
        } else if (cli_is(&a, "--range")) {
            if ((v = cli_value(&a)) == NULL || !cli_opt_list(&a, v, range, 2u, 2u, &nrange)) {
                return 1;
            }
        } else if (cli_is(&a, "--xcol")) {
            if ((v = cli_value(&a)) == NULL || !cli_opt_ulong(&a, v, 1ul, CLI_MAX_FIELD, &xcol)) {
                return 1;
            }
        } else {
            return cli_unknown(&a);
        }
    }
    if (ncoef == 0u) {
        return cli_fail(a.cmd, "--poly is required (see 'hyst sim --help')");
    }
    if (nrange == 0u) {
        return cli_fail(a.cmd, "--range is required (see 'hyst sim --help')");
    }
    f0.degree = (unsigned)(ncoef - 1u);
    f0.lo = (hyst_real_t)range[0];
    f0.hi = (hyst_real_t)range[1];
    for (i = 0u; i <= HYST_MAX_DEGREE; ++i) {
        f0.coeffs[i] = i < ncoef ? (hyst_real_t)coeffs[i] : 0;
    }
    if (!(range[0] < range[1])) {
        return cli_fail(a.cmd, "option --range: LO must be below HI");
    }
    /* Validate the curve before reading any input. */
    {
        hyst_curve_t curve;
        st = hyst_curve_from_poly(&curve, &f0);
        if (st == HYST_ERR_NOT_INCREASING) {
            hyst_wide_t c[HYST_MAX_DEGREE + 1], turn = 0;
            for (i = 0u; i < ncoef; ++i) {
                c[i] = (hyst_wide_t)coeffs[i];
            }
            (void)hyst_poly_is_increasing(c, f0.degree, range[0], range[1], &turn);
            return cli_fail(a.cmd, "option --poly: f0 is not increasing on [%g, %g] "
                                   "(slope negative at x = %.6g)",
                            range[0], range[1], (double)turn);
        }
        if (st != HYST_OK) {
            return cli_fail(a.cmd, "options --poly/--range: %s", hyst_status_str(st));
        }
    }
    if (cli_read_columns(a.cmd, file, &xcol, 1u, &t) != 0) {
        return 1;
    }
    /* n inputs make at most n turning points: the memory never overflows. */
    cap = t.n / 2u + 2u;
    mem = (hyst_real_t *)malloc(4u * cap * sizeof(hyst_real_t));
    if (mem == NULL) {
        cli_table_free(&t);
        return cli_fail(a.cmd, "out of memory");
    }
    rc = 0;
    st = hyst_init(&S, &f0, mem, mem + cap, mem + 2u * cap, mem + 3u * cap, cap);
    if (st != HYST_OK) {
        rc = cli_fail(a.cmd, "%s", hyst_status_str(st));
    }
    for (i = 0u; rc == 0 && i < t.n; ++i) {
        const hyst_real_t y = hyst_step(&S, (hyst_real_t)t.col[0][i]);
        if (tp) {
            (void)printf("%.9g,%lu\n", (double)y, (unsigned long)hyst_tp_count(&S));
        } else {
            (void)printf("%.9g\n", (double)y);
        }
    }
    if (rc == 0 && (hyst_events(&S) & HYST_EVENT_CLAMPED) != 0u) {
        (void)fprintf(stderr, "hyst sim: warning: %s: inputs outside [%g, %g] were clamped\n",
                      cli_file_name(file), range[0], range[1]);
    }
    free(mem);
    cli_table_free(&t);
    if (rc == 0 && fflush(stdout) != 0) {
        rc = cli_fail(a.cmd, "write error on standard output");
    }
    return rc;
}
