/* SPDX-License-Identifier: MIT */
/* The concurrency contract (tcm.h, "Concurrency") on the host: a POSIX
 * interval timer's signal handler plays the sampling interrupt and steps the
 * instance every few tens of microseconds, preempting the test's main loop,
 * which saves snapshots and posts requests the way firmware's main loop
 * does. Each property holds for every interleaving, so the test's outcome
 * does not depend on when the signals arrive; loops end on counts, never on
 * time. A reference instance, stepped by the main loop alone, tells which
 * state the model was in. */
#define _XOPEN_SOURCE 700 /* sigaction, setitimer */
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <sys/time.h>

#include "snapshot_ref.h"
#include "support.h"
#include "unity.h"

#define CAP 2048u
#define N_INPUTS 400000L
#define GUARD 64u
#define GUARD_BYTE 0xA5u

static hyst_t S;
static hyst_real_t s_xl[CAP], s_yl[CAP], s_xr[CAP], s_yr[CAP];
static hyst_t R;
static hyst_real_t r_xl[CAP], r_yl[CAP], r_xr[CAP], r_yr[CAP];
static hyst_t T;
static hyst_real_t t_xl[CAP], t_yl[CAP], t_xr[CAP], t_yr[CAP];
static hyst_real_t input[N_INPUTS];
static unsigned char snap[HYST_SNAPSHOT_SIZE(CAP) + GUARD];
static unsigned char ref_snap[HYST_SNAPSHOT_SIZE(CAP)];
static snapshot_ref_t ref; /* R, stepped by the main loop alone */

static hyst_creep_t K, KR, KT; /* a creep term: stepped, reference, restored */
static unsigned char creep_snap[HYST_CREEP_SNAPSHOT_SIZE + GUARD];
static unsigned char creep_ref[HYST_CREEP_SNAPSHOT_SIZE];

static hyst_rate_t Q, QR, QT; /* a rate term: stepped, reference, restored */
static unsigned char rate_snap[HYST_RATE_SNAPSHOT_SIZE + GUARD];
static unsigned char rate_ref[HYST_RATE_SNAPSHOT_SIZE];

/* Shared with the handler. */
static volatile sig_atomic_t stepping;
static volatile sig_atomic_t stepping_creep; /* the handler steps K instead of S */
static volatile sig_atomic_t stepping_rate;  /* the handler steps Q instead of S */
static volatile long k_done;   /* samples the handler has stepped */
static volatile long served_k; /* the sample at whose end a request was applied */

/* The "interrupt": one sample, and which sample served a request. */
static void on_tick(int sig)
{
    unsigned before;
    (void)sig;
    if (!stepping || k_done >= N_INPUTS) {
        return;
    }
    if (stepping_creep) {
        (void)hyst_creep_step(&K, input[k_done]);
        k_done = k_done + 1;
        return;
    }
    if (stepping_rate) {
        (void)hyst_rate_step(&Q, input[k_done]);
        k_done = k_done + 1;
        return;
    }
    before = S.done_reset + S.done_clear + S.done_deadband;
    (void)hyst_step(&S, input[k_done]);
    if (S.done_reset + S.done_clear + S.done_deadband != before) {
        served_k = k_done;
    }
    k_done = k_done + 1;
}

static void timer_start(void)
{
    struct sigaction sa;
    struct itimerval it;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_tick;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESTART;
    TEST_ASSERT_EQUAL_INT(0, sigaction(SIGALRM, &sa, NULL));
    it.it_interval.tv_sec = 0;
    it.it_interval.tv_usec = 20;
    it.it_value = it.it_interval;
    TEST_ASSERT_EQUAL_INT(0, setitimer(ITIMER_REAL, &it, NULL));
}

static void timer_stop(void)
{
    struct itimerval it;
    memset(&it, 0, sizeof it);
    (void)setitimer(ITIMER_REAL, &it, NULL);
    stepping = 0;
    stepping_creep = 0;
    stepping_rate = 0;
}

/* Waits (busy: the handler runs meanwhile) until the handler has stepped
 * sample k; fails the test if the inputs run out first. */
static void wait_for_sample(long k)
{
    TEST_ASSERT_TRUE_MESSAGE(k < N_INPUTS, "inputs exhausted");
    while (k_done <= k) {
    }
}

/* Decaying oscillations that restart at full amplitude: hundreds of nested
 * loops (turning points) build up, then one swing wipes them out; every
 * 997th sample is outside the domain (clamped: an event). */
static void fill_inputs(void)
{
    long k;
    for (k = 0; k < N_INPUTS; ++k) {
        const long phase = k % 4000L;
        const double amp = 19.0 * (1.0 - (double)phase / 4000.0);
        const double tri = (double)((k % 8L) < 4L ? k % 4L : 4L - k % 4L) / 4.0 * 2.0 - 1.0;
        input[k] = (hyst_real_t)(20.0 + amp * tri + (double)phase * 1e-4);
        if (k % 997L == 996L) {
            input[k] = (hyst_real_t)41.0;
        }
    }
}

static void init_all(void)
{
    fill_inputs();
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init(&S, &paper_eq20, s_xl, s_yl, s_xr, s_yr, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init(&R, &paper_eq20, r_xl, r_yl, r_xr, r_yr, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init(&T, &paper_eq20, t_xl, t_yl, t_xr, t_yr, CAP));
    snapshot_ref_init(&ref, &R, input, N_INPUTS, ref_snap, sizeof ref_snap);
    k_done = 0;
    served_k = -1;
}

void setUp(void) {}
void tearDown(void) { timer_stop(); }

/* Saves from the main loop into a buffer sized for the state just before:
 * never a write past it, and every snapshot that reports OK is exactly the
 * state after one of the samples stepped during the save. Before the
 * consistency check, saves overran such buffers and torn snapshots passed
 * their CRC. */
static void test_save_while_the_interrupt_steps(void)
{
    long saves = 0, ok = 0, nospace = 0, busy = 0, interrupted = 0;
    init_all();
    stepping = 1;
    timer_start();
    while ((interrupted < 300 || k_done < 12000L) && k_done < N_INPUTS - 10L) {
        const long k0 = k_done;
        const size_t size = hyst_snapshot_size(&S);
        size_t len = 0u, g;
        long k1;
        int st;
        memset(snap, GUARD_BYTE, sizeof snap);
        st = hyst_snapshot_save(&S, snap, size, &len);
        k1 = k_done;
        ++saves;
        interrupted += k1 > k0;
        for (g = size; g < size + GUARD; ++g) {
            TEST_ASSERT_EQUAL_HEX8_MESSAGE(GUARD_BYTE, snap[g], "save wrote past its buffer");
        }
        if (st == HYST_ERR_NOSPACE) {
            ++nospace; /* the state grew between size() and save() */
            continue;
        }
        if (st == HYST_ERR_BUSY) {
            ++busy;
            TEST_ASSERT_NOT_EQUAL_MESSAGE(0x48u, snap[0], "a BUSY buffer still looks like a snapshot");
            continue;
        }
        TEST_ASSERT_EQUAL_INT(HYST_OK, st);
        ++ok;
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_restore(&T, snap, len));
        /* One of the states after samples k0-1 .. k1-1. */
        TEST_ASSERT_TRUE_MESSAGE(snapshot_ref_match(&ref, snap, len, k0, k1),
                                 "a snapshot is no state the model was in");
    }
    timer_stop();
    printf("saves %ld: ok %ld, nospace %ld, busy %ld; interrupted by the handler %ld; "
           "samples %ld\n",
           saves, ok, nospace, busy, interrupted, (long)k_done);
    TEST_ASSERT_TRUE_MESSAGE(interrupted > 0, "no save was ever interrupted: nothing tested");
    TEST_ASSERT_TRUE(ok > 0);
}

/* The same for a creep term's snapshot (snapshot.h, "Creep snapshots"):
 * every snapshot that reports OK restores the lags after one of the
 * samples stepped during the save. */
static void test_creep_save_while_the_interrupt_steps(void)
{
    static const hyst_wide_t tau[3] = {7, 150, 3000};
    static const hyst_wide_t weight[3] = {0.5, -0.25, 0.125};
    long k_ref = 0, saves = 0, ok = 0, busy = 0, interrupted = 0;
    fill_inputs();
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_init(&K, 3u, tau, weight, 20.0));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_init(&KR, 3u, tau, weight, 20.0));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_init(&KT, 3u, tau, weight, 20.0));
    k_done = 0;
    stepping_creep = 1;
    stepping = 1;
    timer_start();
    while (interrupted < 200 && k_done < N_INPUTS - 10L) {
        const long k0 = k_done;
        const size_t size = hyst_creep_snapshot_size(&K);
        size_t len = 0u, g, rlen = 0u;
        long k1, k;
        int st, matched = 0;
        memset(creep_snap, GUARD_BYTE, sizeof creep_snap);
        st = hyst_creep_snapshot_save(&K, creep_snap, size, &len);
        k1 = k_done;
        ++saves;
        interrupted += k1 > k0;
        for (g = size; g < size + GUARD; ++g) {
            TEST_ASSERT_EQUAL_HEX8_MESSAGE(GUARD_BYTE, creep_snap[g], "save wrote past its buffer");
        }
        if (st == HYST_ERR_BUSY) {
            ++busy;
            TEST_ASSERT_NOT_EQUAL_MESSAGE(0x48u, creep_snap[0], "a BUSY buffer still looks like a snapshot");
            continue;
        }
        TEST_ASSERT_EQUAL_INT(HYST_OK, st);
        ++ok;
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_snapshot_restore(&KT, creep_snap, len));
        for (; k_ref < k0; ++k_ref) {
            (void)hyst_creep_step(&KR, input[k_ref]);
        }
        for (k = k0; k <= k1 && !matched; ++k) {
            TEST_ASSERT_EQUAL_INT(HYST_OK,
                                  hyst_creep_snapshot_save(&KR, creep_ref, sizeof creep_ref, &rlen));
            matched = rlen == len && memcmp(creep_ref, creep_snap, len) == 0;
            if (!matched && k < k1) {
                (void)hyst_creep_step(&KR, input[k_ref]);
                ++k_ref;
            }
        }
        TEST_ASSERT_TRUE_MESSAGE(matched, "a creep snapshot is no state the lags were in");
    }
    timer_stop();
    printf("creep saves %ld: ok %ld, busy %ld; interrupted by the handler %ld; samples %ld\n",
           saves, ok, busy, interrupted, (long)k_done);
    TEST_ASSERT_TRUE_MESSAGE(interrupted > 0, "no save was ever interrupted: nothing tested");
    TEST_ASSERT_TRUE(ok > 0);
}

/* The same for a rate term's snapshot (snapshot.h, "Rate snapshots"):
 * every snapshot that reports OK holds p and v after one of the samples
 * stepped during the save. */
static void test_rate_save_while_the_interrupt_steps(void)
{
    long k_ref = 0, saves = 0, ok = 0, busy = 0, interrupted = 0;
    fill_inputs();
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_rate_init(&Q, 3.0, 0.5, 20.0));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_rate_init(&QR, 3.0, 0.5, 20.0));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_rate_init(&QT, 3.0, 0.5, 20.0));
    k_done = 0;
    stepping_rate = 1;
    stepping = 1;
    timer_start();
    while (interrupted < 200 && k_done < N_INPUTS - 10L) {
        const long k0 = k_done;
        const size_t size = hyst_rate_snapshot_size(&Q);
        size_t len = 0u, g, rlen = 0u;
        long k1, k;
        int st, matched = 0;
        memset(rate_snap, GUARD_BYTE, sizeof rate_snap);
        st = hyst_rate_snapshot_save(&Q, rate_snap, size, &len);
        k1 = k_done;
        ++saves;
        interrupted += k1 > k0;
        for (g = size; g < size + GUARD; ++g) {
            TEST_ASSERT_EQUAL_HEX8_MESSAGE(GUARD_BYTE, rate_snap[g], "save wrote past its buffer");
        }
        if (st == HYST_ERR_BUSY) {
            ++busy;
            TEST_ASSERT_NOT_EQUAL_MESSAGE(0x48u, rate_snap[0], "a BUSY buffer still looks like a snapshot");
            continue;
        }
        TEST_ASSERT_EQUAL_INT(HYST_OK, st);
        ++ok;
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_rate_snapshot_restore(&QT, rate_snap, len));
        for (; k_ref < k0; ++k_ref) {
            (void)hyst_rate_step(&QR, input[k_ref]);
        }
        for (k = k0; k <= k1 && !matched; ++k) {
            TEST_ASSERT_EQUAL_INT(HYST_OK,
                                  hyst_rate_snapshot_save(&QR, rate_ref, sizeof rate_ref, &rlen));
            matched = rlen == len && memcmp(rate_ref, rate_snap, len) == 0;
            if (!matched && k < k1) {
                (void)hyst_rate_step(&QR, input[k_ref]);
                ++k_ref;
            }
        }
        TEST_ASSERT_TRUE_MESSAGE(matched, "a rate snapshot is no state the term was in");
    }
    timer_stop();
    printf("rate saves %ld: ok %ld, busy %ld; interrupted by the handler %ld; samples %ld\n",
           saves, ok, busy, interrupted, (long)k_done);
    TEST_ASSERT_TRUE_MESSAGE(interrupted > 0, "no save was ever interrupted: nothing tested");
    TEST_ASSERT_TRUE(ok > 0);
}

enum { REQ_RESET, REQ_DEADBAND, REQ_CLEAR, REQ_KINDS };

/* Requests posted from the main loop at arbitrary moments are applied by the
 * stepping context between two samples, exactly as the immediate calls
 * would be there: the reference applies them after the sample that served
 * them and must then equal the instance bit for bit. Before requests,
 * hyst_reset() from the main loop left states the engine cannot reach. */
static void test_requests_while_the_interrupt_steps(void)
{
    rng_t rng;
    long round;
    long count[REQ_KINDS] = {0, 0, 0};
    init_all();
    rng_seed(&rng, 77u);
    stepping = 1;
    timer_start();
    for (round = 0; round < 240; ++round) {
        const int kind = (int)rng_below(&rng, REQ_KINDS);
        const hyst_real_t width = (hyst_real_t)rng_range(&rng, 0.0, 0.4);
        long served, k_stop;
        size_t len = 0u;
        wait_for_sample(k_done + (long)rng_below(&rng, 40u));
        served_k = -1;
        switch (kind) {
        case REQ_RESET: TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_request_reset(&S)); break;
        case REQ_DEADBAND: TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_request_deadband(&S, width)); break;
        default: TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_request_clear_events(&S)); break;
        }
        while (hyst_request_pending(&S)) {
        }
        served = served_k;
        TEST_ASSERT_TRUE_MESSAGE(served >= 0, "applied, but not by a step");
        ++count[kind];
        /* The reference: the same samples, the immediate call after `served`. */
        snapshot_ref_to(&ref, served + 1);
        switch (kind) {
        case REQ_RESET: hyst_reset(&R); break;
        case REQ_DEADBAND: TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_set_deadband(&R, width)); break;
        default: hyst_clear_events(&R); break;
        }
        /* Stop the interrupt a little later and compare whole states. */
        wait_for_sample(served + 1 + (long)rng_below(&rng, 30u));
        stepping = 0;
        k_stop = k_done;
        snapshot_ref_to(&ref, k_stop);
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_save(&S, snap, sizeof snap, &len));
        TEST_ASSERT_EQUAL_size_t(snapshot_ref_save(&ref), len);
        TEST_ASSERT_EQUAL_MEMORY_MESSAGE(ref_snap, snap, len, "the request was not applied as "
                                                                "the immediate call would be");
        TEST_ASSERT_EQUAL_FLOAT(hyst_error_bound(&R), hyst_error_bound(&S));
        stepping = 1;
    }
    timer_stop();
    printf("requests applied: reset %ld, deadband %ld, clear events %ld; samples %ld\n",
           count[REQ_RESET], count[REQ_DEADBAND], count[REQ_CLEAR], (long)k_done);
}

/* Requests on an idle instance are applied by the next step even when that
 * sample repeats the last input (no curve evaluation), and requests posted
 * twice before a step apply once. */
static void test_requests_applied_by_a_repeated_sample(void)
{
    hyst_real_t y;
    init_all();
    (void)hyst_step(&S, (hyst_real_t)30.0);
    (void)hyst_step(&S, (hyst_real_t)10.0);
    y = hyst_step(&S, (hyst_real_t)20.0);
    TEST_ASSERT_EQUAL_size_t(2u, hyst_tp_count(&S));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_request_reset(&S));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_request_reset(&S));
    TEST_ASSERT_TRUE(hyst_request_pending(&S));
    TEST_ASSERT_EQUAL_size_t(2u, hyst_tp_count(&S)); /* not before a step */
    TEST_ASSERT_EQUAL_FLOAT(y, hyst_step(&S, (hyst_real_t)20.0));
    TEST_ASSERT_FALSE(hyst_request_pending(&S));
    TEST_ASSERT_EQUAL_size_t(0u, hyst_tp_count(&S));
    TEST_ASSERT_EQUAL_FLOAT(hyst_output(&R), hyst_output(&S)); /* at A0, as R */
    TEST_ASSERT_EQUAL_UINT(S.req_reset, S.done_reset);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_request_deadband(&S, (hyst_real_t)-1.0));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_request_reset(NULL));
    TEST_ASSERT_FALSE(hyst_request_pending(NULL));
}

/* A step that evaluates nothing, a sample clamped where the input already
 * is (the drive saturated at hi) or a NaN, applies the requests too: a
 * reset posted while the input sat at hi waited for the input to move. */
static void test_requests_applied_by_a_clamped_or_nan_sample(void)
{
    hyst_real_t y;
    init_all();
    (void)hyst_step(&S, (hyst_real_t)10.0);
    y = hyst_step(&S, (hyst_real_t)50.0); /* Eq. 20: 0..40 V, clamped at 40 */
    TEST_ASSERT_EQUAL_INT(HYST_WARN_CLAMPED, hyst_status(&S));
    (void)hyst_step(&S, (hyst_real_t)5.0);
    (void)hyst_step(&S, (hyst_real_t)45.0); /* back at 40: an RTP, then clamped again */
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_request_reset(&S));
    TEST_ASSERT_EQUAL_FLOAT(y, hyst_step(&S, (hyst_real_t)60.0)); /* clamped at 40 again */
    TEST_ASSERT_FALSE(hyst_request_pending(&S));
    TEST_ASSERT_EQUAL_size_t(0u, hyst_tp_count(&S));
    TEST_ASSERT_EQUAL_FLOAT(hyst_output(&R), hyst_output(&S)); /* at A0, as R */
    (void)hyst_step(&S, (hyst_real_t)25.0);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_request_clear_events(&S));
    y = hyst_step(&S, (hyst_real_t)NAN);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NONFINITE, hyst_status(&S));
    TEST_ASSERT_FALSE(hyst_request_pending(&S));
    TEST_ASSERT_EQUAL_UINT(0u, hyst_events(&S));
    TEST_ASSERT_EQUAL_FLOAT(y, hyst_output(&S)); /* nothing lost */
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_requests_applied_by_a_repeated_sample);
    RUN_TEST(test_requests_applied_by_a_clamped_or_nan_sample);
    RUN_TEST(test_save_while_the_interrupt_steps);
    RUN_TEST(test_creep_save_while_the_interrupt_steps);
    RUN_TEST(test_rate_save_while_the_interrupt_steps);
    RUN_TEST(test_requests_while_the_interrupt_steps);
    return UNITY_END();
}
