/* SPDX-License-Identifier: MIT */
/*
 * Host throughput of the block calls, TCM vs PI-10, in the same run: the two
 * models alternate over the same input block and each keeps its best of REPS
 * timings (CLOCK_MONOTONIC via the host port's timing hooks). Three blocks
 * of 12-bit codes:
 *  - the measured drive of a piezo actuator (argv[1]: the shared data's
 *    piezo_major_loop.dat, column 1, 1 Hz at 200 Hz, repeated): the
 *    headline, an actuator's real command;
 *  - a triangle whose amplitude shrinks and grows (the paper's test signal);
 *  - a random walk with jumps (a reversal about every other sample: the
 *    worst case for the slow path and for branch prediction).
 * Wall time: printed, never asserted. Prints "key value" lines.
 */
#include "hyst/hyst.h"
#include "hyst/pi.h"
#include "hyst_port_host.h"
#include "bench_models.h"

#include <stdio.h>

#define NU BENCH_NU
#define BLOCK 65536u
#define REPS 41

HYST_DEFINE(tcm, NU);

static hyst_real_t walk_codes[BLOCK], walk_units[BLOCK];
static hyst_real_t tri_codes[BLOCK], tri_units[BLOCK];
static hyst_real_t drive_codes[BLOCK], drive_units[BLOCK];
static hyst_real_t out[BLOCK];
static volatile hyst_real_t sink;

static void make_signals(void)
{
    unsigned long lcg = 2024u;
    long x = 0;
    unsigned i;
    for (i = 0u; i < BLOCK; ++i) {
        lcg = (lcg * 1103515245u + 12345u) & 0x7fffffffu;
        if ((lcg >> 16) % 64u == 0u) {
            x = (long)((lcg >> 4) % NU);
        } else {
            x += (long)((lcg >> 8) % 129u) - 64;
            x = x < 0 ? 0 : (x > (long)NU - 1 ? (long)NU - 1 : x);
        }
        walk_codes[i] = (hyst_real_t)x;
    }
    /* 256 samples per period, amplitude 100 % -> 10 % -> 100 %. */
    for (i = 0u; i < BLOCK; ++i) {
        const unsigned long ph = i % 256u;
        const unsigned long tri = ph < 128u ? ph : 256u - ph;
        const unsigned long env = i < BLOCK / 2u ? i : BLOCK - i;
        const unsigned long amp = (NU - 1u) - (NU - 1u) * 9u / 10u * env / (BLOCK / 2u);
        tri_codes[i] = (hyst_real_t)(amp * tri / 128u);
    }
    for (i = 0u; i < BLOCK; ++i) {
        walk_units[i] = walk_codes[i] / (hyst_real_t)(NU - 1u);
        tri_units[i] = tri_codes[i] / (hyst_real_t)(NU - 1u);
    }
}

/* Column 1 of the measured data, scaled to the codes 0 .. NU-1 over its own
 * range and repeated to fill the block. Returns the rows read, 0 on error. */
static unsigned long load_drive(const char *path)
{
    static double v[BLOCK];
    unsigned long n = 0u, i;
    double lo = 1e300, hi = -1e300;
    char line[512];
    FILE *f = fopen(path, "r");
    if (f == NULL) {
        return 0u;
    }
    while (n < BLOCK && fgets(line, sizeof line, f) != NULL) {
        if (sscanf(line, "%lf", &v[n]) == 1) {
            lo = v[n] < lo ? v[n] : lo;
            hi = v[n] > hi ? v[n] : hi;
            ++n;
        }
    }
    fclose(f);
    if (n < 2u || !(hi > lo)) {
        return 0u;
    }
    for (i = 0u; i < BLOCK; ++i) {
        const double code = (v[i % n] - lo) / (hi - lo) * (double)(NU - 1u);
        drive_codes[i] = (hyst_real_t)(unsigned long)(code + 0.5);
        drive_units[i] = drive_codes[i] / (hyst_real_t)(NU - 1u);
    }
    return n;
}

/* Direction changes per 100 samples (repeats keep the direction). */
static double reversals_per_100(const hyst_real_t *x)
{
    unsigned long i, rev = 0u;
    int dir = 0;
    for (i = 1u; i < BLOCK; ++i) {
        const int d = x[i] > x[i - 1u] ? 1 : (x[i] < x[i - 1u] ? -1 : 0);
        if (d != 0 && dir != 0 && d != dir) {
            ++rev;
        }
        dir = d != 0 ? d : dir;
    }
    return 100.0 * (double)rev / (double)(BLOCK - 1u);
}

/* One signal's lines: <prefix>_tcm_msamples_per_s, ..._pi10_..., the time
 * ratio and the reversal density. */
static void report(const char *prefix, const hyst_real_t *codes, double t_tcm, double t_pi)
{
    printf("%s_tcm_msamples_per_s %.1f\n", prefix, (double)BLOCK / t_tcm * 1e-6);
    printf("%s_pi10_msamples_per_s %.1f\n", prefix, (double)BLOCK / t_pi * 1e-6);
    printf("%s_tcm_over_pi10_time %.3f\n", prefix, t_tcm / t_pi);
    printf("%s_reversals_per_100_samples %.1f\n", prefix, reversals_per_100(codes));
}

/* Best block time of TCM and of PI-10 over the same inputs, interleaved. */
static void race(hyst_pi_t *pi, const hyst_real_t *codes, const hyst_real_t *units,
                 double *best_tcm, double *best_pi)
{
    int rep;
    *best_tcm = 1e30;
    *best_pi = 1e30;
    for (rep = 0; rep < REPS; ++rep) {
        double t0 = hyst_port_host_elapsed_s(), t;
        hyst_port_timing_begin();
        (void)hyst_process(&tcm, codes, out, BLOCK);
        hyst_port_timing_end();
        sink = out[BLOCK - 1u];
        t = hyst_port_host_elapsed_s() - t0;
        *best_tcm = t < *best_tcm ? t : *best_tcm;

        t0 = hyst_port_host_elapsed_s();
        hyst_port_timing_begin();
        (void)hyst_pi_process(pi, units, out, BLOCK);
        hyst_port_timing_end();
        sink = out[BLOCK - 1u];
        t = hyst_port_host_elapsed_s() - t0;
        *best_pi = t < *best_pi ? t : *best_pi;
    }
}

int main(int argc, char **argv)
{
    hyst_poly_t f0;
    hyst_pi_t pi;
    static hyst_real_t z[BENCH_PI_N];
    double walk_tcm, walk_pi, tri_tcm, tri_pi, drive_tcm, drive_pi;
    unsigned long rows;

    hyst_port_init();
    bench_f0_codes(&f0, 0.0);
    if (HYST_INIT(tcm, &f0) != HYST_OK ||
        hyst_pi_init(&pi, bench_pi10_r, bench_pi10_w, z, BENCH_PI_N) != HYST_OK) {
        fprintf(stderr, "bench_host: init failed\n");
        return 1;
    }
    rows = argc > 1 ? load_drive(argv[1]) : 0u;
    if (rows == 0u) {
        fprintf(stderr, "bench_host: no measured drive (give piezo_major_loop.dat)\n");
        return 1;
    }
    make_signals();
    race(&pi, drive_codes, drive_units, &drive_tcm, &drive_pi);
    race(&pi, tri_codes, tri_units, &tri_tcm, &tri_pi);
    race(&pi, walk_codes, walk_units, &walk_tcm, &walk_pi);
    printf("host_block_samples %u\n", BLOCK);
    printf("host_drive_rows %lu\n", rows);
    report("host", drive_codes, drive_tcm, drive_pi);
    report("host_triangle", tri_codes, tri_tcm, tri_pi);
    report("host_walk", walk_codes, walk_tcm, walk_pi);
    return 0;
}
