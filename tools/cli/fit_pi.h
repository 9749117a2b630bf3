/* SPDX-License-Identifier: MIT */
/* hyst fit --kind pi and --compare-pi (fit_pi.c). */
#ifndef HYST_CLI_FIT_PI_H
#define HYST_CLI_FIT_PI_H

#include "cli.h"
#include "hyst/hyst.h"

#include <stddef.h>

/* Fits the weights of a PI model of ops operators to the record t (x[k]
 * with y[k + delay], from k = skip) and prints them: 0; 1 after a message
 * (nothing printed); 2 when w1 = 0 (printed, and a message). */
int fit_pi_report(const char *name, const cli_table_t *t, size_t ops, size_t skip, size_t delay);

/* The hold-out RMS of a PI model of ops operators beside the TCM's
 * (tcm: "TCM degree 3", its parameter count and tcm_holdout) on the same
 * split, skip and delay, as one comment line into line[0..size) (cut if it
 * does not fit). */
void fit_pi_compare(const cli_table_t *t, size_t ops, size_t skip, size_t delay,
                    const char *tcm, unsigned params, double tcm_holdout, char *line,
                    size_t size);

#endif
