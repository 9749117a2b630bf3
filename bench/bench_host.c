/*
 * Host throughput of the block calls, TCM vs PI-10, in the same run: the two
 * models alternate over the same input block and each keeps its best of REPS
 * timings (CLOCK_MONOTONIC via the host port's timing hooks). Two blocks of
 * 12-bit codes: a random walk with jumps (a reversal every other sample: the
 * hard case for branch prediction) and a slow triangle whose amplitude
 * shrinks and grows (an actuator's usual drive). Wall time: printed, never
 * asserted. Prints "key value" lines.
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

int main(void)
{
    hyst_poly_t f0;
    hyst_pi_t pi;
    static hyst_real_t z[BENCH_PI_N];
    double walk_tcm, walk_pi, tri_tcm, tri_pi;

    hyst_port_init();
    bench_f0_codes(&f0);
    if (HYST_INIT(tcm, &f0) != HYST_OK ||
        hyst_pi_init(&pi, bench_pi10_r, bench_pi10_w, z, BENCH_PI_N) != HYST_OK) {
        fprintf(stderr, "bench_host: init failed\n");
        return 1;
    }
    make_signals();
    race(&pi, walk_codes, walk_units, &walk_tcm, &walk_pi);
    race(&pi, tri_codes, tri_units, &tri_tcm, &tri_pi);
    printf("host_block_samples %u\n", BLOCK);
    printf("host_tcm_msamples_per_s %.1f\n", (double)BLOCK / walk_tcm * 1e-6);
    printf("host_pi10_msamples_per_s %.1f\n", (double)BLOCK / walk_pi * 1e-6);
    printf("host_tcm_over_pi10_time %.3f\n", walk_tcm / walk_pi);
    printf("host_triangle_tcm_msamples_per_s %.1f\n", (double)BLOCK / tri_tcm * 1e-6);
    printf("host_triangle_pi10_msamples_per_s %.1f\n", (double)BLOCK / tri_pi * 1e-6);
    printf("host_triangle_tcm_over_pi10_time %.3f\n", tri_tcm / tri_pi);
    return 0;
}
