/* SPDX-License-Identifier: MIT */
/* libFuzzer harness of the asymmetric kind on a grid (curve.h,
 * hyst_everett_grid_t): its curve, its compensator and its identification
 * (ident.h, hyst_everett_grid_fit_*, hyst_everett_grid_knots()), built with
 * HYST_USE_DOUBLE and checked against the plain double reference
 * tests/support/ref_egrid.c; any failed CHECK aborts.
 *
 * Input layout (reads past the end yield zeros, so every input is valid):
 *   [0]  flags: bit0 raw numbers (arbitrary doubles) else small grids;
 *        bit1 the compensator; bit2 the fit and the knots; bit3 refusal
 *        probes (probe byte below); bit4 the float variant beside
 *   [1]  intervals (byte % 14: 0 and 13 are refused)
 *   [2]  capacity (byte % 40: 0 and 1 are refused)
 *   [3]  the fit's turning points (byte % 48: below 2 refused) and the knot
 *        bins (16 + byte, or 15: refused, when the byte is 0)
 *   [4]  probe: which refusal bit3 tries (probe())
 *   then the grid: structured, lo (signed byte / 8), each interval's width
 *   ((1 + byte % 64) / 4), y_lo (signed byte / 16; 0x80 is 2^23, a 24-bit
 *   ADC's mid-scale) and each cell's mass (byte < 40: 0, else
 *   (byte - 40) / 16, ten times that from 240); raw, the knots, y_lo and
 *   the masses as doubles. Then opcodes until the input ends:
 *   0xF0 a snapshot, restored into the twin (which then runs on), and
 *        refused by an instance of another grid (byte: which mass changes);
 *   0xF1 reset;
 *   0xF2 the next sample exactly on knot (byte % (intervals + 1));
 *   0xF3 an excursion inside the current branch (byte: where) and back;
 *   0xF4 the next sample's output, as the fit and the knots see it, a raw
 *        double (8 bytes);
 *   0xF5 hi, 0xF6 lo; any other byte b a sample lo + (hi - lo) b / 239.
 *
 * Checks: each refusal is the first of curve.h's (ident.h's) checks that
 * fails, and writes nothing (the curve, its table, the fit, the knots, an
 * instance restored into); an accepted grid's major rising branch reaches
 * y_hi within its rounding bound (raw grids too); its outputs equal the reference
 * within (d + 1) times (the curve's rounding bound + 8 eps of the output
 * scale, the reference's own), d the stacked turning points (tcm.h), and
 * within the error bound on top once memory fills; the output never moves
 * against the input; the block call equals the step (a twin driven by
 * hyst_process()); a snapshot restored continues bit for bit; an excursion
 * inside the current branch comes back to the same output bit for bit and
 * then runs on as the twin that stayed (not from an output the monotone
 * guard held: the branch's own value there is a rounding from it); the compensator (the round trip
 * model(compensator(y)) over the model's own outputs y) returns y within
 * (d + 1) times (the model's bound + the steepest branch slope times the
 * compensator's bound), its drive on the domain and never against the
 * desired output, its block call equal to its steps; the float variant
 * refuses no later a check than the double one, and agrees with the
 * reference on float inputs within its own bound; the fit on the grid's
 * knots, of a record the grid made, leaves a residual within 1e-9 of the
 * output scale (the grid itself fits exactly), every mass >= 0, its RMS
 * the fitted grid's own residual (the reference) and its grid accepted;
 * the knots from the record are finite, strictly increasing from lo to hi,
 * and taken by the fit. */

#include "fuzz_common.h"
#include "ref_egrid.h"

#ifndef HYST_USE_DOUBLE
#error "the differential harness compares a double core with double references"
#endif

#define EPS DBL_EPSILON
#define K_MAX HYST_EVERETT_GRID_MAX_INTERVALS
#define CELLS_MAX HYST_EVERETT_GRID_CELLS(K_MAX)
#define TABLE_MAX HYST_EVERETT_GRID_TABLE_LEN(K_MAX)
#define MAX_CAP 40u
#define BIG_CAP 600u
#define MAX_SAMPLES 512u
#define FIT_CAP 48u

static double xl[BIG_CAP], yl[BIG_CAP], xr[BIG_CAP], yr[BIG_CAP];
static double xl2[BIG_CAP], yl2[BIG_CAP], xr2[BIG_CAP], yr2[BIG_CAP];
static double xl3[BIG_CAP], yl3[BIG_CAP], xr3[BIG_CAP], yr3[BIG_CAP];
static float fxl[MAX_CAP], fyl[MAX_CAP], fxr[MAX_CAP], fyr[MAX_CAP];
static double table[TABLE_MAX + 1u], table2[TABLE_MAX], keep_table[TABLE_MAX + 1u];
static float table32[TABLE_MAX];
static double xs[MAX_SAMPLES], ys[MAX_SAMPLES], ys2[MAX_SAMPLES], drive[MAX_SAMPLES];
static double pend_x[MAX_SAMPLES], pend_y[MAX_SAMPLES], pend_out[MAX_SAMPLES];
static hyst_wide_t fx[MAX_SAMPLES], fy[MAX_SAMPLES];
static hyst_wide_t fit_work[HYST_EVERETT_GRID_FIT_WORK(K_MAX, FIT_CAP)];
static hyst_wide_t bins[16u + 255u];
static unsigned char snap[HYST_SNAPSHOT_SIZE(MAX_CAP)];
static ref_everett_t ref, ref32;
static hyst_everett_t dom, dom32;
static hyst_curve_t curve, keep_curve;
static hyst_t S, T, U, keep_u;

/* Whether the reference (and so the fit's record) stacks a turning point
 * when x comes next. */
static int pushes(double x)
{
    const int rising = (ref.n - 1) % 2 == 0;
    return (x > ref.x && !rising) || (x < ref.x && rising);
}

/* Rank of a refusal in curve.h's order of checks (OK last): the float
 * variant refuses no later a check than the double one. */
static int rank(hyst_status_t st)
{
    switch (st) {
    case HYST_ERR_NULL: return 0;
    case HYST_ERR_DEGREE: return 1;
    case HYST_ERR_BREAKPOINTS: return 2;
    case HYST_ERR_COEFF: return 3; /* y_lo, masses; a table entry (5) says COEFF too */
    case HYST_ERR_NOT_MONOTONE: return 4;
    case HYST_ERR_NOSPACE: return 5;
    case HYST_ERR_ILL_CONDITIONED: return 7;
    case HYST_OK: return 8;
    default: return -1;
    }
}

/* curve.h's checks that need no table: the status they give, or HYST_OK. */
static hyst_status_t grid_expected(const hyst_everett_grid_t *g, size_t table_len)
{
    unsigned i;
    double total = 0.0;
    if (g->intervals < 1u || g->intervals > K_MAX) return HYST_ERR_DEGREE;
    for (i = 0u; i <= g->intervals; ++i) {
        if (!isfinite(g->knots[i])) return HYST_ERR_BREAKPOINTS;
        if (i > 0u && !(g->knots[i] > g->knots[i - 1u] && isfinite(g->knots[i] - g->knots[i - 1u]))) {
            return HYST_ERR_BREAKPOINTS;
        }
    }
    if (!isfinite(g->y_lo)) return HYST_ERR_COEFF;
    for (i = 0u; i < HYST_EVERETT_GRID_CELLS(g->intervals); ++i) {
        if (!isfinite(g->weight[i])) return HYST_ERR_COEFF;
    }
    for (i = 0u; i < HYST_EVERETT_GRID_CELLS(g->intervals); ++i) {
        if (g->weight[i] < 0) return HYST_ERR_NOT_MONOTONE;
        total += g->weight[i];
    }
    if (!(total > 0)) return HYST_ERR_NOT_MONOTONE;
    if (table_len < HYST_EVERETT_GRID_TABLE_LEN(g->intervals)) return HYST_ERR_NOSPACE;
    return HYST_OK;
}

/* The constructor on g: the status, and nothing written on a refusal. */
static hyst_status_t build(hyst_curve_t *c, const hyst_everett_grid_t *g, double *tab, size_t len)
{
    hyst_status_t st;
    memset(c, 0x5A, sizeof *c);
    memcpy(&keep_curve, c, sizeof *c);
    memcpy(keep_table, table, sizeof table);
    st = hyst_curve_from_everett_grid(c, g, tab, len);
    if (st != HYST_OK) {
        CHECK(memcmp(c, &keep_curve, sizeof *c) == 0);
        CHECK(memcmp(keep_table, table, sizeof table) == 0);
    }
    return st;
}

/* One damaged copy of an accepted grid (probe byte p), refused with the
 * status curve.h gives it, nothing written; and the NULL arguments. */
static void probe(const hyst_everett_grid_t *g, unsigned p, unsigned pick)
{
    hyst_everett_grid_t bad = *g;
    const unsigned k = g->intervals, cells = HYST_EVERETT_GRID_CELLS(k), i = 1u + pick % k;
    size_t len = TABLE_MAX;
    hyst_status_t want;
    switch (p % 12u) {
    case 0: bad.intervals = 0u; want = HYST_ERR_DEGREE; break;
    case 1: bad.intervals = K_MAX + 1u; want = HYST_ERR_DEGREE; break;
    case 2: bad.knots[i] = bad.knots[i - 1u]; want = HYST_ERR_BREAKPOINTS; break;
    case 3: bad.knots[i] = NAN; want = HYST_ERR_BREAKPOINTS; break;
    case 4: bad.knots[i] = bad.knots[i - 1u] - 1.0; want = HYST_ERR_BREAKPOINTS; break;
    case 5: bad.weight[pick % cells] = INFINITY; want = HYST_ERR_COEFF; break;
    case 6: bad.y_lo = NAN; want = HYST_ERR_COEFF; break;
    case 7: bad.weight[pick % cells] = -1e-300; want = HYST_ERR_NOT_MONOTONE; break;
    case 8: memset(bad.weight, 0, sizeof bad.weight); want = HYST_ERR_NOT_MONOTONE; break;
    case 9: len = HYST_EVERETT_GRID_TABLE_LEN(k) - 1u; want = HYST_ERR_NOSPACE; break;
    case 10: /* a table entry beyond the type: a density of 1e308 over a width below 1 */
        bad.knots[i] = bad.knots[i - 1u] + 0.25;
        bad.weight[(i - 1u) * i / 2u + i - 1u] = 1e308;
        want = grid_expected(&bad, len) != HYST_OK ? grid_expected(&bad, len) : HYST_ERR_COEFF;
        break;
    default: /* a knot as close to the last as the type allows: ill-conditioned or refused */
        bad.knots[i] = nextafter(bad.knots[i - 1u], INFINITY);
        want = HYST_OK;
        break;
    }
    {
        const hyst_status_t st = build(&curve, &bad, table, len);
        if (want == HYST_OK) {
            CHECK(st == HYST_OK || st == HYST_ERR_ILL_CONDITIONED || st == HYST_ERR_COEFF);
        } else {
            CHECK(st == want);
        }
    }
    CHECK(hyst_curve_from_everett_grid(NULL, g, table, TABLE_MAX) == HYST_ERR_NULL);
    CHECK(build(&curve, NULL, table, TABLE_MAX) == HYST_ERR_NULL);
    CHECK(build(&curve, g, NULL, TABLE_MAX) == HYST_ERR_NULL);
    CHECK(hyst_f64_curve_from_everett_grid_(&curve, g, table, TABLE_MAX, HYST_LAYOUT ^ 1ul) ==
          HYST_ERR_LAYOUT);
}

/* The steepest slope of any branch: on interval i at most its row's and
 * column's masses and twice the diagonal cell's, per unit of input. */
static double steepest(const hyst_everett_grid_t *g)
{
    double most = 0.0;
    unsigned i, j;
    for (i = 0u; i < g->intervals; ++i) {
        double sum = g->weight[i * (i + 1u) / 2u + i];
        for (j = 0u; j <= i; ++j) sum += g->weight[i * (i + 1u) / 2u + j];
        for (j = i; j < g->intervals; ++j) sum += g->weight[j * (j + 1u) / 2u + i];
        most = fmax(most, sum / (g->knots[i + 1u] - g->knots[i]));
    }
    return most;
}

/* The compensator over the desired outputs ys[0..n) (the model's own): see
 * the header. */
static void check_compensator(const hyst_everett_grid_t *g, double scale, int raw, size_t n)
{
    hyst_curve_t inv, other;
    hyst_t C, M;
    const double slope = steepest(g);
    memset(&inv, 0x5A, sizeof inv);
    memcpy(&other, &inv, sizeof inv);
    CHECK(hyst_curve_everett_grid_inverse(NULL, &curve) == HYST_ERR_NULL);
    CHECK(hyst_curve_everett_grid_inverse(&inv, NULL) == HYST_ERR_NULL);
    CHECK(hyst_f32_curve_everett_grid_inverse(&inv, &curve) == HYST_ERR_LAYOUT);
    CHECK(memcmp(&inv, &other, sizeof inv) == 0);
    CHECK(hyst_curve_everett_grid_inverse(&inv, &curve) == HYST_OK);
    CHECK(hyst_curve_everett_grid_inverse(&other, &inv) == HYST_ERR_ARG); /* not a forward grid */
    CHECK(hyst_init_curve(&C, &inv, xl2, yl2, xr2, yr2, BIG_CAP) == HYST_OK);
    CHECK(hyst_init_curve(&M, &curve, xl3, yl3, xr3, yr3, BIG_CAP) == HYST_OK);
    /* the round trip's error checked on small grids, not on raw ones */
    (void)fuzz_round_trip(&C, &M, ys, n, g->knots[0], g->knots[g->intervals],
                          raw ? -1.0
                              : hyst_rounding_bound(&M) + slope * hyst_rounding_bound(&C) +
                                    8.0 * EPS * scale,
                          drive);
    CHECK(hyst_init_curve(&C, &inv, xl2, yl2, xr2, yr2, BIG_CAP) == HYST_OK);
    CHECK(hyst_process(&C, ys, ys2, n) >= 0);
    CHECK(n == 0u || memcmp(drive, ys2, n * sizeof ys2[0]) == 0);
}

/* ident.h's knots on the record (x, y)[0..n): see the header. */
static void check_knots(size_t n, double lo, double hi, unsigned k, size_t nbins)
{
    hyst_wide_t knots[K_MAX + 2u], keep[K_MAX + 2u];
    hyst_everett_grid_fit_t fit;
    hyst_status_t st, want = HYST_OK;
    unsigned q;
    if (k < 1u || k > K_MAX) {
        want = HYST_ERR_DEGREE;
    } else if (!isfinite(lo) || !isfinite(hi) || !(lo < hi) || !isfinite(hi - lo)) {
        want = HYST_ERR_DOMAIN;
    } else if (nbins < 16u) {
        want = HYST_ERR_NOSPACE;
    }
    memset(knots, 0x5A, sizeof knots);
    memcpy(keep, knots, sizeof knots);
    CHECK(hyst_everett_grid_knots(NULL, fy, n, lo, hi, k, knots, bins, nbins) == HYST_ERR_NULL);
    CHECK(hyst_everett_grid_knots(fx, fy, n, lo, hi, k, knots, NULL, nbins) == HYST_ERR_NULL);
    st = hyst_everett_grid_knots(fx, fy, n, lo, hi, k, knots, bins, nbins);
    if (want != HYST_OK || st != HYST_OK) {
        /* a domain too narrow for the knots to be gap apart is refused too */
        const double end = fmax(fabs(lo), fabs(hi)), ulp = nextafter(end, INFINITY) - end;
        CHECK(st == want || (want == HYST_OK && st == HYST_ERR_DOMAIN &&
                             (hi - lo) / (16.0 * k) <= 2.0 * ulp));
        CHECK(memcmp(knots, keep, sizeof knots) == 0);
        return;
    }
    CHECK(knots[0] == lo && knots[k] == hi);
    CHECK(memcmp(&knots[k + 1u], &keep[k + 1u], sizeof knots[0]) == 0); /* nothing past them */
    for (q = 1u; q <= k; ++q) {
        CHECK(isfinite(knots[q]) && knots[q] > knots[q - 1u]);
    }
    CHECK(hyst_everett_grid_fit_init(&fit, knots, k, fit_work, sizeof fit_work / sizeof fit_work[0]) ==
          HYST_OK);
}

/* The fit on the grid's knots of the record (x, y)[0..n): see the header.
 * exact: the record is the grid's own (a small grid, no memory filled, no raw output). */
static void check_fit(const hyst_everett_grid_t *g, size_t n, unsigned fit_cap, int exact,
                      double scale, const int *nospace_at)
{
    static hyst_everett_grid_fit_t fit, keep_fit;
    hyst_everett_grid_t got, keep_g;
    hyst_wide_t rms = -1, keep_rms;
    const size_t work_len = HYST_EVERETT_GRID_FIT_WORK(g->intervals, fit_cap);
    hyst_status_t st;
    size_t k, used = 0u;
    memset(&fit, 0x5A, sizeof fit);
    memcpy(&keep_fit, &fit, sizeof fit);
    CHECK(hyst_everett_grid_fit_init(NULL, g->knots, g->intervals, fit_work, work_len) == HYST_ERR_NULL);
    CHECK(hyst_everett_grid_fit_init(&fit, NULL, g->intervals, fit_work, work_len) == HYST_ERR_NULL);
    CHECK(hyst_everett_grid_fit_init(&fit, g->knots, 0u, fit_work, work_len) == HYST_ERR_DEGREE);
    CHECK(hyst_everett_grid_fit_init(&fit, g->knots, K_MAX + 1u, fit_work, work_len) == HYST_ERR_DEGREE);
    {
        hyst_wide_t knots[K_MAX + 1u];
        memcpy(knots, g->knots, sizeof knots);
        knots[g->intervals] = knots[g->intervals - 1u];
        CHECK(hyst_everett_grid_fit_init(&fit, knots, g->intervals, fit_work, work_len) ==
              HYST_ERR_BREAKPOINTS);
    }
    CHECK(memcmp(&fit, &keep_fit, sizeof fit) == 0);
    st = hyst_everett_grid_fit_init(&fit, g->knots, g->intervals, fit_work, work_len);
    if (fit_cap < 2u) {
        CHECK(st == HYST_ERR_NOSPACE && memcmp(&fit, &keep_fit, sizeof fit) == 0);
        return;
    }
    CHECK(st == HYST_OK);
    CHECK(hyst_everett_grid_fit_add(NULL, g->knots[0], 0.0) == HYST_ERR_NULL);
    CHECK(hyst_everett_grid_fit_add(&fit, NAN, 0.0) == HYST_ERR_NONFINITE); /* ignored */
    {
        const double past = nextafter(g->knots[g->intervals], INFINITY); /* ignored */
        CHECK(hyst_everett_grid_fit_add(&fit, past, 0.0) == (isfinite(past) ? HYST_ERR_DOMAIN : HYST_ERR_NONFINITE));
    }
    memset(&got, 0x5A, sizeof got);
    memcpy(&keep_g, &got, sizeof got);
    keep_rms = rms;
    CHECK(hyst_everett_grid_fit_solve(&fit, &got, &rms) == HYST_ERR_SINGULAR); /* nothing yet */
    CHECK(memcmp(&got, &keep_g, sizeof got) == 0 && memcmp(&rms, &keep_rms, sizeof rms) == 0);
    CHECK(hyst_everett_grid_fit_solve(NULL, &got, &rms) == HYST_ERR_NULL);
    CHECK(hyst_everett_grid_fit_determined(NULL) == 0);
    CHECK(hyst_everett_grid_fit_determined(&fit) == 0); /* no sample yet */
    for (k = 0u; k < n; ++k) {
        st = hyst_everett_grid_fit_add(&fit, fx[k], fy[k]);
        if (nospace_at[k]) { /* more turning points than fit_cap: refused, the record stops */
            CHECK(st == HYST_ERR_NOSPACE);
            break;
        }
        CHECK(st == HYST_OK || (st == HYST_ERR_NONFINITE && !isfinite(fy[k])));
        used += st == HYST_OK;
    }
    n = k;
    st = hyst_everett_grid_fit_solve(&fit, &got, &rms);
    {
        /* determined() shares the solver's workspace: a solve after it is
         * the same, bit for bit */
        hyst_everett_grid_t again;
        hyst_wide_t again_rms = -1;
        const int determined = hyst_everett_grid_fit_determined(&fit);
        CHECK(determined == 0 || determined == 1);
        CHECK(used >= 2u || determined == 0);
        memcpy(&again, &keep_g, sizeof again);
        CHECK(hyst_everett_grid_fit_solve(&fit, &again, &again_rms) == st);
        CHECK(memcmp(&again, &got, sizeof again) == 0 && memcmp(&again_rms, &rms, sizeof rms) == 0);
    }
    if (used < 2u) {
        CHECK(st == HYST_ERR_SINGULAR);
        return;
    }
    { /* COEFF: outputs so far apart that the normal equations (sums of their
       * squares, of products with regressors up to 1) may overflow; nothing
       * written */
        double spread = 0.0;
        for (k = 0u; k < n; ++k) {
            if (isfinite(fy[k])) spread = fmax(spread, fabs(fy[k] - fy[0]));
        }
        CHECK(st == HYST_OK || st == HYST_ERR_NOT_MONOTONE ||
              (st == HYST_ERR_COEFF &&
               (!exact || !(spread < sqrt(DBL_MAX / (double)(n * HYST_EVERETT_GRID_FIT_COLS(g->intervals))) / 16.0))));
    }
    if (st == HYST_ERR_COEFF) {
        CHECK(memcmp(&got, &keep_g, sizeof got) == 0 && memcmp(&rms, &keep_rms, sizeof rms) == 0);
        return;
    }
    CHECK(got.intervals == g->intervals && memcmp(got.knots, g->knots, sizeof got.knots) == 0);
    /* accepted: the masses and the RMS finite */
    for (k = 0u; st == HYST_OK && k < HYST_EVERETT_GRID_CELLS(g->intervals); ++k) {
        CHECK(got.weight[k] >= 0 && isfinite(got.weight[k]) && isfinite(rms) && rms >= 0);
    }
    if (st == HYST_OK && exact) {
        hyst_curve_t fitted;
        double ss = 0.0;
        const hyst_status_t cs = hyst_curve_from_everett_grid(&fitted, &got, table2, TABLE_MAX);
        CHECK(cs == HYST_OK || cs == HYST_ERR_ILL_CONDITIONED);
        ref_egrid_init(&ref, &dom, &got);
        for (k = 0u; k < n; ++k) {
            const double d = fy[k] - ref_everett_step(&ref, fx[k]);
            ss += d * d;
        }
        ss = sqrt(ss / (double)n);
        /* the grid itself fits exactly: its residual (the reference's) within
         * the identification's tolerance, 1e-6 of the output scale (as in
         * tests/test_everett_grid.c); the RMS is that residual, up to its
         * rounding: a difference of sums of squares of the outputs, each
         * known to about cols eps scale^2 */
        CHECK(ss <= 1e-6 * scale);
        CHECK(fabs(rms * rms - ss * ss) <= 64.0 * (double)HYST_EVERETT_GRID_FIT_COLS(g->intervals) * EPS * scale * scale);
    }
}

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size)
{
    static int nospace_at[MAX_SAMPLES];
    reader_t rd = {data, size, 0u};
    const unsigned flags = rd_u8(&rd);
    const int raw = (flags & 1u) != 0u;
    hyst_everett_grid_t g;
    size_t cap, n = 0u, npend = 0u, k, nbins;
    unsigned i, fit_cap, probe_byte, cells;
    double scale, total = 0.0, lo, hi, span;
    int full = 0, exact = 1, held = 0;
    hyst_status_t st, want;
    memset(&g, 0, sizeof g);
    g.intervals = rd_u8(&rd) % 14u;
    cap = rd_u8(&rd) % MAX_CAP;
    i = rd_u8(&rd);
    fit_cap = i % FIT_CAP;
    nbins = i == 0u ? 15u : 16u + i;
    probe_byte = rd_u8(&rd);
    cells = g.intervals <= K_MAX ? HYST_EVERETT_GRID_CELLS(g.intervals) : 0u;
    if (raw) {
        for (i = 0u; i <= g.intervals && i <= K_MAX; ++i) g.knots[i] = rd_f64(&rd);
        g.y_lo = rd_f64(&rd);
        for (i = 0u; i < cells; ++i) g.weight[i] = rd_f64(&rd);
    } else {
        g.knots[0] = (double)(signed char)rd_u8(&rd) / 8.0;
        for (i = 1u; i <= g.intervals && i <= K_MAX; ++i) {
            g.knots[i] = g.knots[i - 1u] + (double)(1u + rd_u8(&rd) % 64u) / 4.0;
        }
        g.y_lo = (double)(signed char)rd_u8(&rd) / 16.0;
        if (g.y_lo == -8.0) g.y_lo = 8388608.0; /* byte 0x80: a 24-bit ADC's mid-scale */
        for (i = 0u; i < cells; ++i) {
            const unsigned b = rd_u8(&rd);
            g.weight[i] = b < 40u ? 0.0 : (double)(b - 40u) / 16.0 * (b >= 240u ? 10.0 : 1.0);
        }
    }
    want = grid_expected(&g, TABLE_MAX);
    st = build(&curve, &g, table, TABLE_MAX);
    CHECK(want == HYST_OK ? (st == HYST_OK || st == HYST_ERR_COEFF || st == HYST_ERR_ILL_CONDITIONED)
                          : st == want);
    CHECK(!(st != HYST_OK && !raw) || st == HYST_ERR_DEGREE || st == HYST_ERR_NOT_MONOTONE);
    if (flags & 16u) { /* the float variant: refuses no later a check */
        hyst_curve_t c32;
        const hyst_status_t s32 = hyst_f32_curve_from_everett_grid(&c32, &g, table32, TABLE_MAX);
        CHECK(rank(s32) >= 0 && rank(s32) <= rank(st));
    }
    lo = g.knots[0];
    hi = g.knots[g.intervals <= K_MAX ? g.intervals : 0u];
    span = hi - lo;
    /* the samples (and, for a grid refused, a record for the knots) */
    if (st != HYST_OK) {
        if (flags & 4u) {
            while (rd.at < rd.n && n < MAX_SAMPLES) {
                fx[n] = lo + span * (double)rd_u8(&rd) / 255.0;
                fy[n] = g.y_lo + g.weight[0] * fx[n];
                ++n;
            }
            check_knots(n, lo, hi, g.intervals, nbins);
        }
        return 0;
    }
    if (flags & 8u) {
        probe(&g, probe_byte, (unsigned)rd.at);
        CHECK(build(&curve, &g, table, TABLE_MAX) == HYST_OK);
    }
    for (i = 0u; i < cells; ++i) total += g.weight[i];
    scale = fabs(g.y_lo) + total;
    { /* the model holds every mass: its major rising branch reaches y_hi
       * within one evaluation's rounding bound (and y_hi's own rounding) */
        const double y_hi = curve.y_hi.f64, top = hyst_curve_eval(&curve, hi);
        CHECK(fabs(top - y_hi) <= curve.rounding.f64 + EPS * fabs(y_hi));
    }
    st = hyst_init_curve(&S, &curve, xl, yl, xr, yr, cap);
    if (st != HYST_OK) {
        CHECK(cap < 2u && st == HYST_ERR_CAPACITY);
        return 0;
    }
    fuzz_check_kinds(&curve); /* the twin with its kind named */
    CHECK(hyst_init_kind(&T, &curve, hyst_kind_everett_grid, xl2, yl2, xr2, yr2, cap) == HYST_OK);
    ref_egrid_init(&ref, &dom, &g);
    while (rd.at < rd.n && n < MAX_SAMPLES) {
        const unsigned op = rd_u8(&rd);
        double x, y, y_ref, tol, y_fit;
        int raw_y = 0;
        if (op == 0xF0u || op == 0xF1u || op == 0xF3u) { /* the twin catches up first */
            CHECK(hyst_process(&T, pend_x, pend_out, npend) >= 0);
            CHECK(npend == 0u || memcmp(pend_out, pend_y, npend * sizeof pend_y[0]) == 0);
            npend = 0u;
        }
        if (op == 0xF0u) { /* snapshot: the twin restored from it runs on bit for bit */
            size_t len = 0u;
            const unsigned pick = rd_u8(&rd) % cells;
            hyst_everett_grid_t other = g;
            hyst_curve_t c2;
            CHECK(hyst_snapshot_save(&S, snap, sizeof snap, &len) == HYST_OK);
            hyst_reset(&T);
            CHECK(hyst_snapshot_restore(&T, snap, len) == HYST_OK);
            other.weight[pick] += total; /* not a rounding of the total: another table */
            if (hyst_curve_from_everett_grid(&c2, &other, table2, TABLE_MAX) == HYST_OK &&
                hyst_init_curve(&U, &c2, xl3, yl3, xr3, yr3, cap) == HYST_OK) {
                memcpy(&keep_u, &U, sizeof U);
                CHECK(hyst_snapshot_restore(&U, snap, len) == HYST_ERR_CURVE);
                CHECK(memcmp(&U, &keep_u, sizeof U) == 0);
            }
            continue;
        }
        if (op == 0xF1u) {
            hyst_reset(&S);
            hyst_reset(&T);
            /* the record: back at lo, as a reset leaves it (the fit pushes a
             * reversal there as the reference would) */
            nospace_at[n] = pushes(lo) && (unsigned)ref.n == fit_cap;
            ref_egrid_init(&ref, &dom, &g);
            fx[n] = lo;
            fy[n] = g.y_lo;
            xs[n] = lo;
            ys[n] = g.y_lo;
            ++n;
            continue;
        }
        if (op == 0xF3u) { /* out to x1 inside the current branch and back: the loop closes */
            const double at = (double)(1u + rd_u8(&rd)) / 258.0;
            const double x0 = hyst_input(&S), y0 = hyst_output(&S), tp = ref.tx[ref.n - 1];
            const double x1 = x0 + (tp - x0) * at;
            /* not where the last output was held by the monotone guard (or the
             * branch is flat): the loop closes on the branch's own value there,
             * a rounding from the held one */
            if (!full && !held && hyst_tp_count(&S) + 3u < cap && x1 != x0 && x1 != tp) {
                (void)hyst_step(&S, x1);
                y = hyst_step(&S, x0);
                CHECK(hyst_status(&S) == HYST_OK && memcmp(&y, &y0, sizeof y) == 0);
            }
            continue;
        }
        if (op == 0xF2u) {
            x = g.knots[rd_u8(&rd) % (g.intervals + 1u)];
        } else {
            x = fuzz_sample_input(&rd, op, lo, hi, &y_fit, &raw_y);
        }
        x = x < hi ? x : hi; /* lo + (hi - lo) rounds past hi */
        {
            const double x_prev = hyst_input(&S), y_prev = hyst_output(&S);
            y = hyst_step(&S, x);
            held = x != x_prev && y == y_prev;
            full |= hyst_status(&S) == HYST_WARN_FULL;
            CHECK(hyst_status(&S) == HYST_OK || hyst_status(&S) == HYST_WARN_FULL);
            CHECK(isfinite(y));
            /* monotone: the output never moves against the input */
            CHECK(x > x_prev ? y >= y_prev : x < x_prev ? y <= y_prev : 1);
        }
        /* the fit's record (Madelung's rules as the reference's): a reversal
         * with fit_cap TPs stacked is refused */
        nospace_at[n] = pushes(x) && (unsigned)ref.n == fit_cap;
        y_ref = ref_everett_step(&ref, x);
        tol = (double)(ref.n + 1) * (hyst_rounding_bound(&S) + 8.0 * EPS * scale);
        if (full) {
            tol += hyst_error_bound(&S);
        }
        if (!raw) {
            CHECK(fabs(y - y_ref) <= tol);
        }
        pend_x[npend] = x;
        pend_y[npend] = y;
        ++npend;
        xs[n] = x;
        ys[n] = y;
        fx[n] = x;
        fy[n] = raw_y ? y_fit : y;
        exact &= !raw_y;
        ++n;
    }
    CHECK(hyst_process(&T, pend_x, pend_out, npend) >= 0);
    CHECK(npend == 0u || memcmp(pend_out, pend_y, npend * sizeof pend_y[0]) == 0);
    if (flags & 16u) { /* the float variant on float inputs, against the reference on them */
        hyst_curve_t c32;
        hyst_tcm_t F;
        if (hyst_f32_curve_from_everett_grid(&c32, &g, table32, TABLE_MAX) == HYST_OK &&
            (cap % 2u != 0u /* the kind named, or bound by the curve */
                 ? hyst_f32_init_kind(&F, &c32, hyst_f32_kind_everett_grid, fxl, fyl, fxr, fyr, cap)
                 : hyst_f32_init_curve(&F, &c32, fxl, fyl, fxr, fyr, cap)) == HYST_OK) {
            ref_egrid_init(&ref32, &dom32, &g);
            for (k = 0u; k < n; ++k) {
                const float x = (float)xs[k];
                const double y = (double)hyst_f32_step(&F, x), y_ref = ref_everett_step(&ref32, (double)x);
                double tol = (double)(ref32.n + 1) * ((double)hyst_f32_rounding_bound(&F) + 8.0 * EPS * scale);
                if (hyst_status(&F) == HYST_WARN_FULL || hyst_f32_error_bound(&F) > 0) {
                    break; /* merges: the bound on forgetting is the double run's check */
                }
                /* raw doubles reach the subnormals, where the relative bound says nothing */
                CHECK(hyst_status(&F) == HYST_OK && isfinite(y) && (raw || fabs(y - y_ref) <= tol));
            }
        }
    }
    if (flags & 2u) {
        check_compensator(&g, scale, raw, n);
    }
    if (flags & 4u) {
        /* raw grids: the reference's E underflows (a mass times a width squared) where
         * the library's does not, so the record is not held to it */
        check_fit(&g, n, fit_cap, exact && !full && !raw, scale, nospace_at);
        check_knots(n, lo, hi, g.intervals, nbins);
    }
    return 0;
}
