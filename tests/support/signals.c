/* SPDX-License-Identifier: MIT */
#include "signals.h"

const char *const signal_name[SIG_KINDS] = {"random walk", "random jumps", "paper triangle"};

static double clamp(double v, double lo, double hi)
{
    return v < lo ? lo : (v > hi ? hi : v);
}

void fill_signal(int kind, rng_t *rng, double lo, double hi, hyst_real_t *out, long n)
{
    const double span = hi - lo;
    double x = lo;
    long i = 0;
    if (kind == SIG_PAPER) {
        double levels[32];
        const int n_levels = paper_levels(lo, hi, levels);
        double step = span / 50.0;
        while (i < n) {
            /* a pass ends at lo, so the next pass starts from the same state */
            long got = ramp_path(lo, levels, n_levels, step, out + i, n - i);
            i += got;
            step *= 0.5;
        }
        return;
    }
    for (i = 0; i < n; ++i) {
        if (kind == SIG_WALK) {
            x = clamp(x + rng_range(rng, -0.02, 0.02) * span, lo, hi);
        } else {
            x = rng_range(rng, lo, hi);
        }
        out[i] = (hyst_real_t)clamp(x, lo, hi);
    }
}
