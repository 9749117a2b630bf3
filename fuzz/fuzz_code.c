/* SPDX-License-Identifier: MIT */
/* libFuzzer harness for the integer-code variant (hyst/code.h) and the
 * bounded-memory features (capacity overflow merges, hyst_error_bound,
 * the deadband) of both engines. Arbitrary bytes -> a curve, a code range, a
 * capacity, a deadband and a code sequence, fed to:
 *   C  code instance (deadband set), gets the blocks (hyst_code_process)
 *      and restores of T's snapshots
 *   T  its twin, sample by sample: C and T must stay bit-identical
 *   Z  code instance never given a deadband: bit-identical to C when the
 *      deadband is 0 (explicitly set)
 *   F  the real engine on the codes converted to volts (deadband in volts)
 *   F0 real engine never given a deadband: bit-identical to F at deadband 0
 *   ref  tests/support/ref_tcm.c, double, unlimited memory, on the volts.
 * Checked at every sample (docs/memory.md):
 *   - counts <= capacity, clamping reported, last input = clamped code;
 *   - while nothing was forgotten (never full, deadband 0): the TP count of C
 *     and F equals the reference's and the outputs agree within TOL (below),
 *     and hyst_*error_bound() is exactly 0;
 *   - on curves with f0'' of one sign (the proven case: degree <= 3, checked
 *     exactly), always: |y - y_ref| <= bound + TOL, no jump
 *     (|dy| <= max f0' |dx| + resid + TOL), and each increase of the bound
 *     within its a-priori bound (merge: max|f0''| w^2/4 and g(w); deadband:
 *     max|f0''| deadband^2/4), resid = the code rounding of a merged TP;
 *   - on every other curve the reference accepts (f0'' of any sign, any
 *     degree), while no merge happened since the last reset:
 *     |y - y_ref| <= bound + TOL (the deadband's bound alone).
 * TOL: 1e-9 of the output range plus Horner's rounding bound (fuzz_common.h)
 * times the depth of TPs an output hangs on: the double core, the double
 * reference and the code-to-volt conversion (one rounding of x, times
 * max f0') are all far below it; it is 1e-9 of what the bounds measure.
 * The code variant's outputs are float in every build (types.h): where one
 * is compared (with the reference or with F), TOL grows by
 * the same depth times float_bound() (Horner's bound in float on the
 * normalised curve the code engine evaluates, below); the continuity check
 * also allows the previous output's own float allowance.
 *
 * Input layout (reads past the end yield zeros):
 *   [0] flags: bit0 raw config, bit1 init through hyst_code_init_curve (f32 curve;
 *       with an odd capacity hyst_code_init_kind, its kind named),
 *       bit2 NULL probes, bit3 corrupted curve kind, bit4 raw code range
 *       (24-bit numbers: DOMAIN errors), bit5 deadband on, bit6 invalid
 *       deadband probes, bit7 with [1] >= 240: capacity 4100 (deep stacks)
 *   [1] capacity (byte % 20: 0 and 1 invalid, 2..19 the bounded use)
 *   config (fuzz_common.h), code range, deadband, then opcodes:
 *   0xF0 reset all, 0xF1 block through hyst_code_process, 0xF2 n nested
 *   reversals (16 n deep, n % 40 else; converging on the middle), 0xF3
 *   snapshot twin (T saved, C reset and restored from it, then both go on
 *   bit for bit; a double instance's snapshot refused), 0xF4 w op: a
 *   deadband of w codes requested (hyst_code_request_deadband(), from
 *   "another context") on C, immediately set on T after its next step, and
 *   requested on F in volts: that step (one code of kind op) applies it, C
 *   and T stay bit for bit (an invalid width is refused, nothing posted);
 *   0xF5.. accessors, among them hyst_code_rounding_bound(), which must
 *   cover every exact-mode output (depth times it plus the reference's TOL);
 *   any other byte one code of kind op & 7 (next_code). */
#include "hyst/hyst.h"
#include "ref_tcm.h"
#include "fuzz_common.h"

#ifndef HYST_USE_DOUBLE
#error "the differential harness compares a double core with the double reference"
#endif

#define MAX_CAP 4100u /* flag bit7: deep stacks, every rung of the binary search */
#define MAX_SAMPLES 4096u
#define NO_REQUEST 0xFFFFFFFFul

typedef struct { /* outputs of the code variant are float */
    hyst_t S;
    hyst_code_word_t xl[MAX_CAP], xr[MAX_CAP];
    float yl[MAX_CAP], yr[MAX_CAP];
} cinst_t;

typedef struct {
    hyst_t S;
    hyst_real_t xl[MAX_CAP], yl[MAX_CAP], xr[MAX_CAP], yr[MAX_CAP];
} finst_t;

/* f32 real instance: the engine whose curve checks the code variant shares
 * (its curves are f32 curves), for the expected init status */
typedef struct {
    hyst_t S;
    float xl[MAX_CAP], yl[MAX_CAP], xr[MAX_CAP], yr[MAX_CAP];
} f32inst_t;

static cinst_t C, T, Z, keepc;
/* snapshots: of T (code), and of F (double) for the refusal probe */
static unsigned char snap[HYST_SNAPSHOT_SIZE(MAX_CAP)], snapf[HYST_SNAPSHOT_SIZE(MAX_CAP)];
static f32inst_t F32;
/* C's curve when it is initialised through hyst_code_init_curve (flag bit1):
 * an f32 curve, which C points at, so it outlives C */
static hyst_curve_t code_curve;
/* How often the checks had something to check: FUZZ_CODE_STATS=1 prints
 * these at exit (reported in docs/reliability.md). */
static unsigned long n_exact, n_vs_real, n_bounded, n_merge, n_window, n_nonzero, n_requests,
    n_any_curve;

static void print_stats(void)
{
    fprintf(stderr, "fuzz_code: samples exact %lu, code vs real %lu, bounded %lu (bound > 0: %lu), "
                    "merges checked %lu, deadband windows checked %lu, deadband requests applied %lu, "
                    "deadband bound on curves of any f0'' %lu\n",
            n_exact, n_vs_real, n_bounded, n_nonzero, n_merge, n_window, n_requests, n_any_curve);
}
static finst_t F, F0, keepf;
static ref_tcm_t ref;

/* Curve facts for the proven case, degree <= 3: f0'' is linear, so its sign
 * and max|f0''|, and f0' (monotone then) are decided by the two ends. */
typedef struct {
    int one_signed;
    double slope_max, slope_min, curv_max;
} facts_t;

static double d1(const hyst_poly_t *f, double x)
{
    double a = 0.0;
    unsigned k;
    for (k = 0; k < f->degree; ++k) a = a * x + (double)(f->degree - k) * f->coeffs[k];
    return a;
}

static double d2(const hyst_poly_t *f, double x)
{
    double a = 0.0;
    unsigned k;
    for (k = 0; k + 1u < f->degree; ++k) {
        a = a * x + (double)(f->degree - k) * (double)(f->degree - k - 1u) * f->coeffs[k];
    }
    return a;
}

static facts_t curve_facts(const hyst_poly_t *f)
{
    facts_t q = {0, 0.0, 0.0, 0.0};
    const double a = d2(f, f->lo), b = d2(f, f->hi);
    const double s0 = d1(f, f->lo), s1 = d1(f, f->hi);
    if (f->degree > 3u) return q;
    q.one_signed = (a >= 0.0 && b >= 0.0) || (a <= 0.0 && b <= 0.0);
    q.curv_max = fmax(fabs(a), fabs(b));
    q.slope_max = fmax(s0, s1);
    q.slope_min = fmin(s0, s1);
    return q;
}

/* Rounding of the code variant, whose outputs are float (in every build,
 * HYST_USE_DOUBLE or not): per turning point an output hangs on, the engine
 * evaluates the normalised branch shape G(u) = f0(lo + u (hi - lo)) - f0(lo)
 * = a_1 u + ... + a_n u^n in float, at a float u (the code difference, exact,
 * times a float scale), and adds it to a stored float output. Horner's bound
 * in float on those coefficients (as horner_bound() in double on the raw
 * ones), plus the rounding of the sum y_k +- G: FLT_EPSILON (8 (n + 1) sum |a_k|
 * + 2 max |f0|). The turning-point inputs are codes, exact, so these errors
 * only add up along the stack, as the double ones do (depth factor). The
 * a_k are computed here, in double, from the raw coefficients (Taylor
 * shift), independently of the library's normalisation. */
static double float_bound(const hyst_poly_t *f, double y_lo, double y_hi)
{
    double p[HYST_MAX_DEGREE + 1], scale = 1.0, sum = 0.0;
    const unsigned n = f->degree;
    unsigned i, j;
    for (j = 0; j <= n; ++j) p[j] = f->coeffs[j];
    for (i = 0; i < n; ++i) { /* p(lo + t), highest power first */
        for (j = 1; j <= n - i; ++j) p[j] += f->lo * p[j - 1u];
    }
    for (j = n; j-- > 0u;) { /* p[j] multiplies t^(n - j); t = u (hi - lo) */
        scale *= f->hi - f->lo;
        sum += fabs(p[j]) * scale;
    }
    return FLT_EPSILON * (8.0 * (double)(n + 1u) * sum + 2.0 * fmax(fabs(y_lo), fabs(y_hi)));
}

/* all entries when whole is set or the stack is shallow; else the top four
 * (below the top, a stack that cannot merge, capacity 4100, never changes);
 * db_floor: the narrowest deadband since the last reset (TPs stored under a
 * wider one keep their wider gaps) */
static void check_code_invariants(const cinst_t *I, int whole, unsigned long db_floor)
{
    const hyst_t *S = &I->S;
    const size_t nl = S->n_ltp, nr = S->n_rtp;
    const size_t from = whole || nl < 36u ? 0u : nl - 4u;
    size_t i;
    CHECK(nl >= 1u && nl <= S->capacity && nr <= S->capacity);
    CHECK(nr == nl || nr + 1u == nl);
    CHECK(hyst_rising(S) == (nl > nr));
    CHECK(hyst_tp_count(S) == nl - 1u + nr);
    CHECK(I->xl[0] == S->lo.code);
    for (i = from + 1u; i < nl; ++i) CHECK(I->xl[i] > I->xl[i - 1]);
    for (i = from + 1u; i < nr; ++i) CHECK(I->xr[i] < I->xr[i - 1]);
    if (nr > 0u) CHECK(I->xl[nl - 1u] < I->xr[nr - 1u] && I->xr[0] <= S->hi.code);
    CHECK(hyst_code_input(S) >= S->lo.code && hyst_code_input(S) <= S->hi.code);
    CHECK(hyst_code_error_bound(S) >= 0.0);
    /* a reversal nearer than the deadband is never stored; a merge keeps this
     * (x_R2 - x_V >= x_R2 - x_P > x_R1 - x_P >= deadband) */
    for (i = from; i < nr; ++i) {
        CHECK((unsigned long)(I->xr[i] - I->xl[i]) >= db_floor);
        if (i + 1u < nl) CHECK((unsigned long)(I->xr[i] - I->xl[i + 1u]) >= db_floor);
    }
}

/* Live state bit for bit (entries past the counts are stale: not compared). */
static int same_code(const cinst_t *a, const cinst_t *b)
{
    return a->S.n_ltp == b->S.n_ltp && a->S.n_rtp == b->S.n_rtp &&
           memcmp(a->xl, b->xl, a->S.n_ltp * sizeof(a->xl[0])) == 0 &&
           memcmp(a->yl, b->yl, a->S.n_ltp * sizeof(a->yl[0])) == 0 &&
           memcmp(a->xr, b->xr, a->S.n_rtp * sizeof(a->xr[0])) == 0 &&
           memcmp(a->yr, b->yr, a->S.n_rtp * sizeof(a->yr[0])) == 0 &&
           memcmp(&a->S.y_prev.f32, &b->S.y_prev.f32, sizeof(float)) == 0 &&
           a->S.forgot.f32 == b->S.forgot.f32 && a->S.db_err.f32 == b->S.db_err.f32 &&
           a->S.status == b->S.status && a->S.events == b->S.events;
}

static int same_real(const finst_t *a, const finst_t *b)
{
    return a->S.n_ltp == b->S.n_ltp && a->S.n_rtp == b->S.n_rtp &&
           memcmp(a->xl, b->xl, a->S.n_ltp * sizeof(a->xl[0])) == 0 &&
           memcmp(a->yl, b->yl, a->S.n_ltp * sizeof(a->yl[0])) == 0 &&
           memcmp(a->xr, b->xr, a->S.n_rtp * sizeof(a->xr[0])) == 0 &&
           memcmp(a->yr, b->yr, a->S.n_rtp * sizeof(a->yr[0])) == 0 &&
           memcmp(&a->S.y_prev.HYST_R, &b->S.y_prev.HYST_R, sizeof(hyst_real_t)) == 0 &&
           a->S.forgot.HYST_R == b->S.forgot.HYST_R && a->S.db_err.HYST_R == b->S.db_err.HYST_R;
}


/* Expected init status of a code instance: capacity, then a curve error
 * (the same as the real engine reports: the f32 one, whose curves the code
 * variant runs on), else the code range. */
static void probe_init_errors(const hyst_poly_t *f, size_t cap, unsigned long lo,
                              unsigned long hi, hyst_status_t got, int via_curve)
{
    const int range_ok = lo < hi && hi <= HYST_CODE_MAX;
    hyst_status_t fst;
    hyst_curve_t curve;
    memset(&F32.S, 0, sizeof(F32.S));
    fst = hyst_f32_init(&F32.S, f, F32.xl, F32.yl, F32.xr, F32.yr, cap);
    if (via_curve && hyst_f32_curve_from_poly(&curve, f) != HYST_OK) {
        CHECK(got == hyst_f32_curve_from_poly(&curve, f)); /* the harness's own call failed */
    } else if (cap < 2u) {
        CHECK(got == HYST_ERR_CAPACITY);
    } else if (fst == HYST_OK) {
        CHECK(got == (range_ok ? HYST_OK : HYST_ERR_DOMAIN));
    } else if (range_ok) {
        CHECK(got == fst);
    } else {
        CHECK(got == fst || got == HYST_ERR_DOMAIN);
    }
}

static hyst_status_t init_code(cinst_t *I, const hyst_poly_t *f, size_t cap, int via_curve)
{
    if (via_curve) { /* C only: the curve must outlive the instance */
        hyst_status_t st;
        CHECK(I == &C);
        st = hyst_f32_curve_from_poly(&code_curve, f); /* codes run on f32 curves */
        if (st != HYST_OK) return st;
        fuzz_check_kinds(&code_curve);
        return cap % 2u != 0u ? hyst_code_init_kind(&I->S, &code_curve, hyst_code_kind_poly, clo, chi,
                                                    I->xl, I->yl, I->xr, I->yr, cap)
                              : hyst_code_init_curve(&I->S, &code_curve, clo, chi, I->xl, I->yl,
                                                     I->xr, I->yr, cap);
    }
    return hyst_code_init(&I->S, f, clo, chi, I->xl, I->yl, I->xr, I->yr, cap);
}

typedef struct {
    double y_prev, x_prev, b_prev;
    /* rounding allowance of y_prev beyond that of the current output: 0 for
     * the double engine (1e-9 of the range dominates both); for the code
     * variant the float allowance of the previous sample, which grows with
     * its depth (a deep stack wiped to A0 in one sample: the previous output
     * carried the rounding of thousands of TPs, the new one none) */
    double tol_prev;
    int forgot; /* full or deadband: exact comparison off */
    int full;   /* a merge happened since the last reset */
} track_t;

/* Bound and continuity of one engine's sample (proven case only). */
static void check_bounded(track_t *t, double x, double y, double yr, double bound,
                          const facts_t *q, double tol, double resid)
{
    const double dx = fabs(x - t->x_prev), dy = fabs(y - t->y_prev);
    CHECK(fabs(y - yr) <= bound + tol);
    CHECK(dy <= q->slope_max * dx + resid + tol + t->tol_prev);
}

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    if (getenv("FUZZ_CODE_STATS")) atexit(print_stats);
    return 0;
}

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size)
{
    reader_t r = {data, size, 0};
    hyst_poly_t f;
    const unsigned flags = rd_u8(&r);
    const unsigned cap_byte = rd_u8(&r);
    /* deep stacks are slow (O(depth) reference and invariants per sample):
     * rare, so that most runs exercise the small capacities */
    const size_t cap = (flags & 128u) && cap_byte >= 240u ? MAX_CAP : cap_byte % 20u;
    const int via_curve = (int)(flags & 2u);
    hyst_status_t st;
    unsigned long dbc = 0;
    /* the widest deadband since the start (an open window keeps its error
     * until the stack changes, after a narrower request too); whether any
     * was ever on (Z and F0, never given one, then differ) */
    double dbv = 0.0, dbv_max, range, tol0, fl0, resid, step_v, code_round;
    unsigned long db_floor;
    int db_ever;
    facts_t q;
    track_t tc, tf;
    int compare, proven;
    unsigned n, done = 0; /* samples so far */
    hyst_code_word_t xs[64];
    float ys[64]; /* outputs of the code variant */

    read_config(&r, (int)(flags & 1u), &f);
    if ((flags & 1u) && !getenv("FUZZ_CODE_SLOW")) {
        /* Known slow path (docs/reliability.md, fuzz findings): f0 finite but
         * its normalised (Bernstein) form overflows, and hyst_curve_from_poly
         * subdivides to full depth, 7 s per init under ASan (0.1 s at -O2).
         * Skipped so the CI budget goes to fuzzing; FUZZ_CODE_SLOW=1 replays
         * fuzz/slow/regress_code_init_bernstein_overflow. */
        const double mag = fmax(fabs(f.lo), fabs(f.hi));
        double acc = 0.0;
        unsigned k;
        for (k = 0; k <= f.degree && k <= HYST_MAX_DEGREE; ++k) acc = acc * mag + fabs(f.coeffs[k]);
        if (acc > 1e280) return 0;
    }
    if (flags & 16u) {
        clo = rd_u24(&r);
        chi = rd_u24(&r);
    } else {
        const unsigned shift = rd_u8(&r) % 16u;
        unsigned long span = (unsigned long)rd_u16(&r) >> shift;
        if (span == 0u) span = 1u;
        clo = (unsigned long)rd_u16(&r) % (65536ul - span);
        chi = clo + span;
    }
    vlo = f.lo;
    vhi = f.hi;

    memset(&C, 0, sizeof(C));
    memcpy(&keepc, &C, sizeof(C));
    st = init_code(&C, &f, cap, via_curve);
    probe_init_errors(&f, cap, clo, chi, st, via_curve);
    if (st != HYST_OK) {
        CHECK(st < 0);
        CHECK(memcmp(&keepc, &C, sizeof(C)) == 0); /* init errors write nothing */
        return 0;
    }
    CHECK(init_code(&T, &f, cap, 0) == HYST_OK);
    CHECK(init_code(&Z, &f, cap, 0) == HYST_OK);
    CHECK(hyst_init(&F.S, &f, F.xl, F.yl, F.xr, F.yr, cap) == HYST_OK);
    CHECK(hyst_init(&F0.S, &f, F0.xl, F0.yl, F0.xr, F0.yr, cap) == HYST_OK);
    /* f0(lo), rounded to the code variant's float output */
    CHECK(hyst_code_output(&C.S) == (float)F.S.y_lo.HYST_R && hyst_tp_count(&C.S) == 0u);
    CHECK(hyst_code_error_bound(&C.S) == 0.0 && hyst_error_bound(&F.S) == 0.0);
    step_v = (vhi - vlo) / (double)(chi - clo);

    if (flags & 4u) { /* NULL probes: refused, never dereferenced */
        CHECK(hyst_code_init(NULL, &f, clo, chi, T.xl, T.yl, T.xr, T.yr, cap) == HYST_ERR_NULL);
        CHECK(hyst_code_init(&keepc.S, &f, clo, chi, T.xl, NULL, T.xr, T.yr, cap) == HYST_ERR_NULL);
        CHECK(hyst_code_init(&keepc.S, NULL, clo, chi, T.xl, T.yl, T.xr, T.yr, cap) == HYST_ERR_NULL);
        CHECK(hyst_code_init_curve(&keepc.S, NULL, clo, chi, T.xl, T.yl, T.xr, T.yr, cap) ==
              HYST_ERR_NULL);
        CHECK(hyst_code_process(&C.S, NULL, ys, 1u) == HYST_ERR_NULL);
        CHECK(hyst_code_process(&C.S, xs, NULL, 1u) == HYST_ERR_NULL);
        CHECK(hyst_code_process(&C.S, NULL, NULL, 0u) == HYST_OK);
        CHECK(hyst_code_set_deadband(NULL, 0u) == HYST_ERR_NULL);
        CHECK(hyst_set_deadband(NULL, 0.0) == HYST_ERR_NULL);
        CHECK(hyst_init_curve(&keepf.S, NULL, F.xl, F.yl, F.xr, F.yr, cap) == HYST_ERR_NULL);
        CHECK(hyst_code_step(NULL, clo) == 0.0f); /* per-sample calls: 0 for NULL */
    }
    if (flags & 8u) { /* a curve not made by hyst_curve_*: refused */
        hyst_curve_t bad;
        CHECK(hyst_f32_curve_from_poly(&bad, &f) == HYST_OK); /* C's init accepted f */
        bad.kind = 0x5A;
        CHECK(hyst_code_init_curve(&keepc.S, &bad, clo, chi, T.xl, T.yl, T.xr, T.yr, cap) ==
              HYST_ERR_ARG);
    }
    if (flags & 32u) { /* deadband on */
        dbc = (unsigned long)rd_u16(&r) % ((chi - clo) / 4u + 1u);
        dbv = (double)dbc * step_v;
    }
    if (flags & 64u) { /* invalid deadbands: refused, state untouched */
        const double bad[4] = {-step_v, NAN, INFINITY, -INFINITY};
        unsigned k;
        memcpy(&keepc, &C, sizeof(C));
        CHECK(hyst_code_set_deadband(&C.S, (chi - clo) + 1u + rd_u8(&r)) == HYST_ERR_ARG);
        CHECK(hyst_code_set_deadband(&C.S, 0xFFFFFFFFul) == HYST_ERR_ARG);
        CHECK(memcmp(&keepc, &C, sizeof(C)) == 0);
        memcpy(&keepf, &F, sizeof(F));
        for (k = 0; k < 4u; ++k) CHECK(hyst_set_deadband(&F.S, bad[k]) == HYST_ERR_ARG);
        CHECK(memcmp(&keepf, &F, sizeof(F)) == 0);
        CHECK(hyst_code_set_deadband(&C.S, chi - clo) == HYST_OK); /* the widest allowed */
        CHECK(hyst_code_set_deadband(&C.S, 0u) == HYST_OK);
    }
    dbv_max = dbv;
    db_ever = dbc != 0u;
    db_floor = dbc;
    /* Deadband 0 set explicitly on C, T, F; Z and F0 never see the call. */
    CHECK(hyst_code_set_deadband(&C.S, dbc) == HYST_OK);
    CHECK(hyst_code_set_deadband(&T.S, dbc) == HYST_OK);
    CHECK(hyst_set_deadband(&F.S, dbv) == HYST_OK);

    compare = !(flags & 1u); /* raw curves may defeat the reference itself */
    q = curve_facts(&f);
    proven = compare && q.one_signed;
    ref_init(&ref, f.coeffs, f.degree, f.lo, f.hi);
    range = fabs(F.S.y_hi.HYST_R - F.S.y_lo.HYST_R);
    tol0 = horner_bound(&f);
    fl0 = compare ? float_bound(&f, F.S.y_lo.HYST_R, F.S.y_hi.HYST_R) : 0.0;
    code_round = (double)hyst_code_rounding_bound(&C.S);
    CHECK(code_round >= 0.0 && code_round == (double)hyst_code_rounding_bound(&T.S));
    resid = (q.slope_max - q.slope_min) * step_v; /* a merged TP rounded to a code */
    last_code = clo;
    memset(&tc, 0, sizeof(tc));
    tc.y_prev = F.S.y_lo.HYST_R;
    tc.x_prev = vlo;
    tc.forgot = dbc != 0u;
    tf = tc;
    tc.y_prev = T.S.y_lo.f32; /* the code variant's own f0(lo), in float */
    tc.tol_prev = 1e-9 * range + 2.0 * (tol0 + fl0); /* A0: depth 0 */

    for (n = 0; done < MAX_SAMPLES && r.at < r.n; ++n) {
        unsigned op = rd_u8(&r);
        unsigned long pend = NO_REQUEST; /* a deadband requested for this sample's end */
        unsigned m = 1u, k;
        int blk_full = 0;
        if (op == 0xF0u) { /* reset everything; the deadband is kept */
            hyst_reset(&C.S);
            hyst_reset(&T.S);
            hyst_reset(&Z.S);
            hyst_reset(&F.S);
            hyst_reset(&F0.S);
            db_floor = dbc; /* no TP stored under an earlier width */
            ref_init(&ref, f.coeffs, f.degree, f.lo, f.hi);
            CHECK(hyst_tp_count(&C.S) == 0u && hyst_events(&C.S) == 0u);
            CHECK(hyst_code_error_bound(&C.S) == 0.0 && hyst_error_bound(&F.S) == 0.0);
            CHECK(hyst_code_output(&C.S) == (float)F.S.y_lo.HYST_R && C.S.deadband.code == dbc);
            tc.y_prev = T.S.y_lo.f32;
            tf.y_prev = F.S.y_lo.HYST_R;
            tc.x_prev = tf.x_prev = vlo;
            tc.forgot = tf.forgot = dbc != 0u;
            tc.full = tf.full = 0;
            tc.b_prev = tf.b_prev = 0.0;
            tc.tol_prev = 1e-9 * range + 2.0 * (tol0 + fl0);
            last_code = clo;
            continue;
        }
        if (op == 0xF3u) { /* snapshot twin: T saved, restored into C, both go on */
            const size_t len = hyst_snapshot_size(&T.S);
            size_t got = 0, lenf = 0;
            CHECK(len > 0u && len <= HYST_SNAPSHOT_SIZE(cap));
            CHECK(hyst_snapshot_save(&T.S, snap, len - 1u, NULL) == HYST_ERR_NOSPACE);
            CHECK(hyst_snapshot_save(&T.S, snap, sizeof(snap), &got) == HYST_OK && got == len);
            CHECK(snap[6] == 4u && snap[7] == HYST_VARIANT_CODE); /* float outputs, codes */
            /* a snapshot of a real (double) instance is not one of codes */
            CHECK(hyst_snapshot_save(&F.S, snapf, sizeof(snapf), &lenf) == HYST_OK);
            memcpy(&keepc, &C, sizeof(C));
            CHECK(hyst_snapshot_restore(&C.S, snapf, lenf) == HYST_ERR_VERSION);
            CHECK(memcmp(&keepc, &C, sizeof(C)) == 0);
            /* C, initialised as T (maybe through its own f32 curve), moved away
             * from T's state first so that the restore has to do the work */
            hyst_reset(&C.S);
            CHECK(hyst_snapshot_restore(&C.S, snap, len) == HYST_OK);
            CHECK(same_code(&C, &T) && hyst_code_input(&C.S) == hyst_code_input(&T.S));
            CHECK(hyst_code_error_bound(&C.S) == hyst_code_error_bound(&T.S));
            continue; /* every later sample compares C with T bit for bit */
        }
        if (op == 0xF4u) { /* a deadband requested on C and F, set on T after the step */
            const unsigned long w = (unsigned long)rd_u16(&r) % ((chi - clo) / 4u + 2u);
            const int valid = w <= chi - clo;
            memcpy(&keepc, &C, sizeof(C));
            st = hyst_code_request_deadband(&C.S, w);
            CHECK(st == (valid ? HYST_OK : HYST_ERR_ARG));
            CHECK(hyst_request_pending(&C.S) == valid);
            if (!valid) {
                CHECK(memcmp(&keepc, &C, sizeof(C)) == 0);
                continue;
            }
            CHECK(hyst_request_deadband(&F.S, (double)w * step_v) == HYST_OK);
            op = rd_u8(&r) & 0xEFu; /* one code (never a control opcode) that applies it */
            pend = w;
        }
        if (op > 0xF2u) { /* accessors, clear events */
            CHECK((double)hyst_code_rounding_bound(&C.S) == code_round);
            (void)hyst_status(&C.S);
            (void)hyst_rising(&C.S);
            CHECK(hyst_capacity(&C.S) == cap && hyst_ltp_count(&C.S) + hyst_rtp_count(&C.S) ==
                                                    hyst_tp_count(&C.S));
            hyst_clear_events(&C.S);
            hyst_clear_events(&T.S);
            hyst_clear_events(&Z.S);
            CHECK(hyst_events(&C.S) == 0u);
            continue;
        }
        if (op == 0xF1u) m = rd_u8(&r) % 64u;
        if (op == 0xF2u) { /* nested oscillation: up to 4080 reversals (deep), else 39 */
            m = cap == MAX_CAP ? 16u * rd_u8(&r) : rd_u8(&r) % 40u;
        }
        if (m > MAX_SAMPLES - done) m = MAX_SAMPLES - done; /* the budget of one input */
        done += m;
        for (k = 0; k < m; ++k) {
            /* 0xF2: x_k = mid -+ half (1 - k / (m + 1)), each a reversal */
            const unsigned long half = (chi - clo) / 2u, amp = half - half * k / (m + 1u);
            unsigned long c = op == 0xF2u ? ((k & 1u) ? clo + half + amp : clo + half - amp)
                                          : next_code(&r, op == 0xF1u ? rd_u8(&r) : op);
            if (op == 0xF1u) c &= 0xFFFFul; /* a block holds code words */
            if (op == 0xF1u) xs[k] = (hyst_code_word_t)c;
            if (op != 0xF1u) { /* the single-step path through C, too */
                ys[0] = hyst_code_step(&C.S, c);
            }
            {
                /* T's innermost loop before the step, for the merge bound */
                const double xl1 = volts(T.xl[T.S.n_ltp - 1u]);
                const double xr1 = T.S.n_rtp > 0u ? volts(T.xr[T.S.n_rtp - 1u]) : vhi;
                const int clamped = c < clo || c > chi;
                const unsigned long cc = c < clo ? clo : c > chi ? chi : c;
                const double x = volts(cc);
                const float y = hyst_code_step(&T.S, c);
                const float yz = hyst_code_step(&Z.S, c);
                const hyst_real_t yf = hyst_step(&F.S, x);
                const hyst_real_t yf0 = hyst_step(&F0.S, x);
                const double yr = ref_step(&ref, x);
                const double depth = (double)ref_tp_count(&ref) + 2.0;
                const double tol = 1e-9 * range + depth * tol0;
                /* where a code-variant (float) output is compared */
                const double ftol = tol + depth * fl0;
                last_code = cc;
                if (clamped) {
                    CHECK(hyst_status(&T.S) == HYST_WARN_CLAMPED ||
                          hyst_status(&T.S) == HYST_WARN_FULL);
                    CHECK(hyst_events(&T.S) & HYST_EVENT_CLAMPED);
                } else {
                    CHECK(hyst_status(&T.S) != HYST_WARN_CLAMPED);
                }
                CHECK(hyst_code_input(&T.S) == cc);
                CHECK(hyst_status(&F.S) != HYST_WARN_CLAMPED); /* volts() stays in [lo, hi] */
                if (hyst_status(&T.S) == HYST_WARN_FULL) tc.forgot = tc.full = blk_full = 1;
                if (hyst_status(&F.S) == HYST_WARN_FULL) tf.forgot = tf.full = 1;
                if (!db_ever) { /* deadband 0 is no deadband, bit for bit */
                    CHECK(memcmp(&y, &yz, sizeof(y)) == 0 && same_code(&T, &Z));
                    CHECK(memcmp(&yf, &yf0, sizeof(yf)) == 0 && same_real(&F, &F0));
                }
                if (compare && !tc.forgot) { /* exact: TCM over codes = reference */
                    CHECK(hyst_tp_count(&T.S) == (size_t)ref_tp_count(&ref));
                    CHECK(fabs(y - yr) <= ftol);
                    /* the library's own stated bound (tcm.h, "rounding"): per
                     * TP an output hangs on, plus the reference's TOL */
                    CHECK(fabs(y - yr) <= depth * code_round + tol);
                    CHECK(hyst_code_error_bound(&T.S) == 0.0);
                    ++n_exact;
                }
                if (compare && !tf.forgot) {
                    CHECK(hyst_tp_count(&F.S) == (size_t)ref_tp_count(&ref));
                    CHECK(fabs(yf - yr) <= tol);
                    CHECK(hyst_error_bound(&F.S) == 0.0);
                }
                if (compare && !tc.forgot && !tf.forgot) { /* code vs real engine */
                    CHECK(hyst_tp_count(&T.S) == hyst_tp_count(&F.S));
                    CHECK(fabs(y - yf) <= ftol);
                    ++n_vs_real;
                }
                if (proven) {
                    const double bc = hyst_code_error_bound(&T.S), bf = hyst_error_bound(&F.S);
                    check_bounded(&tc, x, y, yr, bc, &q, ftol, resid);
                    check_bounded(&tf, x, yf, yr, bf, &q, tol, 0.0);
                    ++n_bounded;
                    n_nonzero += bc > 0.0;
                    if (bc > tc.b_prev && hyst_status(&T.S) == HYST_WARN_FULL) {
                        /* a merge of L1, R1 and P: second order in w = x_R1 - x_L1 */
                        const double w = xr1 - xl1;
                        CHECK(bc - tc.b_prev <= q.curv_max * w * w / 4.0 + resid + ftol);
                        ++n_merge;
                    } else if (bc > tc.b_prev) { /* a deadband window opened or widened */
                        CHECK(bc - tc.b_prev <= q.curv_max * dbv_max * dbv_max / 4.0 + resid + ftol);
                        ++n_window;
                    }
                    if (bf > tf.b_prev && hyst_status(&F.S) != HYST_WARN_FULL) {
                        CHECK(bf - tf.b_prev <= q.curv_max * dbv_max * dbv_max / 4.0 + tol);
                    }
                    if (!tc.full) { /* no merge: only the open window counts */
                        CHECK(bc <= q.curv_max * dbv_max * dbv_max / 4.0 + ftol);
                    }
                    if (!tf.full) {
                        CHECK(bf <= q.curv_max * dbv_max * dbv_max / 4.0 + tol);
                    }
                    tc.b_prev = bc;
                    tf.b_prev = bf;
                } else if (compare) {
                    /* any accepted curve (f0'' of any sign, any degree): the
                     * deadband's stated bound holds while nothing was merged */
                    if (!tc.full) {
                        CHECK(fabs(y - yr) <= hyst_code_error_bound(&T.S) + ftol);
                    }
                    if (!tf.full) {
                        CHECK(fabs(yf - yr) <= hyst_error_bound(&F.S) + tol);
                    }
                    n_any_curve += db_ever && !(tc.full && tf.full);
                }
                if (pend != NO_REQUEST) { /* applied at the step's end: as set now */
                    CHECK(!hyst_request_pending(&C.S) && !hyst_request_pending(&F.S));
                    CHECK(C.S.deadband.code == pend && F.S.deadband.HYST_R == (double)pend * step_v);
                    CHECK(hyst_code_set_deadband(&T.S, pend) == HYST_OK);
                    dbc = pend;
                    db_floor = pend < db_floor ? pend : db_floor;
                    dbv = (double)pend * step_v;
                    dbv_max = fmax(dbv_max, dbv);
                    db_ever |= pend != 0u;
                    tc.forgot |= pend != 0u;
                    tf.forgot |= pend != 0u;
                    ++n_requests;
                }
                tc.x_prev = tf.x_prev = x;
                tc.tol_prev = ftol;
                tc.y_prev = y;
                tf.y_prev = yf;
                if (op != 0xF1u) CHECK(memcmp(&ys[0], &y, sizeof(y)) == 0 && same_code(&C, &T));
                if (op == 0xF1u) ys[k] = y; /* expected block output */
            }
            check_code_invariants(&T, (k & 255u) == 255u || k + 1u == m, db_floor);
            CHECK(F.S.n_ltp <= cap && F.S.n_rtp <= cap);
        }
        if (op == 0xF1u) { /* the block through C equals T's steps */
            float yb[64];
            int any_clamp = 0;
            for (k = 0; k < m; ++k) any_clamp |= xs[k] < clo || xs[k] > chi;
            st = hyst_code_process(&C.S, xs, yb, m);
            CHECK(m == 0u || memcmp(yb, ys, m * sizeof(float)) == 0);
            CHECK(same_code(&C, &T));
            /* documented summary: FULL if any overflow (seen on T), else CLAMPED */
            CHECK(st == (blk_full ? HYST_WARN_FULL : any_clamp ? HYST_WARN_CLAMPED : HYST_OK));
        }
    }
    return 0;
}
