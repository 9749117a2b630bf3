/* SPDX-License-Identifier: MIT */
/* libFuzzer harness of the spline kind (curve.h, hyst_spline_t): its curve,
 * its compensators (hyst_curve_spline_inverse(), and tabulated:
 * hyst_curve_spline_inverse_table()) and its fit (ident.h,
 * hyst_spline_fit_*), built with HYST_USE_DOUBLE and checked against the
 * plain double reference tests/support/ref_tcm.c (ref_init_spline(): f0 in
 * the Hermite basis); any failed CHECK aborts.
 *
 * Input layout (reads past the end yield zeros, so every input is valid):
 *   [0]  flags: bit0 raw numbers (arbitrary doubles) else small splines;
 *        bit1 the compensator; bit2 the fit; bit3 refusal probes (probe
 *        byte below); bit4 the float variant beside; bit5 (small splines)
 *        a spline of the fit's space
 *   [1]  intervals K (byte % 34: 0 and 33 are refused)
 *   [2]  capacity (byte % 40: 0 and 1 are refused)
 *   [3]  the fit's turning points (byte % 48: below 2 refused)
 *   [4]  the fit's intervals (byte % 34: 0 and 33 refused)
 *   [5]  probe: which refusal bit3 tries (probe()), and 1 + it % 8 the
 *        tabulated compensator's intervals (bit1)
 *   then the spline: structured, lo (signed byte / 8), the span
 *   ((1 + byte % 64) / 4), value[0] (signed byte / 16; 0x80 is 2^23, a
 *   24-bit ADC's mid-scale), each piece's rise (byte < 40: 0, a flat piece,
 *   else (byte - 40) / 16, ten times that from 240) and each knot's slope
 *   ((byte & 63) / 16 times the smaller secant beside it, the larger with
 *   bit6: from 3 up a piece may dip and be refused), or with bit5 the K + 2
 *   I-spline weights (byte < 64: 0, else (byte - 64) / 16) whose values and
 *   slopes at the knots make the spline; raw, lo, hi, the K + 1 values and
 *   the K + 1 slopes as doubles. Then opcodes until the input ends:
 *   0xF0 a snapshot, restored into the twin (which then runs on), and
 *        refused by an instance of another spline (byte: which change);
 *   0xF1 reset;
 *   0xF2 the next sample on knot (byte % (K + 1)), lo + k (hi - lo) / K;
 *   0xF3 an excursion inside the current branch (byte: where) and back;
 *   0xF4 the next sample's output, as the fit sees it, a raw double
 *        (8 bytes), then the sample's byte;
 *   0xF5 hi, 0xF6 lo; any other byte b a sample lo + (hi - lo) b / 239.
 *
 * Checks: each refusal of hyst_f64_curve_from_spline() is the first of
 * curve.h's checks that fails, and writes nothing (the curve, its table):
 * the harness states each check on its own (a piece's least slope taken at
 * its vertex, overflow-free, the piece scaled by a power of two where its
 * numbers overflow; within the two evaluations' rounding either answer is
 * right); an accepted spline's hyst_spline_eval() and hyst_curve_eval()
 * equal the reference's f0 within one evaluation's bound (eval_bound()),
 * exactly at lo and hi, a forged curve (no table, no intervals, too many)
 * is refused; its outputs equal the reference within (d + 1) times (that
 * bound + 8 eps of the output scale), d the stacked turning points (raw
 * splines too while every number is within 2^+-400 of 1: no overflow, no
 * underflow), and once memory fills within the error bound on top where
 * f0'' keeps one sign (where it is proven, docs/memory.md), within the
 * output range elsewhere; the output never moves against the input; the
 * block call equals the step (a twin driven by hyst_process()); a snapshot
 * restored continues bit for bit, and an instance of a spline whose table
 * differs refuses it (HYST_ERR_CURVE), unchanged; an excursion inside the
 * current branch comes back to the same output bit for bit; the
 * compensator is refused exactly when a piece is flat
 * (HYST_ERR_NOT_INVERTIBLE), nothing written, its inverse is the spline
 * again, it maps y_lo to lo, its round trip model(compensator(y)) over the
 * model's own outputs returns y within (d + 1) times (twice the evaluation
 * bound + 8 eps of the output scale), its drive on the domain and never
 * against the desired output, its block call equal to its steps; the
 * tabulated compensator (hyst_curve_spline_inverse_table()) likewise:
 * refused with it (and for 0 intervals, another kind, no table), nothing
 * written, its error within HYST_INV_TABLE_TOL and the drive's rounding,
 * its inverse the spline, y_lo to lo, its round trip within the solved
 * one's bound plus (d + 1) times twice its error at f0's steepest slope
 * (its error measured at probes: between them more), its drive on the
 * domain and never against the desired output, its block call equal to
 * its steps; the float
 * variant refuses no later a check than the double one, writes nothing
 * when it refuses, and agrees with the reference on float inputs within
 * the same bound in float's epsilon; the fit of any K on the record the
 * spline made (a random Hermite spline is not a C2 spline of the fit's
 * space) refuses what ident.h says, writing nothing, and else gives finite
 * values, every slope >= 0, NOT_MONOTONE exactly when value[K] is not
 * above value[0], a spline the curve accepts (but for a piece the values'
 * rounding can tip, as ident.h allows) and an RMS that is the fitted
 * spline's own residual recomputed with the reference, within the rounding
 * of the normal equations and of the reference; a spline of the fit's
 * space, of its K, is fitted back from its own record within 1e-6 of its
 * output scale. FUZZ_SPLINE_STATS=1 prints how close each check came to
 * its tolerance.
 */

#include "fuzz_common.h"
#include "ref_tcm.h"

#ifndef HYST_USE_DOUBLE
#error "the differential harness compares a double core with a double reference"
#endif

#define EPS DBL_EPSILON
#define K_MAX HYST_SPLINE_MAX_INTERVALS
#define TABLE_MAX HYST_SPLINE_TABLE_LEN(K_MAX)
#define MAX_CAP 40u
#define BIG_CAP 600u
#define MAX_SAMPLES 512u
#define FIT_CAP 48u

static double xl[BIG_CAP], yl[BIG_CAP], xr[BIG_CAP], yr[BIG_CAP];
static double xl2[BIG_CAP], yl2[BIG_CAP], xr2[BIG_CAP], yr2[BIG_CAP];
static double xl3[BIG_CAP], yl3[BIG_CAP], xr3[BIG_CAP], yr3[BIG_CAP];
static float fxl[MAX_CAP], fyl[MAX_CAP], fxr[MAX_CAP], fyr[MAX_CAP];
static double table[TABLE_MAX], table2[TABLE_MAX], keep_table[TABLE_MAX];
static double inv_table[HYST_INV_TABLE_LEN(256u)];
static float table32[TABLE_MAX], keep_table32[TABLE_MAX];
static double xs[MAX_SAMPLES], ys[MAX_SAMPLES], ys2[MAX_SAMPLES], drive[MAX_SAMPLES];
static double pend_x[MAX_SAMPLES], pend_y[MAX_SAMPLES], pend_out[MAX_SAMPLES];
static hyst_wide_t fx[MAX_SAMPLES], fy[MAX_SAMPLES];
static hyst_wide_t fit_work[HYST_SPLINE_FIT_WORK(K_MAX, FIT_CAP)];
static unsigned char snap[HYST_SNAPSHOT_SIZE(MAX_CAP)];
static ref_tcm_t ref, ref2; /* 128 KB each: off the stack */
static hyst_curve_t curve, keep_curve;
static hyst_t S, T, U, keep_u;

/* How often the checks had something to check, and how close they came
 * (error / tolerance): FUZZ_SPLINE_STATS=1 prints these at exit. */
static unsigned long n_accepted, n_refused, n_samples, n_merged, n_snaps, n_foreign, n_loops;
static unsigned long n_comp, n_flat, n_trips, n_f32, n_fits, n_flat_fits, n_tipped;
static unsigned long n_tables, n_table_exact, n_table_trips;
static double worst_model, worst_merged, worst_f0, worst_trip, worst_f32, worst_rms, worst_own;
static double worst_table_trip;

static void print_stats(void)
{
    fprintf(stderr,
            "fuzz_spline: splines accepted %lu, refused %lu; samples against the reference %lu "
            "(worst %.3g of the tolerance; f0 %.3g), after merges with f0'' of one sign %lu "
            "(worst %.3g); snapshots %lu, refused by another spline %lu; loops closed %lu; "
            "compensators %lu (flat pieces refused %lu), round trips %lu (worst %.3g); tabulated "
            "%lu (intervals exact %lu), round trips %lu (worst %.3g); float "
            "samples %lu (worst %.3g); fits %lu (NOT_MONOTONE %lu, refused by the curve for the "
            "values' rounding %lu), RMS worst %.3g, a spline of the fit's space fitted back "
            "worst %.3g\n",
            n_accepted, n_refused, n_samples, worst_model, worst_f0, n_merged, worst_merged, n_snaps,
            n_foreign, n_loops, n_comp, n_flat, n_trips, worst_trip, n_tables, n_table_exact,
            n_table_trips, worst_table_trip, n_f32, worst_f32, n_fits, n_flat_fits, n_tipped, worst_rms, worst_own);
}

/* Records error / tolerance in *worst. */
static void ratio(double *worst, double err, double tol)
{
    if (tol > 0 && err / tol > *worst) *worst = err / tol;
}

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    if (getenv("FUZZ_SPLINE_STATS")) atexit(print_stats);
    return 0;
}

/* Piece k's cubic in t as curve.h defines it, value[k] left out: c[1..3];
 * c[0] its rise, c[4] its end slope per knot interval. */
static void piece(const hyst_spline_t *f, unsigned k, double h, double *c)
{
    const double rise = f->value[k + 1u] - f->value[k];
    const double m0 = h * f->slope[k], m1 = h * f->slope[k + 1u];
    c[0] = rise;
    c[1] = m0;
    c[2] = 3.0 * rise - 2.0 * m0 - m1;
    c[3] = m0 + m1 - 2.0 * rise;
    c[4] = m1;
}

/* The same piece from the knots' numbers scaled by a power of two, every
 * number at most 2: its shape where its own numbers overflow the type.
 * Scaling is exact but for what underflows (which the largest dwarfs), so
 * each coefficient is the unscaled one's rounding, scaled. */
static void piece_scaled(const hyst_spline_t *f, unsigned k, double h, double *c)
{
    int e, e_h, top = -2000;
    unsigned q;
    double rise, m0, m1;
    (void)frexp(h, &e_h);
    for (q = k; q <= k + 1u; ++q) { /* zeros left out: they would scale the rest for nothing */
        (void)frexp(f->value[q], &e);
        top = f->value[q] != 0 && e > top ? e : top;
        (void)frexp(f->slope[q], &e);
        top = f->slope[q] != 0 && e + e_h > top ? e + e_h : top;
    }
    rise = ldexp(f->value[k + 1u], -top) - ldexp(f->value[k], -top);
    m0 = ldexp(h, -e_h) * ldexp(f->slope[k], e_h - top);
    m1 = ldexp(h, -e_h) * ldexp(f->slope[k + 1u], e_h - top);
    c[0] = rise;
    c[1] = m0;
    c[2] = 3.0 * rise - 2.0 * m0 - m1;
    c[3] = m0 + m1 - 2.0 * rise;
    c[4] = m1;
}

/* A piece's least slope in t on [0, 1] against curve.h's "within 64
 * roundings of the piece's scale" (|rise| + both end slopes): 1 passes, 0
 * fails, -1 either. The harness takes it at the vertex, p'(t) = c1 + 2 c2
 * t + 3 c3 t^2 halved (no overflow), the library otherwise: each within 8
 * roundings of the slope's terms, and among subnormals a rounding is
 * absolute (8 times the least number). The ends are the knots' slopes,
 * checked >= 0 exactly before. */
static int piece_passes(const double *c)
{
    const double tol = 64.0 * EPS * fabs(c[0]) + 64.0 * EPS * c[1] + 64.0 * EPS * c[4];
    const double band =
        8.0 * EPS * fabs(c[1]) + 16.0 * EPS * fabs(c[2]) + 24.0 * EPS * fabs(c[3]) + 0x1p-1071;
    double t, half;
    if (!(c[3] > 0 && -c[2] > 0 && -c[2] < 3.0 * c[3])) {
        return 1; /* no inner minimum */
    }
    t = -c[2] / c[3] / 3.0;
    half = 0.5 * c[1] + t * (c[2] + 1.5 * (c[3] * t));
    if (half >= (band - tol) / 2.0) return 1;
    if (half < (-tol - band) / 2.0) return 0;
    return -1;
}

/* curve.h's checks of hyst_*_curve_from_spline() in its order, for the
 * double variant: the status; *alt a second one also right (HYST_OK when
 * none), where a piece is within rounding of the check's edge. A piece
 * whose numbers the type cannot hold is checked for its shape all the
 * same (scaled), and its numbers are the table's refusal, after NOSPACE. */
static hyst_status_t spline_expected(const hyst_spline_t *f, size_t len, hyst_status_t *alt)
{
    const unsigned n = f->intervals;
    double span, h, c[5];
    unsigned k;
    int table_ok = 1, scaled;
    *alt = HYST_OK;
    if (n < 1u || n > K_MAX) return HYST_ERR_DEGREE;
    span = f->hi - f->lo;
    if (!isfinite(f->lo) || !isfinite(f->hi) || !(f->lo < f->hi) || !isfinite(span) ||
        !isfinite((double)n / span)) {
        return HYST_ERR_DOMAIN; /* the knots per unit of input too: the curve's scale */
    }
    for (k = 0u; k <= n; ++k) {
        if (!isfinite(f->value[k]) || !isfinite(f->slope[k])) return HYST_ERR_COEFF;
    }
    for (k = 0u; k <= n; ++k) {
        if (!(f->slope[k] >= 0)) return HYST_ERR_NOT_INCREASING;
    }
    h = span / n;
    for (k = 0u; k < n; ++k) {
        int pass;
        piece(f, k, h, c);
        scaled = !isfinite(c[0]) || !isfinite(c[1]) || !isfinite(c[2]) || !isfinite(c[3]);
        if (scaled) {
            table_ok = 0;
            piece_scaled(f, k, h, c);
        }
        pass = piece_passes(c);
        if (pass == 0) return HYST_ERR_NOT_INCREASING;
        if (pass < 0 && *alt == HYST_OK) *alt = HYST_ERR_NOT_INCREASING;
    }
    if (!(f->value[n] > f->value[0])) return HYST_ERR_NOT_INCREASING;
    if (len < HYST_SPLINE_TABLE_LEN(n)) return HYST_ERR_NOSPACE;
    for (k = 0u; k <= n; ++k) table_ok &= isfinite(f->value[k] - f->value[0]);
    return table_ok ? HYST_OK : HYST_ERR_COEFF;
}

/* Rank of a refusal in curve.h's order (OK last): the float variant
 * refuses no later a check. COEFF is the numbers' check (3) when a value
 * or a slope is not finite, else the table's (6). */
static int rank(hyst_status_t st, const hyst_spline_t *f)
{
    unsigned k;
    switch (st) {
    case HYST_ERR_NULL: return 0;
    case HYST_ERR_DEGREE: return 1;
    case HYST_ERR_DOMAIN: return 2;
    case HYST_ERR_COEFF:
        for (k = 0u; k <= f->intervals && k <= K_MAX; ++k) {
            if (!isfinite(f->value[k]) || !isfinite(f->slope[k])) return 3;
        }
        return 6;
    case HYST_ERR_NOT_INCREASING: return 4;
    case HYST_ERR_NOSPACE: return 5;
    case HYST_OK: return 7;
    default: return -1;
    }
}

/* The constructor on f: the status, and nothing written on a refusal. */
static hyst_status_t build(hyst_curve_t *c, const hyst_spline_t *f, double *tab, size_t len)
{
    hyst_status_t st;
    memset(c, 0x5A, sizeof *c);
    memcpy(&keep_curve, c, sizeof *c);
    memcpy(keep_table, table, sizeof table);
    st = hyst_curve_from_spline(c, f, tab, len);
    if (st != HYST_OK) {
        CHECK(memcmp(c, &keep_curve, sizeof *c) == 0);
        CHECK(memcmp(keep_table, table, sizeof table) == 0);
    }
    return st;
}

static hyst_status_t build32(hyst_curve_t *c, const hyst_spline_t *f)
{
    hyst_curve_t keep;
    hyst_status_t st;
    memset(c, 0x5A, sizeof *c);
    memcpy(&keep, c, sizeof *c);
    memset(table32, 0x5A, sizeof table32);
    memcpy(keep_table32, table32, sizeof table32);
    st = hyst_f32_curve_from_spline(c, f, table32, TABLE_MAX);
    if (st != HYST_OK) {
        CHECK(memcmp(c, &keep, sizeof *c) == 0);
        CHECK(memcmp(keep_table32, table32, sizeof table32) == 0);
    }
    return st;
}

/* One damaged copy of an accepted spline (probe byte p), refused with the
 * status curve.h gives it (the harness's own reading, and for a small
 * spline of rises and slopes, strict, the one the damage is meant to hit),
 * nothing written; and the NULL arguments and the layout. */
static void probe(const hyst_spline_t *f, unsigned p, unsigned pick, int strict)
{
    hyst_spline_t bad = *f;
    const unsigned n = f->intervals, i = pick % (n + 1u), j = pick % n;
    size_t len = TABLE_MAX;
    hyst_status_t meant, want, alt, st;
    unsigned k;
    switch (p % 15u) {
    case 0: bad.intervals = 0u; meant = HYST_ERR_DEGREE; break;
    case 1: bad.intervals = K_MAX + 1u; meant = HYST_ERR_DEGREE; break;
    case 2: bad.hi = bad.lo; meant = HYST_ERR_DOMAIN; break;
    case 3: bad.lo = NAN; bad.slope[i] = -1.0; meant = HYST_ERR_DOMAIN; break;
    case 4: bad.lo = -DBL_MAX; bad.hi = DBL_MAX; meant = HYST_ERR_DOMAIN; break;
    case 5: bad.value[i] = NAN; bad.slope[j] = -1.0; meant = HYST_ERR_COEFF; break; /* before the slopes */
    case 6: bad.slope[i] = INFINITY; meant = HYST_ERR_COEFF; break;
    case 7: bad.slope[i] = -1e-300; len = 0u; meant = HYST_ERR_NOT_INCREASING; break; /* before NOSPACE */
    case 8: /* piece j flat between its knots with a slope at its start: it dips */
        bad.value[j + 1u] = bad.value[j];
        bad.slope[j] = bad.slope[j] > 0 ? bad.slope[j] : 1.0;
        meant = HYST_ERR_NOT_INCREASING;
        break;
    case 9: /* constant */
        for (k = 0u; k <= n; ++k) {
            bad.value[k] = f->value[0];
            bad.slope[k] = 0.0;
        }
        meant = HYST_ERR_NOT_INCREASING;
        break;
    case 10: len = HYST_SPLINE_TABLE_LEN(n) - 1u; meant = HYST_ERR_NOSPACE; break;
    case 11: { /* the same shape near the type's largest numbers: values from
                * 0 (value[0] taken off) and slopes scaled by the power of two
                * that brings the largest of them, and of the slopes per knot
                * interval, to [2^1023, 2^1024): NOSPACE first, then the
                * table's COEFF where a piece's numbers overflow */
        const double h = (f->hi - f->lo) / n;
        double big = 0.0;
        int e;
        for (k = 0u; k <= n; ++k) {
            big = fmax(big, fmax(fabs(f->value[k] - f->value[0]), fmax(h * f->slope[k], f->slope[k])));
        }
        (void)frexp(big, &e);
        for (k = 0u; k <= n; ++k) {
            bad.value[k] = ldexp(f->value[k] - f->value[0], DBL_MAX_EXP - e);
            bad.slope[k] = ldexp(f->slope[k], DBL_MAX_EXP - e);
        }
        len = (p / 15u) & 1u ? HYST_SPLINE_TABLE_LEN(n) - 1u : TABLE_MAX;
        meant = (p / 15u) & 1u ? HYST_ERR_NOSPACE : HYST_OK; /* or COEFF */
        break;
    }
    case 12: /* a slope far beyond the rise (the piece's numbers may overflow):
              * not increasing, before NOSPACE */
        bad.slope[i] = DBL_MAX;
        len = (p / 15u) & 1u ? HYST_SPLINE_TABLE_LEN(n) - 1u : TABLE_MAX;
        meant = HYST_ERR_NOT_INCREASING;
        break;
    case 13: /* a knot within a rounding of the last: a span the type holds, or refused */
        bad.hi = nextafter(bad.lo, INFINITY);
        meant = HYST_OK; /* not asserted: depends on the slopes */
        break;
    default: /* a value raised within rounding: the piece's check at its edge */
        bad.value[i] = nextafter(bad.value[i], INFINITY);
        meant = HYST_OK; /* not asserted */
        break;
    }
    want = spline_expected(&bad, len, &alt);
    if (strict && p % 15u < 13u) {
        CHECK(want == meant || (meant == HYST_OK && want == HYST_ERR_COEFF));
    }
    st = build(&curve, &bad, table, len);
    CHECK(st == want || st == alt);
    CHECK(hyst_curve_from_spline(NULL, f, table, TABLE_MAX) == HYST_ERR_NULL);
    CHECK(build(&curve, NULL, table, TABLE_MAX) == HYST_ERR_NULL);
    CHECK(build(&curve, f, NULL, TABLE_MAX) == HYST_ERR_NULL);
    CHECK(build(&curve, &bad, NULL, 0u) == HYST_ERR_NULL);
    CHECK(hyst_f64_curve_from_spline_(&curve, &bad, table, len, HYST_LAYOUT ^ 1ul) == HYST_ERR_LAYOUT);
}

/* What one evaluation of G (or of f0) may differ by from the reference's,
 * eps the type's: the table's coefficients (a few roundings of each
 * piece's rise and end slopes) and the cubic's evaluation (of its terms
 * and c0), the reference's own in the Hermite basis (of the values and
 * slopes), then where each reads the input: the library's s = (x - x_tp) K
 * / (hi - lo) within 4 eps of K knot intervals, the reference's lo + d and
 * x - (lo + k h) within 3 eps of max(|lo|, |hi|) / h intervals (4 eps of
 * the ends in float, which rounds lo and hi themselves), times the
 * steepest piece's slope per knot interval, |c1| + 2 |c2| + 3 |c3|. */
static double eval_bound(const hyst_spline_t *f, double eps)
{
    const unsigned n = f->intervals;
    const double span = f->hi - f->lo, h = span / n;
    const double ends = fmax(fabs(f->lo), fabs(f->hi));
    double v = 0.0, a = 0.0, terms = 0.0, steep = 0.0, c[5];
    unsigned k;
    for (k = 0u; k <= n; ++k) {
        v = fmax(v, fabs(f->value[k]));
        a = fmax(a, fabs(f->value[k] - f->value[0]));
    }
    for (k = 0u; k < n; ++k) {
        piece(f, k, h, c);
        terms = fmax(terms, fabs(c[0]) + fabs(c[1]) + fabs(c[2]) + fabs(c[3]) + c[4]);
        steep = fmax(steep, fabs(c[1]) + 2.0 * fabs(c[2]) + 3.0 * fabs(c[3]));
    }
    return 32.0 * eps * (v + a + terms) + 8.0 * eps * steep * ((double)n + ends / h + 1.0);
}

/* The output scale: the largest value and the range. */
static double out_scale(const hyst_spline_t *f)
{
    double v = 0.0;
    unsigned k;
    for (k = 0u; k <= f->intervals; ++k) v = fmax(v, fabs(f->value[k]));
    return v + (f->value[f->intervals] - f->value[0]);
}

/* Every number of a raw spline within 2^+-400 of 1 (or 0): the bounds'
 * relative roundings hold, nothing overflows or underflows. */
static int tame(const hyst_spline_t *f)
{
    const double big = 0x1p400, small = 0x1p-400, h = (f->hi - f->lo) / f->intervals;
    double v[2 * K_MAX + 6];
    unsigned k, m = 0u;
    v[m++] = f->lo;
    v[m++] = f->hi;
    v[m++] = h;
    v[m++] = f->intervals / (f->hi - f->lo);
    for (k = 0u; k <= f->intervals; ++k) {
        v[m++] = f->value[k];
        v[m++] = h * f->slope[k];
    }
    for (k = 0u; k < m; ++k) {
        if (v[k] != 0 && !(fabs(v[k]) <= big && fabs(v[k]) >= small)) return 0;
    }
    return 1;
}

/* Whether f0'' keeps one sign on [lo, hi] (each piece's, linear in t, at
 * both its ends): where it does not, hyst_error_bound() is not proven
 * (docs/memory.md), and outputs after a merge are held to the output range
 * only. */
static int one_signed(const hyst_spline_t *f)
{
    const double h = (f->hi - f->lo) / f->intervals;
    double c[5];
    int pos = 0, neg = 0;
    unsigned k;
    for (k = 0u; k < f->intervals; ++k) {
        piece(f, k, h, c);
        pos |= c[2] > 0 || c[2] + 3.0 * c[3] > 0;
        neg |= c[2] < 0 || c[2] + 3.0 * c[3] < 0;
    }
    return !(pos && neg);
}

/* Whether the reference (and so the fit's record) stacks a turning point
 * when x comes next. */
static int pushes(double x)
{
    const int rising = (ref.n - 1) % 2 == 0;
    return (x > ref.xp && !rising) || (x < ref.xp && rising);
}

/* Whether c is the spline curve of f, number for number (a compensator's
 * inverse). */
static int is_the_curve(const hyst_curve_t *c, const hyst_spline_t *f)
{
    return c->kind == (unsigned)HYST_CURVE_SPLINE && c->lo.f64 == curve.lo.f64 &&
           c->hi.f64 == curve.hi.f64 && c->y_lo.f64 == curve.y_lo.f64 &&
           c->y_hi.f64 == curve.y_hi.f64 && c->unit.f64 == curve.unit.f64 &&
           c->u.spline.table.f64 == table && c->u.spline.intervals == f->intervals &&
           c->u.spline.span.f64 == curve.u.spline.span.f64;
}

/* A compensator inv of the spline f over the desired outputs ys[0..n) (the
 * model's own) into a model: its drive on the domain and never against the
 * desired output, the model at it within (d + 1) tol of the desired output
 * (d the stacked turning points; tol < 0: not checked), its block call its
 * steps. */
static void round_trip(const hyst_curve_t *inv, const hyst_spline_t *f, double tol, size_t n,
                       double *worst, unsigned long *trips)
{
    hyst_t C, M;
    double most;
    CHECK(hyst_init_curve(&C, inv, xl2, yl2, xr2, yr2, BIG_CAP) == HYST_OK);
    CHECK(hyst_init_curve(&M, &curve, xl3, yl3, xr3, yr3, BIG_CAP) == HYST_OK);
    most = fuzz_round_trip(&C, &M, ys, n, f->lo, f->hi, tol, drive);
    if (tol >= 0) {
        *worst = fmax(*worst, most);
        *trips += (unsigned long)n;
    }
    CHECK(hyst_init_curve(&C, inv, xl2, yl2, xr2, yr2, BIG_CAP) == HYST_OK);
    CHECK(hyst_process(&C, ys, ys2, n) >= 0);
    CHECK(n == 0u || memcmp(drive, ys2, n * sizeof ys2[0]) == 0);
}

/* The tabulated compensator of an invertible spline over the desired
 * outputs ys[0..n): see the header. */
static void check_table_compensator(const hyst_spline_t *f, double e_g, double scale, int checked,
                                    size_t n, size_t intervals)
{
    hyst_curve_t inv, back;
    const double lo = f->lo, hi = f->hi, span = hi - lo, h = span / f->intervals;
    const double end = fmax(fabs(lo), fabs(hi));
    double steep = 0.0, err, c[5];
    size_t k;
    const hyst_status_t st = hyst_curve_spline_inverse_table(&inv, &curve, inv_table, intervals);
    if (st == HYST_ERR_ILL_CONDITIONED) { /* intervals over the output range overflow */
        CHECK(f->value[f->intervals] - f->value[0] < 0x1p-1000);
        return;
    }
    CHECK(st == HYST_OK && inv.kind == (unsigned)HYST_CURVE_SPLINE_INV_TABLE);
    ++n_tables;
    n_table_exact += (unsigned long)inv.u.inv_table.exact;
    /* the tolerance and the drive's last rounding, rounded up to a float */
    err = hyst_curve_inverse_error(&inv);
    CHECK(err >= 0 && (!checked || err <= (HYST_INV_TABLE_TOL + EPS * end / span) * (1.0 + 1e-6)));
    /* its inverse is the spline again, number for number */
    CHECK(hyst_curve_spline_inverse(&back, &inv) == HYST_OK);
    CHECK(is_the_curve(&back, f));
    CHECK(hyst_curve_eval(&inv, f->value[0]) == lo);
    for (k = 0u; k < f->intervals; ++k) {
        piece(f, (unsigned)k, h, c);
        steep = fmax(steep, (fabs(c[1]) + 2.0 * fabs(c[2]) + 3.0 * fabs(c[3])) / h);
    }
    /* the solved compensator's round trip, and the table's error per
     * stacked TP in the drive, at f0's steepest slope: twice the error
     * measured at its probes, for between them */
    round_trip(&inv, f, checked ? 2.0 * e_g + 8.0 * EPS * scale + steep * 2.0 * err * span : -1.0, n,
               &worst_table_trip, &n_table_trips);
}

/* The compensator over the desired outputs ys[0..n) (the model's own): see
 * the header. */
static void check_compensator(const hyst_spline_t *f, double e_g, double scale, int checked, size_t n,
                              size_t intervals)
{
    static const hyst_poly_t p = {3, 0.0, 1.0, {1.0, 0.0, 1.0, 0.0}};
    hyst_curve_t inv, other, back;
    const double lo = f->lo, hi = f->hi;
    const double end = fmax(fabs(lo), fabs(hi)), ulp = nextafter(end, INFINITY) - end;
    int flat = 0;
    size_t k;
    for (k = 0u; k < f->intervals; ++k) {
        flat |= !(f->value[k + 1u] - f->value[0] > f->value[k] - f->value[0]);
    }
    memset(&inv, 0x5A, sizeof inv);
    memcpy(&other, &inv, sizeof inv);
    CHECK(hyst_curve_spline_inverse(NULL, &curve) == HYST_ERR_NULL);
    CHECK(hyst_curve_spline_inverse(&inv, NULL) == HYST_ERR_NULL);
    CHECK(hyst_curve_inverse(&inv, &curve) == HYST_ERR_ARG);
    CHECK(hyst_curve_check(&curve) == HYST_ERR_ARG);
    back = curve;
    back.layout ^= 1ul;
    CHECK(hyst_curve_spline_inverse(&inv, &back) == HYST_ERR_LAYOUT);
    CHECK(hyst_curve_from_poly(&back, &p) == HYST_OK);
    CHECK(hyst_curve_spline_inverse(&inv, &back) == HYST_ERR_ARG); /* another kind */
    CHECK(memcmp(&inv, &other, sizeof inv) == 0);
    inv_table[0] = 123.0;
    CHECK(hyst_curve_spline_inverse_table(&inv, &curve, inv_table, 0u) == HYST_ERR_ARG);
    CHECK(hyst_curve_spline_inverse_table(&inv, &back, inv_table, intervals) == HYST_ERR_ARG);
    CHECK(hyst_curve_spline_inverse_table(&inv, &curve, NULL, intervals) == HYST_ERR_NULL);
    CHECK(memcmp(&inv, &other, sizeof inv) == 0 && inv_table[0] == 123.0);
    if (flat) {
        CHECK(hyst_curve_spline_inverse(&inv, &curve) == HYST_ERR_NOT_INVERTIBLE);
        CHECK(hyst_curve_spline_inverse_table(&inv, &curve, inv_table, intervals) ==
              HYST_ERR_NOT_INVERTIBLE);
        ++n_flat;
        CHECK(memcmp(&inv, &other, sizeof inv) == 0 && inv_table[0] == 123.0);
        return;
    }
    CHECK(hyst_curve_spline_inverse(&inv, &curve) == HYST_OK);
    ++n_comp;
    CHECK(inv.kind == (unsigned)HYST_CURVE_SPLINE_INV);
    CHECK(hyst_curve_inverse(&other, &inv) == HYST_ERR_ARG);
    /* its inverse is the spline again; in place too */
    CHECK(hyst_curve_spline_inverse(&back, &inv) == HYST_OK);
    CHECK(is_the_curve(&back, f));
    other = curve;
    CHECK(hyst_curve_spline_inverse(&other, &other) == HYST_OK && other.kind == inv.kind &&
          other.lo.f64 == inv.lo.f64 && other.hi.f64 == inv.hi.f64 && other.unit.f64 == inv.unit.f64);
    /* the ends: y_lo to lo exactly, y_hi to hi within the drive's rounding;
     * a knot's output (where y_lo plus it gives it back exactly) to the
     * knot, lo + k h, exactly */
    CHECK(hyst_curve_eval(&inv, f->value[0]) == lo);
    CHECK(fabs(hyst_curve_eval(&inv, f->value[f->intervals]) - hi) <= 2.0 * ulp);
    for (k = 1u; k < f->intervals; ++k) {
        const double y = f->value[0] + table[4u * k];
        if (y - f->value[0] == table[4u * k]) {
            CHECK(hyst_curve_eval(&inv, y) == lo + (double)k * ((hi - lo) / f->intervals));
        }
    }
    /* G^-1 stops within its cubic's rounding of the output step (within
     * e_g) or on neighbouring numbers, the drive adds its roundings (e_g's
     * input terms), and the model evaluates once more (e_g) */
    round_trip(&inv, f, checked ? 2.0 * e_g + 8.0 * EPS * scale : -1.0, n, &worst_trip, &n_trips);
    check_table_compensator(f, e_g, scale, checked, n, intervals);
}

/* Whether the curve may refuse a fitted spline as not increasing: ident.h
 * allows it where the values' rounding tips a piece. A knot's value is
 * y_lo plus the rise summed from lo, each within a few roundings of
 * |value| + |value - y_lo|, which moves the piece's least slope by 1.5
 * times as much: when that reaches the check's margin over its own
 * evaluation (half its 64 roundings of the piece's scale). */
static int values_may_tip(const hyst_spline_t *f)
{
    const double h = (f->hi - f->lo) / f->intervals;
    unsigned k;
    for (k = 0u; k < f->intervals; ++k) {
        const double a0 = fabs(f->value[k]) + fabs(f->value[k] - f->value[0]);
        const double a1 = fabs(f->value[k + 1u]) + fabs(f->value[k + 1u] - f->value[0]);
        const double piece_scale =
            fabs(f->value[k + 1u] - f->value[k]) + h * (f->slope[k] + f->slope[k + 1u]);
        if (16.0 * (a0 + a1) >= 32.0 * piece_scale) return 1;
    }
    return 0;
}

/* The fit of fit_k intervals of the record (fx, fy)[0..n) on [lo, hi]:
 * see the header. */
static void check_fit(double lo, double hi, unsigned fit_k, unsigned fit_cap, size_t n, int exact,
                      const int *nospace_at, double own)
{
    static hyst_spline_fit_t fit, keep_fit;
    hyst_spline_t got, keep_f;
    hyst_wide_t rms = -1, keep_rms;
    const size_t work_len = fit_k >= 1u && fit_k <= K_MAX ? HYST_SPLINE_FIT_WORK(fit_k, fit_cap) : 0u;
    hyst_status_t st;
    size_t k, used = 0u;
    double y0 = 0.0, spread = 0.0;
    memset(&fit, 0x5A, sizeof fit);
    memcpy(&keep_fit, &fit, sizeof fit);
    CHECK(hyst_spline_fit_init(NULL, 1u, lo, hi, fit_work, work_len) == HYST_ERR_NULL);
    CHECK(hyst_spline_fit_init(&fit, 1u, lo, hi, NULL, work_len) == HYST_ERR_NULL);
    CHECK(hyst_spline_fit_init(&fit, 0u, lo, hi, fit_work, work_len) == HYST_ERR_DEGREE);
    CHECK(hyst_spline_fit_init(&fit, K_MAX + 1u, lo, hi, fit_work, work_len) == HYST_ERR_DEGREE);
    CHECK(hyst_spline_fit_init(&fit, 1u, hi, lo, fit_work, work_len) == HYST_ERR_DOMAIN);
    CHECK(hyst_spline_fit_init(&fit, 1u, NAN, hi, fit_work, work_len) == HYST_ERR_DOMAIN);
    CHECK(hyst_spline_fit_init(&fit, 1u, -DBL_MAX, DBL_MAX, fit_work, work_len) == HYST_ERR_DOMAIN);
    CHECK(hyst_spline_fit_init(&fit, 1u, lo, hi, fit_work, HYST_SPLINE_FIT_WORK(1u, 2u) - 1u) ==
          HYST_ERR_NOSPACE);
    CHECK(memcmp(&fit, &keep_fit, sizeof fit) == 0);
    st = hyst_spline_fit_init(&fit, fit_k, lo, hi, fit_work, work_len);
    if (fit_k < 1u || fit_k > K_MAX || !isfinite(fit_k / (hi - lo)) || fit_cap < 2u) {
        /* the spline's domain, with the fit's knots per unit of input */
        CHECK(st == (fit_k < 1u || fit_k > K_MAX       ? HYST_ERR_DEGREE
                     : !isfinite(fit_k / (hi - lo)) ? HYST_ERR_DOMAIN
                                                     : HYST_ERR_NOSPACE));
        CHECK(memcmp(&fit, &keep_fit, sizeof fit) == 0);
        return;
    }
    CHECK(st == HYST_OK);
    CHECK(hyst_spline_fit_add(NULL, lo, 0.0) == HYST_ERR_NULL);
    CHECK(hyst_spline_fit_add(&fit, NAN, 0.0) == HYST_ERR_NONFINITE); /* ignored */
    {
        const double past = nextafter(hi, INFINITY); /* ignored */
        CHECK(hyst_spline_fit_add(&fit, past, 0.0) ==
              (isfinite(past) ? HYST_ERR_DOMAIN : HYST_ERR_NONFINITE));
    }
    memset(&got, 0x5A, sizeof got);
    memcpy(&keep_f, &got, sizeof got);
    keep_rms = rms;
    CHECK(hyst_spline_fit_solve(&fit, &got, &rms) == HYST_ERR_SINGULAR); /* nothing yet */
    CHECK(hyst_spline_fit_solve(NULL, &got, &rms) == HYST_ERR_NULL);
    CHECK(hyst_spline_fit_solve(&fit, NULL, &rms) == HYST_ERR_NULL);
    CHECK(hyst_spline_fit_solve(&fit, &got, NULL) == HYST_ERR_NULL);
    CHECK(memcmp(&got, &keep_f, sizeof got) == 0 && memcmp(&rms, &keep_rms, sizeof rms) == 0);
    for (k = 0u; k < n; ++k) {
        st = hyst_spline_fit_add(&fit, fx[k], fy[k]);
        if (nospace_at[k]) { /* more turning points than fit_cap: refused, the record stops */
            CHECK(st == HYST_ERR_NOSPACE);
            break;
        }
        CHECK(st == HYST_OK || (st == HYST_ERR_NONFINITE && !isfinite(fy[k])));
        if (st == HYST_OK) {
            if (used == 0u) y0 = fy[k];
            spread = fmax(spread, fabs(fy[k] - y0));
            ++used;
        }
    }
    n = k;
    st = hyst_spline_fit_solve(&fit, &got, &rms);
    if (used < 2u) {
        CHECK(st == HYST_ERR_SINGULAR);
        CHECK(memcmp(&got, &keep_f, sizeof got) == 0 && memcmp(&rms, &keep_rms, sizeof rms) == 0);
        return;
    }
    /* COEFF: outputs so far apart (or so large) that the normal equations
     * (sums of their squares, of products with regressors up to 1) or the
     * values may overflow, or slopes (the spread per knot interval, times
     * the knots per unit of input) near the type's largest; nothing written */
    if (st == HYST_ERR_COEFF) {
        CHECK(!exact || !(spread < sqrt(DBL_MAX / (double)(n * HYST_SPLINE_FIT_COLS(fit_k))) / 16.0) ||
              !(fabs(y0) < DBL_MAX / 16.0) || !(spread * (fit_k / (hi - lo)) < 0x1p-20 * DBL_MAX));
        CHECK(memcmp(&got, &keep_f, sizeof got) == 0 && memcmp(&rms, &keep_rms, sizeof rms) == 0);
        return;
    }
    CHECK(st == HYST_OK || st == HYST_ERR_NOT_MONOTONE);
    CHECK(got.intervals == fit_k && got.lo == lo && got.hi == hi);
    CHECK(isfinite(rms) && rms >= 0);
    for (k = 0u; k <= fit_k; ++k) {
        CHECK(isfinite(got.value[k]) && isfinite(got.slope[k]) && got.slope[k] >= 0);
    }
    /* NOT_MONOTONE: every weight 0, or value[K] not above value[0] */
    CHECK((st == HYST_ERR_NOT_MONOTONE) == !(got.value[fit_k] > got.value[0]));
    {
        hyst_curve_t fitted;
        hyst_status_t alt;
        const hyst_status_t cs = hyst_curve_from_spline(&fitted, &got, table2, TABLE_MAX);
        const hyst_status_t want = spline_expected(&got, TABLE_MAX, &alt);
        ++n_fits;
        n_flat_fits += st == HYST_ERR_NOT_MONOTONE;
        n_tipped += st == HYST_OK && cs == HYST_ERR_NOT_INCREASING;
        if (st == HYST_ERR_NOT_MONOTONE) {
            CHECK(cs == HYST_ERR_NOT_INCREASING || cs == HYST_ERR_COEFF);
        } else {
            CHECK(cs == HYST_OK || (cs == HYST_ERR_NOT_INCREASING && values_may_tip(&got)) ||
                  (cs == HYST_ERR_COEFF && want == HYST_ERR_COEFF));
        }
    }
    { /* the RMS: the fitted spline's residual on the record, by the reference */
        const double e_g = eval_bound(&got, EPS);
        const double h = (hi - lo) / fit_k;
        double ss = 0.0, most, delta, tol, v0 = 0.0, a = 0.0, weights, steep = 0.0;
        long depth = 0;
        size_t m = 0u;
        for (k = 0u; k <= fit_k; ++k) {
            v0 = fmax(v0, fabs(got.value[k]));
            a = fmax(a, fabs(got.value[k] - got.value[0]));
            steep = fmax(steep, got.slope[k]);
        }
        /* the weights' sum: value[K] - value[0] is their sum, each weight
         * times its I-spline at hi, 1/6 at least */
        weights = 6.0 * (got.value[fit_k] - got.value[0]);
        ref_init_spline(&ref2, fit_k, got.value, got.slope, lo, hi, 0);
        for (k = 0u; k < n; ++k) {
            const double y = ref_step(&ref2, fx[k]);
            depth = ref2.n > depth ? ref2.n : depth;
            if (isfinite(fy[k])) {
                const double d = fy[k] - y;
                ss += d * d;
                ++m;
            }
        }
        CHECK(m == used);
        ss = sqrt(ss / (double)m);
        /* a record of a spline of the fit's space, its own outputs: fitted
         * back within the identification's tolerance, 1e-6 of its output
         * scale (own) */
        CHECK(!(own > 0) || ss <= 1e-6 * own);
        ratio(&worst_own, ss, 1e-6 * own);
        most = fmax(ss, rms);
        /* delta: how far the reference's outputs of the spline returned may
         * be from the fit's own model (its weights), at each stacked
         * turning point: the reference's evaluation, the values returned
         * (y_lo plus a sum of K + 2 terms, within K + 4 roundings of
         * |value| + |rise| + the weights' sum) and the slopes returned
         * (within 3 roundings, or one subnormal where they underflow),
         * which a branch weighs by at most 8/27 knot interval */
        delta = (double)(depth + 1) * (e_g + 8.0 * EPS * (v0 + a) +
                                       4.0 * (double)(fit_k + 4u) * EPS * (v0 + a + weights) +
                                       h * (3.0 * EPS * steep + 0x1p-1074));
        /* the RMS from the normal equations: the sum of squares about the
         * first output less the fitted part, each term known within
         * (samples + columns) roundings of (spread + the weights' sum)^2
         * (regressors up to 1): the weights, not the fit, set it where the
         * record barely moves a weight's column and its weight grows;
         * where the squares are subnormal, each rounding is absolute */
        tol = 16.0 * (double)(m + HYST_SPLINE_FIT_COLS(fit_k)) *
                  (EPS * (spread + weights) * (spread + weights) + 0x1p-1074) +
              2.0 * delta * (most + delta);
        CHECK(fabs(rms * rms - ss * ss) <= tol || !isfinite(tol));
        ratio(&worst_rms, fabs(rms * rms - ss * ss), tol);
    }
}

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size)
{
    static int nospace_at[MAX_SAMPLES];
    reader_t rd = {data, size, 0u};
    const unsigned flags = rd_u8(&rd);
    const int raw = (flags & 1u) != 0u, in_space = !raw && (flags & 32u) != 0u;
    hyst_spline_t f;
    size_t cap, n = 0u, npend = 0u, k;
    unsigned i, fit_cap, fit_k, probe_byte, nk;
    double scale, e_g, lo, hi, span;
    int full = 0, exact = 1, held = 0, checked, one_sign;
    hyst_status_t st, want, alt;
    memset(&f, 0, sizeof f);
    f.intervals = rd_u8(&rd) % 34u;
    cap = rd_u8(&rd) % MAX_CAP;
    fit_cap = rd_u8(&rd) % FIT_CAP;
    fit_k = rd_u8(&rd) % 34u;
    probe_byte = rd_u8(&rd);
    nk = f.intervals <= K_MAX ? f.intervals : K_MAX;
    if (raw) {
        f.lo = rd_f64(&rd);
        f.hi = rd_f64(&rd);
        for (i = 0u; i <= nk; ++i) f.value[i] = rd_f64(&rd);
        for (i = 0u; i <= nk; ++i) f.slope[i] = rd_f64(&rd);
    } else {
        double rise[K_MAX], h;
        f.lo = (double)(signed char)rd_u8(&rd) / 8.0;
        f.hi = f.lo + (double)(1u + rd_u8(&rd) % 64u) / 4.0;
        f.value[0] = (double)(signed char)rd_u8(&rd) / 16.0;
        if (f.value[0] == -8.0) f.value[0] = 8388608.0; /* byte 0x80: a 24-bit ADC's mid-scale */
        h = (f.hi - f.lo) / (nk > 0u ? nk : 1u);
        if (in_space) { /* f0 = value[0] + sum w_j I_j: values and slopes at the knots */
            double w[K_MAX + 2];
            for (i = 0u; i <= nk + 1u; ++i) {
                const unsigned b = rd_u8(&rd);
                w[i] = b < 64u ? 0.0 : (double)(b - 64u) / 16.0;
            }
            for (i = 0u; i <= nk; ++i) {
                /* I_j(x_i): B_j's pieces (whole integrals 1/6, 2/3, 1/6) on
                 * the intervals j - 2 .. j, those from lo to x_i */
                static const double whole[3] = {1.0 / 6.0, 2.0 / 3.0, 1.0 / 6.0};
                double sum = 0.0;
                unsigned j, q;
                for (j = 0u; j <= nk + 1u; ++j) {
                    for (q = 0u; q < 3u; ++q) {
                        if (j + q >= 2u && j + q - 2u < i) sum += w[j] * whole[q];
                    }
                }
                f.value[i] = f.value[0] + sum;
                f.slope[i] = (w[i] + w[i + 1u]) / 2.0 / h; /* B_i and B_(i+1) are 1/2 at x_i */
            }
        }
        for (i = 0u; i < nk && !in_space; ++i) {
            const unsigned b = rd_u8(&rd);
            rise[i] = b < 40u ? 0.0 : (double)(b - 40u) / 16.0 * (b >= 240u ? 10.0 : 1.0);
            f.value[i + 1u] = f.value[i] + rise[i];
        }
        for (i = 0u; i <= nk && nk > 0u && !in_space; ++i) {
            const unsigned b = rd_u8(&rd);
            const double left = rise[i > 0u ? i - 1u : 0u] / h, right = rise[i < nk ? i : nk - 1u] / h;
            f.slope[i] = (double)(b & 63u) / 16.0 * ((b & 64u) ? fmax(left, right) : fmin(left, right));
        }
    }
    want = spline_expected(&f, TABLE_MAX, &alt);
    st = build(&curve, &f, table, TABLE_MAX);
    CHECK(st == want || st == alt);
    CHECK(raw || st == HYST_OK || st == HYST_ERR_DEGREE || st == HYST_ERR_NOT_INCREASING);
    if (flags & 16u) { /* the float variant: refuses no later a check, writes nothing then */
        hyst_curve_t c32;
        const hyst_status_t s32 = build32(&c32, &f);
        CHECK(rank(s32, &f) >= 0 && rank(s32, &f) <= rank(st, &f));
    }
    lo = f.lo;
    hi = f.hi;
    span = hi - lo;
    ++*(st == HYST_OK ? &n_accepted : &n_refused);
    if (st != HYST_OK) {
        if (flags & 4u) { /* the fit's refusals of the domain */
            hyst_spline_fit_t fit;
            const hyst_status_t fs = hyst_spline_fit_init(&fit, nk > 0u ? nk : 1u, lo, hi, fit_work,
                                                          sizeof fit_work / sizeof fit_work[0]);
            const double s = (double)(nk > 0u ? nk : 1u) / span;
            CHECK(fs == (isfinite(lo) && isfinite(hi) && lo < hi && isfinite(span) && isfinite(s)
                             ? HYST_OK
                             : HYST_ERR_DOMAIN));
        }
        return 0;
    }
    if (flags & 8u) {
        probe(&f, probe_byte, (unsigned)rd.at, !raw && !in_space);
        CHECK(build(&curve, &f, table, TABLE_MAX) == HYST_OK);
    }
    checked = !raw || tame(&f);
    one_sign = one_signed(&f);
    e_g = eval_bound(&f, EPS);
    scale = out_scale(&f);
    /* f0 itself: exact at the ends, the reference's elsewhere */
    CHECK(hyst_spline_eval(NULL, lo) == 0.0);
    CHECK(hyst_spline_eval(&f, lo) == f.value[0] && hyst_spline_eval(&f, lo - 1.0) == f.value[0]);
    CHECK(hyst_spline_eval(&f, hi) == f.value[f.intervals] &&
          hyst_spline_eval(&f, INFINITY) == f.value[f.intervals]);
    CHECK(hyst_curve_eval(&curve, lo) == f.value[0]);
    { /* a spline of no intervals or too many: 0; a curve forged so: refused */
        hyst_spline_t g = f;
        hyst_curve_t forged = curve, inv;
        g.intervals = (unsigned)rd.at % 2u ? 0u : K_MAX + 1u;
        CHECK(hyst_spline_eval(&g, lo) == 0.0);
        if ((unsigned)rd.at % 3u == 0u) {
            forged.u.spline.table.f64 = NULL;
        } else {
            forged.u.spline.intervals = g.intervals;
        }
        CHECK(hyst_init_curve(&U, &forged, xl3, yl3, xr3, yr3, MAX_CAP) == HYST_ERR_ARG);
        CHECK(hyst_curve_spline_inverse(&inv, &forged) == HYST_ERR_ARG);
    }
    ref_init_spline(&ref, f.intervals, f.value, f.slope, lo, hi, 0);
    if (checked) {
        const double top = hyst_curve_eval(&curve, hi);
        CHECK(fabs(top - f.value[f.intervals]) <= e_g + 8.0 * EPS * scale);
    }
    st = hyst_init_curve(&S, &curve, xl, yl, xr, yr, cap);
    if (st != HYST_OK) {
        CHECK(cap < 2u && st == HYST_ERR_CAPACITY);
        return 0;
    }
    fuzz_check_kinds(&curve); /* the twin with its kind named */
    CHECK(hyst_init_kind(&T, &curve, hyst_kind_spline, xl2, yl2, xr2, yr2, cap) == HYST_OK);
    CHECK(hyst_output(&S) == f.value[0]);
    while (rd.at < rd.n && n < MAX_SAMPLES) {
        const unsigned op = rd_u8(&rd);
        double x, y, y_ref, tol, y_fit = 0.0;
        int raw_y = 0;
        if (op == 0xF0u || op == 0xF1u || op == 0xF3u) { /* the twin catches up first */
            CHECK(hyst_process(&T, pend_x, pend_out, npend) >= 0);
            CHECK(npend == 0u || memcmp(pend_out, pend_y, npend * sizeof pend_y[0]) == 0);
            npend = 0u;
        }
        if (op == 0xF0u) { /* snapshot: the twin restored from it runs on bit for bit */
            size_t len = 0u;
            const unsigned pick = rd_u8(&rd);
            hyst_spline_t other = f;
            hyst_curve_t c2;
            CHECK(hyst_snapshot_save(&S, snap, sizeof snap, &len) == HYST_OK);
            ++n_snaps;
            hyst_reset(&T);
            CHECK(hyst_snapshot_restore(&T, snap, len) == HYST_OK);
            switch (pick % 3u) { /* another spline, on the same domain */
            case 0:
                for (i = 0u; i <= f.intervals; ++i) {
                    other.value[i] *= 2.0;
                    other.slope[i] *= 2.0;
                }
                break;
            case 1: other.slope[(pick / 3u) % (f.intervals + 1u)] *= 0.5; break;
            default: other.value[f.intervals] += f.value[f.intervals] - f.value[0]; break;
            }
            if (hyst_curve_from_spline(&c2, &other, table2, TABLE_MAX) == HYST_OK &&
                memcmp(table, table2, HYST_SPLINE_TABLE_LEN(f.intervals) * sizeof table[0]) != 0 &&
                hyst_init_curve(&U, &c2, xl3, yl3, xr3, yr3, cap) == HYST_OK) {
                memcpy(&keep_u, &U, sizeof U);
                CHECK(hyst_snapshot_restore(&U, snap, len) == HYST_ERR_CURVE);
                CHECK(memcmp(&U, &keep_u, sizeof U) == 0);
                ++n_foreign;
            }
            continue;
        }
        if (op == 0xF1u) {
            hyst_reset(&S);
            hyst_reset(&T);
            CHECK(hyst_output(&S) == f.value[0]);
            /* the record: back at lo, as a reset leaves it (the fit pushes a
             * reversal there as the reference would) */
            nospace_at[n] = pushes(lo) && (unsigned)ref.n == fit_cap;
            ref_init_spline(&ref, f.intervals, f.value, f.slope, lo, hi, 0);
            fx[n] = lo;
            fy[n] = f.value[0];
            xs[n] = lo;
            ys[n] = f.value[0];
            ++n;
            held = 0;
            continue;
        }
        if (op == 0xF3u) { /* out to x1 inside the current branch and back: the loop closes */
            const double at = (double)(1u + rd_u8(&rd)) / 258.0;
            const double x0 = hyst_input(&S), y0 = hyst_output(&S), tp = ref.x[ref.n - 1];
            const double x1 = x0 + (tp - x0) * at;
            /* not where the last output was held by the monotone guard: the
             * loop closes on the branch's own value there, a rounding from
             * the held one */
            if (!full && !held && hyst_tp_count(&S) + 3u < cap && x1 != x0 && x1 != tp) {
                (void)hyst_step(&S, x1);
                y = hyst_step(&S, x0);
                CHECK(hyst_status(&S) == HYST_OK && memcmp(&y, &y0, sizeof y) == 0);
                ++n_loops;
            }
            continue;
        }
        if (op == 0xF2u) {
            const unsigned q = rd_u8(&rd) % (f.intervals + 1u);
            x = lo + span * q / f.intervals;
        } else {
            x = fuzz_sample_input(&rd, op, lo, hi, &y_fit, &raw_y);
        }
        x = x < hi ? x : hi; /* lo + (hi - lo) rounds past hi */
        {
            const double x_prev = hyst_input(&S), y_prev = hyst_output(&S);
            y = hyst_step(&S, x);
            if (x != x_prev) { /* a repeated input keeps the output, held or not */
                held = y == y_prev;
            }
            full |= hyst_status(&S) == HYST_WARN_FULL;
            CHECK(hyst_status(&S) == HYST_OK || hyst_status(&S) == HYST_WARN_FULL);
            CHECK(isfinite(y));
            /* monotone: the output never moves against the input */
            CHECK(x > x_prev ? y >= y_prev : x < x_prev ? y <= y_prev : 1);
        }
        /* the fit's record: a reversal with fit_cap TPs stacked is refused */
        nospace_at[n] = pushes(x) && (unsigned)ref.n == fit_cap;
        y_ref = ref_step(&ref, x);
        tol = (double)(ref.n + 1) * (e_g + 8.0 * EPS * scale);
        if (full) {
            tol += hyst_error_bound(&S);
        }
        if (checked) {
            if (!full || one_sign) {
                CHECK(fabs(y - y_ref) <= tol);
                ratio(full ? &worst_merged : &worst_model, fabs(y - y_ref), tol);
                ++*(full ? &n_merged : &n_samples);
            } else { /* forgotten loops, the bound not proven: the output range */
                CHECK(y >= f.value[0] - tol && y <= f.value[f.intervals] + tol);
            }
            CHECK(fabs(hyst_spline_eval(&f, x) - ref_f0(&ref, x)) <= e_g);
            ratio(&worst_f0, fabs(hyst_spline_eval(&f, x) - ref_f0(&ref, x)), e_g);
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
    if ((flags & 16u) && !raw) { /* the float variant on float inputs, against the reference on them */
        hyst_curve_t c32;
        hyst_tcm_t F;
        const double e32 = eval_bound(&f, FLT_EPSILON);
        if (build32(&c32, &f) == HYST_OK &&
            hyst_f32_init_curve(&F, &c32, fxl, fyl, fxr, fyr, cap) == HYST_OK) {
            ref_init_spline(&ref2, f.intervals, f.value, f.slope, lo, hi, 0);
            for (k = 0u; k < n; ++k) {
                const float x = (float)xs[k];
                const double y = (double)hyst_f32_step(&F, x), y_ref = ref_step(&ref2, (double)x);
                const double tol = (double)(ref2.n + 1) * (e32 + 8.0 * FLT_EPSILON * scale);
                if (hyst_status(&F) == HYST_WARN_FULL || hyst_f32_error_bound(&F) > 0) {
                    break; /* merges: the bound on forgetting is the double run's check */
                }
                CHECK(hyst_status(&F) == HYST_OK && isfinite(y) && fabs(y - y_ref) <= tol);
                ratio(&worst_f32, fabs(y - y_ref), tol);
                ++n_f32;
            }
        }
    }
    if (flags & 2u) {
        check_compensator(&f, e_g, scale, checked, n, 1u + probe_byte % 8u);
    }
    if (flags & 4u) {
        check_fit(lo, hi, fit_k, fit_cap, n, exact, nospace_at,
                  in_space && fit_k == f.intervals && exact && !full ? scale : 0.0);
    }
    return 0;
}
