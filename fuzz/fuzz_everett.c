/* SPDX-License-Identifier: MIT */
/* libFuzzer harness of the asymmetric kind (curve.h, hyst_everett_t) and
 * its identification (ident.h, hyst_everett_fit_*), built with
 * HYST_USE_DOUBLE; any failed CHECK aborts.
 *
 * Input layout (reads past the end yield zeros, so every input is valid):
 *   [0]  flags: bit0 raw coefficients (arbitrary doubles) else small grids;
 *        bit1 feed the outputs to an E fit and check its solution;
 *        bit2 feed the outputs to the compensator (hyst_curve_inverse()) and
 *             to the tabulated one (hyst_curve_everett_inverse_table(),
 *             refused only as not invertible, or as ill-conditioned for a
 *             tiny output range,
 *             rows 3 + 4 ((flags >> 4) & 3), intervals 1 + 10 (flags >> 6));
 *        bit3 the fit of bit1 keeps the terms of t up to (flags >> 3) % degree
 *   [1]  degree (byte % 6: 0 and 5 are invalid), [2] capacity (byte % 40)
 *   then lo, hi, y_lo (structured: byte 0x80 is 2^23, a 24-bit ADC's
 *   mid-scale) and the coefficients e[i][j], then samples: each byte
 *   an input on a 256-step grid of the domain.
 *
 * Checks: on the structured grids, an accepted E is monotone on sampled
 * points of its triangle (the proof is sound) and outputs equal the double
 * reference (tests/support/ref_everett.c) within rounding until memory
 * fills, then within the stated error bound; always, finite outputs; the block call equals the per-sample call bit for bit; the
 * fit never fails on a record it accepted but for E the monotone
 * conditions cannot give, its E is accepted by the curve and its RMS is
 * finite; the plain least squares (hyst_everett_fit_solve_unconstrained())
 * is singular where the fit is, is the fit's E bit for bit where the curve
 * accepts it, and else has no larger a residual; the
 * compensator's drive stays on the domain (up to 8 units in the last place
 * of its larger end: the output range tcm.h states), fed to the model gives
 * the outputs back (on the
 * structured grids, until either memory fills), never moves against them,
 * and its block call equals its steps; the tabulated compensator (if its
 * builder accepts the curve) keeps its drive on the domain (as above) and never
 * against the outputs, agrees with the exact one within twice the error
 * its init measured (a sampled figure) on the structured grids until the
 * outputs first turn back (from there on its turning points carry its own
 * error), and its block call equals its steps; it runs from a copy of
 * its table taken as from flash (hyst_curve_table_seal(), then
 * hyst_curve_everett_inverse_table_const(): accepted, the build's curve),
 * and that copy with one bit flipped is refused (HYST_ERR_CRC); pieces
 * changed and sealed again are refused (HYST_ERR_CURVE): a slope halved, a
 * knot's slope halved on both sides, an interval the build solves given
 * back the pieces its rows were built with. */

#include "fuzz_common.h"
#include "ref_everett.h"

static const double table_tol = HYST_INV_TABLE_TOL;

#include "everett_inv_keeping_pieces.h"

#define MAX_CAP 40u
#define MAX_SAMPLES 512u

static double xl[MAX_CAP], yl[MAX_CAP], xr[MAX_CAP], yr[MAX_CAP];
static double xl2[MAX_CAP], yl2[MAX_CAP], xr2[MAX_CAP], yr2[MAX_CAP];
static double xs[MAX_SAMPLES], ys[MAX_SAMPLES], ys2[MAX_SAMPLES], drive[MAX_SAMPLES];
static hyst_wide_t fit_work[HYST_EVERETT_FIT_WORK(MAX_SAMPLES + 2u)];
static ref_everett_t ref;

/* The smallest sampled dE/da and -dE/db over the triangle, relative to
 * E's scale (finite differences inside the triangle). */
static double sampled_slack(const hyst_everett_t *e, double scale)
{
    const double span = e->hi - e->lo, h = span * 1e-6;
    double worst = 1e300;
    int i, j;
    for (i = 1; i < 24; ++i) {
        for (j = 1; i + j < 24; ++j) {
            const double b = e->lo + span * (double)j / 24.0, a = b + span * (double)i / 24.0;
            const double da = ref_everett_e(e, a + h, b) - ref_everett_e(e, a - h, b);
            const double db = ref_everett_e(e, a, b - h) - ref_everett_e(e, a, b + h);
            worst = fmin(worst, fmin(da, db));
        }
    }
    return worst / (2.0 * h * scale / span);
}

/* x in E's domain up to 8 units in the last place of its larger end (the
 * output range tcm.h states: the rounding of a turning point's value plus a
 * step). */
static int on_domain(const hyst_everett_t *e, double x)
{
    const double end = fmax(fabs(e->lo), fabs(e->hi)), ulp = nextafter(end, INFINITY) - end;
    return x >= e->lo - 8.0 * ulp && x <= e->hi + 8.0 * ulp;
}

/* The compensator of the accepted curve on the desired outputs ys[0..n):
 * see the header. */
static void check_compensator(const hyst_curve_t *curve, const hyst_everett_t *e, double scale,
                              int raw, size_t n)
{
    static double cl[MAX_CAP], cyl[MAX_CAP], cr[MAX_CAP], cyr[MAX_CAP];
    hyst_curve_t inv;
    hyst_t C, M;
    size_t k;
    int full = 0;
    CHECK(hyst_curve_inverse(&inv, curve) == HYST_OK);
    CHECK(hyst_init_curve(&C, &inv, cl, cyl, cr, cyr, MAX_CAP) == HYST_OK);
    CHECK(hyst_init_curve(&M, curve, xl2, yl2, xr2, yr2, MAX_CAP) == HYST_OK);
    for (k = 0u; k < n; ++k) {
        const double x = hyst_step(&C, ys[k]);
        const double y = hyst_step(&M, x);
        drive[k] = x;
        full |= hyst_status(&C) == HYST_WARN_FULL || hyst_status(&M) == HYST_WARN_FULL;
        CHECK(hyst_status(&C) >= 0 && isfinite(x) && on_domain(e, x));
        if (k > 0u && !full) { /* monotone: never against the desired output */
            CHECK(ys[k] > ys[k - 1u] ? x >= drive[k - 1u] : ys[k] < ys[k - 1u] ? x <= drive[k - 1u] : 1);
        }
        if (!raw && !full) { /* Newton's tolerance in the drive, times E's slope, and rounding */
            CHECK(fabs(y - ys[k]) <= 1e-9 * (scale + fabs(ys[k])));
        }
    }
    CHECK(hyst_init_curve(&C, &inv, cl, cyl, cr, cyr, MAX_CAP) == HYST_OK);
    CHECK(hyst_process(&C, ys, ys2, n) >= 0);
    CHECK(n == 0u || memcmp(drive, ys2, n * sizeof ys2[0]) == 0);
}

/* The tabulated compensator of the accepted curve on ys[0..n), against the
 * exact one's drive[0..n) (check_compensator() ran first): see the header. */
static void check_tabulated(const hyst_curve_t *curve, const hyst_everett_t *e, unsigned flags,
                            size_t n)
{
    static double table[HYST_EVERETT_INV_TABLE_LEN(15u, 31u)];
    static double flash[HYST_EVERETT_INV_TABLE_LEN(15u, 31u)]; /* the table as firmware holds it */
    static double tl[MAX_CAP], tyl[MAX_CAP], tr[MAX_CAP], tyr[MAX_CAP], tab[MAX_SAMPLES];
    const size_t rows = 3u + 4u * ((flags >> 4) & 3u), intervals = 1u + 10u * (flags >> 6);
    const size_t len = HYST_EVERETT_INV_TABLE_LEN(rows, intervals);
    hyst_table_seal_t seal;
    hyst_curve_t tinv, exact, from_flash;
    uint64_t bits;
    hyst_t C;
    double allowed;
    size_t k;
    int first_sweep = 1, full = 0;
    const hyst_status_t st = hyst_curve_everett_inverse_table(&tinv, curve, table, rows, intervals);
    /* refused as ill-conditioned only where its interval index could
     * overflow: outputs spanning under 2^31 / DBL_MAX (curve.h) */
    CHECK(st == HYST_OK || st == HYST_ERR_NOT_INVERTIBLE ||
          (st == HYST_ERR_ILL_CONDITIONED &&
           ref_everett_e(e, e->hi, e->lo) < 4.0 * 0x1p31 / DBL_MAX));
    if (st != HYST_OK) {
        return;
    }
    CHECK(hyst_curve_inverse(&exact, curve) == HYST_OK);
    /* the pieces within the tolerance, plus the drive's last rounding (curve.h) */
    CHECK(hyst_curve_inverse_error(&tinv) >= 0 &&
          hyst_curve_inverse_error(&tinv) <=
              table_tol * (1.0 + 1e-6) +
                  DBL_EPSILON * fmax(fabs(e->lo), fabs(e->hi)) / (e->hi - e->lo) * (1.0 + 1e-6));
    /* the same table as firmware takes it from flash: sealed, accepted, the
     * build's curve (the samples below run on it) */
    CHECK(hyst_curve_table_seal(&tinv, &seal) == HYST_OK);
    memcpy(flash, table, len * sizeof table[0]);
    CHECK(hyst_curve_everett_inverse_table_const(&from_flash, curve, flash, rows, intervals,
                                                 &seal) == HYST_OK);
    CHECK(from_flash.u.everett.exact == tinv.u.everett.exact &&
          hyst_curve_inverse_error(&from_flash) == hyst_curve_inverse_error(&tinv) &&
          memcmp(&from_flash.rounding, &tinv.rounding, sizeof tinv.rounding) == 0);
    tinv = from_flash;
    /* init's error is the worst of 8 probes per interval and anchor: between
     * probes a cubic's error may exceed it (one interval of 15 rows: by 3 %) */
    allowed = hyst_curve_inverse_error(&tinv) * (e->hi - e->lo) * 2.0 + 2.0 * exact.rounding.f64;
    CHECK(hyst_init_curve(&C, &tinv, tl, tyl, tr, tyr, MAX_CAP) == HYST_OK);
    for (k = 0u; k < n; ++k) {
        const double x = hyst_step(&C, ys[k]);
        tab[k] = x;
        full |= hyst_status(&C) == HYST_WARN_FULL;
        CHECK(hyst_status(&C) >= 0 && isfinite(x) && on_domain(e, x));
        if (k > 0u && !full) {
            CHECK(ys[k] > ys[k - 1u] ? x >= tab[k - 1u] : ys[k] < ys[k - 1u] ? x <= tab[k - 1u] : 1);
            first_sweep &= ys[k] >= ys[k - 1u];
        }
        if (first_sweep && !full && !(flags & 1u)) {
            CHECK(fabs(x - drive[k]) <= allowed);
        }
    }
    CHECK(hyst_init_curve(&C, &tinv, tl, tyl, tr, tyr, MAX_CAP) == HYST_OK);
    CHECK(hyst_process(&C, ys, ys2, n) >= 0);
    CHECK(n == 0u || memcmp(tab, ys2, n * sizeof ys2[0]) == 0);
    /* a piece's slope halved and the table sealed again (the samples pick
     * which): the knots still lie on the model, the seal's error does not
     * hold; refused unless that interval is solved instead or the change
     * stays within the error sealed (a slope of 0 or a tiny one) */
    k = (n * 40503u + flags) % (len / 4u);
    if (k % (intervals + 1u) != intervals && !(flash[4u * k] < 0) &&
        fabs(flash[4u * k + 1u]) > 64.0 * hyst_curve_inverse_error(&tinv) * (e->hi - e->lo)) {
        hyst_curve_t resealed = tinv;
        const double keep = flash[4u * k + 1u];
        hyst_table_seal_t seal2;
        flash[4u * k + 1u] = keep * 0.5;
        CHECK(hyst_curve_table_seal(&resealed, &seal2) == HYST_OK);
        CHECK(hyst_curve_everett_inverse_table_const(&from_flash, curve, flash, rows, intervals,
                                                     &seal2) == HYST_ERR_CURVE);
        flash[4u * k + 1u] = keep;
    }
    /* the slope at a knot halved alike on both sides (the end slope of the
     * piece before, the start slope of the piece after: each still a cubic
     * Hermite piece between the same knots, within Fritsch and Carlson's
     * limits) and the table sealed again: refused on the same terms */
    k = (n * 7919u + flags) % (len / 4u);
    if (k % (intervals + 1u) != 0u && k % (intervals + 1u) != intervals &&
        !(flash[4u * k - 4u] < 0) && !(flash[4u * k] < 0) &&
        fabs(flash[4u * k + 1u]) > 64.0 * hyst_curve_inverse_error(&tinv) * (e->hi - e->lo)) {
        hyst_curve_t resealed = tinv;
        double keep[8], change;
        hyst_table_seal_t seal2;
        memcpy(keep, &flash[4u * k - 4u], sizeof keep);
        change = -0.5 * flash[4u * k + 1u];
        flash[4u * k - 2u] -= change; /* the piece before: its end slope */
        flash[4u * k - 1u] += change;
        flash[4u * k + 1u] += change; /* the piece after: its start slope */
        flash[4u * k + 2u] -= 2.0 * change;
        flash[4u * k + 3u] += change;
        CHECK(hyst_curve_table_seal(&resealed, &seal2) == HYST_OK);
        CHECK(hyst_curve_everett_inverse_table_const(&from_flash, curve, flash, rows, intervals,
                                                     &seal2) == HYST_ERR_CURVE);
        memcpy(&flash[4u * k - 4u], keep, sizeof keep);
    }
    /* an interval the build solves (the samples pick which) given back the
     * pieces its rows were built with, and the table sealed again: refused */
    if (tinv.u.everett.exact > 0u) {
        static double kept[HYST_EVERETT_INV_TABLE_LEN(15u, 31u)];
        const size_t row = HYST_INV_TABLE_LEN(intervals);
        hyst_curve_t unsolved, resealed = tinv;
        hyst_table_seal_t seal2;
        hyst_ptr_t to;
        size_t r, i, at = 0u, seen = 0u, pick = (n * 31u + flags) % tinv.u.everett.exact;
        to.f64 = kept;
        CHECK(build_keeping_pieces(&unsolved, curve, to, rows, intervals,
                                   (unsigned)HYST_VARIANT_F64) == HYST_OK &&
              unsolved.u.everett.exact == 0u);
        for (k = 0u; k < 2u * intervals; ++k) { /* interval k % intervals of direction k / intervals */
            at = (k / intervals) * (rows + 1u) * row + 4u * (k % intervals);
            if (flash[at] < 0 && seen++ == pick) {
                break;
            }
        }
        CHECK(k < 2u * intervals);
        for (r = 0u; r <= rows; ++r) {
            for (i = 0u; i < 4u; ++i) {
                flash[at + r * row + i] = kept[at + r * row + i];
            }
        }
        --resealed.u.everett.exact;
        CHECK(hyst_curve_table_seal(&resealed, &seal2) == HYST_OK);
        CHECK(hyst_curve_everett_inverse_table_const(&from_flash, curve, flash, rows, intervals,
                                                     &seal2) == HYST_ERR_CURVE);
        memcpy(flash, table, len * sizeof table[0]);
    }
    /* one bit of one number flipped (the samples pick which): refused */
    k = (n * 2654435761u + flags) % len;
    memcpy(&bits, &flash[k], sizeof bits);
    bits ^= (uint64_t)1 << (n % 64u);
    memcpy(&flash[k], &bits, sizeof bits);
    CHECK(hyst_curve_everett_inverse_table_const(&from_flash, curve, flash, rows, intervals,
                                                 &seal) == HYST_ERR_CRC);
}

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size)
{
    reader_t rd = {data, size, 0u};
    const unsigned flags = rd_u8(&rd);
    hyst_everett_t e;
    hyst_curve_t curve;
    hyst_t S, T;
    size_t cap, n = 0u, k;
    double scale = 0.0, range;
    unsigned i, j;
    int full = 0;
    memset(&e, 0, sizeof e);
    e.degree = rd_u8(&rd) % 6u;
    cap = rd_u8(&rd) % MAX_CAP;
    if (flags & 1u) {
        e.lo = rd_f64(&rd);
        e.hi = rd_f64(&rd);
        e.y_lo = rd_f64(&rd);
    } else {
        e.lo = ((double)(signed char)rd_u8(&rd)) / 8.0;
        e.hi = e.lo + (double)(1u + rd_u8(&rd) % 64u) / 4.0;
        e.y_lo = ((double)(signed char)rd_u8(&rd)) / 16.0;
        if (e.y_lo == -8.0) {
            e.y_lo = 8388608.0; /* byte 0x80: a 24-bit ADC's mid-scale (the fit's RMS cancelled) */
        }
    }
    for (i = 0u; i < (unsigned)HYST_EVERETT_MAX_DEGREE; ++i) {
        for (j = 0u; j < (unsigned)HYST_EVERETT_MAX_DEGREE; ++j) {
            if (flags & 1u) {
                e.e[i][j] = rd_f64(&rd);
            } else if (i + j + 1u <= e.degree) {
                e.e[i][j] = ((double)(signed char)rd_u8(&rd)) / 32.0 + (i + j == 0u ? 4.0 : 0.0);
            }
            scale += fabs(e.e[i][j]);
        }
    }
    if (hyst_curve_from_everett(&curve, &e) != HYST_OK) {
        return 0;
    }
    CHECK(e.degree >= 1u && e.degree <= (unsigned)HYST_EVERETT_MAX_DEGREE);
    range = ref_everett_e(&e, e.hi, e.lo);
    CHECK(range > 0.0);
    /* accepted: monotone where sampled (on the structured grids: raw
     * doubles reach subnormal and huge scales where sampling says nothing) */
    CHECK((flags & 1u) || sampled_slack(&e, scale) > -1e-6);
    if (hyst_init_curve(&S, &curve, xl, yl, xr, yr, cap) != HYST_OK) {
        CHECK(cap < 2u);
        return 0;
    }
    /* the twin with its kind named: the same outputs (process() below) */
    fuzz_check_kinds(&curve);
    CHECK(hyst_init_kind(&T, &curve, hyst_kind_everett, xl2, yl2, xr2, yr2, cap) == HYST_OK);
    while (rd.at < rd.n && n < MAX_SAMPLES) { /* on the domain: lo + (hi - lo) rounds past hi */
        const double x = e.lo + (e.hi - e.lo) * (double)rd_u8(&rd) / 255.0;
        xs[n++] = x < e.hi ? x : e.hi;
    }
    ref_everett_init(&ref, &e);
    for (k = 0u; k < n; ++k) {
        const double x = xs[k];
        const double y = hyst_step(&S, x), y_ref = ref_everett_step(&ref, x);
        /* rounding: a few ulps of the scale per stacked TP */
        const double tol = 64.0 * DBL_EPSILON * (scale + fabs(e.y_lo)) * (double)(ref.n + 1);
        ys[k] = y;
        full |= hyst_status(&S) == HYST_WARN_FULL;
        CHECK(hyst_status(&S) >= 0 && isfinite(y));
        if (flags & 1u) {
            continue; /* raw doubles: no differential check */
        }
        if (!full) {
            CHECK(fabs(y - y_ref) <= tol);
        } else {
            CHECK(fabs(y - y_ref) <= hyst_error_bound(&S) + tol);
        }
    }
    CHECK(hyst_process(&T, xs, ys2, n) >= 0);
    CHECK(n == 0u || memcmp(ys, ys2, n * sizeof ys[0]) == 0);
    if (flags & 4u) {
        check_compensator(&curve, &e, scale, (int)(flags & 1u), n);
        check_tabulated(&curve, &e, flags, n);
    }
    if ((flags & 2u) && n > 0u) {
        hyst_everett_fit_t fit;
        hyst_everett_t got;
        hyst_wide_t rms = -1;
        hyst_status_t st;
        /* every term of the degree, or those of t up to (flags >> 3) % degree */
        const unsigned t_degree = (flags >> 3) % e.degree;
        CHECK(((flags >> 3) & 1u) != 0u
                  ? hyst_everett_fit_init_terms(&fit, e.degree, t_degree, e.lo, e.hi, fit_work,
                                                sizeof fit_work / sizeof fit_work[0]) == HYST_OK
                  : hyst_everett_fit_init(&fit, e.degree, e.lo, e.hi, fit_work,
                                          sizeof fit_work / sizeof fit_work[0]) == HYST_OK);
        for (k = 0u; k < n; ++k) {
            CHECK(hyst_everett_fit_add(&fit, xs[k], ys[k]) == HYST_OK); /* room for every TP */
        }
        st = hyst_everett_fit_solve(&fit, &got, &rms);
        /* NOT_MONOTONE: no E of the sufficient conditions fits (ident.h); or
         * what the curve refuses that E with, itself */
        CHECK(st == HYST_OK || st == HYST_ERR_SINGULAR || st == HYST_ERR_NOT_MONOTONE ||
              ((st == HYST_ERR_ILL_CONDITIONED || st == HYST_ERR_COEFF) &&
               hyst_curve_from_everett(&curve, &got) == st));
        { /* the plain least squares (ident.h): singular alike; the same E bit for
           * bit where the curve accepts it; else a residual no larger than the
           * monotone fit's (up to the solvers' rounding: 1e-9 of it and of the
           * outputs' scale) */
            hyst_everett_t free_e;
            hyst_wide_t rms_free = -1, scale_y = 0;
            hyst_curve_t free_curve;
            const hyst_status_t su = hyst_everett_fit_solve_unconstrained(&fit, &free_e, &rms_free);
            CHECK(su == HYST_OK || su == HYST_ERR_SINGULAR);
            CHECK((su == HYST_ERR_SINGULAR) == (st == HYST_ERR_SINGULAR));
            for (k = 0u; k < n; ++k) scale_y = fmax(scale_y, fabs((double)ys[k]));
            if (su == HYST_OK) {
                CHECK(rms_free >= 0 && isfinite(rms_free));
                if (hyst_curve_from_everett(&free_curve, &free_e) == HYST_OK) {
                    CHECK(st == HYST_OK && memcmp(&got, &free_e, sizeof got) == 0 && rms == rms_free);
                } else {
                    /* both RMS are the factor's |Q'y - R s|: each square is known to
                     * about 64 eps of the mean (y - y_ref)^2, at most (2 scale_y)^2,
                     * which dominates when the fit is near exact */
                    const double slack = 256 * DBL_EPSILON * scale_y * scale_y;
                    CHECK(rms_free * rms_free <= rms * rms * (1 + 1e-9) + slack ||
                          rms_free <= rms * (1 + 1e-9) + 1e-9 * scale_y);
                }
            }
        }
        if (st == HYST_OK) {
            hyst_curve_t fitted;
            CHECK(rms >= 0 && isfinite(rms));
            /* what the fit returns, the curve accepts */
            CHECK(hyst_curve_from_everett(&fitted, &got) == HYST_OK);
            CHECK(got.degree == e.degree && got.lo == e.lo && got.hi == e.hi);
            if (!(flags & 1u)) { /* the RMS is the E's own residual, whatever the offset */
                double ss = 0.0;
                ref_everett_init(&ref, &got);
                for (k = 0u; k < n; ++k) {
                    const double d = ys[k] - ref_everett_step(&ref, xs[k]);
                    ss += d * d;
                }
                ss = sqrt(ss / (double)n);
                CHECK(fabs(rms - ss) <= 1e-6 * (range + ss));
            }
            for (i = 0u; i < (unsigned)HYST_EVERETT_MAX_DEGREE; ++i) { /* the terms not fitted: 0 */
                for (j = 0u; j < (unsigned)HYST_EVERETT_MAX_DEGREE; ++j) {
                    CHECK(got.e[i][j] == 0 || (i + j + 1u <= e.degree &&
                                               (((flags >> 3) & 1u) == 0u || j <= t_degree)));
                }
            }
        }
    }
    return 0;
}
