/* SPDX-License-Identifier: MIT */
/* hyst pi: a Prandtl-Ishlinskii model over input samples, one output per line. */
#include "cli.h"
#include "hyst/hyst.h"

#include <stdio.h>

#define PI_MAX_OPERATORS 512u

static const char help[] =
    "usage: hyst pi --weights w1,...,wN --thresholds r1,...,rN [--offset C]\n"
    "               [--xcol I] [--decimal-comma] [FILE]\n"
    "\n"
    "Runs the Prandtl-Ishlinskii model of N one-sided play operators (the paper's\n"
    "Eq. 15; docs/theory.md) over the input samples of FILE (standard input if FILE is\n"
    "absent or '-'), from the reset state (every operator at 0):\n"
    "  z_i = max(x - r_i, min(x, z_i before)),  y = C + w1 z_1 + ... + wN z_N.\n"
    "Prints one output per line with 9 significant digits. The model has no domain:\n"
    "every input is used as is (nothing is clamped).\n"
    "\n"
    "  --weights W       w1,...,wN, the operator weights; every partial sum\n"
    "                    w1 + ... + wi must be positive (the loading curve rises)\n"
    "  --thresholds R    r1,...,rN, one per weight: r1 = 0, strictly increasing\n"
    "                    (N <= 512)\n"
    "  --offset C        added to every output (default 0), as 'hyst fit --kind pi'\n"
    "                    prints it\n"
    CLI_HELP_XCOL
    CLI_HELP_DECIMAL
    "  --help            this text\n"
    "\n"
    CLI_HELP_EXIT;

typedef struct pi_run {
    hyst_real_t r[PI_MAX_OPERATORS], w[PI_MAX_OPERATORS], z[PI_MAX_OPERATORS];
    hyst_pi_t P;
    double offset;
} pi_run_t;

static int pi_step(void *ctx, double x, double *y, int *clamped)
{
    *clamped = 0;
    pi_run_t *run = (pi_run_t *)ctx;
    *y = (double)hyst_pi_step(&run->P, (hyst_real_t)x) + run->offset;
    return 0;
}

/* Which parameter hyst_pi_check() refused, named by option and index. */
static int explain(const char *cmd, hyst_status_t st, const double *r, const double *w, size_t n)
{
    double sum = 0.0;
    size_t i;
    if (st == HYST_ERR_BREAKPOINTS) {
        if (r[0] != 0.0) {
            return cli_fail(cmd, "option --thresholds: %s: r1 is %g, must be 0",
                            hyst_status_str(st), r[0]);
        }
        for (i = 1u; i < n; ++i) {
            if (!(r[i] > r[i - 1u])) {
                return cli_fail(cmd, "option --thresholds: %s: r%lu = %g is not above r%lu = %g",
                                hyst_status_str(st), (unsigned long)i + 1ul, r[i],
                                (unsigned long)i, r[i - 1u]);
            }
        }
        return cli_fail(cmd, "option --thresholds: %s", hyst_status_str(st));
    }
    if (st == HYST_ERR_WEIGHTS) {
        for (i = 0u; i < n; ++i) {
            sum += w[i];
            if (!(sum > 0.0)) {
                return cli_fail(cmd, "option --weights: %s: w1 + ... + w%lu = %g is not positive",
                                hyst_status_str(st), (unsigned long)i + 1ul, sum);
            }
        }
        return cli_fail(cmd, "option --weights: %s", hyst_status_str(st));
    }
    return cli_fail(cmd, "options --weights/--thresholds: %s", hyst_status_str(st));
}

int cmd_pi(int argc, char **argv)
{
    static pi_run_t run; /* large: keep it off the stack */
    double r[PI_MAX_OPERATORS], w[PI_MAX_OPERATORS], offset = 0.0;
    size_t nr = 0u, no = 0u, nw = 0u, i;
    cli_args_t a;
    cli_samples_t s;
    cli_map_t m;
    const char *v;
    hyst_status_t st;
    int kind;

    cli_args_init(&a, "pi", argc, argv);
    cli_samples_init(&s);
    while ((kind = cli_samples_next(&a, &s, help)) == CLI_OPT) {
        if (cli_is(&a, "--weights")) {
            if ((v = cli_value(&a)) == NULL || !cli_opt_list(&a, v, w, 1u, PI_MAX_OPERATORS, &nw)) {
                return 1;
            }
        } else if (cli_is(&a, "--thresholds")) {
            if ((v = cli_value(&a)) == NULL || !cli_opt_list(&a, v, r, 1u, PI_MAX_OPERATORS, &nr)) {
                return 1;
            }
        } else if (cli_is(&a, "--offset")) {
            if ((v = cli_value(&a)) == NULL || !cli_opt_list(&a, v, &offset, 1u, 1u, &no)) {
                return 1;
            }
        } else {
            return cli_unknown(&a);
        }
    }
    if (kind != CLI_END) {
        return kind == CLI_HELP ? 0 : 1;
    }
    if (nw == 0u) {
        return cli_fail(a.cmd, "--weights is required (see 'hyst pi --help')");
    }
    if (nr == 0u) {
        return cli_fail(a.cmd, "--thresholds is required (see 'hyst pi --help')");
    }
    if (nw != nr) {
        return cli_fail(a.cmd, "options --weights and --thresholds: %lu weight%s but %lu "
                               "threshold%s (one weight per threshold)",
                        (unsigned long)nw, nw == 1u ? "" : "s", (unsigned long)nr,
                        nr == 1u ? "" : "s");
    }
    for (i = 0u; i < nr; ++i) {
        run.r[i] = (hyst_real_t)r[i];
        run.w[i] = (hyst_real_t)w[i];
    }
    run.offset = offset;
    st = hyst_pi_init(&run.P, run.r, run.w, run.z, nr);
    if (st != HYST_OK) {
        return explain(a.cmd, st, r, w, nr);
    }
    m.ctx = &run;
    m.begin = NULL;
    m.step = pi_step;
    m.col2 = NULL;
    m.digits = 9;
    m.clamp_what = "inputs";
    m.lo = m.hi = 0.0;
    m.step_checks_range = 0;
    m.has_identified = 0;
    return cli_map_samples(a.cmd, &s, &m);
}
