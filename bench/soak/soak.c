/* SPDX-License-Identifier: MIT */
/* Soak benchmark (host, not in CI): N samples (default 10^9) of mixed
 * signals through one float TCM instance (the target's type), with
 *  - per-sample checks: output continuous (|dy| <= max slope * |dx| + tol),
 *    inside the major loop, counts consistent; NaN/Inf ignored unchanged;
 *    (jumps while a loop forgotten on overflow is still stored are counted,
 *    not failed: that is the documented cost of an overflow);
 *  - every 4096 samples: the full nesting/alternation invariant of the TPs;
 *  - periodic segments: after a warm-up period, each period's outputs are
 *    bit-identical to the previous period's (no drift).
 * Usage: soak [samples] [seed]. Exit 1 on the first violation. */
#include "hyst/hyst.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define CAP 2048u      /* 12-bit DAC: Nu/2 */
#define SEG 1000003ul  /* samples per segment of one signal kind */
#define PERIOD_MAX 8192u

static const hyst_poly_t f0 = {3u, 0.0f, 40.0f, {-6.1876e-6f, 1.1949e-3f, 8.6444e-2f, 5.8517e-1f}};
static hyst_real_t xl[CAP], yl[CAP], xr[CAP], yr[CAP];
static hyst_t S;
static hyst_real_t period_out[2][PERIOD_MAX];
static hyst_real_t period_in[PERIOD_MAX];

static unsigned long long done, nonfinite_fed, full_events, clamped, periods_compared;
static unsigned long long invariant_checks, max_tp;
static unsigned long long jumps_after_full;
static double max_slope, tol_abs, y_min, y_max, max_jump;
static int tainted; /* a loop was forgotten (memory full) since the last return to A0 */
static unsigned long rng_state = 12345u;

static double urand(void) /* xorshift32 in [0, 1) */
{
    unsigned long x = rng_state;
    x ^= (x << 13) & 0xFFFFFFFFul;
    x ^= x >> 17;
    x ^= (x << 5) & 0xFFFFFFFFul;
    rng_state = x & 0xFFFFFFFFul;
    return (double)(rng_state >> 8) / 16777216.0;
}

static void fail(const char *what)
{
    printf("VIOLATION after %llu samples: %s (tp=%lu x=%.9g y=%.9g)\n", done, what,
           (unsigned long)hyst_tp_count(&S), (double)hyst_input(&S), (double)hyst_output(&S));
    exit(1);
}

static void check_nesting(void)
{
    const size_t nl = S.n_ltp, nr = S.n_rtp;
    size_t i;
    ++invariant_checks;
    if (nl < 1u || nl > CAP || !(nr == nl || nr + 1u == nl)) fail("counts");
    if (xl[0] != f0.lo) fail("A0 moved");
    for (i = 1; i < nl; ++i) if (!(xl[i] > xl[i - 1])) fail("LTPs not ascending");
    for (i = 1; i < nr; ++i) if (!(xr[i] < xr[i - 1])) fail("RTPs not descending");
    if (nr > 0u && !(xl[nl - 1u] < xr[nr - 1u])) fail("LTP above RTP");
    if (nr > 0u && xr[0] > f0.hi) fail("RTP above hi");
    if (nl > nr) {
        if (!(hyst_input(&S) >= xl[nl - 1u] && (nr == 0u || hyst_input(&S) < xr[nr - 1u]))) fail("x off rising branch");
    } else if (!(hyst_input(&S) > xl[nl - 1u] && hyst_input(&S) <= xr[nr - 1u])) {
        fail("x off falling branch");
    }
}

/* One sample with the per-sample checks. */
static hyst_real_t feed(double v)
{
    const hyst_real_t x1 = hyst_input(&S), y1 = hyst_output(&S);
    const size_t tp1 = hyst_tp_count(&S);
    const hyst_real_t y = hyst_step(&S, (hyst_real_t)v);
    const int st = hyst_status(&S);
    ++done;
    if (st == HYST_ERR_NONFINITE) {
        if (y != y1 || hyst_input(&S) != x1 || hyst_tp_count(&S) != tp1) fail("NaN changed state");
        return y;
    }
    if (st == HYST_WARN_FULL) {
        ++full_events;
        tainted = 1;
    }
    if (st == HYST_WARN_CLAMPED) ++clamped;
    {
        const double dx = fabs((double)hyst_input(&S) - (double)x1);
        const double dy = fabs((double)y - (double)y1);
        if (dy > max_slope * dx + tol_abs) {
            /* After an overflow forgot a loop, the trajectory no longer lies on
             * the branches of the stored TPs: a later wipe-out may jump. Only
             * count those; outside that window a jump is a violation. */
            if (!tainted) fail("output discontinuous");
            ++jumps_after_full;
            if (dy - max_slope * dx > max_jump) max_jump = dy - max_slope * dx;
        }
        if ((double)y < y_min - tol_abs || (double)y > y_max + tol_abs) fail("outside major loop");
    }
    if (hyst_tp_count(&S) == 0u) tainted = 0; /* back on the major loop: clean */
    if (hyst_tp_count(&S) > max_tp) max_tp = hyst_tp_count(&S);
    if ((done & 4095u) == 0u) check_nesting();
    return y;
}

static double clampd(double v, double a, double b) { return v < a ? a : (v > b ? b : v); }

static void seg_random_walk(unsigned long n)
{
    static double x = 20.0;
    unsigned long i;
    for (i = 0; i < n; ++i) {
        x = clampd(x + (urand() - 0.5) * 0.4, 0.0, 40.0);
        feed(x);
    }
}

static void seg_jumps(unsigned long n) /* uniform jumps, 5% beyond both ends */
{
    unsigned long i;
    for (i = 0; i < n; ++i) feed(-2.0 + 44.0 * urand());
}

static void seg_codes(unsigned long n) /* 12-bit DAC codes, random walk of codes */
{
    static long code = 2048;
    unsigned long i;
    for (i = 0; i < n; ++i) {
        code += (long)(urand() * 65.0) - 32;
        code = code < 0 ? 0 : (code > 4095 ? 4095 : code);
        feed(40.0 * (double)code / 4095.0);
    }
}

static void seg_sine(unsigned long n) /* damped then growing sine around the centre */
{
    unsigned long i;
    const double w = 2.0 * 3.14159265358979 / (200.0 + 800.0 * urand());
    for (i = 0; i < n; ++i) {
        const double env = fabs(1.0 - 2.0 * (double)i / (double)n);
        feed(20.0 + 20.0 * env * sin(w * (double)i));
    }
}

static void seg_dither(unsigned long n) /* slow triangle + noise: many small loops */
{
    unsigned long i;
    for (i = 0; i < n; ++i) {
        const double t = (double)(i % 20000u) / 20000.0;
        const double tri = t < 0.5 ? 80.0 * t : 80.0 * (1.0 - t);
        const double noise = (urand() - 0.5) * 0.2;
        feed(urand() < 1e-4 ? (urand() < 0.5 ? NAN : INFINITY) : tri + noise);
        if (hyst_status(&S) == HYST_ERR_NONFINITE) ++nonfinite_fed;
    }
}

/* Periodic input with nested minor loops; no drift after the warm-up period. */
static void seg_periodic(unsigned long n)
{
    const unsigned p = 1000u + (unsigned)(urand() * (PERIOD_MAX - 1000u));
    unsigned i;
    unsigned long periods, j;
    for (i = 0; i < p; ++i) { /* a random smooth-ish path, quantised by float */
        period_in[i] = (hyst_real_t)(20.0 + 19.0 * sin(6.283185307179586 * i / p) +
                                     3.0 * sin(6.283185307179586 * 7.0 * i / p) * urand());
    }
    periods = n / p;
    for (j = 0; j < periods; ++j) {
        hyst_real_t *out = period_out[j & 1u];
        for (i = 0; i < p; ++i) out[i] = feed((double)period_in[i]);
        if (j >= 2u) { /* period 0 is warm-up, period 1 the first full one */
            if (memcmp(period_out[0], period_out[1], p * sizeof(hyst_real_t)) != 0) fail("periodic output drifted");
            ++periods_compared;
        }
    }
}

int main(int argc, char **argv)
{
    const unsigned long long n = argc > 1 ? strtoull(argv[1], NULL, 10) : 1000000000ull;
    clock_t t0;
    double secs;
    int kind = 0;
    int i;
    if (argc > 2) rng_state = strtoul(argv[2], NULL, 10) | 1u;
    if (hyst_init(&S, &f0, xl, yl, xr, yr, CAP) != HYST_OK) return 2;
    /* Lipschitz bound of f0 on the domain, sampled densely, with margin */
    for (i = 0; i <= 100000; ++i) {
        const double x = 40.0 * i / 100000.0;
        const double d = 3 * -6.1876e-6 * x * x + 2 * 1.1949e-3 * x + 8.6444e-2;
        if (d > max_slope) max_slope = d;
    }
    max_slope *= 1.001;
    y_min = (double)hyst_poly_eval(&f0, 0.0f);
    y_max = (double)hyst_poly_eval(&f0, 40.0f);
    tol_abs = 1e-5 * (y_max - y_min); /* float rounding over deep TP chains */
    t0 = clock();
    while (done < n) {
        const unsigned long left = (unsigned long)(n - done < SEG ? n - done : SEG);
        switch (kind++ % 6) {
        case 0: seg_random_walk(left); break;
        case 1: seg_jumps(left); break;
        case 2: seg_codes(left); break;
        case 3: seg_sine(left); break;
        case 4: seg_dither(left); break;
        default: seg_periodic(left > 50000ul ? left : 50000ul); break;
        }
        check_nesting();
    }
    secs = (double)(clock() - t0) / CLOCKS_PER_SEC;
    printf("soak: %llu samples in %.1f s CPU (%.1f ns/sample incl. signal generation and checks)\n",
           done, secs, 1e9 * secs / (double)done);
    printf("soak: 0 violations; %llu full nesting checks, %llu periods compared bit-identical,\n"
           "      %llu NaN/Inf ignored, %llu clamped, %llu memory-full events, max %llu TPs (capacity %u per array)\n",
           invariant_checks, periods_compared, nonfinite_fed, clamped, full_events, max_tp, CAP);
    printf("soak: %llu output jumps after memory-full events (largest %.3g = %.3g%% of the output range)\n",
           jumps_after_full, max_jump, 100.0 * max_jump / (y_max - y_min));
    return 0;
}
