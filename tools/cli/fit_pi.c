/* SPDX-License-Identifier: MIT */
/* hyst fit --kind pi: the Prandtl-Ishlinskii model's weights by non-negative
 * least squares (hyst_pi_fit_record()), printed so that 'hyst pi' takes
 * them, with the same hold-out score as the TCM's automatic choice; and
 * --compare-pi, that score beside the TCM's. */
#include "fit_pi.h"

#include "fit_select.h"

#include <math.h>
#include <stdio.h>

static void print_list(const char *lead, const double *v, size_t n)
{
    size_t i;
    (void)fputs(lead, stdout);
    for (i = 0u; i < n; ++i) {
        (void)printf("%s%.15g", i ? "," : "", v[i]);
    }
}

/* A failed library call as the message 'hyst fit' gives for it. */
static int pi_failure(const char *name, hyst_status_t st, size_t ops, size_t skip, size_t delay,
                      size_t nread)
{
    switch (st) {
    case HYST_ERR_ARG:
        return cli_fail("fit", "%s: --skip %lu and --delay %lu leave no sample of the %lu read",
                        name, (unsigned long)skip, (unsigned long)delay, (unsigned long)nread);
    case HYST_ERR_SINGULAR:
        return cli_fail("fit", "%s: too few samples for %lu operators (the weights and the "
                               "offset need %lu)",
                        name, (unsigned long)ops, (unsigned long)ops + 1ul);
    case HYST_ERR_DOMAIN:
        return cli_fail("fit", "%s: the inputs do not span a range (all equal?)", name);
    default:
        return cli_fail("fit", "%s: %s", name, hyst_status_str(st));
    }
}

int fit_pi_report(const char *name, const cli_table_t *t, size_t ops, size_t skip, size_t delay)
{
    static double r[HYST_PI_FIT_MAX_OPERATORS], w[HYST_PI_FIT_MAX_OPERATORS];
    static double work[HYST_PI_FIT_WORK(HYST_PI_FIT_MAX_OPERATORS)];
    hyst_pi_fit_config_t cfg = {0};
    hyst_pi_fit_result_t res, train;
    hyst_status_t st, st_train;
    double r_train[HYST_PI_FIT_MAX_OPERATORS], w_train[HYST_PI_FIT_MAX_OPERATORS];
    double holdout, lo = 0.0, hi = 0.0;
    const size_t pairs = t->n > skip + delay ? t->n - skip - delay : 0u;
    cfg.operators = ops;
    cfg.skip = skip;
    cfg.delay = delay;
    st = hyst_pi_fit_record(&cfg, t->col[0], t->col[1], t->n, work, sizeof work / sizeof work[0],
                            r, w, &res);
    if (st != HYST_OK) {
        return pi_failure(name, st, ops, skip, delay, t->n);
    }
    if (!isfinite((double)res.rms) || !isfinite((double)res.offset)) {
        return cli_fail("fit", "%s: the result is not finite (RMS %g, offset %g): the numbers "
                               "are too large, rescale them",
                        name, (double)res.rms, (double)res.offset);
    }
    holdout = fit_pi_holdout(&cfg, t->col[0], t->col[1], t->n, &st_train, &train, r_train,
                             w_train);
    print_list("", w, ops);
    print_list("\n", r, ops);
    (void)printf("\n%.15g\n%.6g,%.6g\n", (double)res.offset, (double)res.rms,
                 (double)res.max_abs);
    (void)hyst_ident_domain(t->col[0] + skip, pairs, &lo, &hi); /* the fit succeeded: a range */
    (void)printf("# weights, thresholds, offset, residual rms,max above: PI model of %lu one-sided "
                 "play operators, thresholds (i - 1) (%.9g - %.9g) / %lu over the inputs' range, "
                 "weights >= 0 by non-negative least squares; %lu of %lu samples used\n",
                 (unsigned long)ops, hi, lo, (unsigned long)ops, (unsigned long)res.used,
                 (unsigned long)pairs);
    print_list("# hyst pi --weights ", w, ops);
    print_list(" --thresholds ", r, ops);
    (void)printf(" --offset %.15g\n", (double)res.offset);
    (void)printf("# %lu of the %lu weights are 0\n", (unsigned long)(ops - res.positive),
                 (unsigned long)ops);
    if (isfinite(holdout)) {
        (void)printf("# hold-out rms %.6g (fitted on the first two thirds, predicting the last "
                     "third)\n",
                     holdout);
    } else {
        (void)printf("# hold-out: not scored (%s)\n",
                     st_train != HYST_OK ? hyst_status_str(st_train) : "w1 = 0 on the first two thirds");
    }
    (void)printf("# delay %lu samples\n# parameters %lu (%lu weights and the offset; the "
                 "thresholds are fixed)\n",
                 (unsigned long)delay, (unsigned long)ops + 1ul, (unsigned long)ops);
    if (!res.invertible) {
        if (fflush(stdout) != 0) {
            return 1;
        }
        (void)fprintf(stderr,
                      "hyst fit: %s: the fitted w1 is 0: the loading curve is flat from 0 to "
                      "r2, which 'hyst pi' refuses (no inverse); try fewer operators\n",
                      name);
        return 2;
    }
    return 0;
}

void fit_pi_compare(const cli_table_t *t, size_t ops, size_t skip, size_t delay,
                    const char *tcm, unsigned params, double tcm_holdout, char *line,
                    size_t size)
{
    double r[HYST_PI_FIT_MAX_OPERATORS], w[HYST_PI_FIT_MAX_OPERATORS];
    hyst_pi_fit_config_t cfg = {0};
    hyst_pi_fit_result_t res;
    hyst_status_t st;
    size_t len = 0u;
    double pi;
    cfg.operators = ops;
    cfg.skip = skip;
    cfg.delay = delay;
    pi = fit_pi_holdout(&cfg, t->col[0], t->col[1], t->n, &st, &res, r, w);
    (void)cli_append(line, size, &len,
                     "# compare on the last third (both fitted on the first two thirds, delay "
                     "%lu): hold-out rms %s (%u parameters) ",
                     (unsigned long)delay, tcm, params);
    if (isfinite(tcm_holdout)) {
        (void)cli_append(line, size, &len, "%.6g, ", tcm_holdout);
    } else {
        (void)cli_append(line, size, &len, "not scored, ");
    }
    if (isfinite(pi) && isfinite(tcm_holdout)) {
        (void)cli_append(line, size, &len, "PI %lu operators (%lu parameters) %.6g; PI/TCM %.3g\n",
                         (unsigned long)ops, (unsigned long)ops + 1ul, pi, pi / tcm_holdout);
    } else if (isfinite(pi)) {
        (void)cli_append(line, size, &len, "PI %lu operators (%lu parameters) %.6g\n",
                         (unsigned long)ops, (unsigned long)ops + 1ul, pi);
    } else {
        (void)cli_append(line, size, &len, "PI %lu operators not scored (%s)\n",
                         (unsigned long)ops, st != HYST_OK ? hyst_status_str(st) : "w1 = 0");
    }
}
