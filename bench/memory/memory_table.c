/* SPDX-License-Identifier: MIT */
/* Bounded memory, measured (docs/memory.md): the integer-code TCM with K
 * entries per array against the unbounded double-precision reference
 * (tests/support/ref_tcm.c), on
 *   walk:     a random walk in codes, 200000 samples, steps up to 0.2 % of
 *             the range, reflected at the ends;
 *   nested:   adversarial: random oscillations that shrink slowly (each
 *             extreme 2..30 % of the last swing short of the previous one),
 *             so that loops nest 60 to 100 deep, restarted from the full
 *             range every 400 extremes; 200000 samples;
 *   paper:    the paper's test signal (paper_levels + a ramp of 1/2000 of
 *             the range per sample);
 *   measured: column 1 of tests/data/piezo_major_loop.dat (0..3.6 V),
 *             quantised over its range;
 *   noisy:    the measured input, each sample held for 20 samples with
 *             uniform noise of +-0.1 % of the range added to every one (a
 *             noisy command: the deadband's use case).
 * Curve: the paper's Eq. 20 on [0, 40] V; for the measured input the same
 * curve scaled to the data's range (code c means 40 c / (2^bits - 1) V).
 * K = 4096 stands for "unbounded" (no overflow on these signals): its
 * error is the float32 arithmetic alone.
 * Output, one line per (bits, K, signal):
 *   bits K signal max_err_pct rms_err_pct ref_peak_tp peak_tp overflows
 * errors in % of the output range f0(40) - f0(0).
 * Usage: memory_table <data file> <deadband codes> <bits>... (each bits <=
 * HYST_CODE_BITS of this build). */
#include "hyst/hyst.h"
#include "ref_tcm.h"
#include "support.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define MAXK 4096 /* the "full" row: never overflows on these signals */
#define MAXN 200000L

static hyst_code_word_t xs[2][MAXK];
static float ys[2][MAXK]; /* the code variant's outputs are float */
static hyst_tcm_t S;
static ref_tcm_t ref;
static uint_least32_t codes[MAXN];
static double data[MAXN];
static long n_data;

static long load(const char *path)
{
    FILE *f = fopen(path, "r");
    char line[512];
    long n = 0;
    if (f == NULL) {
        return -1;
    }
    while (n < MAXN && fgets(line, sizeof line, f) != NULL) {
        char *end;
        const double v = strtod(line, &end);
        if (end != line) {
            data[n++] = v;
        }
    }
    fclose(f);
    return n;
}

static long make_walk(uint_least32_t top)
{
    rng_t r;
    long i, c = (long)top / 2;
    const long step = (long)top / 500 + 1;
    rng_seed(&r, 99u);
    for (i = 0; i < MAXN; ++i) {
        c += (long)rng_below(&r, (uint32_t)(2 * step + 1)) - step;
        c = c < 0 ? -c : (c > (long)top ? 2 * (long)top - c : c);
        codes[i] = (uint_least32_t)c;
    }
    return MAXN;
}

static long make_nested(uint_least32_t top)
{
    rng_t r;
    const long stride = (long)top / 2000 + 1;
    long n = 0, at = 0, prev = 0, target = (long)top, level = 0;
    rng_seed(&r, 5u);
    while (n < MAXN) {
        while (at != target && n < MAXN) {
            at = at < target ? (at + stride > target ? target : at + stride)
                             : (at - stride < target ? target : at - stride);
            codes[n++] = (uint_least32_t)at;
        }
        if (++level % 400 == 0) {
            prev = 0;
            target = (long)top;
        } else {
            const long next = at + (long)((double)(prev - at) * rng_range(&r, 0.70, 0.98));
            prev = at;
            target = next;
        }
    }
    return n;
}

static long make_paper(uint_least32_t top)
{
    double levels[32];
    const int nl = paper_levels(0.0, (double)top, levels);
    const long stride = (long)top / 2000 + 1;
    long at = 0, n = 0;
    int k;
    for (k = 0; k < nl; ++k) {
        const long target = (long)(levels[k] + 0.5);
        while (at != target && n < MAXN) {
            at = at < target ? (at + stride > target ? target : at + stride)
                             : (at - stride < target ? target : at - stride);
            codes[n++] = (uint_least32_t)at;
        }
    }
    return n;
}

static long make_measured(uint_least32_t top, double noise, long hold)
{
    double lo = data[0], hi = data[0];
    long i, h, n = 0;
    rng_t r;
    rng_seed(&r, 7u);
    for (i = 1; i < n_data; ++i) {
        lo = data[i] < lo ? data[i] : lo;
        hi = data[i] > hi ? data[i] : hi;
    }
    for (i = 0; i < n_data; ++i) {
        for (h = 0; h < hold && n < MAXN; ++h) {
            double c = (data[i] - lo) / (hi - lo) * (double)top;
            c += noise * (double)top * rng_range(&r, -1.0, 1.0);
            c = c < 0.0 ? 0.0 : (c > (double)top ? (double)top : c);
            codes[n++] = (uint_least32_t)(c + 0.5);
        }
    }
    return n;
}

static void measure(unsigned bits, size_t k, unsigned long deadband, const char *name, long n)
{
    const uint_least32_t top = (uint_least32_t)((1ul << bits) - 1ul);
    double worst = 0.0, sum2 = 0.0, range;
    long i, peak = 0, fulls = 0;
    size_t own = 0;
    if (hyst_code_init(&S, &paper_eq20, 0u, top, xs[0], ys[0], xs[1], ys[1], k) != HYST_OK ||
        hyst_code_set_deadband(&S, (uint_least32_t)deadband) != HYST_OK) {
        printf("# init failed\n");
        exit(1);
    }
    ref_init(&ref, paper_eq20_coeffs, 3u, 0.0, 40.0);
    range = ref_f0(&ref, 40.0) - ref_f0(&ref, 0.0);
    for (i = 0; i < n; ++i) {
        const double y = (double)hyst_code_step(&S, codes[i]);
        const double yr = ref_step(&ref, 40.0 * (double)codes[i] / (double)top);
        const double e = fabs(y - yr);
        worst = e > worst ? e : worst;
        sum2 += e * e;
        peak = ref_tp_count(&ref) > peak ? ref_tp_count(&ref) : peak;
        fulls += hyst_status(&S) == HYST_WARN_FULL;
        own = hyst_tp_count(&S) > own ? hyst_tp_count(&S) : own;
    }
    printf("%u %u %s %.6f %.6f %ld %u %ld\n", bits, (unsigned)k, name, 100.0 * worst / range,
           100.0 * sqrt(sum2 / (double)n) / range, peak, (unsigned)own, fulls);
}

int main(int argc, char **argv)
{
    static const size_t ks[] = {8u, 16u, 32u, 64u, 128u, MAXK};
    unsigned long deadband;
    int a;
    if (argc < 4) {
        fprintf(stderr, "usage: %s <data file> <deadband codes> <bits>...\n", argv[0]);
        return 2;
    }
    n_data = load(argv[1]);
    if (n_data <= 0) {
        fprintf(stderr, "cannot read %s\n", argv[1]);
        return 1;
    }
    deadband = strtoul(argv[2], NULL, 10);
    for (a = 3; a < argc; ++a) {
        const unsigned bits = (unsigned)strtoul(argv[a], NULL, 10);
        const uint_least32_t top = (uint_least32_t)((1ul << bits) - 1ul);
        unsigned j;
        if (bits < 2u || bits > HYST_CODE_BITS) {
            fprintf(stderr, "bits %u outside 2..%d in this build\n", bits, HYST_CODE_BITS);
            return 2;
        }
        for (j = 0; j < sizeof ks / sizeof ks[0]; ++j) {
            /* the deadband is given for 16-bit codes: scale to this width */
            const unsigned long db = bits >= 16u ? deadband << (bits - 16u) : deadband >> (16u - bits);
            measure(bits, ks[j], db, "walk", make_walk(top));
            measure(bits, ks[j], db, "nested", make_nested(top));
            measure(bits, ks[j], db, "paper", make_paper(top));
            measure(bits, ks[j], db, "measured", make_measured(top, 0.0, 1));
            measure(bits, ks[j], db, "noisy", make_measured(top, 0.001, 20));
        }
    }
    return 0;
}
