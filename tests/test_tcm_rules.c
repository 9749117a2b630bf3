/* SPDX-License-Identifier: MIT */
/* Madelung's rules as properties over random inputs, quantised inputs, the
 * paper's experiment shape, the full-array policy and independent instances. */
#include "ref_tcm.h"
#include "support.h"
#include "unity.h"

#include <math.h>

#define TRIALS 300
#define CAP 64

static hyst_real_t xl[CAP], yl[CAP], xr[CAP], yr[CAP];
static hyst_real_t xl2[CAP], yl2[CAP], xr2[CAP], yr2[CAP];
static hyst_t A, B;
static rng_t rng;

void setUp(void) { rng_seed(&rng, 12345u); }
void tearDown(void) {}

static double output_range(const hyst_t *S) { return (double)(S->y_hi.HYST_R - S->y_lo.HYST_R); }

/* Drives S through n random samples (walk with occasional jumps). */
static void random_history(hyst_t *S, rng_t *r, int n)
{
    double x = (double)hyst_input(S);
    int i;
    for (i = 0; i < n; ++i) {
        if (rng_below(r, 8u) == 0u) {
            x = rng_range(r, 0.0, 40.0);
        } else {
            x += rng_range(r, -3.0, 3.0);
        }
        x = x < 0.0 ? 0.0 : (x > 40.0 ? 40.0 : x);
        (void)hyst_step(S, (hyst_real_t)x);
    }
}

/* x of the current TP (where the present branch starts). */
static hyst_real_t ctp_x(const hyst_t *S)
{
    return hyst_rising(S) ? S->xltp.HYST_R[S->n_ltp - 1u] : S->xrtp.HYST_R[S->n_rtp - 1u];
}

/* Rule 2 and 3: any excursion inside the current branch's range returns to
 * the same output bit for bit, and the trajectory afterwards is that of a
 * twin that never made the excursion. */
static void test_minor_loops_close_and_old_branch_resumes(void)
{
    int trial, checked = 0;
    for (trial = 0; trial < TRIALS; ++trial) {
        hyst_real_t xa, ya, xc;
        double inner_lo, inner_hi;
        size_t count;
        int i, n;
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init(&A, &paper_eq20, xl, yl, xr, yr, CAP));
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init(&B, &paper_eq20, xl2, yl2, xr2, yr2, CAP));
        n = (int)rng_below(&rng, 60u);
        {
            rng_t r2 = rng;
            random_history(&A, &rng, n);
            random_history(&B, &r2, n);
        }
        xa = hyst_input(&A);
        ya = hyst_output(&A);
        xc = ctp_x(&A);
        count = hyst_tp_count(&A);
        inner_lo = (double)(xa < xc ? xa : xc);
        inner_hi = (double)(xa < xc ? xc : xa);
        if (inner_hi - inner_lo < 0.05) {
            continue;
        }
        /* excursion strictly between the CTP and xa, then back to xa */
        for (i = 0; i < 1 + (int)rng_below(&rng, 20u); ++i) {
            const double span = inner_hi - inner_lo;
            (void)hyst_step(&A, (hyst_real_t)rng_range(&rng, inner_lo + 0.01 * span,
                                                       inner_hi - 0.01 * span));
        }
        TEST_ASSERT_EQUAL_MEMORY(&ya, (hyst_real_t[]){hyst_step(&A, xa)}, sizeof ya);
        TEST_ASSERT_EQUAL_UINT((unsigned)count, (unsigned)hyst_tp_count(&A));
        /* the same continuation on both: identical, sample by sample */
        for (i = 0; i < 40; ++i) {
            const hyst_real_t x = (hyst_real_t)rng_range(&rng, 0.0, 40.0);
            const hyst_real_t ya2 = hyst_step(&A, x);
            const hyst_real_t yb2 = hyst_step(&B, x);
            TEST_ASSERT_EQUAL_MEMORY(&yb2, &ya2, sizeof ya2);
            TEST_ASSERT_EQUAL_UINT((unsigned)hyst_tp_count(&B), (unsigned)hyst_tp_count(&A));
        }
        ++checked;
    }
    TEST_ASSERT_TRUE(checked > TRIALS / 2);
}

/* Rule 4: an ascending and a descending branch between the same two TPs are
 * point reflections of each other about the loop's centre. */
static void test_loops_are_point_symmetric(void)
{
    int trial, checked = 0;
    for (trial = 0; trial < TRIALS; ++trial) {
        hyst_real_t xa, xb, ya, yb, limit;
        double tol;
        hyst_real_t up[9];
        int k;
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init(&A, &paper_eq20, xl, yl, xr, yr, CAP));
        random_history(&A, &rng, 1 + (int)rng_below(&rng, 60u));
        if (hyst_rising(&A)) { /* make xa an LTP: step down a little first */
            (void)hyst_step(&A, (hyst_real_t)((double)hyst_input(&A) * 0.9));
        }
        xa = hyst_input(&A);
        ya = hyst_output(&A);
        limit = A.n_rtp > 0u ? A.xrtp.HYST_R[A.n_rtp - 1u] : HYST_REAL_C(40.0);
        if ((double)(limit - xa) < 0.05) {
            continue;
        }
        xb = (hyst_real_t)rng_range(&rng, (double)xa, (double)limit);
        if (!(xb > xa && xb < limit)) {
            continue;
        }
        for (k = 1; k <= 9; ++k) {
            up[k - 1] = hyst_step(&A, (hyst_real_t)((double)xa + ((double)xb - (double)xa) * k / 10.0));
        }
        yb = hyst_step(&A, xb);
        tol = TOL_OF_RANGE * output_range(&A);
        for (k = 1; k <= 9; ++k) { /* descending at the reflected input */
            const hyst_real_t down =
                hyst_step(&A, (hyst_real_t)((double)xb - ((double)xb - (double)xa) * k / 10.0));
            TEST_ASSERT_DOUBLE_WITHIN(tol, (double)ya + (double)yb,
                                      (double)up[k - 1] + (double)down);
        }
        ++checked;
    }
    TEST_ASSERT_TRUE(checked > TRIALS / 2);
}

/* The major loop is the reflection of f0 about the centre of [lo, hi]. */
static void test_major_falling_branch_is_reflected_f0(void)
{
    const double tol = TOL_OF_RANGE * 5.0;
    int k;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init(&A, &paper_eq20, xl, yl, xr, yr, CAP));
    (void)hyst_step(&A, HYST_REAL_C(40.0));
    for (k = 39; k >= 0; --k) {
        const double x = (double)k;
        const double y = (double)hyst_step(&A, (hyst_real_t)x);
        const double f0lo = (double)hyst_poly_eval(&paper_eq20, 0);
        const double f0hi = (double)hyst_poly_eval(&paper_eq20, 40);
        TEST_ASSERT_DOUBLE_WITHIN(tol, f0hi + f0lo - (double)hyst_poly_eval(&paper_eq20, (hyst_real_t)(40.0 - x)), y);
    }
}

/* Rule 1: the branch leaving a TP depends on its coordinates alone. */
static void test_branch_depends_only_on_its_turning_point(void)
{
    int trial, checked = 0;
    for (trial = 0; trial < TRIALS; ++trial) {
        const hyst_real_t xk = (hyst_real_t)rng_range(&rng, 10.0, 30.0);
        hyst_real_t ya0, yb0, reach;
        double tol;
        int i;
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init(&A, &paper_eq20, xl, yl, xr, yr, CAP));
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init(&B, &paper_eq20, xl2, yl2, xr2, yr2, CAP));
        random_history(&A, &rng, (int)rng_below(&rng, 40u));
        random_history(&B, &rng, (int)rng_below(&rng, 40u));
        /* both arrive at xk from above, then rise: xk becomes an LTP in both */
        (void)hyst_step(&A, HYST_REAL_C(39.0) < xk + 5 ? HYST_REAL_C(39.0) : xk + 5);
        (void)hyst_step(&B, HYST_REAL_C(39.0) < xk + 5 ? HYST_REAL_C(39.0) : xk + 5);
        ya0 = hyst_step(&A, xk);
        yb0 = hyst_step(&B, xk);
        reach = A.xrtp.HYST_R[A.n_rtp - 1u] < B.xrtp.HYST_R[B.n_rtp - 1u] ? A.xrtp.HYST_R[A.n_rtp - 1u] : B.xrtp.HYST_R[B.n_rtp - 1u];
        tol = TOL_OF_RANGE * output_range(&A);
        for (i = 1; i < 10; ++i) {
            const hyst_real_t x = (hyst_real_t)((double)xk + ((double)reach - (double)xk) * i / 10.0);
            const double da = (double)hyst_step(&A, x) - (double)ya0;
            const double db = (double)hyst_step(&B, x) - (double)yb0;
            TEST_ASSERT_DOUBLE_WITHIN(tol, da, db);
        }
        checked += (ya0 != yb0);
    }
    TEST_ASSERT_TRUE(checked > TRIALS / 2); /* histories really differed */
}

static void test_repeated_samples_create_no_turning_point(void)
{
    hyst_real_t y1, y2;
    int i;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init(&A, &paper_eq20, xl, yl, xr, yr, CAP));
    (void)hyst_step(&A, HYST_REAL_C(10.0));
    y1 = hyst_step(&A, HYST_REAL_C(20.0));
    for (i = 0; i < 100; ++i) {
        y2 = hyst_step(&A, HYST_REAL_C(20.0));
        TEST_ASSERT_EQUAL_MEMORY(&y1, &y2, sizeof y1);
    }
    TEST_ASSERT_EQUAL_UINT(0u, (unsigned)hyst_tp_count(&A));
    (void)hyst_step(&A, HYST_REAL_C(25.0)); /* still rising: no TP */
    TEST_ASSERT_EQUAL_UINT(0u, (unsigned)hyst_tp_count(&A));
    (void)hyst_step(&A, HYST_REAL_C(25.0));
    (void)hyst_step(&A, HYST_REAL_C(22.0)); /* reversal: one RTP at 25 */
    TEST_ASSERT_EQUAL_UINT(1u, (unsigned)hyst_rtp_count(&A));
    TEST_ASSERT_EQUAL_FLOAT(25.0f, (float)A.xrtp.HYST_R[0]);
}

/* 12-bit DAC codes: Nu = 4096, arrays of Nu/2. Guard words around each array
 * catch any write out of bounds. */
#define NU 4096u
#define QCAP HYST_CAPACITY(NU)
#define GUARD 4
static hyst_real_t qbuf[4][QCAP + 2 * GUARD];
static const hyst_real_t canary = HYST_REAL_C(-12345.0);

static void arm_guards(void)
{
    int a, g;
    for (a = 0; a < 4; ++a) {
        for (g = 0; g < GUARD; ++g) {
            qbuf[a][g] = canary;
            qbuf[a][QCAP + GUARD + (unsigned)g] = canary;
        }
    }
}

static void check_guards(void)
{
    int a, g;
    for (a = 0; a < 4; ++a) {
        for (g = 0; g < GUARD; ++g) {
            TEST_ASSERT_EQUAL_FLOAT((float)canary, (float)qbuf[a][g]);
            TEST_ASSERT_EQUAL_FLOAT((float)canary, (float)qbuf[a][QCAP + GUARD + (unsigned)g]);
        }
    }
}

static hyst_status_t init_quantised(hyst_t *S, size_t cap)
{
    arm_guards();
    return hyst_init(S, &paper_eq20, qbuf[0] + GUARD, qbuf[1] + GUARD, qbuf[2] + GUARD,
                     qbuf[3] + GUARD, cap);
}

static hyst_real_t code_to_volts(long code) { return (hyst_real_t)(40.0 * (double)code / (double)(NU - 1u)); }

static void test_adversarial_codes_fill_but_never_overflow(void)
{
    long k;
    size_t max_l = 0, max_r = 0;
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_quantised(&A, QCAP));
    /* 4095, 1, 4094, 2, ...: every reversal nests inside the previous one */
    for (k = 1; k <= (long)NU / 2; ++k) {
        (void)hyst_step(&A, code_to_volts((long)NU - k));
        (void)hyst_step(&A, code_to_volts(k));
        max_l = hyst_ltp_count(&A) > max_l ? hyst_ltp_count(&A) : max_l;
        max_r = hyst_rtp_count(&A) > max_r ? hyst_rtp_count(&A) : max_r;
        TEST_ASSERT_TRUE(A.n_ltp <= QCAP && A.n_rtp <= QCAP);
    }
    TEST_ASSERT_EQUAL_UINT(0u, hyst_events(&A) & HYST_EVENT_FULL);
    TEST_ASSERT_EQUAL_UINT(QCAP - 1u, (unsigned)max_l); /* plus A0: all QCAP entries */
    TEST_ASSERT_EQUAL_UINT(QCAP - 1u, (unsigned)max_r);
    check_guards();
}

static void test_random_codes_never_overflow(void)
{
    long i;
    long code = 2048;
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_quantised(&A, QCAP));
    for (i = 0; i < 200000; ++i) {
        if (rng_below(&rng, 16u) == 0u) {
            code = (long)rng_below(&rng, NU);
        } else {
            code += (long)rng_below(&rng, 41u) - 20;
            code = code < 0 ? 0 : (code >= (long)NU ? (long)NU - 1 : code);
        }
        (void)hyst_step(&A, code_to_volts(code));
        TEST_ASSERT_TRUE(A.n_ltp <= QCAP && A.n_rtp <= QCAP);
    }
    TEST_ASSERT_EQUAL_UINT(0u, hyst_events(&A));
    check_guards();
}

/* Largest slope of Eq. 20 on [0, 40]. */
static double paper_max_slope(void)
{
    const double *c = paper_eq20_coeffs;
    double best = 0.0;
    int k;
    for (k = 0; k <= 400; ++k) {
        const double x = 0.1 * k;
        const double s = 3.0 * c[0] * x * x + 2.0 * c[1] * x + c[2];
        best = s > best ? s : best;
    }
    return best;
}

/* Full array: the innermost loop (L1, R1) and the new TP P merge into one LTP
 * V whose branch starts exactly through P (continuous at the overflow
 * sample) and lies on the outer branch (continuous at every later wipe-out);
 * the outer TPs are kept bit for bit; every sample stays within
 * hyst_error_bound() of the unbounded model; nothing is written out of
 * bounds; reaching hi makes the model exact again. */
static void test_full_array_forgets_innermost_loop(void)
{
    static ref_tcm_t ref;
    const size_t cap = 4u;
    const double tol = TOL_OF_RANGE * 5.0;
    const double lmax = paper_max_slope();
    int i, fulls = 0;
    double lo = 0.0, hi = 40.0, y_ref;
    hyst_real_t y, x_prev = HYST_REAL_C(0.0), y_prev;
    hyst_curve_t eq20; /* the instance's curve, for g */
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_quantised(&A, cap));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_poly(&eq20, &paper_eq20));
    ref_init(&ref, paper_eq20_coeffs, 3u, 0.0, 40.0);
    y_prev = hyst_output(&A);
    for (i = 0; i < 40; ++i) { /* ever narrower nested loops */
        const double x = (i % 2 == 0) ? hi : lo;
        const hyst_real_t xr_ = (hyst_real_t)x;
        hyst_real_t outer_x[2 * CAP];
        size_t k, nl_before = A.n_ltp, nr_before = A.n_rtp;
        const hyst_real_t l1_before = A.xltp.HYST_R[A.n_ltp - 1u];
        for (k = 0; k + 1u < cap; ++k) {
            outer_x[k] = A.xltp.HYST_R[k];
            outer_x[cap + k] = A.xrtp.HYST_R[k];
        }
        y_ref = ref_step(&ref, (double)xr_);
        y = hyst_step(&A, xr_);
        TEST_ASSERT_TRUE(A.n_ltp <= cap && A.n_rtp <= cap);
        TEST_ASSERT_TRUE(fabs((double)y - y_ref) <= (double)hyst_error_bound(&A) + tol);
        TEST_ASSERT_TRUE(fabs((double)y - (double)y_prev) <= lmax * fabs(x - (double)x_prev) + tol);
        if (hyst_status(&A) == HYST_WARN_FULL) {
            const hyst_real_t xv = A.xltp.HYST_R[cap - 1u], yv = A.yltp.HYST_R[cap - 1u];
            ++fulls;
            TEST_ASSERT_EQUAL_UINT(cap, (unsigned)nl_before);
            TEST_ASSERT_EQUAL_UINT(cap, (unsigned)A.n_ltp);
            TEST_ASSERT_EQUAL_UINT(nr_before - 1u, (unsigned)A.n_rtp); /* R1 gone */
            for (k = 0; k + 1u < cap; ++k) { /* outer TPs untouched */
                TEST_ASSERT_EQUAL_MEMORY(&outer_x[k], &A.xltp.HYST_R[k], sizeof xv);
                TEST_ASSERT_EQUAL_MEMORY(&outer_x[cap + k], &A.xrtp.HYST_R[k], sizeof xv);
            }
            TEST_ASSERT_TRUE(xv >= l1_before && xv <= x_prev); /* V between L1 and P */
            /* V's branch passes through P: no step at this sample */
            TEST_ASSERT_DOUBLE_WITHIN(tol, (double)y_prev,
                                      (double)(yv + hyst_curve_g(&eq20, x_prev - xv)));
            /* V lies on the falling branch of R2, now the RTP below it */
            TEST_ASSERT_DOUBLE_WITHIN(tol, (double)A.yrtp.HYST_R[A.n_rtp - 1u] -
                                               (double)hyst_curve_g(&eq20, A.xrtp.HYST_R[A.n_rtp - 1u] - xv),
                                      (double)yv);
            TEST_ASSERT_TRUE(hyst_error_bound(&A) > 0);
        }
        x_prev = xr_;
        y_prev = y;
        if (i % 2 == 0) {
            hi -= 1.0;
        } else {
            lo += 1.0;
        }
        if (i == 0) {
            lo = 1.0;
        }
    }
    TEST_ASSERT_TRUE(fulls > 10);
    TEST_ASSERT_EQUAL_UINT(HYST_EVENT_FULL, hyst_events(&A) & HYST_EVENT_FULL);
    check_guards();
    /* the trajectory still closes loops and saturates normally, exactly */
    y = hyst_step(&A, HYST_REAL_C(40.0));
    y_ref = ref_step(&ref, 40.0);
    TEST_ASSERT_EQUAL_UINT(0u, (unsigned)hyst_tp_count(&A));
    TEST_ASSERT_DOUBLE_WITHIN(tol, y_ref, (double)y);
    TEST_ASSERT_EQUAL_FLOAT(0.0f, (float)hyst_error_bound(&A));
}

/* Paper experiment shape (Fig. 14): shrinking then growing triangle on Eq. 20. */
static void test_paper_signal_turning_point_count(void)
{
    static hyst_real_t x[8192];
    double levels[32];
    const int n_levels = paper_levels(0.0, 40.0, levels);
    const long n = ramp_path(0.0, levels, n_levels, 0.1, x, 8192);
    size_t prev = 0u, peak = 0u, peak_l = 0u, peak_r = 0u;
    long i;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init(&A, &paper_eq20, xl, yl, xr, yr, CAP));
    for (i = 0; i < n; ++i) {
        size_t now;
        (void)hyst_step(&A, x[i]);
        now = hyst_tp_count(&A);
        /* rises one at a time, falls in pairs; reaching lo or hi forgets all */
        TEST_ASSERT_TRUE(now == prev || now == prev + 1u || now == 0u ||
                         (now < prev && (prev - now) % 2u == 0u));
        if (now > peak) {
            peak = now;
            peak_l = hyst_ltp_count(&A);
            peak_r = hyst_rtp_count(&A);
        }
        prev = now;
    }
    TEST_ASSERT_EQUAL_UINT(14u, (unsigned)peak);
    TEST_ASSERT_EQUAL_UINT(7u, (unsigned)peak_l);
    TEST_ASSERT_EQUAL_UINT(7u, (unsigned)peak_r);
    TEST_ASSERT_EQUAL_UINT(0u, (unsigned)hyst_tp_count(&A)); /* back at lo: memory gone */
}

/* Two axes side by side equal each axis alone. */
static void test_instances_are_independent(void)
{
    const hyst_poly_t other = {2u, HYST_REAL_C(-5.0), HYST_REAL_C(5.0),
                               {HYST_REAL_C(0.1), HYST_REAL_C(2.0), HYST_REAL_C(1.0)}};
    static hyst_real_t xs[500], ya[500], yb[500];
    int i;
    for (i = 0; i < 500; ++i) {
        xs[i] = (hyst_real_t)rng_range(&rng, -6.0, 42.0);
    }
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init(&A, &paper_eq20, xl, yl, xr, yr, CAP));
    (void)hyst_process(&A, xs, ya, 500u);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init(&B, &other, xl2, yl2, xr2, yr2, CAP));
    (void)hyst_process(&B, xs, yb, 500u);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init(&A, &paper_eq20, xl, yl, xr, yr, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init(&B, &other, xl2, yl2, xr2, yr2, CAP));
    for (i = 0; i < 500; ++i) { /* interleaved */
        const hyst_real_t a = hyst_step(&A, xs[i]);
        const hyst_real_t b = hyst_step(&B, xs[i]);
        TEST_ASSERT_EQUAL_MEMORY(&ya[i], &a, sizeof a);
        TEST_ASSERT_EQUAL_MEMORY(&yb[i], &b, sizeof b);
    }
}

/* Status of a block as hyst_process() documents it, from per-sample ones. */
static int fold_status(const int *st, size_t n)
{
    int worst = HYST_OK, failed = 0;
    size_t i;
    for (i = 0u; i < n; ++i) {
        failed |= st[i] < 0;
        worst = st[i] > worst ? st[i] : worst;
    }
    return failed ? HYST_ERR_NONFINITE : worst;
}

/* Smooth runs, reversals, jumps, repeats, NaN, out-of-domain samples and
 * shrinking zigzags (nested loops: they fill small arrays). */
typedef struct {
    double x, dx, centre, amp;
    int zig;
} mix_t;

static hyst_real_t mixed_sample(mix_t *m)
{
    uint32_t r;
    if (m->zig > 0) {
        m->x = m->centre + ((m->zig & 1) ? m->amp : -m->amp);
        m->amp *= 0.85;
        --m->zig;
        return (hyst_real_t)m->x;
    }
    r = rng_below(&rng, 64u);
    if (r == 0u) {
        return (hyst_real_t)NAN;
    }
    if (r == 1u) {
        return (hyst_real_t)rng_range(&rng, -10.0, 50.0); /* often clamped */
    }
    if (r == 13u) {
        m->centre = rng_range(&rng, 10.0, 30.0);
        m->amp = rng_range(&rng, 2.0, 10.0);
        m->zig = 30;
    }
    if (r < 4u) {
        m->x = rng_range(&rng, 0.0, 40.0);
    } else if (r < 10u) {
        m->dx = -m->dx; /* reversal */
    } else if (r < 12u) {
        m->dx = rng_range(&rng, -0.5, 0.5);
    }
    if (r != 12u) { /* 12: a repeated sample */
        m->x += m->dx;
    }
    m->x = m->x < 0.0 ? 0.0 : (m->x > 40.0 ? 40.0 : m->x);
    return (hyst_real_t)m->x;
}

/* hyst_process() runs samples on one branch through its own loop: it must
 * equal hyst_step() per sample bit for bit, state and statuses included,
 * for every chunking, in place or not, with merges (capacity 8), with the
 * deadband, and with a curve evaluated out of line (no fast path). */
static void test_block_call_equals_per_sample_steps(void)
{
    static const hyst_real_t px[4] = {HYST_REAL_C(0.0), HYST_REAL_C(10.0), HYST_REAL_C(25.0), HYST_REAL_C(40.0)};
    static const hyst_real_t py[4] = {HYST_REAL_C(0.0), HYST_REAL_C(1.0), HYST_REAL_C(3.5), HYST_REAL_C(6.0)};
    enum { N = 20000, SMALL_CAP = 8 };
    static hyst_real_t xs[N], ya[N], yb[N];
    static int st[N];
    int config;
    for (config = 0; config < 3; ++config) {
        hyst_curve_t pwl;
        mix_t mix = {20.0, 0.05, 0.0, 0.0, 0};
        size_t i = 0u, blocks = 0u, inplace = 0u;
        if (config == 2) {
            TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_pwl(&pwl, px, py, 4u));
            TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&A, &pwl, xl, yl, xr, yr, SMALL_CAP));
            TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&B, &pwl, xl2, yl2, xr2, yr2, SMALL_CAP));
        } else {
            TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init(&A, &paper_eq20, xl, yl, xr, yr, SMALL_CAP));
            TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init(&B, &paper_eq20, xl2, yl2, xr2, yr2, SMALL_CAP));
        }
        if (config == 1) {
            TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_set_deadband(&A, HYST_REAL_C(0.3)));
            TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_set_deadband(&B, HYST_REAL_C(0.3)));
        }
        for (i = 0u; i < (size_t)N; ++i) {
            xs[i] = mixed_sample(&mix);
            ya[i] = hyst_step(&A, xs[i]);
            st[i] = hyst_status(&A);
        }
        for (i = 0u; i < (size_t)N; blocks++) {
            size_t n = 1u + (size_t)rng_below(&rng, 300u), k;
            int got;
            n = i + n > (size_t)N ? (size_t)N - i : n;
            if (rng_below(&rng, 2u) == 0u) { /* in place: y is x */
                for (k = 0u; k < n; ++k) {
                    yb[i + k] = xs[i + k];
                }
                got = hyst_process(&B, &yb[i], &yb[i], n);
                ++inplace;
            } else {
                got = hyst_process(&B, &xs[i], &yb[i], n);
            }
            TEST_ASSERT_EQUAL_INT(fold_status(&st[i], n), got);
            TEST_ASSERT_EQUAL_INT(st[i + n - 1u], hyst_status(&B));
            i += n;
        }
        TEST_ASSERT_EQUAL_MEMORY(ya, yb, sizeof ya);
        TEST_ASSERT_EQUAL_UINT(hyst_events(&A), hyst_events(&B));
        TEST_ASSERT_EQUAL_UINT((unsigned)A.n_ltp, (unsigned)B.n_ltp);
        TEST_ASSERT_EQUAL_UINT((unsigned)A.n_rtp, (unsigned)B.n_rtp);
        TEST_ASSERT_EQUAL_MEMORY(xl, xl2, A.n_ltp * sizeof xl[0]);
        TEST_ASSERT_EQUAL_MEMORY(yl, yl2, A.n_ltp * sizeof yl[0]);
        if (A.n_rtp > 0u) {
            TEST_ASSERT_EQUAL_MEMORY(xr, xr2, A.n_rtp * sizeof xr[0]);
            TEST_ASSERT_EQUAL_MEMORY(yr, yr2, A.n_rtp * sizeof yr[0]);
        }
        {
            const hyst_real_t oa = hyst_output(&A), ob = hyst_output(&B);
            const hyst_real_t ia = hyst_input(&A), ib = hyst_input(&B);
            const hyst_real_t ea = hyst_error_bound(&A), eb = hyst_error_bound(&B);
            TEST_ASSERT_EQUAL_MEMORY(&oa, &ob, sizeof oa);
            TEST_ASSERT_EQUAL_MEMORY(&ia, &ib, sizeof ia);
            TEST_ASSERT_EQUAL_MEMORY(&ea, &eb, sizeof ea);
        }
        TEST_PRINTF("config %d: %u blocks (%u in place), events %u", config, (unsigned)blocks,
                    (unsigned)inplace, hyst_events(&A));
        /* the mix must reach every status: NaN, clamping, and the full array */
        TEST_ASSERT_EQUAL_UINT(HYST_EVENT_NONFINITE | HYST_EVENT_CLAMPED | HYST_EVENT_FULL,
                               hyst_events(&A) & (HYST_EVENT_NONFINITE | HYST_EVENT_CLAMPED | HYST_EVENT_FULL));
    }
}

static void test_define_macro_declares_a_working_instance(void)
{
    HYST_DEFINE(axis, 64);
    TEST_ASSERT_EQUAL_UINT(32u, (unsigned)(sizeof axis_xltp / sizeof axis_xltp[0]));
    TEST_ASSERT_EQUAL_INT(HYST_OK, HYST_INIT(axis, &paper_eq20));
    TEST_ASSERT_EQUAL_UINT(32u, (unsigned)axis.capacity);
    (void)hyst_step(&axis, HYST_REAL_C(30.0));
    (void)hyst_step(&axis, HYST_REAL_C(20.0));
    TEST_ASSERT_EQUAL_UINT(1u, (unsigned)hyst_tp_count(&axis));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_minor_loops_close_and_old_branch_resumes);
    RUN_TEST(test_loops_are_point_symmetric);
    RUN_TEST(test_major_falling_branch_is_reflected_f0);
    RUN_TEST(test_branch_depends_only_on_its_turning_point);
    RUN_TEST(test_repeated_samples_create_no_turning_point);
    RUN_TEST(test_adversarial_codes_fill_but_never_overflow);
    RUN_TEST(test_random_codes_never_overflow);
    RUN_TEST(test_full_array_forgets_innermost_loop);
    RUN_TEST(test_paper_signal_turning_point_count);
    RUN_TEST(test_instances_are_independent);
    RUN_TEST(test_block_call_equals_per_sample_steps);
    RUN_TEST(test_define_macro_declares_a_working_instance);
    return UNITY_END();
}
