/* SPDX-License-Identifier: MIT */
/* libFuzzer harness: arbitrary bytes -> a configuration, a capacity and a
 * sample sequence, fed to every public entry point; on valid configurations
 * the core (built with HYST_USE_DOUBLE) is compared with the linear-scan
 * reference of the tests (tests/support/ref_tcm.c), and the snapshot twin
 * B, initialised from the curve sealed (hyst_init_sealed), with A bit for
 * bit. Any mismatch or broken
 * invariant aborts, which libFuzzer reports as a crash.
 *
 * Input layout (every read past the end yields zeros, so every input is valid):
 *   [0]      flags: bit0 raw config (arbitrary doubles) else structured,
 *            bit1 init through hyst_curve_from_poly + hyst_init_curve,
 *            bit2 NULL-pointer probes, bit3 corrupted curve kind probe,
 *            bit4 (structured) the curve moved far from 0: its domain shifted
 *            by 2^(8 + byte % 36) and its coefficients expanded about 0
 *            again (rounded, as a user prints them); accepted only with a
 *            rounding bound that holds: the branch shape at 8 points within
 *            it of the exact value of those coefficients (double-double;
 *            lo + d exact up to 2^43)
 *   [1]      capacity (byte % 48: 0 and 1 are invalid)
 *   [2]      degree (byte % 12: 0, 10, 11 are invalid)
 *   config   raw: lo, hi, coeffs as 8-byte doubles; structured: small grids
 *   then     opcodes: 0xF0..0xFF are control opcodes (the switch in
 *            LLVMFuzzerTestOneInput: reset, snapshot twin, forged restores,
 *            block through hyst_process, requests from another context
 *            applied by the next step, bit-flipped snapshot, accessors);
 *            any other byte is one sample of kind op & 7 (next_sample).
 *
 * Adding an entry point: give it a control opcode in that switch (0xF7..0xFF
 * fall to the default case, the accessors, today) and a seed in
 * fuzz/make_corpus.py that uses it. fuzz/run lists every function declared in
 * include/hyst/ (all headers, by glob) that neither this file nor
 * fuzz_models.c (PI, PWL, inverse, identification) calls. */
#include "hyst/hyst.h"
#include "ref_tcm.h"
#include "support.h"
#include "fuzz_common.h"

#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef HYST_USE_DOUBLE
#error "the differential harness compares a double core with the double reference"
#endif

#define MAX_CAP 48u
#define MAX_SAMPLES 4096u
#define SNAP_MAX HYST_SNAPSHOT_SIZE(MAX_CAP)

typedef struct {
    hyst_t S;
    hyst_real_t xl[MAX_CAP], yl[MAX_CAP], xr[MAX_CAP], yr[MAX_CAP];
} inst_t;

static inst_t A, B, C, keep;
/* The curve A is initialised with through hyst_init_curve (flag bit1): the
 * instance keeps a pointer to it, so it lives as long as A. Not in inst_t,
 * so that "init errors write nothing" compares the instance alone. */
static hyst_curve_t curve_a;
static ref_tcm_t ref;
static unsigned char snap[SNAP_MAX], forged[SNAP_MAX];

/* f0 moved to [lo + off, hi + off]: f(x) = f0(x - off), expanded about 0
 * again in double (Ruffini-Horner shift by -off). */
static void shift_far(hyst_poly_t *f, double off)
{
    unsigned i, j;
    if (f->degree < 1u || f->degree > HYST_MAX_DEGREE) return;
    for (i = 0u; i < f->degree; ++i) {
        for (j = 1u; j <= f->degree - i; ++j) f->coeffs[j] -= off * f->coeffs[j - 1u];
    }
    f->lo += off;
    f->hi += off;
}

/* Nesting, alternation, counts <= capacity, last input on the current branch. */
static void check_invariants(const inst_t *I)
{
    const hyst_t *S = &I->S;
    const size_t nl = S->n_ltp, nr = S->n_rtp;
    size_t i;
    CHECK(nl >= 1u && nl <= S->capacity && nr <= S->capacity);
    CHECK(nr == nl || nr + 1u == nl);
    CHECK(hyst_rising(S) == (nl > nr));
    CHECK(hyst_tp_count(S) == nl - 1u + nr);
    CHECK(I->xl[0] == S->lo.HYST_R && I->yl[0] == S->y_lo.HYST_R);
    for (i = 1; i < nl; ++i) CHECK(I->xl[i] > I->xl[i - 1]);
    for (i = 1; i < nr; ++i) CHECK(I->xr[i] < I->xr[i - 1]);
    if (nr > 0u) {
        CHECK(I->xl[nl - 1u] < I->xr[nr - 1u]);
        CHECK(I->xr[0] <= S->hi.HYST_R);
    }
    CHECK(hyst_input(S) >= S->lo.HYST_R && hyst_input(S) <= S->hi.HYST_R);
    if (nl > nr) {
        CHECK(hyst_input(S) >= I->xl[nl - 1u] && (nr == 0u || hyst_input(S) < I->xr[nr - 1u]));
    } else {
        CHECK(hyst_input(S) > I->xl[nl - 1u] && hyst_input(S) <= I->xr[nr - 1u]);
    }
}

/* Called when hyst_curve_from_poly accepted the domain and coefficients
 * (OK or NOT_INCREASING): the direct call must agree. Not called on other
 * finite input: a curve that overflows once normalised makes the subdivision
 * run to full depth (seconds), see docs/reliability.md. */
static void probe_config(const hyst_poly_t *f, int increasing)
{
    hyst_wide_t c[HYST_MAX_DEGREE + 1];
    hyst_wide_t turn = 0;
    unsigned k;
    int finite = isfinite(f->lo) && isfinite(f->hi) && f->lo < f->hi &&
                 f->degree >= 1u && f->degree <= HYST_MAX_DEGREE;
    for (k = 0; finite && k <= f->degree; ++k) {
        c[k] = f->coeffs[k];
        finite = isfinite(c[k]);
    }
    if (finite) {
        const int inc = hyst_poly_is_increasing(c, f->degree, f->lo, f->hi, &turn);
        CHECK(inc == increasing);
        if (!inc) { /* exactly in [lo, hi] (regress_turn_rounding once rounded past hi) */
            CHECK(turn >= f->lo && turn <= f->hi);
        }
        (void)hyst_poly_eval(f, f->lo);
    }
}

static double next_sample(reader_t *r, const hyst_poly_t *f, unsigned op)
{
    const double span = f->hi - f->lo;
    switch (op & 7u) {
    case 0: return NAN;
    case 1: return (op & 8u) ? INFINITY : -INFINITY;
    case 2: return rd_f64(r);                                  /* anything */
    case 3: return (op & 8u) ? f->hi : f->lo;                  /* the ends */
    case 4: return f->lo + span * ((double)rd_u8(r) / 255.0);  /* 8-bit codes: repeats */
    default:                                                    /* 16-bit, 10% beyond */
        return f->lo - 0.1 * span + 1.2 * span * ((double)rd_u16(r) / 65535.0);
    }
}

/* Restore of forged bytes: on error nothing changes; on success the state
 * must satisfy every invariant. fix = make magic/version/length/CRC right so
 * the state validation itself is exercised. */
static void restore_forged(reader_t *r, int fix)
{
    size_t len = rd_u16(r) % (SNAP_MAX + 1u), i;
    hyst_status_t st;
    memset(forged, 0, sizeof(forged));
    for (i = 0; i < len; ++i) forged[i] = (unsigned char)rd_u8(r);
    if (fix) {
        size_t good = 0, nl, nr;
        unsigned long crc;
        CHECK(hyst_snapshot_save(&A.S, snap, sizeof(snap), &good) == HYST_OK);
        const int keep_id = forged[30] & 1u; /* then: the curve id of the input */
        unsigned char id[4];
        memcpy(id, forged + 12, 4u);
        memcpy(forged, snap, 16u); /* magic, version, R, curve id */
        if (keep_id) memcpy(forged + 12, id, 4u);
        nl = 1u + forged[16] % MAX_CAP;
        nr = nl - (forged[20] & 1u);
        /* L = 40 + (X + R)(1 + n_ltp + n_rtp) + 2R + X (snapshot.h), X = R
         * = sizeof(hyst_real_t) for a real variant */
        len = 40u + 2u * sizeof(hyst_real_t) * (1u + nl + nr) + 3u * sizeof(hyst_real_t);
        if (len > SNAP_MAX) return;
        memset(forged + 16, 0, 4);
        memset(forged + 20, 0, 4);
        forged[16] = (unsigned char)nl;
        forged[20] = (unsigned char)nr;
        forged[8] = (unsigned char)(len & 0xFFu);
        forged[9] = (unsigned char)(len >> 8);
        forged[10] = forged[11] = 0u;
        crc = hyst_crc32(0ul, forged, len - 4u);
        for (i = 0; i < 4u; ++i) forged[len - 4u + i] = (unsigned char)((crc >> (8u * i)) & 0xFFu);
    }
    memcpy(&keep, &C, sizeof(C));
    st = hyst_snapshot_restore(&C.S, forged, len);
    if (st != HYST_OK) {
        CHECK(st < 0);
        CHECK(memcmp(&keep, &C, sizeof(C)) == 0); /* untouched */
    } else { /* accepted: a reachable state, and it keeps running sanely */
        check_invariants(&C);
        (void)hyst_step(&C.S, C.S.lo.HYST_R + 0.5 * (C.S.hi.HYST_R - C.S.lo.HYST_R));
        check_invariants(&C);
        (void)hyst_step(&C.S, C.S.lo.HYST_R);
        check_invariants(&C);
    }
}

static int init_instance(inst_t *I, const hyst_poly_t *f, size_t cap, int via_curve)
{
    if (via_curve) { /* A only: the curve must outlive the instance */
        hyst_status_t st;
        CHECK(I == &A);
        st = hyst_curve_from_poly(&curve_a, f);
        if (st != HYST_OK) return st;
        return hyst_init_curve(&I->S, &curve_a, I->xl, I->yl, I->xr, I->yr, cap);
    }
    return hyst_init(&I->S, f, I->xl, I->yl, I->xr, I->yr, cap);
}

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size)
{
    reader_t r = {data, size, 0};
    hyst_poly_t f;
    const unsigned flags = rd_u8(&r);
    const size_t cap = rd_u8(&r) % MAX_CAP;
    hyst_status_t st;
    int compare, full = 0;
    double range, tol0;
    unsigned n;
    hyst_real_t xs[64], ys[64];
    hyst_curve_t curve; /* A's curve: its own (bit1) or the same polynomial's */

    read_config(&r, (int)(flags & 1u), &f);
    (void)hyst_status_str((int)(signed char)flags);
    if ((flags & 17u) == 16u) {
        shift_far(&f, ldexp(1.0, 8 + (int)(rd_u8(&r) % 36u)));
    }

    memset(&A, 0, sizeof(A));
    memcpy(&keep, &A, sizeof(A));
    st = (hyst_status_t)init_instance(&A, &f, cap, (int)(flags & 2u));
    if (st == HYST_OK || st == HYST_ERR_NOT_INCREASING) {
        probe_config(&f, st == HYST_OK);
    }
    if (st != HYST_OK) {
        CHECK(st < 0);
        CHECK(memcmp(&keep, &A, sizeof(A)) == 0); /* init errors write nothing */
        return 0;
    }
    CHECK(cap >= 2u);
    /* the instance points at the caller's curve; a polynomial init keeps none */
    CHECK(A.S.curve == ((flags & 2u) ? &curve_a : NULL));
    if (A.S.curve != NULL) {
        curve = *A.S.curve;
    } else {
        CHECK(hyst_curve_from_poly(&curve, &f) == HYST_OK); /* init accepted f */
    }
    CHECK(hyst_curve_g(&curve, 0.0) == 0.0); /* documented: exactly 0 */
    if ((flags & 17u) == 16u) { /* the stated bound against the coefficients' exact value */
        const double y0 = poly_eval_exact(f.coeffs, f.degree, f.lo);
        unsigned j;
        for (j = 1u; j <= 8u; ++j) {
            const double d = (f.hi - f.lo) * (double)j / 8.0;
            const double g = poly_eval_exact(f.coeffs, f.degree, f.lo + d) - y0;
            CHECK(fabs(hyst_curve_g(&curve, d) - g) <= 2.0 * curve.rounding.f64);
        }
    }
    check_invariants(&A);
    if (flags & 4u) { /* NULL probes: refused, never dereferenced */
        CHECK(hyst_init(NULL, &f, A.xl, A.yl, A.xr, A.yr, cap) == HYST_ERR_NULL);
        CHECK(hyst_init(&B.S, &f, A.xl, NULL, A.xr, A.yr, cap) == HYST_ERR_NULL);
        CHECK(hyst_process(&A.S, NULL, ys, 1u) == HYST_ERR_NULL);
        CHECK(hyst_process(&A.S, NULL, NULL, 0u) == HYST_OK);
        CHECK(hyst_step(NULL, f.lo) == 0.0); /* per-sample calls: 0 for NULL */
        CHECK(hyst_snapshot_save(&A.S, NULL, 1u, NULL) == HYST_ERR_NULL);
        CHECK(hyst_snapshot_restore(&A.S, NULL, 0u) == HYST_ERR_NULL);
    }
    if (flags & 8u) { /* a curve not made by hyst_curve_*: refused */
        hyst_curve_t bad = curve;
        bad.kind = 0x5A;
        CHECK(hyst_init_curve(&B.S, &bad, B.xl, B.yl, B.xr, B.yr, cap) == HYST_ERR_ARG);
    }
    /* B: snapshot twin of A, from f sealed (hyst_seal_poly: what A's init
     * accepted; the sealed init gives the same instance, bit for bit);
     * C: target of forged snapshots */
    {
        hyst_sealed_poly_t sealed;
        CHECK(hyst_seal_poly(&sealed, &f) == HYST_OK);
        CHECK(hyst_init_sealed(&B.S, &sealed, B.xl, B.yl, B.xr, B.yr, cap) == HYST_OK);
        sealed.a[0] = nextafter(sealed.a[0], INFINITY); /* one unit off, the seal kept: refused */
        CHECK(hyst_init_sealed(&C.S, &sealed, C.xl, C.yl, C.xr, C.yr, cap) == HYST_ERR_CRC);
    }
    CHECK(init_instance(&C, &f, cap, 0) == HYST_OK);

    /* Differential only on structured curves: raw ones may be so badly
     * conditioned that the reference itself is wrong. */
    compare = !(flags & 1u);
    ref_init(&ref, f.coeffs, f.degree, f.lo, f.hi);
    range = fabs(A.S.y_hi.HYST_R - A.S.y_lo.HYST_R);
    tol0 = horner_bound(&f);

    for (n = 0; n < MAX_SAMPLES && r.at < r.n; ++n) {
        const unsigned op = rd_u8(&r);
        if ((op & 0xF0u) == 0xF0u) { /* control opcodes */
            switch (op & 0x0Fu) {
            case 0: /* reset: A, B, reference back at A0 */
                hyst_reset(&A.S);
                hyst_reset(&B.S);
                ref_init(&ref, f.coeffs, f.degree, f.lo, f.hi);
                full = 0;
                CHECK(hyst_tp_count(&A.S) == 0u && hyst_events(&A.S) == 0u);
                break;
            case 1: { /* snapshot A into B, then they must run bit-identically */
                size_t len = 0;
                CHECK(hyst_snapshot_save(&A.S, snap, sizeof(snap), &len) == HYST_OK);
                CHECK(len == hyst_snapshot_size(&A.S) && len <= HYST_SNAPSHOT_SIZE(cap));
                /* format v3: octets per real, then the variant */
                CHECK(snap[4] == HYST_SNAPSHOT_VERSION && snap[6] == sizeof(hyst_real_t) &&
                      snap[7] == HYST_DEFAULT_VARIANT);
                CHECK(hyst_snapshot_restore(&B.S, snap, len) == HYST_OK);
                CHECK(memcmp(B.xl, A.xl, A.S.n_ltp * sizeof(hyst_real_t)) == 0);
                CHECK(hyst_snapshot_save(&A.S, snap, len - 1u, NULL) == HYST_ERR_NOSPACE);
                break;
            }
            case 2: restore_forged(&r, 0); break;
            case 3: restore_forged(&r, 1); break;
            case 4: { /* a block through hyst_process, the reference sample by sample */
                unsigned k, m = rd_u8(&r) % 64u;
                for (k = 0; k < m; ++k) xs[k] = next_sample(&r, &f, rd_u8(&r));
                if (m >= 3u) { /* an output overlapping the input, shifted (two samples
                                * or more: one output one past one input does not
                                * overlap it): refused, nothing written, the
                                * instance unchanged */
                    static hyst_t keep;
                    hyst_real_t x0[64];
                    memcpy(&keep, &A.S, sizeof keep);
                    memcpy(x0, xs, m * sizeof xs[0]);
                    CHECK(hyst_process(&A.S, xs, xs + 1u, m - 1u) == HYST_ERR_OVERLAP);
                    CHECK(memcmp(&keep, &A.S, sizeof keep) == 0 &&
                          memcmp(x0, xs, m * sizeof xs[0]) == 0);
                }
                st = hyst_process(&A.S, xs, ys, m);
                for (k = 0; k < m; ++k) { /* the block call equals per-sample steps */
                    const hyst_real_t yb = hyst_step(&B.S, xs[k]);
                    CHECK(memcmp(&ys[k], &yb, sizeof(yb)) == 0);
                    if (isfinite(xs[k])) (void)ref_step(&ref, xs[k]);
                }
                CHECK(m == 0u || memcmp(&ys[m - 1u], &A.S.y_prev.HYST_R, sizeof(hyst_real_t)) == 0);
                if (st == HYST_WARN_FULL || (hyst_events(&A.S) & HYST_EVENT_FULL)) full = 1;
                break;
            }
            case 5: { /* requests, posted as from a context the stepping one preempts
                       * (byte: bit0 the reset posted twice, bit1 a clear of the
                       * events too), then one sample of kind 4 (in the domain):
                       * that step computes its output, then applies them, once,
                       * as the immediate calls between it and the next sample */
                const unsigned what = rd_u8(&r);
                const double x = next_sample(&r, &f, 4u);
                hyst_real_t y, yb;
                double yr;
                CHECK(hyst_request_pending(&A.S) == 0 && hyst_request_pending(&B.S) == 0);
                CHECK(hyst_request_reset(&A.S) == HYST_OK && hyst_request_reset(&B.S) == HYST_OK);
                if (what & 1u) {
                    CHECK(hyst_request_reset(&A.S) == HYST_OK && hyst_request_reset(&B.S) == HYST_OK);
                }
                if (what & 2u) {
                    CHECK(hyst_request_clear_events(&A.S) == HYST_OK &&
                          hyst_request_clear_events(&B.S) == HYST_OK);
                }
                CHECK(hyst_request_pending(&A.S) == 1 && hyst_request_pending(&B.S) == 1);
                CHECK(hyst_request_reset(NULL) == HYST_ERR_NULL && hyst_request_pending(NULL) == 0);
                y = hyst_step(&A.S, x);
                yb = hyst_step(&B.S, x);
                yr = ref_step(&ref, x);
                CHECK(memcmp(&y, &yb, sizeof(y)) == 0);
                /* the sample on the state before the reset (its status is the
                 * reset's: whether it filled an array, the reference's count
                 * tells) */
                if (compare && !full && (size_t)ref_tp_count(&ref) < hyst_capacity(&A.S)) {
                    CHECK(fabs(y - yr) <= 1e-9 * range + ((double)ref_tp_count(&ref) + 2.0) * tol0);
                }
                /* then the reset: at A0, events cleared */
                CHECK(hyst_request_pending(&A.S) == 0 && hyst_request_pending(&B.S) == 0);
                CHECK(hyst_tp_count(&A.S) == 0u && hyst_events(&A.S) == 0u);
                CHECK(hyst_input(&A.S) == (hyst_real_t)f.lo);
                ref_init(&ref, f.coeffs, f.degree, f.lo, f.hi);
                full = 0;
                break;
            }
            case 6: { /* a real snapshot of A with one bit flipped: always refused */
                size_t len = 0, bit;
                CHECK(hyst_snapshot_save(&A.S, snap, sizeof(snap), &len) == HYST_OK);
                bit = rd_u16(&r) % (8u * len);
                snap[bit / 8u] = (unsigned char)(snap[bit / 8u] ^ (1u << (bit % 8u)));
                memcpy(&keep, &C, sizeof(C));
                CHECK(hyst_snapshot_restore(&C.S, snap, len) < 0);
                CHECK(memcmp(&keep, &C, sizeof(C)) == 0);
                break;
            }
            default: /* clear events, read accessors */
                hyst_clear_events(&A.S);
                hyst_clear_events(&B.S);
                (void)hyst_output(&A.S);
                (void)hyst_input(&A.S);
                (void)hyst_ltp_count(&A.S);
                (void)hyst_rtp_count(&A.S);
                /* the rounding bound of a polynomial curve: what init checked */
                CHECK(hyst_rounding_bound(&A.S) >= 0 &&
                      hyst_rounding_bound(&A.S) <= HYST_MAX_ROUNDING * range * (1 + 1e-12));
                CHECK(hyst_error_bound(&A.S) >= 0 && isfinite(hyst_error_bound(&A.S)));
                break;
            }
        } else { /* one sample to A, B and the reference */
            const double x = next_sample(&r, &f, op);
            const hyst_real_t y = hyst_step(&A.S, x);
            const hyst_real_t yb = hyst_step(&B.S, x);
            CHECK(memcmp(&y, &yb, sizeof(y)) == 0); /* twin: bit-identical */
            if (!isfinite(x)) {
                CHECK(hyst_status(&A.S) == HYST_ERR_NONFINITE);
                CHECK(y == A.S.y_prev.HYST_R);
            } else {
                const double yr = ref_step(&ref, x);
                if (hyst_status(&A.S) == HYST_WARN_FULL) full = 1;
                if (compare && !full) {
                    const double depth = (double)hyst_tp_count(&A.S) + 2.0;
                    CHECK(hyst_tp_count(&A.S) == (size_t)ref_tp_count(&ref));
                    CHECK(fabs(y - yr) <= 1e-9 * range + depth * tol0);
                }
            }
        }
        check_invariants(&A);
        check_invariants(&B);
        CHECK(A.S.n_ltp == B.S.n_ltp && A.S.n_rtp == B.S.n_rtp);
    }
    return 0;
}
