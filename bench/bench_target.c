/* SPDX-License-Identifier: MIT */
/*
 * Per-sample cost of hyst_step() (and of a PI-10 model) on the target, one
 * timing pulse per measured sample. Runs under QEMU with tools/qemu_count.py,
 * which counts the instructions executed inside each pulse.
 *
 * Inputs are the codes of a 12-bit DAC (Nu = 4096, x in 0..4095, curve =
 * the paper's Eq. 20 stretched over the codes), so each TP array holds
 * HYST_CAPACITY(4096) = 2048 entries. The trajectory 0, 4095, 1, 4094, 2, ...
 * nests one more TP pair per reversal; the states along it carry m = 1 .. 2047
 * TPs in the array a wipe-out searches. At each state the firmware snapshots
 * the instance, times one sample of a kind, checks the result, restores.
 *
 * Pulse 0 calibrates (see tools/qemu_count.py); pulses 1..6 are the typical
 * and deepest samples at the largest m (profiled by bench/analyse.py).
 * After all pulses it prints one line per pulse, in pulse order:
 *   @pulse <kind> <m> <k> <p>
 * m = entries in the searched array, k = entries that survive, p = comparisons
 * the search makes (0 when no search runs); and a few "# key value" lines.
 *
 * Build switches: BENCH_SWEEP_ALL (every m, else a sparse set), BENCH_EXHAUSTIVE
 * (every survivor count k at the largest m), BENCH_PI (PI-10 pulses),
 * BENCH_OFFSET (codes shifted by this much, e.g. -2048: a domain across
 * zero, whose searches take both ladders of the keyed search),
 * BENCH_BOUNDED (bounded memory: every sample of a nesting random signal
 * through 32-entry arrays, with and without a deadband),
 * BENCH_LINEAR (the engine with a linear scan, bench/linear_engine.c:
 * changes the p model), BENCH_INVERSE (the compensator of Eq. 20, tabulated
 * (inverse.h, HYST_INIT_INVERSE): the codes are desired outputs; no PI or
 * bounded-memory pulses),
 * changes the p model), BENCH_Q31 (the q31 variant, hyst/q31.h, on the
 * doubled codes 2, 4, ..., 8192: the half codes are the odd ones; with
 * BENCH_PI=0 and BENCH_BOUNDED=0), BENCH_Q31_INV (its compensator on
 * Eq. 20 over codes 0..4095, HYST_Q31_INIT_INVERSE: the codes are 4096
 * levels of the desired output; the same restrictions).
 */
#include "hyst/hyst.h"
#include "hyst/pi.h"
#include "hyst_port.h"
#include "bench_models.h"

#ifdef BENCH_LINEAR
/* The same firmware on the linear-scan engine (bench/linear_engine.c). */
float bench_lin_step(hyst_tcm_t *S, float x);
hyst_status_t bench_lin_init_(hyst_tcm_t *S, const hyst_poly_t *f0, float *xltp, float *yltp,
                              float *xrtp, float *yrtp, size_t capacity, unsigned long layout);
#undef hyst_step
#define hyst_step bench_lin_step
#undef HYST_INIT
#define HYST_INIT(name, f0) bench_lin_init_(&(name), (f0), HYST_ARRAYS_(name), HYST_LAYOUT)
#endif

#include <stdio.h>

/* The variant measured: input and output types, the step, code c's input
 * (CODE), k codes (CODES), half a code (HALF). */
#if defined(BENCH_Q31_INV)
/* Desired outputs q: NU levels from -2^27 to 2^27 (the model's output
 * range), level c at half-level 2c of 2 (NU - 1) (rounded: within one q of
 * uniform, so every half level lies strictly between its neighbours). */
typedef hyst_q31_t bench_x_t;
typedef hyst_q31_t bench_y_t;
#define bench_step hyst_q31_inv_step
#define bench_input hyst_q31_inv_input
#define HALVES_ (2 * ((int_least64_t)NU - 1))
#define CODE(c)                                                                 \
    ((bench_x_t)((((int_least64_t)(2u * (c)) << 28) + HALVES_ / 2) / HALVES_ - \
                 ((int_least64_t)1 << 27)))
#define CODES(k) ((bench_x_t)((((int_least64_t)(k) << 28) + HALVES_ / 4) / (HALVES_ / 2)))
#define HALF ((bench_x_t)(((int_least64_t)1 << 28) / HALVES_))
#define CAL_X 1
#define NULL_RESULT(S, x) ((bench_y_t)(uintptr_t)(S))
#elif defined(BENCH_Q31)
typedef uint_least32_t bench_x_t;
typedef hyst_q31_t bench_y_t;
#define bench_step hyst_q31_step
#define bench_input hyst_q31_input
#define CODE(c) ((bench_x_t)(2u * (c) + 2u))
#define CODES(k) ((bench_x_t)(2u * (k)))
#define HALF 1u
#define CAL_X 1u
/* What the calibration callee returns: the value already in the result
 * register (S), so that its body is one "bx lr" as in the real variants. */
#define NULL_RESULT(S, x) ((bench_y_t)(uintptr_t)(S))
#else
typedef hyst_real_t bench_x_t;
typedef hyst_real_t bench_y_t;
#define bench_step hyst_step
#define bench_input hyst_input
/* Input value of code c (exact in hyst_real_t, like the half codes). */
#define OFF ((hyst_real_t)(BENCH_OFFSET))
#define CODE(c) ((hyst_real_t)(c) + OFF)
#define CODES(k) ((hyst_real_t)(k))
#define HALF HYST_REAL_C(0.5)
#define CAL_X HYST_REAL_C(1.0)
#define NULL_RESULT(S, x) (x)
#endif

#ifndef BENCH_SWEEP_ALL
#define BENCH_SWEEP_ALL 1
#endif
#ifndef BENCH_EXHAUSTIVE
#define BENCH_EXHAUSTIVE 1
#endif
#ifndef BENCH_PI
#define BENCH_PI 1
#endif
#ifndef BENCH_OFFSET
#define BENCH_OFFSET 0
#endif
#ifndef BENCH_EVERETT
#define BENCH_EVERETT 0 /* 1: the asymmetric kind instead of the polynomial; 2: its compensator;
                         * 3: its tabulated compensator; 4: the asymmetric kind on a grid;
                         * 5: its compensator; 6: a spline f0; 7: its compensator;
                         * 8: its tabulated compensator */
#endif
#ifndef BENCH_EVERETT_DEGREE
#define BENCH_EVERETT_DEGREE 3u /* the asymmetric kind's degree (BENCH_EVERETT 1): 3 or 4 */
#endif
#ifndef BENCH_BOUNDED
#define BENCH_BOUNDED 1
#endif

/* Keeps GCC from specialising the timed wrappers per callee: the wrapper's
 * code must be the same for the calibration call and the measured one. */
#if defined(__GNUC__) && !defined(__clang__)
#define BENCH_NOIPA __attribute__((noipa))
#else
#define BENCH_NOIPA __attribute__((noinline))
#endif

#define NU BENCH_NU
#define CAP HYST_CAPACITY(NU)
#define CODE_HI CODE(NU - 1u)
#define PI_SAMPLES 256u
#define MAX_RECORDS 32000u

#if defined(BENCH_INVERSE)
HYST_DEFINE_INVERSE(tcm, NU);
#define BENCH_MODEL(f0, offset) bench_f0_inverse_codes((f0), (offset))
#define BENCH_INIT(f0) HYST_INIT_INVERSE(tcm, (f0))
#elif defined(BENCH_Q31_INV)
HYST_Q31_DEFINE_INVERSE(tcm, NU);
#define BENCH_MODEL(f0, offset) bench_f0_codes((f0), (offset))
#define BENCH_INIT(f0) HYST_Q31_INIT_INVERSE(tcm, (f0), 0u, NU - 1u)
#elif defined(BENCH_Q31)
HYST_Q31_DEFINE(tcm, NU);
#define BENCH_MODEL(f0, offset) bench_f0_codes((f0), (offset))
#define BENCH_INIT(f0) HYST_Q31_INIT(tcm, (f0), CODE(0u), CODE_HI)
#else
HYST_DEFINE(tcm, NU);
#define BENCH_MODEL(f0, offset) bench_f0_codes((f0), (offset))
#define BENCH_INIT(f0) HYST_INIT(tcm, (f0))
#endif

typedef struct {
    const char *kind;
    unsigned m, k, p;
} record_t;

static record_t records[MAX_RECORDS];
static unsigned n_records;
static int failures;
static volatile bench_y_t sink;

/* BENCH_TIMED(name, type) defines, for a model of instance type `type`:
 *  - null_<name>(): the calibration callee, whose whole body is the return
 *    (one instruction);
 *  - timed_<name>(fn, S, x): one pulse around one call of fn. The pulse also
 *    covers the wrapper's own instructions between the two pin writes; the
 *    calibration pulse (same wrapper, null callee) measures those, and the
 *    analysis subtracts them. */
#define BENCH_TIMED(name, type)                                               \
    BENCH_NOIPA static bench_y_t null_##name(type *S, bench_x_t x)           \
    {                                                                         \
        (void)S;                                                              \
        (void)x;                                                              \
        return NULL_RESULT(S, x);                                             \
    }                                                                         \
    BENCH_NOIPA static void timed_##name(bench_y_t (*fn)(type *, bench_x_t),  \
                                         type *S, bench_x_t x)                \
    {                                                                         \
        bench_y_t y;                                                          \
        hyst_port_timing_begin();                                             \
        y = fn(S, x);                                                         \
        hyst_port_timing_end();                                               \
        sink = y;                                                             \
    }

BENCH_TIMED(tcm, hyst_t)

static void record(const char *kind, unsigned m, unsigned k, unsigned p)
{
    if (n_records < MAX_RECORDS) {
        records[n_records].kind = kind;
        records[n_records].m = m;
        records[n_records].k = k;
        records[n_records].p = p;
    } else {
        failures |= 1;
    }
    ++n_records;
}

/* Comparisons ltp_below()/rtp_above() make over n entries of which the
 * first k satisfy the predicate (the arrays are sorted). */
static unsigned search_probes(unsigned n, unsigned k)
{
#ifdef BENCH_LINEAR
    return (n - k) + (k > 0u ? 1u : 0u);
#else
    unsigned left = 0u, p = 0u;
    while (n > 0u) {
        const unsigned half = n / 2u;
        ++p;
        if (left + half < k) {
            left += half + 1u;
            n -= half + 1u;
        } else {
            n = half;
        }
    }
    return p;
#endif
}

static void expect_counts(size_t ltp, size_t rtp)
{
    if (hyst_ltp_count(&tcm) != ltp || hyst_rtp_count(&tcm) != rtp ||
        hyst_status(&tcm) < 0) {
        failures |= 2;
    }
}

/* A sample on the current branch, or a reversal that only pushes a TP. */
static void time_plain(const char *kind, unsigned m, bench_x_t x)
{
    const hyst_t snap = tcm;
    const size_t tps = hyst_tp_count(&tcm);
    timed_tcm(bench_step, &tcm, x);
    if (hyst_tp_count(&tcm) < tps) {
        failures |= 4; /* it wiped: not the kind it claims to be */
    }
    record(kind, m, 0u, 0u);
    tcm = snap;
}

/* A falling wipe-out (x <= the LTP below): the first k of the n searched LTPs
 * survive; the model is back on the falling branch from RTP k-1, or at A0. */
static void time_wipe_fall(const char *kind, unsigned n, unsigned k, bench_x_t x)
{
    const hyst_t snap = tcm;
    timed_tcm(bench_step, &tcm, x);
    expect_counts(k > 0u ? k - 1u : 0u, k);
    record(kind, n, k, search_probes(n, k));
    tcm = snap;
}

/* A rising wipe-out: k of n searched RTPs survive, rising from LTP k. */
static void time_wipe_rise(const char *kind, unsigned n, unsigned k, bench_x_t x)
{
    const hyst_t snap = tcm;
    timed_tcm(bench_step, &tcm, x);
    expect_counts(k, k);
    record(kind, n, k, search_probes(n, k));
    tcm = snap;
}

/* LTP codes are 0, 1, 2, ...: x = k - 0.5 leaves k of them (x = 0 none). */
static bench_x_t ltp_target(unsigned k)
{
    return k == 0u ? CODE(0u) : CODE(k) - HALF;
}

/* RTP codes are 4095, 4094, ...: x = 4095.5 - k leaves k (x = 4095 none). */
static bench_x_t rtp_target(unsigned k)
{
    return k == 0u ? CODE_HI : CODE_HI + HALF - CODES(k);
}

static int sparse_m(unsigned m)
{
    unsigned b;
    if (m <= 8u || m == CAP - 1u || m == CAP - 2u) {
        return 1;
    }
    for (b = 8u; b <= CAP; b *= 2u) {
        if (m + 1u == b || m == b || m == b + 1u) {
            return 1;
        }
    }
    return 0;
}

static int in_sweep(unsigned m) { return BENCH_SWEEP_ALL || sparse_m(m); }

/* Falling state F_j: LTPs 0..j-1, RTPs 4095..4096-j, x_prev = j. */
static void measure_falling(unsigned j, int last)
{
    const unsigned n = j - 1u; /* searched by both wipe kinds */
    const bench_x_t xj = CODE(j);
    unsigned k;
    if (sparse_m(j)) {
        time_plain("typ_fall", n, xj - HALF);
        time_plain("rev_rise", n, xj + HALF);
    }
    if (n >= 1u && in_sweep(n)) {
        for (k = 0u; k <= 1u; ++k) { /* to lo or hi, and just short of it */
            time_wipe_fall("wipe_fall", n, k, ltp_target(k));
            time_wipe_rise("wipe_revrise", n, k, rtp_target(k));
        }
    }
    if (BENCH_EXHAUSTIVE && last) {
        for (k = 0u; k <= n; ++k) {
            time_wipe_fall("exh_wipe_fall", n, k, ltp_target(k));
            time_wipe_rise("exh_wipe_revrise", n, k, rtp_target(k));
        }
        /* Out of the domain: clamped to hi, then the deepest rising wipe. */
        time_wipe_rise("clamp_hi", n, 0u, CODE_HI + CODES(1u));
    }
}

/* Rising state R_i: LTPs 0..i-1, RTPs 4095..4097-i, x_prev = 4096-i. */
static void measure_rising(unsigned i, int last)
{
    const unsigned n_rise = i - 2u, n_fall = i - 1u;
    const bench_x_t xp = bench_input(&tcm);
    unsigned k;
    if (sparse_m(i) && i >= 2u) {
        time_plain("typ_rise", n_fall, xp + HALF);
        time_plain("rev_fall", n_fall, xp - HALF);
        time_plain("repeat", n_fall, xp);
    }
    for (k = 0u; k <= 1u; ++k) { /* to lo or hi, and just short of it */
        if (i >= 3u && in_sweep(n_rise)) {
            time_wipe_rise("wipe_rise", n_rise, k, rtp_target(k));
        }
        if (i >= 2u && in_sweep(n_fall)) {
            time_wipe_fall("wipe_revfall", n_fall, k, ltp_target(k));
        }
    }
    if (BENCH_EXHAUSTIVE && last) {
        for (k = 0u; k <= n_fall; ++k) {
            if (k <= n_rise) {
                time_wipe_rise("exh_wipe_rise", n_rise, k, rtp_target(k));
            }
            time_wipe_fall("exh_wipe_revfall", n_fall, k, ltp_target(k));
        }
        time_wipe_fall("clamp_lo", n_fall, 0u, CODE(0u) - CODES(1u));
#if !defined(BENCH_Q31) && !defined(BENCH_Q31_INV) /* integers have no NaN */
        {
            const hyst_t snap = tcm;
            volatile hyst_real_t zero = HYST_REAL_C(0.0);
            const hyst_real_t nan = zero / zero;
            timed_tcm(hyst_step, &tcm, nan);
            if (hyst_status(&tcm) != HYST_ERR_NONFINITE) {
                failures |= 8;
            }
            record("nan", n_fall, 0u, 0u);
            tcm = snap;
        }
#endif
    }
}

/* Next reversal of the trajectory 0, 4095, 1, 4094, ...: peak i leads to
 * R_i, valley i to F_i. */
static void step_peak(unsigned i) { (void)bench_step(&tcm, CODE(NU - i)); }
static void step_valley(unsigned i) { (void)bench_step(&tcm, CODE(i)); }

/* The cheapest and the deepest sample of each kind at the largest m, first
 * in the pulse order (pulses 1..6) so that the analysis can profile them. */
static void showcase(void)
{
    unsigned i;
    for (i = 1u; i < CAP; ++i) {
        step_peak(i);
        step_valley(i);
    }
    time_plain("show_typ_fall", CAP - 2u, CODE(CAP - 1u) - HALF);
    time_wipe_fall("show_wipe_fall", CAP - 2u, 0u, ltp_target(0u));
    time_wipe_rise("show_wipe_revrise", CAP - 2u, 0u, rtp_target(0u));
    step_peak(CAP);
    time_plain("show_typ_rise", CAP - 1u, bench_input(&tcm) + HALF);
    time_wipe_rise("show_wipe_rise", CAP - 2u, 0u, rtp_target(0u));
    time_wipe_fall("show_wipe_revfall", CAP - 1u, 0u, ltp_target(0u));
    hyst_reset(&tcm);
}

#if BENCH_EVERETT == 3
/* The tabulated asymmetric compensator's default table: built at init
 * (init_table), then taken as firmware takes it from flash, its seal and
 * model checked (init_const); the samples run on the second curve. Both are
 * callees of the timing wrapper, so their counts are exact. */
static hyst_real_t table[HYST_EVERETT_INV_TABLE_LEN(HYST_EVERETT_INV_ROWS,
                                                    HYST_EVERETT_INV_INTERVALS)];
static hyst_curve_t table_fwd, table_built, table_from_flash;
static hyst_table_seal_t table_seal;
static hyst_status_t table_status;

BENCH_NOIPA static bench_y_t build_table(hyst_t *S, bench_x_t x)
{
    (void)S;
    table_status = hyst_curve_everett_inverse_table(&table_built, &table_fwd, table,
                                                    HYST_EVERETT_INV_ROWS,
                                                    HYST_EVERETT_INV_INTERVALS);
    return x;
}

BENCH_NOIPA static bench_y_t table_from_const(hyst_t *S, bench_x_t x)
{
    (void)S;
    table_status = hyst_curve_everett_inverse_table_const(
        &table_from_flash, &table_fwd, table, HYST_EVERETT_INV_ROWS, HYST_EVERETT_INV_INTERVALS,
        &table_seal);
    return x;
}

/* Both, timed; the curve the samples run on, or NULL. */
static const hyst_curve_t *timed_table(const hyst_everett_t *e)
{
    if (hyst_curve_from_everett(&table_fwd, e) != HYST_OK) {
        return NULL;
    }
    timed_tcm(build_table, &tcm, CAL_X);
    record("init_table", 0u, 0u, 0u);
    if (table_status != HYST_OK || hyst_curve_table_seal(&table_built, &table_seal) != HYST_OK) {
        return NULL;
    }
    timed_tcm(table_from_const, &tcm, CAL_X);
    record("init_const", 0u, 0u, 0u);
    return table_status == HYST_OK ? &table_from_flash : NULL;
}
#endif

static void bench_tcm(void)
{
    hyst_poly_t f0;
    unsigned i;
    /* first: the init of the tabulated asymmetric compensator is timed */
    record("cal_tcm", 0u, 0u, 0u);
    timed_tcm(null_tcm, &tcm, CAL_X);
    BENCH_MODEL(&f0, (double)BENCH_OFFSET);
#if BENCH_EVERETT
    {
        static hyst_curve_t curve; /* the asymmetric kind keeps its curve */
        hyst_everett_t e;
        hyst_status_t st;
#if BENCH_EVERETT == 2 /* its compensator: the codes are desired outputs */
        bench_everett_inverse_codes(&e, (double)BENCH_OFFSET);
        st = hyst_curve_from_everett(&curve, &e);
        if (st == HYST_OK) {
            st = hyst_curve_inverse(&curve, &curve);
        }
#elif BENCH_EVERETT == 3 /* its tabulated compensator, the default table, from "flash" */
        const hyst_curve_t *from_flash;
        bench_everett_inverse_codes(&e, (double)BENCH_OFFSET);
        from_flash = timed_table(&e);
        st = from_flash != NULL ? HYST_OK : HYST_ERR_ARG;
        if (st == HYST_OK) {
            curve = *from_flash;
        }
#elif BENCH_EVERETT == 4 /* on a grid of 6 intervals over the codes, a near step inside */
        static hyst_real_t grid_table[HYST_EVERETT_GRID_TABLE_LEN(6u)];
        hyst_everett_grid_t g;
        (void)e;
        bench_grid_codes(&g, (double)BENCH_OFFSET);
        st = hyst_curve_from_everett_grid(&curve, &g, grid_table, HYST_EVERETT_GRID_TABLE_LEN(6u));
#elif BENCH_EVERETT == 5 /* the grid's compensator: the codes are desired outputs */
        static hyst_real_t grid_table[HYST_EVERETT_GRID_TABLE_LEN(6u)];
        static hyst_curve_t fwd;
        hyst_everett_grid_t g;
        (void)e;
        st = bench_grid_inverse_codes(&fwd, &g, (double)BENCH_OFFSET, grid_table,
                                      HYST_EVERETT_GRID_TABLE_LEN(6u));
        if (st == HYST_OK) {
            st = hyst_curve_everett_grid_inverse(&curve, &fwd);
        }
#elif BENCH_EVERETT >= 6 && BENCH_EVERETT <= 8 /* a spline of 16 intervals; its compensators */
        static hyst_real_t spline_table[HYST_SPLINE_TABLE_LEN(16u)];
        hyst_spline_t f;
        (void)e;
#if BENCH_EVERETT == 6
        bench_spline_codes(&f, (double)BENCH_OFFSET, 0.0, 1.0);
        st = hyst_curve_from_spline(&curve, &f, spline_table, HYST_SPLINE_TABLE_LEN(16u));
#elif BENCH_EVERETT == 7 /* the codes are desired outputs */
        bench_spline_codes(&f, 0.0, (double)BENCH_OFFSET, (double)(BENCH_NU - 1u));
        st = hyst_curve_from_spline(&curve, &f, spline_table, HYST_SPLINE_TABLE_LEN(16u));
        if (st == HYST_OK) {
            st = hyst_curve_spline_inverse(&curve, &curve);
        }
#else /* tabulated in HYST_INV_TABLE intervals; the codes are desired outputs */
        static hyst_real_t inv_table[HYST_INV_TABLE_LEN(HYST_INV_TABLE)];
        hyst_curve_t fwd;
        bench_spline_codes(&f, 0.0, (double)BENCH_OFFSET, (double)(BENCH_NU - 1u));
        st = hyst_curve_from_spline(&fwd, &f, spline_table, HYST_SPLINE_TABLE_LEN(16u));
        if (st == HYST_OK) {
            st = hyst_curve_spline_inverse_table(&curve, &fwd, inv_table, HYST_INV_TABLE);
        }
#endif
#else
        bench_everett_codes(&e, (double)BENCH_OFFSET, BENCH_EVERETT_DEGREE);
        st = hyst_curve_from_everett(&curve, &e);
#endif
        if (st != HYST_OK || HYST_INIT_CURVE(tcm, &curve) != HYST_OK) {
            failures |= 16;
            return;
        }
    }
#else
    if (BENCH_INIT(&f0) != HYST_OK) {
        failures |= 16;
        return;
    }
#endif
    showcase();

    for (i = 1u; i <= CAP; ++i) {
        step_peak(i);
        if (hyst_ltp_count(&tcm) != i - 1u || hyst_rtp_count(&tcm) != i - 1u) {
            failures |= 32;
            return;
        }
        measure_rising(i, i == CAP);
        if (i == CAP) {
            break;
        }
        step_valley(i);
        measure_falling(i, i == CAP - 1u);
    }
}

#ifdef BENCH_INVERSE
/* The intervals of an inverse table evaluated exactly (curve.h): x^3 on
 * [-1, 1] has a flat point at 0, where the table's cubic misses the
 * tolerance. Times samples of a rise through it, labelled "inv_exact" if
 * they land in such an interval (m = interval), else "inv_table". */
#define FLAT_SAMPLES 64u

static void bench_exact_intervals(void)
{
    static const hyst_poly_t cube = {3u, HYST_REAL_C(-1.0), HYST_REAL_C(1.0), {1.0, 0.0, 0.0, 0.0}};
    HYST_DEFINE_INVERSE(flat, 64u);
    unsigned t;
    if (HYST_INIT_INVERSE(flat, &cube) != HYST_OK || flat_curve.u.inv_table.exact == 0u) {
        failures |= 512;
        return;
    }
    (void)hyst_step(&flat, HYST_REAL_C(-0.05));
    for (t = 1u; t <= FLAT_SAMPLES; ++t) {
        const hyst_real_t yd = HYST_REAL_C(-0.05) + HYST_REAL_C(0.1) * (hyst_real_t)t / (hyst_real_t)FLAT_SAMPLES;
        const unsigned k = (unsigned)((yd - flat_curve.lo.HYST_R) * flat_curve.unit.HYST_R);
        timed_tcm(hyst_step, &flat, yd);
        record(flat_curve.u.inv_table.table.HYST_R[4u * k] < 0 ? "inv_exact" : "inv_table", k, 0u, 0u);
    }
}
#endif

#if BENCH_BOUNDED
/* Bounded memory (docs/memory.md), 32 entries per array on the 12-bit
 * codes: a random walk with nesting zigzags times every sample, labelled
 * "bnd_merge" (it merged a loop: status HYST_WARN_FULL), "bnd_detour" (a
 * merge or a deadband excursion was alive, hyst_error_bound() > 0: the slow
 * path with its bookkeeping) or "bnd_plain". m = TPs, k = deadband on. */
#define BND_CAP 32u
#define BND_SAMPLES 2000u

static void bench_bounded(hyst_real_t deadband)
{
    static hyst_real_t xl[BND_CAP], yl[BND_CAP], xr[BND_CAP], yr[BND_CAP];
    static hyst_t S;
    hyst_poly_t f0;
    unsigned t, lcg = 777u, zig = 0u;
    long x = 2048, amp = 0, centre = 0, dx = 8;
    bench_f0_codes(&f0, (double)BENCH_OFFSET);
    if (hyst_init(&S, &f0, xl, yl, xr, yr, BND_CAP) != HYST_OK ||
        hyst_set_deadband(&S, deadband) != HYST_OK) {
        failures |= 128;
        return;
    }
    for (t = 0u; t < BND_SAMPLES; ++t) {
        const int alive = hyst_error_bound(&S) > 0;
        lcg = lcg * 1664525u + 1013904223u;
        if (zig > 0u) { /* nested loops: each swing smaller */
            x = centre + ((zig & 1u) ? amp : -amp);
            amp = amp * 15 / 16;
            --zig;
        } else if ((lcg >> 26) == 0u) {
            zig = 80u;
            centre = 1024 + (long)((lcg >> 8) % 2048u);
            amp = 300 + (long)((lcg >> 12) % 600u);
        } else {
            if ((lcg >> 28) < 3u) {
                dx = -dx;
            }
            x += dx + (long)((lcg >> 16) % 5u) - 2;
        }
        x = x < 0 ? 0 : (x > (long)NU - 1 ? (long)NU - 1 : x);
        timed_tcm(hyst_step, &S, CODE((unsigned long)x));
        record(hyst_status(&S) == HYST_WARN_FULL ? "bnd_merge" : alive ? "bnd_detour" : "bnd_plain",
               (unsigned)hyst_tp_count(&S), deadband > 0 ? 1u : 0u, 0u);
    }
    if ((hyst_events(&S) & HYST_EVENT_FULL) == 0u) {
        failures |= 256; /* the signal must overflow the arrays */
    }
}
#endif

#if BENCH_PI
BENCH_TIMED(pi, hyst_pi_t)

static void bench_pi(void)
{
    static hyst_real_t z[BENCH_PI_N];
    hyst_pi_t P;
    unsigned t, lcg = 12345u;
    hyst_real_t x = HYST_REAL_C(0.0);
    if (hyst_pi_init(&P, bench_pi10_r, bench_pi10_w, z, BENCH_PI_N) != HYST_OK) {
        failures |= 64;
        return;
    }
    record("cal_pi", 0u, 0u, 0u);
    timed_pi(null_pi, &P, HYST_REAL_C(0.5));
    /* A random walk with jumps over [0, 1]: every operator path is taken. */
    for (t = 0u; t < PI_SAMPLES; ++t) {
        lcg = lcg * 1664525u + 1013904223u;
        if ((lcg >> 28) == 0u) {
            x = (hyst_real_t)(lcg >> 8) * HYST_REAL_C(5.9604645e-8);
        } else {
            x += ((hyst_real_t)(lcg >> 20) - HYST_REAL_C(2048.0)) * HYST_REAL_C(1e-4);
            x = x < HYST_REAL_C(0.0) ? HYST_REAL_C(0.0) : (x > HYST_REAL_C(1.0) ? HYST_REAL_C(1.0) : x);
        }
        timed_pi(hyst_pi_step, &P, x);
        record("pi10", 10u, 0u, 0u);
    }
}
#endif

#if BENCH_PI && !defined(BENCH_Q31) && !defined(BENCH_Q31_INV)
BENCH_TIMED(creep, hyst_creep_t)

/* The creep term (hyst/creep.h) beside the model: one lag (the
 * identification's choice on the measured record) and two, on the same walk
 * over [0, 1] as PI-10. */
static void bench_creep(void)
{
    static const hyst_wide_t tau[2] = {5000, 300}, weight[2] = {0.32, -0.05};
    static const char *const kind[2] = {"creep1", "creep2"};
    hyst_creep_t C;
    unsigned t, n, lcg = 12345u;
    hyst_real_t x = HYST_REAL_C(0.0);
    for (n = 1u; n <= 2u; ++n) {
        if (hyst_creep_init(&C, n, tau, weight, 0) != HYST_OK) {
            failures |= 64;
            return;
        }
        record("cal_creep", 0u, 0u, 0u);
        timed_creep(null_creep, &C, HYST_REAL_C(0.5));
        for (t = 0u; t < 32u; ++t) {
            lcg = lcg * 1664525u + 1013904223u;
            x = (hyst_real_t)(lcg >> 8) * HYST_REAL_C(5.9604645e-8);
            timed_creep(hyst_creep_step, &C, x);
            record(kind[n - 1u], n, 0u, 0u);
        }
    }
}
#endif

/* Small buffered writer: printf per record would dominate the run (every
 * instruction of it is logged too). */
static char out_buf[4096];
static unsigned out_len;

static void out_flush(void)
{
    out_buf[out_len] = '\0';
    hyst_port_puts(out_buf);
    out_len = 0u;
}

static void out_str(const char *s)
{
    if (out_len + 64u >= sizeof out_buf) { /* no line is longer */
        out_flush();
    }
    while (*s != '\0') {
        out_buf[out_len++] = *s++;
    }
}

static void out_uint(unsigned long v)
{
    char d[12];
    unsigned n = 0u;
    do {
        d[n++] = (char)('0' + (int)(v % 10u));
        v /= 10u;
    } while (v != 0u);
    while (n > 0u) {
        out_buf[out_len++] = d[--n];
    }
}

static void out_kv(const char *key, unsigned long v)
{
    out_str("# ");
    out_str(key);
    out_str(" ");
    out_uint(v);
    out_str("\n");
}

int main(void)
{
    unsigned r;
    hyst_port_init();
    bench_tcm();
#ifdef BENCH_INVERSE
    bench_exact_intervals();
#endif
#if BENCH_BOUNDED
    bench_bounded(HYST_REAL_C(0.0));
    bench_bounded(HYST_REAL_C(4.0)); /* a 4-code deadband */
#endif
#if BENCH_PI
    bench_pi();
#endif
#if BENCH_PI && !defined(BENCH_Q31) && !defined(BENCH_Q31_INV)
    bench_creep();
#endif
    for (r = 0u; r < n_records && r < MAX_RECORDS; ++r) {
        out_str("@pulse ");
        out_str(records[r].kind);
        out_str(" ");
        out_uint(records[r].m);
        out_buf[out_len++] = ' ';
        out_uint(records[r].k);
        out_buf[out_len++] = ' ';
        out_uint(records[r].p);
        out_buf[out_len++] = '\n';
    }
    out_kv("nu", NU);
    out_kv("capacity", CAP);
    out_kv("sizeof_hyst_t", sizeof(hyst_t));
    out_kv("sizeof_real", sizeof(hyst_real_t));
    out_kv("offset_neg", (unsigned long)(BENCH_OFFSET < 0 ? -(BENCH_OFFSET) : 0));
#ifdef BENCH_LINEAR
    out_kv("linear_search", 1u);
#else
    out_kv("linear_search", 0u);
#endif
#ifdef BENCH_INVERSE
    /* the table's worst error against the exact inverse, as init measured
     * it, in parts per 10^9 of the drive range */
    out_kv("inv_max_err_rel_ppb", (unsigned long)(hyst_curve_inverse_error(&tcm_curve) * 1e9 + 0.5));
#endif
#if BENCH_EVERETT == 3
    /* the asymmetric compensator's default table: the same, from flash (the seal's) */
    out_kv("inv_max_err_rel_ppb",
           (unsigned long)(hyst_curve_inverse_error(&table_from_flash) * 1e9 + 0.5));
#endif
    out_kv("failures", (unsigned long)failures);
    out_flush();
    hyst_port_exit(failures != 0 ? 1 : 0);
}
