/*
 * Host throughput of the block calls, TCM vs PI-10, in the same run: the two
 * models alternate over the same input block (12-bit codes, a random walk
 * with jumps), and each keeps its best of REPS timings (CLOCK_MONOTONIC via
 * the host port's timing hooks). Wall time: printed, never asserted.
 * Prints "key value" lines.
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

static hyst_real_t codes[BLOCK], units[BLOCK], out[BLOCK];
static volatile hyst_real_t sink;

static void make_signal(void)
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
        codes[i] = (hyst_real_t)x;
        units[i] = (hyst_real_t)x / (hyst_real_t)(NU - 1u);
    }
}

static double timed_s(void)
{
    return hyst_port_host_elapsed_s();
}

int main(void)
{
    hyst_poly_t f0;
    hyst_pi_t pi;
    static hyst_real_t z[BENCH_PI_N];
    double best_tcm = 1e30, best_pi = 1e30;
    int rep;

    hyst_port_init();
    bench_f0_codes(&f0);
    if (HYST_INIT(tcm, &f0) != HYST_OK ||
        hyst_pi_init(&pi, bench_pi10_r, bench_pi10_w, z, BENCH_PI_N) != HYST_OK) {
        fprintf(stderr, "bench_host: init failed\n");
        return 1;
    }
    make_signal();
    for (rep = 0; rep < REPS; ++rep) {
        double t0 = timed_s(), t1;
        hyst_port_timing_begin();
        (void)hyst_process(&tcm, codes, out, BLOCK);
        hyst_port_timing_end();
        sink = out[BLOCK - 1u];
        t1 = timed_s();
        best_tcm = t1 - t0 < best_tcm ? t1 - t0 : best_tcm;

        t0 = timed_s();
        hyst_port_timing_begin();
        (void)hyst_pi_process(&pi, units, out, BLOCK);
        hyst_port_timing_end();
        sink = out[BLOCK - 1u];
        t1 = timed_s();
        best_pi = t1 - t0 < best_pi ? t1 - t0 : best_pi;
    }
    printf("host_block_samples %u\n", BLOCK);
    printf("host_tcm_msamples_per_s %.1f\n", (double)BLOCK / best_tcm * 1e-6);
    printf("host_pi10_msamples_per_s %.1f\n", (double)BLOCK / best_pi * 1e-6);
    printf("host_tcm_ns_per_sample %.2f\n", best_tcm / (double)BLOCK * 1e9);
    printf("host_pi10_ns_per_sample %.2f\n", best_pi / (double)BLOCK * 1e9);
    printf("host_tcm_over_pi10_time %.3f\n", best_tcm / best_pi);
    printf("host_tcm_tps_end %lu\n", (unsigned long)hyst_tp_count(&tcm));
    return 0;
}
