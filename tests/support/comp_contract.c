/* SPDX-License-Identifier: MIT */
#include "comp_contract.h"

#include "unity.h"

void contract_drive_is_monotone(hyst_t *h, double lo, double hi, double jump, long samples,
                                rng_t *rng)
{
    hyst_real_t y = (hyst_real_t)(lo + (hi - lo) * rng_range(rng, 0.2, 0.8));
    hyst_real_t prev = hyst_step(h, y);
    long k;
    int up = 1;
    for (k = 0; k < samples; ++k) {
        hyst_real_t x;
        if (rng_below(rng, 50u) == 0u) {
            up = !up;
        }
        y = up ? NEXT(y, (hyst_real_t)hi) : NEXT(y, (hyst_real_t)lo);
        if (rng_below(rng, 100u) == 0u) {
            y = (hyst_real_t)(y + (up ? 1 : -1) * (hi - lo) * jump);
        }
        x = hyst_step(h, y);
        TEST_ASSERT_TRUE(up ? x >= prev : x <= prev);
        prev = x;
    }
}

static void init(const comp_instance_t *c)
{
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(c->h, c->curve, c->xl, c->yl, c->xr, c->yr,
                                                   c->capacity));
}

void contract_block_and_snapshots(const comp_instance_t *a, const comp_instance_t *b,
                                  hyst_t *other, const hyst_real_t *yd, hyst_real_t *drive,
                                  hyst_real_t *drive2, long n, unsigned char *snap, size_t size)
{
    size_t len = 0u;
    long k;
    for (k = 0; k < n; ++k) {
        drive[k] = hyst_step(a->h, yd[k]);
    }
    init(b);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_process(b->h, yd, drive2, (size_t)n));
    TEST_ASSERT_EQUAL_MEMORY(drive, drive2, (size_t)n * sizeof *drive);
    for (k = 100; k < n; k += 97) {
        long j;
        init(a);
        for (j = 0; j < k; ++j) {
            (void)hyst_step(a->h, yd[j]);
        }
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_save(a->h, snap, size, &len));
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_restore(b->h, snap, len));
        for (j = k; j < k + 200 && j < n; ++j) {
            const hyst_real_t x = hyst_step(a->h, yd[j]), x2 = hyst_step(b->h, yd[j]);
            TEST_ASSERT_EQUAL_MEMORY(&x, &x2, sizeof x);
            TEST_ASSERT_EQUAL_MEMORY(&drive[j], &x, sizeof x);
        }
    }
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_save(other, snap, size, &len));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_CURVE, hyst_snapshot_restore(b->h, snap, len));
}
