/* SPDX-License-Identifier: MIT */
/* The concurrency contract (tcm.h, "Concurrency") on the Cortex-M under
 * QEMU: the SysTick interrupt steps the instance while main() saves
 * snapshots, as firmware's main loop does. Every snapshot that reports OK
 * must be the state after one of the samples stepped during the save, its
 * last input and last output from the same sample. The interrupt period is
 * swept so that the interrupt lands on every instruction of the save;
 * with -icount shift=0 the run is the same every time. */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "snapshot_ref.h"
#include "support.h"
#include "unity.h"

#define CAP 16u
#define SAMPLES_PER_PERIOD 2500L
#define N_INPUTS 2000L /* the input sequence, repeated */

#define SYST_CSR (*(volatile uint32_t *)0xE000E010u)
#define SYST_RVR (*(volatile uint32_t *)0xE000E014u)
#define SYST_CVR (*(volatile uint32_t *)0xE000E018u)

static hyst_t S, R, T;
static hyst_real_t s_xl[CAP], s_yl[CAP], s_xr[CAP], s_yr[CAP];
static hyst_real_t r_xl[CAP], r_yl[CAP], r_xr[CAP], r_yr[CAP];
static hyst_real_t t_xl[CAP], t_yl[CAP], t_xr[CAP], t_yr[CAP];
static hyst_real_t input[N_INPUTS];
static unsigned char snap[HYST_SNAPSHOT_SIZE(CAP)];
static unsigned char ref_snap[HYST_SNAPSHOT_SIZE(CAP)];

static volatile long k_done; /* samples the interrupt has stepped */
static volatile int stepping;

void SysTick_Handler(void);
void SysTick_Handler(void)
{
    if (stepping && k_done < SAMPLES_PER_PERIOD) {
        (void)hyst_step(&S, input[k_done % N_INPUTS]);
        k_done = k_done + 1;
    }
}

/* Long runs on each branch (mostly fast-path samples, whose last input and
 * output change without the sequence counter), reversals nested a few deep,
 * inputs that are exact binary fractions (an f64 input's low word then
 * repeats from sample to sample: a torn read of it would pass for whole). */
static void fill_inputs(void)
{
    long k;
    for (k = 0; k < N_INPUTS; ++k) {
        const long phase = k % 200L;
        const long tri = phase < 100L ? phase : 200L - phase;
        const long amp = 10L + (k / 200L) % 7L;
        input[k] = (hyst_real_t)(2.0 + (double)(tri * amp) * (1.0 / 32.0));
    }
}

void setUp(void) {}
void tearDown(void)
{
    SYST_CSR = 0u;
    stepping = 0;
}

/* One interrupt period (SysTick reload, processor clock). Returns the
 * saves that the interrupt preempted. */
static long run_period(uint32_t reload, long *ok_total)
{
    snapshot_ref_t ref;
    long interrupted = 0, ok = 0;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init(&S, &paper_eq20, s_xl, s_yl, s_xr, s_yr, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init(&R, &paper_eq20, r_xl, r_yl, r_xr, r_yr, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init(&T, &paper_eq20, t_xl, t_yl, t_xr, t_yr, CAP));
    snapshot_ref_init(&ref, &R, input, N_INPUTS, ref_snap, sizeof ref_snap);
    k_done = 0;
    stepping = 1;
    SYST_RVR = reload;
    SYST_CVR = 0u;
    SYST_CSR = 7u; /* processor clock, interrupt, enabled */
    while (k_done < SAMPLES_PER_PERIOD - 1L) {
        const long k0 = k_done;
        size_t len = 0u;
        long k1;
        int st, matched;
        st = hyst_snapshot_save(&S, snap, sizeof snap, &len);
        k1 = k_done;
        interrupted += k1 > k0;
        if (st == HYST_ERR_BUSY) {
            continue;
        }
        TEST_ASSERT_EQUAL_INT(HYST_OK, st);
        ++ok;
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_restore(&T, snap, len));
        matched = snapshot_ref_match(&ref, snap, len, k0, k1);
        if (!matched) {
            printf("reload %lu: the save during samples %ld..%ld is no state the model was in\n",
                   (unsigned long)reload, k0, k1);
        }
        TEST_ASSERT_TRUE_MESSAGE(matched, "a snapshot is no state the model was in");
    }
    SYST_CSR = 0u;
    stepping = 0;
    *ok_total += ok;
    return interrupted;
}

static void test_save_while_systick_steps(void)
{
    long interrupted = 0, ok = 0;
    uint32_t reload;
    fill_inputs();
    /* periods from a fraction of a save to several saves, in steps that
     * are prime to the save's length: the phase walks through the save */
    for (reload = 997u; reload < 6000u; reload += 331u) {
        interrupted += run_period(reload, &ok);
    }
    printf("saves OK %ld, preempted by the interrupt %ld\n", ok, interrupted);
    TEST_ASSERT_TRUE_MESSAGE(interrupted > 1000, "too few saves preempted: nothing tested");
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_save_while_systick_steps);
    return UNITY_END();
}
