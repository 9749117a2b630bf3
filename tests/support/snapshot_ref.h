/* SPDX-License-Identifier: MIT */
/* Which state a snapshot is (tcm.h, "Concurrency"): a reference instance,
 * stepped on the same inputs by the main loop alone, against a snapshot
 * saved while an interrupt stepped the instance. Shared by the host's
 * signal-driven test and the Cortex-M's SysTick test. */
#ifndef HYST_TEST_SNAPSHOT_REF_H
#define HYST_TEST_SNAPSHOT_REF_H

#include <stddef.h>

#include "hyst/hyst.h"

typedef struct {
    hyst_t *model;            /* initialised as the stepped instance was */
    const hyst_real_t *input; /* the inputs the interrupt steps, repeated */
    long inputs;
    long k;                   /* samples the reference has stepped */
    unsigned char *snap;      /* room for its snapshot */
    size_t size;
} snapshot_ref_t;

void snapshot_ref_init(snapshot_ref_t *r, hyst_t *model, const hyst_real_t *input, long inputs,
                       unsigned char *snap, size_t size);

/* Steps the reference up to sample k (exclusive). */
void snapshot_ref_to(snapshot_ref_t *r, long k);

/* The reference's snapshot into r->snap (asserted OK); its length. */
size_t snapshot_ref_save(snapshot_ref_t *r);

/* 1 if snap (len bytes) is, byte for byte, the state after one of the
 * samples k0 - 1 .. k1 - 1 (those the interrupt stepped while it was
 * saved); the reference is left at the first that matches, else at k1. */
int snapshot_ref_match(snapshot_ref_t *r, const unsigned char *snap, size_t len, long k0, long k1);

#endif
