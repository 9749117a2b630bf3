/* SPDX-License-Identifier: MIT */
/* Test input sequences on [lo, hi] that start from lo: random walks, random
 * jumps and the paper's shrinking/growing triangle, sample by sample. */
#ifndef HYST_TEST_SIGNALS_H
#define HYST_TEST_SIGNALS_H

#include "support.h"

enum { SIG_WALK, SIG_JUMPS, SIG_PAPER, SIG_KINDS };

extern const char *const signal_name[SIG_KINDS];

/* Fills out[0..n) with signal `kind` on [lo, hi]. SIG_WALK: steps uniform in
 * +-2 % of the span, clamped; SIG_JUMPS: uniform in [lo, hi]; SIG_PAPER: the
 * paper's test signal (support.h paper_levels) repeated with finer and
 * finer steps. Every value lies in [lo, hi]. */
void fill_signal(int kind, rng_t *rng, double lo, double hi, hyst_real_t *out, long n);

#endif
