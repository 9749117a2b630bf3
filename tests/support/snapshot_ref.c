/* SPDX-License-Identifier: MIT */
#include "snapshot_ref.h"

#include <string.h>

#include "unity.h"

void snapshot_ref_init(snapshot_ref_t *r, hyst_t *model, const hyst_real_t *input, long inputs,
                       unsigned char *snap, size_t size)
{
    r->model = model;
    r->input = input;
    r->inputs = inputs;
    r->k = 0;
    r->snap = snap;
    r->size = size;
}

void snapshot_ref_to(snapshot_ref_t *r, long k)
{
    for (; r->k < k; ++r->k) {
        (void)hyst_step(r->model, r->input[r->k % r->inputs]);
    }
}

size_t snapshot_ref_save(snapshot_ref_t *r)
{
    size_t len = 0u;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_save(r->model, r->snap, r->size, &len));
    return len;
}

int snapshot_ref_match(snapshot_ref_t *r, const unsigned char *snap, size_t len, long k0, long k1)
{
    long k;
    snapshot_ref_to(r, k0);
    for (k = k0; k <= k1; ++k) {
        if (snapshot_ref_save(r) == len && memcmp(r->snap, snap, len) == 0) {
            return 1;
        }
        if (k < k1) {
            snapshot_ref_to(r, k + 1);
        }
    }
    return 0;
}
