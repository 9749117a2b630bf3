/* SPDX-License-Identifier: MIT */
/* libFuzzer harness for the modules around the TCM core: the PI model and
 * its inverse, piecewise-linear curves, inverse curves and the compensator,
 * and the identification. fuzz_hyst.c covers the core, polynomial curves and
 * snapshots. Built with HYST_USE_DOUBLE; any failed CHECK aborts.
 *
 * Input layout (reads past the end yield zeros, so every input is valid):
 *   [0]  module (byte % 4): 0 PI, 1 PWL curve, 2 polynomial inverse, 3 ident;
 *        252..255: creep (fuzz_creep()), 248..251: rate (fuzz_rate())
 *   [1]  flags: bit1 raw parameters (arbitrary doubles) else structured
 *        grids; bit2 a module-specific corruption (ident: REFLECT, or the
 *        domain from the data; PI fit: a workspace one entry short); bit3
 *        NULL-pointer probes (ident known f0: explicit domain); bit4 (ident)
 *        a known f0 through the TCM, (inverse) the tabulated compensator; bit5
 *        (ident) the PI weights by NNLS
 *        instead (fuzz_pi_fit())
 *   then the module's parameters, then opcodes until the input ends (see
 *   each fuzz_* function). 0xF0..0xFF are control opcodes in the PI, PWL
 *   and inverse modules; any other byte is one sample of kind op & 7
 *   (next_pos()).
 *
 * Adding an entry point: a control opcode (or a call at set-up) in the
 * module's function, and a seed in fuzz/make_corpus.py. fuzz/run lists
 * every public function that neither harness calls.
 *
 * Tolerances: EPS is DBL_EPSILON. Each check names its bound and why. */
#include "fuzz_common.h"

#ifndef HYST_USE_DOUBLE
#error "the differential harness compares a double core with double references"
#endif

#define EPS DBL_EPSILON
/* Spacing of the subnormals: the absolute rounding error of one operation
 * whose result underflows (relative bounds alone would say 0). */
#define UNDER (DBL_MIN * DBL_EPSILON)
#define MAX_PI 16u
#define MAX_PTS 33u
#define CAP 64u
#define MAX_OPS 2048u
#define MAX_REC 512u

/* CLOSE: CHECK(err <= tol). With FUZZ_STATS set in the environment it also
 * keeps the largest err / tol per check and prints them at exit: how close
 * the library comes to each bound (docs/reliability.md quotes them). */
#define CLOSE(name, err, tol) close_(name, (err), (tol), __LINE__)
typedef struct {
    const char *name;
    double ratio;
    unsigned long n;
} stat_t;
static stat_t stats[32];

static void print_stats(void)
{
    unsigned k;
    for (k = 0; k < 32u && stats[k].name != NULL; ++k) {
        fprintf(stderr, "stat: %-28s max err/tol %.3g over %lu checks\n", stats[k].name,
                stats[k].ratio, stats[k].n);
    }
}

static void close_(const char *name, double err, double tol, int line)
{
    static int on = -1;
    unsigned k;
    if (!(err <= tol)) {
        fprintf(stderr, "fuzz: %s:%d: check %s failed: err %.17g > tol %.17g\n", __FILE__, line,
                name, err, tol);
        abort();
    }
    if (on < 0) {
        on = getenv("FUZZ_STATS") != NULL;
        if (on) atexit(print_stats);
    }
    if (!on) return;
    for (k = 0; k < 31u && stats[k].name != NULL && strcmp(stats[k].name, name) != 0; ++k) {
    }
    stats[k].name = name;
    ++stats[k].n;
    if (tol > 0.0 && err / tol > stats[k].ratio) stats[k].ratio = err / tol;
}

typedef struct {
    hyst_t S;
    hyst_real_t xl[CAP], yl[CAP], xr[CAP], yr[CAP];
} tcm_t;

static tcm_t T, Ti, G, keep_t;
/* Storage of the compensator's inverse curve (hyst_init_inverse_exact writes it;
 * Ti points at it, so it outlives Ti). */
static hyst_curve_t ti_curve;
/* The tabulated compensator's table (flag bit4 of module 2), and the one of
 * the same curve made by the two calls init makes. */
#define TI_MAX_INTERVALS 64u
static hyst_real_t ti_table[HYST_INV_TABLE_LEN(TI_MAX_INTERVALS)];
static hyst_real_t ct_table[HYST_INV_TABLE_LEN(TI_MAX_INTERVALS)];

/* The engine's own evaluation of g (what hyst_curve_g_unit() and
 * hyst_curve_g_unit_other() exposed before the curve became a tagged union):
 * from A0, one step to x in the domain gives y_lo + g(x - lo), computed by
 * the instance's per-sample path (G.S, initialised on c). It must equal
 * hyst_curve_g bit for bit. */
static int engine_g_matches(const hyst_curve_t *c, double x)
{
    const double xc = x < c->lo.HYST_R ? c->lo.HYST_R : (x > c->hi.HYST_R ? c->hi.HYST_R : x);
    double y, want;
    hyst_reset(&G.S);
    y = hyst_step(&G.S, x);
    want = c->y_lo.HYST_R + hyst_curve_g(c, xc - c->lo.HYST_R);
    return y == want;
}

static int init_on(tcm_t *I, const hyst_curve_t *c, size_t cap)
{
    return hyst_init_curve(&I->S, c, I->xl, I->yl, I->xr, I->yr, cap);
}

/* A sample as a position relative to [lo, lo + span]: NaN, +-Inf, any double,
 * the ends exactly, 8-bit codes (repeats), 16-bit positions 10% beyond. */
static double next_pos(reader_t *r, unsigned op, double lo, double span)
{
    switch (op & 7u) {
    case 0: return NAN;
    case 1: return (op & 8u) ? INFINITY : -INFINITY;
    case 2: return rd_f64(r);
    case 3: return (op & 8u) ? lo + span : lo;
    case 4: return lo + span * ((double)rd_u8(r) / 255.0);
    default: return lo - 0.1 * span + 1.2 * span * ((double)rd_u16(r) / 65535.0);
    }
}

/* Inside [lo, hi] up to one interpolation's rounding (the quotient in
 * y_k + (x - x_k) dy / dx can overshoot dy by 2 ulps): 4 eps of the ends. */
static int in_domain(double v, double lo, double hi)
{
    const double slack = 4.0 * EPS * (fabs(lo) + fabs(hi));
    return v >= lo - slack && v <= hi + slack;
}

static double clampd(double v, double lo, double hi) { return v < lo ? lo : (v > hi ? hi : v); }

static int g_raw; /* raw parameters of the current input */
static int pwl_extreme(const hyst_real_t *px, const hyst_real_t *py, size_t n);
static int at_breakpoint(const hyst_curve_t *c, const hyst_real_t *px, const hyst_real_t *py,
                         size_t n, size_t i);

/* ------------------------------------------------------------------ PI --- */

static hyst_real_t pr[MAX_PI], pw[MAX_PI], pz[MAX_PI], ri[MAX_PI], wi[MAX_PI], zq[MAX_PI];
static hyst_real_t ri2[MAX_PI], wi2[MAX_PI], z2[MAX_PI], rr[MAX_PI], wr[MAX_PI];
static hyst_real_t bx[MAX_PI + 1u], by[MAX_PI + 1u];
static double refz[MAX_PI];
static hyst_pi_t P, Q, P2, keep_p;

/* pi.h's documented checks, in their order. */
static hyst_status_t pi_expected(const hyst_real_t *r, const hyst_real_t *w, size_t n)
{
    double sum = 0.0;
    size_t i;
    if (n == 0u) return HYST_ERR_ARG;
    if (r[0] != 0.0) return HYST_ERR_BREAKPOINTS;
    for (i = 1; i < n; ++i) {
        if (!isfinite(r[i]) || !(r[i] > r[i - 1u])) return HYST_ERR_BREAKPOINTS;
    }
    for (i = 0; i < n; ++i) {
        sum += w[i];
        if (!isfinite(w[i]) || !(sum > 0.0)) return HYST_ERR_WEIGHTS;
    }
    return HYST_OK;
}

/* Eq. 15 written out, z_i = 0 before the first sample. Returns y; *mag gets
 * sum |w_i z_i|, the scale of the summation's rounding. */
static double ref_pi_step(size_t n, double x, double *mag)
{
    double y = 0.0;
    size_t i;
    *mag = 0.0;
    for (i = 0; i < n; ++i) {
        refz[i] = fmax(x - pr[i], fmin(x, refz[i]));
        y += pw[i] * refz[i];
        *mag += fabs(pw[i] * refz[i]);
    }
    return y;
}

/* f_PI(x) = sum w_i max(0, x - r_i), and sum |w_i| max(0, x - r_i). */
static double f_pi(size_t n, double x, double *mag)
{
    double y = 0.0;
    size_t i;
    *mag = 0.0;
    for (i = 0; i < n; ++i) {
        y += pw[i] * fmax(0.0, x - pr[i]);
        *mag += fabs(pw[i]) * fmax(0.0, x - pr[i]);
    }
    return y;
}

static int all_finite(const hyst_real_t *v, size_t n)
{
    size_t i;
    for (i = 0; i < n; ++i) {
        if (!isfinite(v[i])) return 0;
    }
    return 1;
}

static void pi_reset_all(size_t n)
{
    hyst_pi_reset(&P);
    hyst_pi_reset(&Q);
    hyst_pi_reset(&P2);
    memset(refz, 0, sizeof(refz));
    CHECK(hyst_pi_output(&P) == 0.0 && hyst_pi_events(&P) == 0u && hyst_pi_size(&P) == n);
}

/* One PI sample, compared with Eq. 15. Same z in both (one rounding of
 * x - r_i, exact min/max): only the sum's rounding differs, bounded by
 * n eps sum|w_i z_i| (gamma_n). */
static double pi_sample(size_t n, double x)
{
    const double y_before = hyst_pi_output(&P);
    const double y = hyst_pi_step(&P, x);
    double mag, yr;
    if (!isfinite(x)) {
        CHECK(hyst_pi_status(&P) == HYST_ERR_NONFINITE);
        CHECK((y == y_before || (isnan(y) && isnan(y_before))) &&
              (hyst_pi_events(&P) & HYST_EVENT_NONFINITE));
        return y;
    }
    CHECK(hyst_pi_status(&P) == HYST_OK);
    yr = ref_pi_step(n, x, &mag);
    CHECK((isnan(y) && isnan(yr)) || y == yr || fabs(y - yr) <= 2.0 * (double)n * (EPS * mag + UNDER));
    return y;
}

/* Parameters: n = byte % 17; structured: r_i += k/16 (k = 0 repeats a
 * threshold), w_1 = (1..64)/32, w_i = (-128..127)/64 (partial sums can fall
 * to 0 or below), hi = r_N + (-128..127)/16; corruption flag: r_1 != 0.
 * Opcodes: samples (x on [-0.1 hi, 1.1 hi]); 0xF0 reset; 0xF1 a block
 * through hyst_pi_process; others: clear events, accessors. */
static void fuzz_pi(reader_t *rd, unsigned flags)
{
    const size_t n = rd_u8(rd) % (MAX_PI + 1u);
    const int raw = (int)(flags & 2u);
    hyst_status_t exp, st;
    hyst_curve_t curve, inv, keep_c;
    double hi, range = 0.0, wsum = 0.0, wmin = INFINITY, wmax = 0.0, acc = 0.0;
    int have_curve = 0, have_inv = 0, tcm_ok = 0, chain_ok = 0, itcm_ok = 0;
    unsigned ops;
    size_t i;

    for (i = 0; i < n; ++i) {
        if (raw) {
            pr[i] = rd_f64(rd);
            pw[i] = rd_f64(rd);
        } else {
            pr[i] = i == 0u ? 0.0 : pr[i - 1u] + (double)(rd_u8(rd) % 16u) / 16.0;
            pw[i] = i == 0u ? (double)(1u + rd_u8(rd) % 64u) / 32.0
                            : (double)(signed char)rd_u8(rd) / 64.0;
        }
    }
    if ((flags & 4u) && n > 0u) pr[0] = (double)(signed char)rd_u8(rd) / 16.0;
    hi = raw ? rd_f64(rd) : (n > 0u ? pr[n - 1u] : 0.0) + (double)(signed char)rd_u8(rd) / 16.0;

    exp = pi_expected(pr, pw, n);
    CHECK(hyst_pi_check(pr, pw, n) == exp);
    if (flags & 8u) {
        CHECK(hyst_pi_check(NULL, pw, n) == HYST_ERR_NULL);
        CHECK(hyst_pi_check(pr, NULL, n) == HYST_ERR_NULL);
        CHECK(hyst_pi_init(NULL, pr, pw, pz, n) == HYST_ERR_NULL);
        CHECK(hyst_pi_init(&P, pr, pw, NULL, n) == HYST_ERR_NULL);
        CHECK(hyst_pi_init_inverse(&Q, NULL, ri, wi, zq) == HYST_ERR_NULL);
        CHECK(hyst_pi_loading_curve(NULL, pr, pw, n, hi, bx, by) ==
              (exp == HYST_OK ? HYST_ERR_NULL : exp));
        CHECK(hyst_pi_inverse_params(pr, pw, n, NULL, wi) == (exp == HYST_OK ? HYST_ERR_NULL : exp));
    }
    /* init errors write nothing: neither the instance nor the states */
    memset(&P, 0xA5, sizeof(P));
    memset(pz, 0x5A, sizeof(pz));
    memcpy(&keep_p, &P, sizeof(P));
    memcpy(zq, pz, sizeof(pz));
    st = hyst_pi_init(&P, pr, pw, pz, n);
    CHECK(st == exp);
    memset(ri, 0x33, sizeof(ri));
    memcpy(ri2, ri, sizeof(ri));
    memset(&curve, 0x44, sizeof(curve));
    memcpy(&keep_c, &curve, sizeof(curve));
    if (st != HYST_OK) {
        CHECK(memcmp(&P, &keep_p, sizeof(P)) == 0 && memcmp(pz, zq, sizeof(pz)) == 0);
        CHECK(hyst_pi_inverse_params(pr, pw, n, ri, wi) == exp);
        CHECK(hyst_pi_loading_curve(&curve, pr, pw, n, hi, bx, by) == exp);
        CHECK(memcmp(ri, ri2, sizeof(ri)) == 0 && memcmp(&curve, &keep_c, sizeof(curve)) == 0);
        return;
    }
    pi_reset_all(n);
    for (i = 0; i < n; ++i) {
        acc += pw[i]; /* partial sums W_i: the slopes of the loading curve */
        wmin = fmin(wmin, acc);
        wmax = fmax(wmax, acc);
        wsum += fabs(pw[i]);
    }

    /* Analytic inverse: refused only for thresholds rounding made equal or
     * inverse weights that fail hyst_pi_check() once rounded (docs/reliability.md, unchecked inverse PI weights,
     * regress_pi_inverse_overflow/_cancel, fixed), and then nothing written. */
    st = hyst_pi_inverse_params(pr, pw, n, ri, wi);
    CHECK(st == HYST_OK || st == HYST_ERR_BREAKPOINTS || st == HYST_ERR_WEIGHTS);
    if (st != HYST_OK) {
        CHECK(memcmp(ri, ri2, sizeof(ri)) == 0);
        CHECK(hyst_pi_init_inverse(&Q, &P, ri2, wi2, zq) == st);
    } else if (!all_finite(wi, n) || hyst_pi_check(ri, wi, n) != HYST_OK) {
        CHECK(0); /* pi.h: the inverse's parameters satisfy hyst_pi_check() */
    } else {
        for (i = 0; i < n; ++i) { /* r'_i = f_PI(r_i): a sum of n products, gamma_n */
            double mag;
            const double fr = f_pi(n, pr[i], &mag);
            CLOSE("pi_inv_thresholds", fabs(ri[i] - fr), 4.0 * (double)n * (EPS * mag + UNDER));
        }
        CHECK(hyst_pi_init_inverse(&Q, &P, ri2, wi2, zq) == HYST_OK);
        CHECK(memcmp(ri2, ri, n * sizeof(ri[0])) == 0 && memcmp(wi2, wi, n * sizeof(wi[0])) == 0);
        CHECK(hyst_pi_init(&P2, pr, pw, z2, n) == HYST_OK);
        /* Inverse of the inverse gives (r, w) back. Structured: W_i in
         * [1/64, 34], so 1/W_i is computed with relative error ~n eps and the
         * round trip loses at most cond = W_max/W_min <= 2200 of it: below
         * 1e-9 relative to the largest threshold / weight sum. */
        if (!raw && hyst_pi_inverse_params(ri, wi, n, rr, wr) == HYST_OK) {
            for (i = 0; i < n; ++i) {
                CLOSE("pi_inv_inv_r", fabs(rr[i] - pr[i]), 1e-9 * (1.0 + pr[n - 1u]));
                CLOSE("pi_inv_inv_w", fabs(wr[i] - pw[i]), 1e-9 * wsum);
            }
        }
        chain_ok = !raw;
    }

    /* Loading curve: documented errors in order; structured parameters
     * (W_i >= 1/64, steps >= 1/16) always give a valid strictly increasing curve. */
    st = hyst_pi_loading_curve(&curve, pr, pw, n, hi, bx, by);
    if (!isfinite(hi) || !(hi > pr[n - 1u])) {
        CHECK(st == HYST_ERR_DOMAIN && memcmp(&curve, &keep_c, sizeof(curve)) == 0);
    } else if (raw) {
        CHECK(st == HYST_OK || st == HYST_ERR_COEFF || st == HYST_ERR_NOT_INCREASING ||
              st == HYST_ERR_BREAKPOINTS);
    } else {
        CHECK(st == HYST_OK);
    }
    if (st == HYST_OK) {
        have_curve = 1;
        CHECK(curve.kind == HYST_CURVE_PWL && curve.lo.HYST_R == 0.0 && curve.hi.HYST_R == hi);
        range = curve.y_hi.HYST_R - curve.y_lo.HYST_R;
        for (i = 0; i <= n; ++i) { /* f_PI at the breakpoints: gamma_n again */
            double mag;
            const double fr = f_pi(n, bx[i], &mag);
            CLOSE("pi_loading_values", fabs(by[i] - fr), 4.0 * (double)n * (EPS * mag + UNDER));
            CHECK(pwl_extreme(bx, by, n + 1u) || at_breakpoint(&curve, bx, by, n + 1u, i));
        }
        if (!raw) {
            CHECK(init_on(&T, &curve, CAP) == HYST_OK);
            tcm_ok = 1;
            CHECK(hyst_curve_inverse(&inv, &curve) == HYST_OK); /* slopes W_i > 0 */
            CHECK(init_on(&Ti, &inv, CAP) == HYST_OK);
            have_inv = itcm_ok = chain_ok;
        }
    }
    if (!have_curve) hi = pr[n - 1u] + 1.0;

    for (ops = 0; ops < MAX_OPS && rd->at < rd->n; ++ops) {
        const unsigned op = rd_u8(rd);
        if ((op & 0xF0u) == 0xF0u) {
            switch (op & 0x0Fu) {
            case 0:
                pi_reset_all(n);
                if (have_curve && !raw) {
                    hyst_reset(&T.S);
                    hyst_reset(&Ti.S);
                    tcm_ok = 1;
                    itcm_ok = have_inv;
                }
                break;
            case 1: { /* a block, in place half of the time (documented) */
                hyst_real_t xin[32], xs[32], ys[32], *out;
                const unsigned b = rd_u8(rd), m = b % 32u;
                unsigned k, bad = 0;
                double prev = hyst_pi_output(&P);
                for (k = 0; k < m; ++k) {
                    xin[k] = xs[k] = next_pos(rd, rd_u8(rd), 0.0, hi);
                    bad |= !isfinite(xin[k]);
                }
                out = (b & 0x80u) ? xs : ys;
                st = hyst_pi_process(&P, xs, out, m);
                CHECK(st == (bad ? HYST_ERR_NONFINITE : HYST_OK));
                for (k = 0; k < m; ++k) {
                    if (isfinite(xin[k])) {
                        double mag;
                        const double yr = ref_pi_step(n, xin[k], &mag);
                        CHECK((isnan(out[k]) && isnan(yr)) || out[k] == yr ||
                              fabs(out[k] - yr) <= 2.0 * (double)n * (EPS * mag + UNDER));
                    } else { /* ignored: the previous output again */
                        CHECK(out[k] == prev || (isnan(out[k]) && isnan(prev)));
                    }
                    prev = out[k];
                }
                CHECK(hyst_pi_process(&P, NULL, ys, 1u) == HYST_ERR_NULL);
                CHECK(hyst_pi_process(&P, NULL, NULL, 0u) == HYST_OK);
                tcm_ok = 0; /* P moved without T */
                break;
            }
            default:
                hyst_pi_clear_events(&P);
                CHECK(hyst_pi_events(&P) == 0u);
                (void)hyst_pi_status(&P);
                break;
            }
            continue;
        }
        {
            const double x = next_pos(rd, op, 0.0, hi);
            const double y = pi_sample(n, x);
            if (!isfinite(x)) continue;
            if ((op & 7u) == 2u) { /* arbitrary doubles: beyond the scales below */
                tcm_ok = chain_ok = itcm_ok = 0;
                continue;
            }
            /* TCM with f0 = f_PI reproduces PI exactly for inputs in [0, hi]
             * from 0 (docs/theory.md, the PI model as a TCM). Rounding: PI sums n <= 16 products of
             * size <= range, TCM adds one PWL interpolation per sample (a
             * few eps of range): far below 1e-9 of the range. */
            if (tcm_ok) {
                if (x < 0.0 || x > hi) {
                    tcm_ok = 0;
                } else {
                    const double yt = hyst_step(&T.S, x);
                    if (hyst_status(&T.S) == HYST_WARN_FULL) {
                        tcm_ok = 0;
                    } else {
                        CLOSE("pi_vs_tcm", fabs(yt - y), 1e-9 * range);
                    }
                }
            }
            /* PI(PI^-1(yd)) = yd for any input sequence from reset (pi.h).
             * Rounding of PI^-1's output (n eps relative) is amplified by at
             * most the forward slope ratio W_max/W_min <= 2200 (structured):
             * ~1e-11 of the scale, so 1e-9 of max(range, |yd|) holds. */
            if (chain_ok) {
                const double yd = x * (have_curve ? range / hi : 1.0);
                const double u = hyst_pi_step(&Q, yd);
                const double back = hyst_pi_step(&P2, u);
                CLOSE("pi_inverse_round_trip", fabs(back - yd), 1e-9 * fmax(fmax(range, 1.0), fabs(yd)));
                /* The inverse TCM on f_PI^-1 equals PI^-1 on [0, f_PI(hi)]
                 * from 0: the same argument as above, in the (y, x) plane,
                 * with values of size <= hi. */
                if (itcm_ok) {
                    if (yd < 0.0 || yd > range) {
                        itcm_ok = 0;
                    } else {
                        const double ut = hyst_step(&Ti.S, yd);
                        if (hyst_status(&Ti.S) == HYST_WARN_FULL) {
                            itcm_ok = 0;
                        } else {
                            CLOSE("pi_inverse_vs_inverse_tcm", fabs(ut - u), 1e-9 * hi);
                        }
                    }
                }
            }
        }
    }
}

/* ----------------------------------------------------------------- PWL --- */

static hyst_real_t qx[MAX_PTS], qy[MAX_PTS];

/* curve.h's documented checks of hyst_curve_from_pwl, in their order. */
static hyst_status_t pwl_expected(size_t n)
{
    size_t i;
    if (n < 2u) return HYST_ERR_ARG;
    for (i = 0; i < n; ++i) {
        if (!isfinite(qx[i]) || (i > 0u && !(qx[i] > qx[i - 1u]))) return HYST_ERR_BREAKPOINTS;
    }
    if (!isfinite(qx[n - 1u] - qx[0])) return HYST_ERR_BREAKPOINTS; /* span must be finite */
    for (i = 0; i < n; ++i) {
        if (!isfinite(qy[i])) return HYST_ERR_COEFF;
    }
    if (!isfinite(qy[n - 1u] - qy[0])) return HYST_ERR_COEFF; /* so must the value span */
    for (i = 1; i < n; ++i) {
        if (qy[i] < qy[i - 1u]) return HYST_ERR_NOT_INCREASING;
    }
    return qy[n - 1u] > qy[0] ? HYST_OK : HYST_ERR_NOT_INCREASING;
}

/* PWL interpolation overflow and underflow (docs/reliability.md, regress_pwl_overflow, regress_pwl_underflow),
 * fixed: hyst_pwl_eval_() divides first and both spans must be finite, so
 * products no longer overflow or underflow. Still skipped (raw parameters
 * only): subnormal differences, which have no relative accuracy left. */
static int pwl_extreme(const hyst_real_t *px, const hyst_real_t *py, size_t n)
{
    size_t i;
    for (i = 0; i + 1u < n; ++i) {
        const double dx = px[i + 1u] - px[i], dy = py[i + 1u] - py[i];
        if ((dy != 0.0 && fabs(dy) < DBL_MIN) || fabs(dx) < DBL_MIN) {
            return 1;
        }
    }
    return 0;
}

/* hyst_curve_eval() works on d = x - lo and re-adds lo (the engine's form):
 * x moves by up to 2 eps (|lo| + |x|), which the steepest adjacent segment
 * (k - 1 or k) turns into an output error. */
static double x_rounding(const hyst_real_t *px, const hyst_real_t *py, size_t n, size_t k, double x)
{
    /* x itself is off by up to e (the rounding of lo + (x - lo)). While
     * x +- e stays within the neighbouring segments, f moves by at most their
     * largest slope times e, computed as dy * (e / dx) since dy / dx may
     * underflow; beyond them, by the values between the breakpoints that
     * bracket x +- e (f is monotone). */
    const double e = 4.0 * EPS * (fabs(px[0]) + fabs(x));
    size_t a = k > 0u ? k - 1u : 0u;
    size_t b = k + 2u < n ? k + 2u : n - 1u;
    double bound = 0.0;
    size_t j;
    if (x - e >= px[a] && x + e <= px[b]) {
        for (j = a; j < b; ++j) {
            bound = fmax(bound, fabs(py[j + 1u] - py[j]) * (e / (px[j + 1u] - px[j])));
        }
        return isfinite(bound) ? bound : INFINITY;
    }
    while (a > 0u && px[a] > x - e) --a;
    while (b + 1u < n && px[b] < x + e) ++b;
    return py[b] - py[a];
}

/* f(px[i]) == py[i]: curve.h says a PWL curve is exact at its breakpoints,
 * and on the structured grids (multiples of 1/16) every operation is exact,
 * so there it must be. With raw doubles hyst_curve_eval() computes
 * y_lo + g(x - lo), g = interp(lo + (x - lo)) - y_lo, and the last
 * breakpoint is interpolated in the last segment as y_n-2 + ((x_n-1 -
 * x_n-2) dy) / dx: exact only when those roundings are (regress_pwl_last_point:
 * breakpoints -1, 4e-314, 2 give f(4e-314) = 0). Allowed there: 4 eps of the
 * magnitudes involved, plus x_rounding() (reported as a documentation
 * precision, not a bug). */
static int at_breakpoint(const hyst_curve_t *c, const hyst_real_t *px, const hyst_real_t *py,
                         size_t n, size_t i)
{
    const double v = hyst_curve_eval(c, px[i]);
    if (v != py[i] && g_raw) {
        const double near = i > 0u ? fabs(py[i - 1u]) : 0.0;
        return fabs(v - py[i]) <= 4.0 * EPS * (fabs(py[0]) + fabs(py[i]) + near) +
                                      x_rounding(px, py, n, i, px[i]);
    }
    return v == py[i];
}

/* Segment containing x (largest k with qx[k] <= x, k <= n - 2). */
static size_t seg(size_t n, double x)
{
    size_t k = 0;
    while (k + 2u < n && qx[k + 1u] <= x) ++k;
    return k;
}

/* Points: n = byte % 34; structured: x_0 = (-128..127)/16, steps k/16
 * (k = 0: equal breakpoints), y steps (0..31)/16 (0: a flat piece), minus
 * 2/16 with the corruption flag (decreasing pieces). Then a capacity byte.
 * Opcodes: samples are desired outputs for the compensator round trip
 * (10% beyond the range); 0xF0 reset; 0xF1 probes of eval between
 * breakpoints; others: inverse of the inverse, g_unit, accessors. */
static void fuzz_pwl(reader_t *rd, unsigned flags)
{
    const size_t n = rd_u8(rd) % (MAX_PTS + 1u);
    const int raw = (int)(flags & 2u);
    hyst_curve_t c, inv, back, keep_c;
    hyst_status_t exp, st;
    size_t i, cap;
    double R, mx = 0.0, my = 0.0, L = 0.0, tol;
    int strict = 1, run_ok;
    unsigned ops;

    for (i = 0; i < n; ++i) {
        if (raw) {
            qx[i] = rd_f64(rd);
            qy[i] = rd_f64(rd);
        } else {
            const double dy = (double)(rd_u8(rd) % 32u) - ((flags & 4u) ? 2.0 : 0.0);
            qx[i] = i == 0u ? (double)(signed char)rd_u8(rd) / 16.0
                            : qx[i - 1u] + (double)(rd_u8(rd) % 16u) / 16.0;
            qy[i] = i == 0u ? dy / 16.0 - 1.0 : qy[i - 1u] + dy / 16.0;
        }
    }
    cap = rd_u8(rd) % CAP;
    exp = pwl_expected(n);
    if (flags & 8u) {
        CHECK(hyst_curve_from_pwl(NULL, qx, qy, n) == HYST_ERR_NULL);
        CHECK(hyst_curve_from_pwl(&c, qx, NULL, n) == HYST_ERR_NULL);
        CHECK(hyst_curve_check(NULL) == HYST_ERR_NULL);
        CHECK(hyst_curve_inverse(&inv, NULL) == HYST_ERR_NULL);
    }
    memset(&c, 0x6B, sizeof(c));
    memcpy(&keep_c, &c, sizeof(c));
    st = hyst_curve_from_pwl(&c, qx, qy, n);
    CHECK(st == exp);
    if (st != HYST_OK) {
        CHECK(memcmp(&c, &keep_c, sizeof(c)) == 0);
        return;
    }
    CHECK(hyst_curve_check(&c) == HYST_OK);
    CHECK(c.kind == HYST_CURVE_PWL && c.lo.HYST_R == qx[0] && c.hi.HYST_R == qx[n - 1u] &&
          c.y_lo.HYST_R == qy[0] && c.y_hi.HYST_R == qy[n - 1u]);
    if (flags & 8u) {
        CHECK(hyst_curve_inverse(NULL, &c) == HYST_ERR_NULL);
        back = c;
        back.kind = 0x5A; /* not a prepared curve */
        CHECK(hyst_curve_check(&back) == HYST_ERR_ARG && hyst_curve_inverse(&inv, &back) == HYST_ERR_ARG);
        back = c;
        back.u.pwl.n = 1u;
        CHECK(hyst_curve_check(&back) == HYST_ERR_ARG);
    }
    R = qy[n - 1u] - qy[0];
    if (pwl_extreme(qx, qy, n)) { /* FINDING: see pwl_extreme() */
        CHECK(raw);
        return;
    }
    for (i = 0; i < n; ++i) {
        mx = fmax(mx, fabs(qx[i]));
        my = fmax(my, fabs(qy[i]));
        CHECK(at_breakpoint(&c, qx, qy, n, i)); /* curve.h: exact at the breakpoints */
        if (i > 0u) L = fmax(L, (qy[i] - qy[i - 1u]) / (qx[i] - qx[i - 1u]));
        if (i > 0u) strict &= qy[i] > qy[i - 1u];
    }
    CHECK(hyst_curve_g(&c, 0.0) == 0.0);
    CHECK(init_on(&G, &c, 2u) == HYST_OK); /* probe of the engine's g */
    /* Interpolation between breakpoints lies between the neighbours' values
     * (so f is monotone), up to the rounding of (x - x_k) dy / dx (the
     * quotient can exceed dy by 2 ulps) and of eval's y_lo + (interp - y_lo):
     * 4 eps of the magnitudes involved, plus x_rounding(). */
    for (i = 0; i + 1u < n; ++i) {
        const double t = (double)rd_u8(rd) / 255.0;
        const double x = fmin(qx[i] + t * (qx[i + 1u] - qx[i]), qx[i + 1u]);
        const double v = hyst_curve_eval(&c, x);
        const double slack = 4.0 * EPS * (fabs(qy[0]) + fabs(qy[i]) + fabs(qy[i + 1u])) +
                             x_rounding(qx, qy, n, i, x);
        CHECK(v >= qy[i] - slack && v <= qy[i + 1u] + slack);
        CHECK(engine_g_matches(&c, x)); /* per-sample g == hyst_curve_g */
    }

    memset(&inv, 0x6B, sizeof(inv));
    st = hyst_curve_inverse(&inv, &c);
    if (!strict) { /* a flat piece: no inverse, nothing written */
        CHECK(st == HYST_ERR_NOT_INVERTIBLE && memcmp(&inv, &keep_c, sizeof(inv)) == 0);
        return;
    }
    CHECK(st == HYST_OK && inv.kind == HYST_CURVE_PWL_INV && hyst_curve_check(&inv) == HYST_OK);
    CHECK(inv.lo.HYST_R == c.y_lo.HYST_R && inv.hi.HYST_R == c.y_hi.HYST_R &&
          inv.y_lo.HYST_R == c.lo.HYST_R && inv.y_hi.HYST_R == c.hi.HYST_R);
    CHECK(hyst_curve_inverse(&back, &inv) == HYST_OK && back.kind == HYST_CURVE_PWL);
    fuzz_check_kinds(&c);
    fuzz_check_kinds(&inv);
    CHECK(back.u.pwl.x.HYST_R == qx && back.u.pwl.y.HYST_R == qy && back.lo.HYST_R == c.lo.HYST_R &&
          back.hi.HYST_R == c.hi.HYST_R);
    for (i = 0; i < n; ++i) CHECK(at_breakpoint(&inv, qy, qx, n, i)); /* swapped axes: exact */
    /* Round trip f(f^-1(v)) = v. Per point: the drive's rounding (a few eps
     * of max|x|) times the steepest slope L, plus a few eps of |v|; with
     * structured points that is far below 1e-9 R, which is the product's bound;
     * raw points can be arbitrarily steep, so the rounding term is kept. */
    if (!isfinite(R) || !isfinite(L) || !isfinite(mx * L) || !(R >= DBL_MIN / EPS)) return;
    tol = 1e-9 * R + 16.0 * EPS * (my + mx * L);
    for (i = 0; i + 1u < n; ++i) {
        const double v = qy[i] + (double)rd_u8(rd) / 255.0 * (qy[i + 1u] - qy[i]);
        const double xv = hyst_curve_eval(&inv, v);
        CHECK(in_domain(xv, c.lo.HYST_R, c.hi.HYST_R));
        /* the drive's rounding through f, as x_rounding() bounds it: the
         * slope term above underflows for spans like 1e-149 over 1e303 */
        CHECK(xv >= qx[seg(n, xv)] &&
              fabs(hyst_curve_eval(&c, xv) - v) <=
                  tol + fmax(0.0, 2.0 * x_rounding(qx, qy, n, seg(n, xv), xv) - 16.0 * EPS * mx * L));
    }
    if (raw) return;

    /* Compensator round trip through two engines: Ti on f^-1, T on f. */
    memset(&Ti, 0, sizeof(Ti));
    memcpy(&keep_t, &Ti, sizeof(Ti));
    st = init_on(&Ti, &inv, cap);
    CHECK(st == (cap < 2u ? HYST_ERR_CAPACITY : HYST_OK));
    if (st != HYST_OK) {
        CHECK(memcmp(&Ti, &keep_t, sizeof(Ti)) == 0);
        return;
    }
    CHECK(init_on(&T, &c, cap) == HYST_OK);
    run_ok = 1;
    for (ops = 0; ops < MAX_OPS && rd->at < rd->n; ++ops) {
        const unsigned op = rd_u8(rd);
        if (op == 0xF0u) {
            hyst_reset(&T.S);
            hyst_reset(&Ti.S);
            run_ok = 1;
            continue;
        }
        if ((op & 0xF0u) == 0xF0u) {
            (void)hyst_output(&Ti.S);
            hyst_clear_events(&Ti.S);
            continue;
        }
        {
            const double yd = next_pos(rd, op, qy[0], R);
            const double xd = hyst_step(&Ti.S, yd);
            if (!isfinite(yd)) {
                CHECK(hyst_status(&Ti.S) == HYST_ERR_NONFINITE);
                continue;
            }
            if (hyst_status(&Ti.S) == HYST_WARN_FULL) run_ok = 0;
            CHECK(in_domain(xd, c.lo.HYST_R, c.hi.HYST_R)); /* see fuzz_inverse() */
            CHECK((hyst_status(&Ti.S) == HYST_WARN_CLAMPED) ==
                      (yd < c.y_lo.HYST_R || yd > c.y_hi.HYST_R) ||
                  hyst_status(&Ti.S) == HYST_WARN_FULL);
            {
                const double yf = hyst_step(&T.S, xd);
                if (hyst_status(&T.S) == HYST_WARN_FULL) run_ok = 0;
                /* (TPs + 2) per-point bounds: the turning points each output
                 * hangs on carry their own rounding (as in fuzz_hyst.c). */
                if (run_ok) {
                    const double depth = (double)hyst_tp_count(&T.S) + 2.0;
                    CLOSE("pwl_tcm_round_trip", fabs(yf - clampd(yd, c.y_lo.HYST_R, c.y_hi.HYST_R)),
                          depth * tol);
                }
            }
        }
    }
}

/* ---------------------------------------------------- polynomial inverse --- */

/* Smallest slope of f0 on a 1025-point grid, relative to the mean slope
 * R / span; the Newton inverse is well conditioned where it is not small. */
static double min_rel_slope(const hyst_poly_t *f, double R)
{
    double m = INFINITY;
    unsigned j, k;
    for (j = 0; j <= 1024u; ++j) {
        const double x = f->lo + (f->hi - f->lo) * (double)j / 1024.0;
        double d = 0.0;
        for (k = 0; k < f->degree; ++k) d = d * x + (double)(f->degree - k) * f->coeffs[k];
        m = fmin(m, d);
    }
    return m * (f->hi - f->lo) / R;
}

/* Upper bound of |f0'| on the domain: sum k |c_k| M^(k-1). */
static double slope_bound(const hyst_poly_t *f)
{
    const double m = fmax(fabs(f->lo), fabs(f->hi));
    double acc = 0.0;
    unsigned k;
    for (k = 0; k < f->degree; ++k) acc = acc * m + (double)(f->degree - k) * fabs(f->coeffs[k]);
    return acc;
}

/* Config as fuzz_hyst.c (read_config), then a capacity byte, and with flag
 * bit4 (the tabulated compensator) an intervals byte (1..64). Init must
 * report the curve error first, then the instance's. Opcodes: samples are
 * desired outputs (10% beyond [f0(lo), f0(hi)]); 0xF0 reset; others:
 * accessors. */
static void fuzz_inverse(reader_t *rd, unsigned flags)
{
    hyst_poly_t f;
    hyst_curve_t cf, ci, ct, back;
    hyst_status_t exp, st, cst;
    size_t cap, intervals = 0u;
    double R, tol, M, rel, prev_d = 0.0, prev_yd = 0.0, prev_xd = 0.0;
    int run_ok, flat, moved = 0;
    const int tab = (flags & 16u) != 0u;
    unsigned ops, j;

    memset(&ct, 0, sizeof ct);
    read_config(rd, (int)(flags & 2u), &f);
    cap = rd_u8(rd) % CAP;
    if (tab) {
        intervals = 1u + rd_u8(rd) % TI_MAX_INTERVALS;
    }
    cst = hyst_curve_from_poly(&cf, &f);
    exp = cst;
    if (cst == HYST_OK) {
        cst = hyst_curve_inverse(&ci, &cf);
        if (cst == HYST_OK && tab) {
            cst = hyst_curve_inverse_table(&ct, &cf, ct_table, intervals);
        }
        if (cst == HYST_OK && tab) { /* the same table as from flash: the build's curve */
            hyst_table_seal_t seal;
            hyst_curve_t from_flash;
            CHECK(hyst_curve_table_seal(&ct, &seal) == HYST_OK);
            CHECK(hyst_curve_inverse_table_const(&from_flash, &cf, ct_table, intervals, &seal) ==
                  HYST_OK);
            CHECK(from_flash.u.inv_table.exact == ct.u.inv_table.exact &&
                  hyst_curve_inverse_error(&from_flash) == hyst_curve_inverse_error(&ct) &&
                  memcmp(&from_flash.unit, &ct.unit, sizeof ct.unit) == 0);
        }
        exp = cst != HYST_OK ? cst : (cap < 2u ? HYST_ERR_CAPACITY : HYST_OK);
    }
    if (flags & 8u) {
        CHECK(hyst_init_inverse_exact(&Ti.S, &ti_curve, NULL, Ti.xl, Ti.yl, Ti.xr, Ti.yr, cap) ==
              HYST_ERR_NULL);
        CHECK(hyst_init_inverse_exact(&Ti.S, NULL, &f, Ti.xl, Ti.yl, Ti.xr, Ti.yr, cap) == HYST_ERR_NULL);
        if (cst == HYST_OK) {
            CHECK(hyst_init_inverse_exact(NULL, &ti_curve, &f, Ti.xl, Ti.yl, Ti.xr, Ti.yr, cap) ==
                  HYST_ERR_NULL);
            CHECK(hyst_init_inverse_exact(&Ti.S, &ti_curve, &f, Ti.xl, NULL, Ti.xr, Ti.yr, cap) ==
                  HYST_ERR_NULL);
        }
    }
    memset(&Ti, 0x77, sizeof(Ti));
    memcpy(&keep_t, &Ti, sizeof(Ti));
    /* the compensator under test: tabulated (the firmware's) or exact */
    st = tab ? hyst_init_inverse_table(&Ti.S, &ti_curve, &f, ti_table, intervals, Ti.xl, Ti.yl,
                                       Ti.xr, Ti.yr, cap)
             : hyst_init_inverse_exact(&Ti.S, &ti_curve, &f, Ti.xl, Ti.yl, Ti.xr, Ti.yr, cap);
    CHECK(st == exp);
    if (st != HYST_OK) {
        CHECK(memcmp(&Ti, &keep_t, sizeof(Ti)) == 0);
        return;
    }
    CHECK(Ti.S.curve == &ti_curve); /* the instance points at the caller's storage */
    CHECK(hyst_curve_check(&ci) == HYST_OK);
    if (tab) { /* same table as the two calls, its error measured */
        CHECK(Ti.S.curve->kind == HYST_CURVE_INV_TABLE && hyst_curve_check(Ti.S.curve) == HYST_OK);
        CHECK(memcmp(ti_table, ct_table, sizeof(hyst_real_t) * HYST_INV_TABLE_LEN(intervals)) == 0);
        CHECK(hyst_curve_inverse_error(Ti.S.curve) == hyst_curve_inverse_error(&ct));
        CHECK(hyst_curve_inverse_error(&ct) >= 0.0 && hyst_curve_inverse_error(&ct) <= 1.0);
        {   /* sealed with its table (hyst_seal_inverse_table): the same curve, bit for bit */
            static hyst_curve_t sealed_curve;
            hyst_sealed_inverse_t sealed;
            unsigned k;
            CHECK(hyst_seal_inverse_table(&sealed, &ct) == HYST_OK);
            CHECK(hyst_init_inverse_sealed(&G.S, &sealed_curve, &sealed, ct_table, G.xl, G.yl, G.xr,
                                           G.yr, 2u) == HYST_OK);
            CHECK(hyst_curve_inverse_error(&sealed_curve) == hyst_curve_inverse_error(&ct));
            for (k = 0u; k <= 16u; ++k) {
                const double e = (ct.hi.HYST_R - ct.lo.HYST_R) * ((double)k / 16.0);
                const double a = hyst_curve_g(&sealed_curve, e), b = hyst_curve_g(&ct, e);
                CHECK(memcmp(&a, &b, sizeof a) == 0);
            }
        }
    } else {
        CHECK(Ti.S.curve->kind == HYST_CURVE_POLY_INV);
        CHECK(memcmp(Ti.S.curve, &ci, sizeof(ci)) == 0); /* same as the two calls */
    }
    CHECK(hyst_curve_inverse(&back, &ci) == HYST_OK && back.kind == HYST_CURVE_POLY);
    fuzz_check_kinds(&cf);
    fuzz_check_kinds(&ci);
    R = cf.y_hi.HYST_R - cf.y_lo.HYST_R;
    M = fmax(fabs(f.lo), fabs(f.hi));
    /* g(g^-1(e)) = e: the product's 1e-9 of the range, plus the drive's
     * rounding (8 eps M) times the steepest slope and Horner's bound (raw
     * curves can be badly scaled). Flat points (f0' below 1% of its mean
     * slope somewhere) are held to the same bound since the monotone bisection replaced Newton
     * (docs/reliability.md; regress_inverse_flat_point gave 3.9e-9 of the
     * range with Newton); the flag only names the check. */
    rel = min_rel_slope(&f, R);
    flat = !(rel >= 1e-2);
    tol = 1e-9 * R + 8.0 * EPS * M * slope_bound(&f) + 4.0 * horner_bound(&f);
    /* A range within 1/eps of the subnormals has no relative accuracy left
     * (raw curves only): init and the structural checks above suffice. */
    if (!isfinite(tol) || !(R >= DBL_MIN / EPS)) return;
    /* Within 64 (n + 1) of DBL_MAX, Horner's partial sums of G can overflow
     * (the Newton solver before the monotone bisection lost G' there: 4e-4 of the
     * range on regress_inverse_knot_overflow, R = 5.3e307); an infinite G(m)
     * sends the bisection left. Raw curves only, noted in
     * docs/reliability.md; only the bound below is checked. */
    if (!isfinite(R * 64.0 * (double)(f.degree + 1u))) {
        /* What is still guaranteed there: the knot table brackets e within
         * one of HYST_INV_KNOTS equal slices of the range, and the answer
         * stays in that bracket, so the residual is at most R / K. Before
         * the fill_knots overflow fix it was 0.75 R. */
        for (j = 0; j <= 64u; ++j) {
            const double e = R * ((double)j / 64.0);
            const double d = hyst_curve_g(&ci, e), g = hyst_curve_g(&cf, d);
            CHECK(d >= 0.0 && d <= cf.hi.HYST_R - cf.lo.HYST_R && d >= prev_d); /* monotone here too */
            prev_d = d;
            if (isfinite(g)) CLOSE("poly_inv_near_dbl_max", fabs(g - e), R / HYST_INV_KNOTS * (1.0 + 1e-9));
        }
        return;
    }
    CHECK(init_on(&G, &ci, 2u) == HYST_OK); /* probe of the engine's g^-1 */
    for (j = 0; j <= 64u; ++j) { /* curve level: g(g^-1(e)) = e */
        const double e = R * ((double)j / 64.0); /* no overflow near DBL_MAX */
        const double d = hyst_curve_g(&ci, e);
        CHECK(d >= 0.0 && d <= cf.hi.HYST_R - cf.lo.HYST_R);
        /* g^-1 non-decreasing (monotone bisection): grid and neighbouring doubles */
        CHECK(d >= prev_d && hyst_curve_g(&ci, nextafter(e, -INFINITY)) <= d &&
              hyst_curve_g(&ci, nextafter(e, INFINITY)) >= d);
        prev_d = d;
        CHECK(engine_g_matches(&ci, ci.lo.HYST_R + e)); /* per-sample g == hyst_curve_g */
        CLOSE(flat ? "poly_inv_curve_flat" : "poly_inv_curve_round_trip", fabs(hyst_curve_g(&cf, d) - e), tol);
        CLOSE("poly_inv_of_inv", fabs(hyst_curve_g(&back, d) - hyst_curve_g(&cf, d)), 4.0 * EPS * R + horner_bound(&f));
    }
    if (flags & 2u) return; /* raw: init and the curve level only */
    if (tab) { /* the table's drive error, measured at init, as an output error */
        tol += 4.0 * (double)hyst_curve_inverse_error(&ct) * (cf.hi.HYST_R - cf.lo.HYST_R) *
               slope_bound(&f);
    }
    CHECK(init_on(&T, &cf, cap) == HYST_OK);
    run_ok = 1;
    for (ops = 0; ops < MAX_OPS && rd->at < rd->n; ++ops) {
        const unsigned op = rd_u8(rd);
        if (op == 0xF0u) {
            hyst_reset(&T.S);
            hyst_reset(&Ti.S);
            run_ok = 1;
            moved = 0;
            continue;
        }
        if ((op & 0xF0u) == 0xF0u) {
            (void)hyst_input(&Ti.S);
            continue;
        }
        {
            const double yd = next_pos(rd, op, cf.y_lo.HYST_R, R);
            const double xd = hyst_step(&Ti.S, yd);
            if (!isfinite(yd)) continue;
            /* the drive never moves against the desired output (both
             * compensators: the monotone guard) */
            CHECK(!moved || !((yd > prev_yd && xd < prev_xd) || (yd < prev_yd && xd > prev_xd)));
            moved = 1;
            prev_yd = yd;
            prev_xd = xd;
            if (hyst_status(&Ti.S) == HYST_WARN_FULL) run_ok = 0;
            /* The drive stays in [lo, hi], after a merge too (the output clamp after a full array,
             * regress_full_drive_overrange, fixed: the engine clamps). */
            CHECK(in_domain(xd, cf.lo.HYST_R, cf.hi.HYST_R));
            {
                const double yf = hyst_step(&T.S, xd);
                if (hyst_status(&T.S) == HYST_WARN_FULL) run_ok = 0;
                /* H(H^-1(yd)) = clamp(yd); per-TP bound as above, on flat
                 * curves too: g^-1 is monotone since the monotone bisection replaced Newton (before,
                 * regress_inverse_flat_reversal reversed the drive and the
                 * model missed yd by 1.2e-5 of the range). */
                if (run_ok) {
                    const double depth = (double)hyst_tp_count(&T.S) + 2.0;
                    CLOSE("poly_inv_tcm_round_trip",
                          fabs(yf - clampd(yd, cf.y_lo.HYST_R, cf.y_hi.HYST_R)), depth * tol);
                }
            }
        }
    }
}

/* ------------------------------------------------------- identification --- */

static hyst_ident_t id, id2, keep_id;
static hyst_wide_t recx[MAX_REC], recy[MAX_REC];

typedef struct {
    int started, dir;
    double prev;
} dir_t;

/* ident.h: direction of travel; a repeated input keeps it; 0 until it moves. */
static int classify(dir_t *d, double x)
{
    if (d->started && x != d->prev) d->dir = x > d->prev ? 1 : -1;
    d->started = 1;
    d->prev = x;
    return d->dir;
}

static hyst_status_t ident_init_expected(const hyst_ident_config_t *cfg)
{
    if (cfg->degree < 1u || cfg->degree > HYST_MAX_DEGREE) return HYST_ERR_DEGREE;
    if (!isfinite(cfg->lo) || !isfinite(cfg->hi) || !(cfg->lo < cfg->hi) ||
        !isfinite(cfg->hi - cfg->lo)) {
        return HYST_ERR_DOMAIN;
    }
    return cfg->method >= 0 && cfg->method <= 2 ? HYST_OK : HYST_ERR_ARG;
}

static hyst_status_t sample_expected(const hyst_ident_config_t *cfg, double x, double y)
{
    if (!isfinite(x) || !isfinite(y)) return HYST_ERR_NONFINITE;
    return x < cfg->lo || x > cfg->hi ? HYST_ERR_DOMAIN : HYST_OK;
}

/* f0 by Horner's rule on the user's coefficients, in double. */
static double ref_f0c(const hyst_poly_t *f, double x)
{
    double acc = 0.0;
    unsigned k;
    for (k = 0; k <= f->degree; ++k) acc = acc * x + f->coeffs[k];
    return acc;
}

static double horner_w(const hyst_wide_t *c, unsigned n, double x)
{
    double acc = 0.0;
    unsigned k;
    for (k = 0; k <= n; ++k) acc = acc * x + c[k];
    return acc;
}

/* Known f0 through the TCM, no noise: four full legs lo->hi->lo->hi->lo
 * with M points each. Full-range legs wipe the memory, so rising samples lie
 * on f0 and falling ones on the major falling branch: both estimators must
 * give f0 back. */
static void ident_known(reader_t *rd, unsigned flags)
{
    hyst_poly_t f, p;
    hyst_ident_config_t cfg;
    hyst_ident_result_t res;
    size_t m = 0;
    unsigned M, leg, k, j;
    double tol, scale = 0.0;
    hyst_status_t st;

    read_config(rd, 0, &f);
    if (hyst_init(&T.S, &f, T.xl, T.yl, T.xr, T.yr, 8u) != HYST_OK) return;
    M = 8u * (f.degree + 1u) + rd_u8(rd) % 32u;
    for (leg = 0; leg < 4u; ++leg) {
        for (k = (leg == 0u ? 0u : 1u); k <= M; ++k) {
            double x = f.lo + (f.hi - f.lo) * (double)k / (double)M;
            if (k == M) x = f.hi;
            if (leg & 1u) x = f.lo + f.hi - x;
            if (leg & 1u && k == M) x = f.lo;
            recx[m] = x;
            recy[m] = hyst_step(&T.S, x);
            ++m;
        }
    }
    memset(&cfg, 0, sizeof(cfg));
    cfg.degree = f.degree;
    cfg.method = (flags & 4u) ? HYST_IDENT_REFLECT : HYST_IDENT_JOINT;
    if (flags & 8u) { /* explicit domain, else from the data (lo == hi) */
        cfg.lo = f.lo;
        cfg.hi = f.hi;
    }
    st = hyst_ident_fit(&cfg, recx, recy, m, &id, &res);
    CHECK(st == HYST_OK);
    CHECK(res.lo == f.lo && res.hi == f.hi && res.used + 1u == m && res.degree == f.degree);
    for (j = 0; j <= 64u; ++j) scale = fmax(scale, fabs(ref_f0c(&f, f.lo + (f.hi - f.lo) * j / 64.0)));
    /* Data: TCM outputs, within 2 Horner bounds of f0 (fuzz_hyst.c checks
     * that). Least squares by Givens rotations is backward stable; the
     * Chebyshev basis on >= 8(n+1) equispaced points is well conditioned
     * (2-norm condition 1.6 at n = 1, 2.8 at n = 9, computed for this grid),
     * so the fitted Chebyshev series is f0 to about sqrt(samples) n eps cond
     * ~ 1e-13 of max|f0|.
     * Converting to monomials in user units and evaluating them costs
     * Horner's bound of the fitted coefficients (the dominant term when
     * |lo| >> span). 1e-11 of max|f0| covers the first, the two Horner terms
     * the rest. Measured: err/tol <= 3e-4 (docs/reliability.md). */
    tol = 1e-11 * scale + 8.0 * horner_bound(&f);
    CHECK(hyst_ident_poly(&res, &p) == HYST_OK);
    tol += 8.0 * horner_bound(&p);
    for (j = 0; j <= 64u; ++j) {
        const double x = f.lo + (f.hi - f.lo) * j / 64.0;
        CLOSE("ident_known_fit", fabs(horner_w(res.coeffs, res.degree, x) - ref_f0c(&f, x)), tol);
    }
    CHECK(res.max_abs >= 0.0 && res.max_abs <= 2.0 * tol);
}

/* Arbitrary streams. Config: degree byte % 12, method (-128..127) % 4,
 * domain (raw or grid). Opcodes: op >> 6 = 0, 1 add; 2 check; 3 control
 * (op & 3: solve, residuals, ident_poly, re-init). Every return code is
 * predicted from ident.h; init errors write nothing. Then hyst_ident_domain
 * and hyst_ident_fit on the recorded samples. */
static void fuzz_pi_fit(reader_t *rd, unsigned flags);

static void fuzz_ident(reader_t *rd, unsigned flags)
{
    hyst_ident_config_t cfg;
    hyst_ident_result_t res;
    hyst_poly_t p;
    hyst_status_t exp, st;
    dir_t d = {0, 0, 0.0};
    size_t used = 0, rising = 0, falling = 0, checked = 0, m = 0, i;
    int phase = 0, have_res = 0, ok, moves;
    unsigned ops;

    if (flags & 32u) {
        fuzz_pi_fit(rd, flags);
        return;
    }
    if (flags & 16u) {
        ident_known(rd, flags);
        return;
    }
    memset(&cfg, 0, sizeof(cfg));
    cfg.degree = rd_u8(rd) % 12u;
    cfg.method = (int)(signed char)rd_u8(rd) % 4;
    if (flags & 2u) {
        cfg.lo = rd_f64(rd);
        cfg.hi = rd_f64(rd);
    } else {
        cfg.lo = (double)(signed char)rd_u8(rd) / 16.0;
        cfg.hi = cfg.lo + (double)(rd_u8(rd) % 64u) / 16.0;
    }
    exp = ident_init_expected(&cfg);
    if (flags & 8u) {
        CHECK(hyst_ident_init(NULL, &cfg) == HYST_ERR_NULL);
        CHECK(hyst_ident_init(&id, NULL) == HYST_ERR_NULL);
        CHECK(hyst_ident_solve(NULL, &res) == HYST_ERR_NULL);
        CHECK(hyst_ident_residuals(NULL, &res) == HYST_ERR_NULL);
        CHECK(hyst_ident_domain(NULL, 1u, &cfg.lo, &cfg.hi) == HYST_ERR_NULL);
        CHECK(hyst_ident_fit(&cfg, NULL, recy, 1u, &id, &res) == HYST_ERR_NULL);
        CHECK(hyst_ident_poly(NULL, &p) == HYST_ERR_NULL);
    }
    memset(&id, 0x3C, sizeof(id));
    memcpy(&keep_id, &id, sizeof(id));
    st = hyst_ident_init(&id, &cfg);
    CHECK(st == exp);
    ok = st == HYST_OK;
    if (!ok) CHECK(memcmp(&id, &keep_id, sizeof(id)) == 0);
    if (ok && (flags & 8u)) CHECK(hyst_ident_solve(&id, NULL) == HYST_ERR_NULL);

    for (ops = 0; ops < MAX_OPS && rd->at < rd->n && ok; ++ops) {
        const unsigned op = rd_u8(rd);
        const unsigned kind = op >> 6;
        if (kind < 3u) {
            const unsigned yb = rd_u8(rd);
            const double x = next_pos(rd, op, cfg.lo, cfg.hi - cfg.lo);
            double y = yb == 0u ? NAN : yb == 1u ? INFINITY : yb == 2u ? rd_f64(rd)
                                                                     : (double)(signed char)yb / 8.0 + x;
            /* Outputs up to DBL_MAX: the slow identification on huge outputs (fuzz/slow/regress_ident_overflow_solve,
             * seconds per solve before) is fixed, no clamp any more. */
            exp = sample_expected(&cfg, x, y);
            /* a sample refused for its output alone still sets the direction
             * (ident.h: a gap in a record keeps the branch) */
            moves = exp != HYST_OK && isfinite(x) && x >= cfg.lo && x <= cfg.hi;
            if (kind < 2u) {
                st = hyst_ident_add(&id, x, y);
                if (phase != 0) exp = HYST_ERR_ARG;
                if (phase == 0 && moves) (void)classify(&d, x);
                if (exp == HYST_OK && classify(&d, x) != 0) {
                    ++used;
                    if (d.dir > 0) ++rising; else ++falling;
                }
            } else {
                st = hyst_ident_check(&id, x, y);
                if (phase != 1) exp = HYST_ERR_ARG;
                if (phase == 1 && moves) (void)classify(&d, x);
                if (exp == HYST_OK && classify(&d, x) != 0) ++checked;
            }
            CHECK(st == exp);
            if (m < MAX_REC) {
                recx[m] = x;
                recy[m] = y;
                ++m;
            }
            continue;
        }
        switch (op & 3u) {
        case 0:
            {
                hyst_ident_result_t before;
                memcpy(&before, &res, sizeof res);
                st = hyst_ident_solve(&id, &res);
                if (phase != 0) {
                    CHECK(st == HYST_ERR_ARG);
                } else if (used < cfg.degree + 1u) { /* fewer rows than unknowns */
                    CHECK(st == HYST_ERR_SINGULAR);
                } else { /* ILL_CONDITIONED: coefficients that cannot hold the fit (ident.h) */
                    CHECK(st == HYST_OK || st == HYST_ERR_SINGULAR || st == HYST_ERR_ILL_CONDITIONED);
                }
                if (st == HYST_ERR_ILL_CONDITIONED) CHECK(memcmp(&before, &res, sizeof res) == 0);
            }
            if (st == HYST_OK) {
                CHECK(res.degree == cfg.degree && res.lo == cfg.lo && res.hi == cfg.hi);
                CHECK(res.method == (cfg.method == 0 ? HYST_IDENT_JOINT : cfg.method));
                CHECK(res.used == used && res.rising == rising && res.falling == falling);
                CHECK(res.max_abs < 0.0); /* no check pass yet */
                phase = 1;
                have_res = 1;
                d.started = d.dir = 0; /* the check pass classifies afresh */
                checked = 0;
            }
            break;
        case 1:
            st = hyst_ident_residuals(&id, &res);
            CHECK(st == (phase == 1 && checked > 0u ? HYST_OK : HYST_ERR_ARG));
            if (st == HYST_OK) CHECK(!(res.rms < 0.0) && !(res.max_abs < 0.0));
            break;
        case 2:
            if (have_res) {
                unsigned k;
                int fin = isfinite(res.lo) && isfinite(res.hi);
                for (k = 0; k <= res.degree; ++k) fin &= isfinite(res.coeffs[k]) != 0;
                st = hyst_ident_poly(&res, &p);
                CHECK(st == (fin ? HYST_OK : HYST_ERR_COEFF));
                if (st == HYST_OK) CHECK(p.degree == res.degree && p.coeffs[0] == res.coeffs[0]);
            }
            break;
        default:
            CHECK(hyst_ident_init(&id, &cfg) == HYST_OK);
            phase = 0;
            used = rising = falling = checked = 0;
            d.started = d.dir = 0;
            break;
        }
    }

    /* hyst_ident_domain: range of the finite entries */
    {
        double lo = 0.0, hi = 0.0, a = INFINITY, b = -INFINITY;
        for (i = 0; i < m; ++i) {
            if (isfinite(recx[i])) {
                a = fmin(a, recx[i]);
                b = fmax(b, recx[i]);
            }
        }
        st = hyst_ident_domain(recx, m, &lo, &hi);
        CHECK(st == (a < b ? HYST_OK : HYST_ERR_DOMAIN));
        if (st == HYST_OK) CHECK(lo == a && hi == b);
    }
    /* hyst_ident_fit against the same calls made by hand on a second instance */
    cfg.skip = rd_u8(rd) % 8u;
    cfg.delay = rd_u8(rd) % 8u;
    if (flags & 4u) cfg.lo = cfg.hi = 0.0;
    st = hyst_ident_fit(&cfg, recx, recy, m, &id, &res);
    if (cfg.skip >= m || cfg.delay >= m - cfg.skip) {
        CHECK(st == HYST_ERR_ARG);
        return;
    }
    {
        hyst_ident_config_t c2 = cfg;
        hyst_ident_result_t r2;
        const size_t count = m - cfg.skip - cfg.delay;
        hyst_status_t s2 = HYST_OK;
        if (c2.lo == c2.hi) s2 = hyst_ident_domain(recx + cfg.skip, count, &c2.lo, &c2.hi);
        if (s2 == HYST_OK) s2 = hyst_ident_init(&id2, &c2);
        if (s2 == HYST_OK) {
            for (i = 0; i < count; ++i) (void)hyst_ident_add(&id2, recx[cfg.skip + i], recy[cfg.skip + cfg.delay + i]);
            s2 = hyst_ident_solve(&id2, &r2);
        }
        if (s2 == HYST_OK) {
            for (i = 0; i < count; ++i) (void)hyst_ident_check(&id2, recx[cfg.skip + i], recy[cfg.skip + cfg.delay + i]);
            s2 = hyst_ident_residuals(&id2, &r2);
        }
        CHECK(st == s2);
        if (st == HYST_OK) CHECK(memcmp(res.coeffs, r2.coeffs, sizeof(res.coeffs)) == 0);
        /* and once more at HYST_MAX_DEGREE, lowered to the degree: the same
         * solve bit for bit (ident.h); errors write nothing */
        c2.degree = HYST_MAX_DEGREE; /* on the domain found above */
        if (hyst_ident_init(&id2, &c2) == HYST_OK) {
            for (i = 0; i < count; ++i) (void)hyst_ident_add(&id2, recx[cfg.skip + i], recy[cfg.skip + cfg.delay + i]);
            memcpy(&keep_id, &id, sizeof(id));
            s2 = hyst_ident_lower_degree(&id2, cfg.degree, &id);
            CHECK(s2 == (cfg.degree >= 1u && cfg.degree <= HYST_MAX_DEGREE ? HYST_OK : HYST_ERR_DEGREE));
            if (s2 != HYST_OK) {
                CHECK(memcmp(&id, &keep_id, sizeof(id)) == 0);
            } else {
                s2 = hyst_ident_solve(&id, &r2);
                if (st == HYST_OK || st == HYST_ERR_SINGULAR || st == HYST_ERR_ILL_CONDITIONED) CHECK(s2 == st);
                if (s2 == HYST_OK) CHECK(memcmp(res.coeffs, r2.coeffs, sizeof(res.coeffs)) == 0);
                if (s2 == HYST_OK) CHECK(hyst_ident_lower_degree(&id, 1u, &id2) == HYST_ERR_ARG); /* solved */
            }
        }
    }
}

/* ------------------------------------------- PI weights by NNLS (ident.h) --- */

static hyst_wide_t fit_work[HYST_PI_FIT_WORK(HYST_PI_FIT_MAX_OPERATORS)];
static hyst_wide_t fit_work2[HYST_PI_FIT_WORK(HYST_PI_FIT_MAX_OPERATORS)];
static hyst_wide_t fit_r[HYST_PI_FIT_MAX_OPERATORS + 6u], fit_w[HYST_PI_FIT_MAX_OPERATORS + 6u];
static hyst_wide_t fit_r2[HYST_PI_FIT_MAX_OPERATORS + 6u], fit_w2[HYST_PI_FIT_MAX_OPERATORS + 6u];
static double fit_z[HYST_PI_FIT_MAX_OPERATORS], fit_g[HYST_PI_FIT_MAX_OPERATORS];

static hyst_status_t pi_fit_init_expected(const hyst_wide_t *r, size_t n, size_t len)
{
    size_t i;
    if (n < 1u || n > HYST_PI_FIT_MAX_OPERATORS) return HYST_ERR_ARG;
    if (len < HYST_PI_FIT_WORK(n)) return HYST_ERR_NOSPACE;
    if (r[0] != 0.0) return HYST_ERR_BREAKPOINTS;
    for (i = 1; i < n; ++i) {
        if (!isfinite(r[i]) || !(r[i] > r[i - 1u])) return HYST_ERR_BREAKPOINTS;
    }
    return HYST_OK;
}

/* KKT of the solved fit against the samples recx/recy[0..m) (all of them
 * added since init, in order), with the operators written out here: the
 * objective's gradient -Z'e is ~0 on positive weights and >= ~0 on zero
 * ones, e = y - offset - Z w. The bound: rounding of the normal equations,
 * relative to |Z| |e| + |Z|^2 sum w (Cauchy-Schwarz on each entry); and on
 * zero weights the Cholesky's rejection of near-dependent columns: a column
 * whose pivot is below 1e4 eps of its diagonal stays out, and differs from
 * the span of the others by r, |r|^2 <= 1e4 eps |z_i|^2, so its gradient
 * r'e may reach sqrt(1e4 eps) |Z| |e|. */
static void pi_fit_kkt(size_t n, const hyst_pi_fit_result_t *res, size_t m)
{
    double z2 = 0.0, e2 = 0.0, wsum = 0.0, tol;
    size_t i, k;
    for (k = 0; k < m; ++k) { /* raw doubles among the samples: the bound means nothing */
        if ((isfinite(recx[k]) && fabs(recx[k]) > 1e6) || (isfinite(recy[k]) && fabs(recy[k]) > 1e6)) {
            return;
        }
    }
    for (i = 0; i < n; ++i) {
        fit_z[i] = 0.0;
        fit_g[i] = 0.0;
        wsum += fit_w[i];
    }
    for (k = 0; k < m; ++k) {
        double e = recy[k] - res->offset;
        if (!isfinite(recx[k])) continue;
        for (i = 0; i < n; ++i) {
            const double low = fmin(recx[k], fit_z[i]);
            fit_z[i] = fmax(recx[k] - fit_r[i], low);
        }
        if (!isfinite(recy[k])) continue;
        for (i = 0; i < n; ++i) e -= fit_w[i] * fit_z[i];
        for (i = 0; i < n; ++i) {
            fit_g[i] -= fit_z[i] * e;
            z2 += fit_z[i] * fit_z[i];
        }
        e2 += e * e;
    }
    tol = 1e-8 * (sqrt(z2 * e2) + z2 * wsum) + 1e-300;
    for (i = 0; i < n; ++i) {
        if (fit_w[i] > 0.0) {
            CLOSE("pi fit KKT positive", fabs(fit_g[i]), tol);
        } else {
            CLOSE("pi fit KKT zero", fmax(-fit_g[i], 0.0),
                  tol + sqrt(1e4 * DBL_EPSILON) * sqrt(z2 * e2));
        }
    }
}

/* Layout after the flags: n (byte % 70: 0 and above 64 are refused),
 * thresholds (byte bit0: given as increments on a 1/16 grid, a first byte
 * with bit7 set making r1 != 0; raw: doubles; else uniform over [0, span]),
 * the span (grid), then opcodes: op >> 6 < 3 one sample (x in [0, span] by
 * next_pos(), y from one byte as in fuzz_ident()), else op & 3: 0 solve,
 * 1 re-init, 2-3 nothing. At the end hyst_pi_fit_record() on the samples
 * kept, against the streaming calls made by hand. */
static void fuzz_pi_fit(reader_t *rd, unsigned flags)
{
    const size_t n = rd_u8(rd) % 70u;
    const unsigned mode = rd_u8(rd);
    const int raw = (flags & 2u) != 0;
    const size_t len = HYST_PI_FIT_WORK(HYST_PI_FIT_MAX_OPERATORS) - ((flags & 4u) ? 1u : 0u);
    const size_t need = n <= HYST_PI_FIT_MAX_OPERATORS ? HYST_PI_FIT_WORK(n) : 0u;
    double span = raw ? rd_f64(rd) : (double)(rd_u8(rd) % 64u + 1u) / 16.0;
    hyst_pi_fit_t fit, fit2;
    hyst_pi_fit_result_t res, res2;
    hyst_status_t st, exp;
    size_t used = 0, m = 0, i, ops;
    double xmin = INFINITY, xmax = -INFINITY;
    int phase = 0, ok;
    const size_t work_len = (flags & 4u) && need > 0u ? need - 1u : len;

    for (i = 0; i < HYST_PI_FIT_MAX_OPERATORS + 6u; ++i) fit_r[i] = 0.0;
    if (mode & 1u) { /* given thresholds */
        const size_t cnt = n < HYST_PI_FIT_MAX_OPERATORS + 6u ? n : HYST_PI_FIT_MAX_OPERATORS + 6u;
        for (i = 0; i < cnt; ++i) {
            const unsigned b = rd_u8(rd);
            if (raw) {
                fit_r[i] = rd_f64(rd);
            } else if (i == 0) {
                fit_r[0] = (b & 0x80u) ? (double)(b & 0x7Fu) / 16.0 : 0.0;
            } else {
                fit_r[i] = fit_r[i - 1u] + (double)(b % 32u) / 16.0;
            }
        }
    } else {
        st = hyst_pi_fit_thresholds(0.0, span, n, fit_r);
        if (n < 1u || n > HYST_PI_FIT_MAX_OPERATORS) {
            CHECK(st == HYST_ERR_ARG);
        } else if (!isfinite(span) || !(span > 0.0)) {
            CHECK(st == HYST_ERR_DOMAIN);
        } else {
            CHECK(st == HYST_OK);
            for (i = 0; i < n; ++i) CHECK(fit_r[i] == span * (double)i / (double)n);
        }
    }
    if (!isfinite(span) || !(span > 0.0)) span = 1.0; /* the samples' range */
    if (flags & 8u) {
        CHECK(hyst_pi_fit_init(NULL, fit_r, 1u, fit_work, len) == HYST_ERR_NULL);
        CHECK(hyst_pi_fit_init(&fit, NULL, 1u, fit_work, len) == HYST_ERR_NULL);
        CHECK(hyst_pi_fit_init(&fit, fit_r, 1u, NULL, len) == HYST_ERR_NULL);
        CHECK(hyst_pi_fit_add(NULL, 0.0, 0.0) == HYST_ERR_NULL);
        CHECK(hyst_pi_fit_solve(NULL, fit_w, &res) == HYST_ERR_NULL);
        CHECK(hyst_pi_fit_thresholds(0.0, 1.0, 1u, NULL) == HYST_ERR_NULL);
        CHECK(hyst_pi_fit_record(NULL, recx, recy, 1u, fit_work, len, fit_r, fit_w, &res) ==
              HYST_ERR_NULL);
    }
    exp = pi_fit_init_expected(fit_r, n, work_len);
    st = hyst_pi_fit_init(&fit, fit_r, n, fit_work, work_len);
    CHECK(st == exp);
    ok = st == HYST_OK;
    if (ok && (flags & 8u)) CHECK(hyst_pi_fit_solve(&fit, NULL, &res) == HYST_ERR_NULL);

    for (ops = 0; ops < MAX_OPS && rd->at < rd->n && ok; ++ops) {
        const unsigned op = rd_u8(rd);
        if ((op >> 6) < 3u) {
            const unsigned yb = rd_u8(rd);
            const double x = next_pos(rd, op, 0.0, span);
            const double y = yb == 0u ? NAN : yb == 1u ? INFINITY : yb == 2u ? rd_f64(rd)
                                                                           : (double)(signed char)yb / 8.0 + x;
            st = hyst_pi_fit_add(&fit, x, y);
            exp = phase != 0 ? HYST_ERR_ARG : (isfinite(x) && isfinite(y) ? HYST_OK : HYST_ERR_NONFINITE);
            CHECK(st == exp);
            if (phase == 0) {
                if (isfinite(x)) {
                    xmin = fmin(xmin, x);
                    xmax = fmax(xmax, x);
                }
                used += st == HYST_OK;
                if (m < MAX_REC) {
                    recx[m] = x;
                    recy[m] = y;
                }
                ++m;
            }
            continue;
        }
        if ((op & 3u) == 0u) {
            st = hyst_pi_fit_solve(&fit, fit_w, &res);
            if (phase != 0) {
                CHECK(st == HYST_ERR_ARG);
            } else if (used < n + 1u) {
                CHECK(st == HYST_ERR_SINGULAR);
            } else if (!(xmax > xmin)) {
                CHECK(st == HYST_ERR_DOMAIN);
            } else {
                /* DOMAIN also when the input moved only in samples not used */
                CHECK(st == HYST_OK || st == HYST_ERR_DOMAIN);
            }
            if (st == HYST_OK) {
                size_t pos = 0;
                phase = 1;
                CHECK(res.used == used && res.operators == n && res.max_abs < 0.0);
                for (i = 0; i < n; ++i) {
                    CHECK(!(fit_w[i] < 0.0));
                    pos += fit_w[i] > 0.0;
                }
                CHECK(res.positive == pos && res.invertible == (fit_w[0] > 0.0));
                if (!raw && m <= MAX_REC) pi_fit_kkt(n, &res, m);
            }
        } else if ((op & 3u) == 1u) {
            CHECK(hyst_pi_fit_init(&fit, fit_r, n, fit_work, work_len) == HYST_OK);
            phase = 0;
            used = 0;
            m = 0;
            xmin = INFINITY;
            xmax = -INFINITY;
        }
    }
    if (!ok || m > MAX_REC) return;
    /* hyst_pi_fit_record (thresholds given: those above) against the streaming calls by hand */
    {
        hyst_pi_fit_config_t cfg;
        size_t count;
        int finite = 1;
        memset(&cfg, 0, sizeof(cfg));
        cfg.operators = n;
        cfg.thresholds = fit_r;
        cfg.skip = rd_u8(rd) % 4u;
        cfg.delay = rd_u8(rd) % 4u;
        st = hyst_pi_fit_record(&cfg, recx, recy, m, fit_work, work_len, fit_r2, fit_w2, &res);
        if (cfg.skip >= m || cfg.delay >= m - cfg.skip) {
            CHECK(st == HYST_ERR_ARG);
            return;
        }
        count = m - cfg.skip - cfg.delay;
        for (i = 0; i < count; ++i) {
            finite &= isfinite(recx[cfg.skip + i]) && isfinite(recy[cfg.skip + cfg.delay + i]);
        }
        if (!finite) {
            CHECK(st == HYST_ERR_NONFINITE);
            return;
        }
        CHECK(hyst_pi_fit_init(&fit2, fit_r, n, fit_work2, work_len) == HYST_OK);
        for (i = 0; i < count; ++i) {
            CHECK(hyst_pi_fit_add(&fit2, recx[cfg.skip + i], recy[cfg.skip + cfg.delay + i]) == HYST_OK);
        }
        CHECK(st == hyst_pi_fit_solve(&fit2, fit_w, &res2));
        if (st == HYST_OK) {
            CHECK(memcmp(fit_w, fit_w2, n * sizeof(fit_w[0])) == 0);
            CHECK(memcmp(fit_r, fit_r2, n * sizeof(fit_r[0])) == 0);
            CHECK(memcmp(&res.offset, &res2.offset, sizeof(res.offset)) == 0);
            CHECK(res.used == count && !(res.max_abs < 0.0));
        }
    }
}

/* ----------------------------------------------------------------- creep --- */

/* Config: terms byte (% 6: 0 and 5 refused), then per term a time constant
 * (structured: 1 + b^2 / 4 samples, up to 16 257, or 0.5 for b = 255; raw: any
 * double), a weight ((signed char) / 16; raw: any double), then the rest
 * drive ((signed char) / 8; raw: any double). Opcodes: 0xF0 reset to the
 * rest drive; 0xF1 a NaN sample; 0xF2 the fit of the samples so far; 0xF3
 * the next sample fed to the fit without its equation (a missing
 * residual); 0xF4 a snapshot (two bytes: an octet to damage, a mask) that
 * a twin refuses damaged, changing nothing, and then restores whole: its
 * states, status and events bit for bit; any other byte a drive sample (structured: (signed char) b2 /
 * 8; raw: a double). Each sample also goes into a fit as the residual r =
 * c_ref + 0.25 + the drive's low bits (a known lag plus an offset plus
 * noise).
 * Checks: init refuses exactly what creep.h says, in its order, writing
 * nothing; output() is bit for bit the next step's value; each value
 * within the header's bound of a double reference of the same lags (its
 * rates 1 / tau computed here: the same rounding); the states stay in the
 * drives' hull (one step past it for tau < 2); a NaN sample changes no
 * state and says HYST_ERR_NONFINITE (cleared by hyst_creep_clear_events());
 * the fit's solution zeroes the gradient of its least-squares objective (to
 * 1e-9 of its terms' scale), or the fit says SINGULAR, and
 * hyst_creep_fit_holdout() over the same samples gives the same numbers bit
 * for bit (the same fit, the same order). */
static void fuzz_creep(reader_t *rd, unsigned flags)
{
    static hyst_creep_t C, keep_c;
    static hyst_creep_fit_t F;
    const int raw = (flags & 2u) != 0u;
    const size_t n = rd_u8(rd) % 6u;
    hyst_wide_t tau[HYST_CREEP_MAX_TERMS + 1u], w[HYST_CREEP_MAX_TERMS + 1u], x_rest;
    double x_limit;
    double s_ref[HYST_CREEP_MAX_TERMS + 1u], a_ref[HYST_CREEP_MAX_TERMS + 1u];
    double lo_x, hi_x, xs[MAX_OPS], rs[MAX_OPS];
    hyst_status_t st, want = HYST_OK;
    size_t k, count = 0u;
    unsigned ops;
    int missing = 0; /* 0xF3: the next sample's residual is missing */
    for (k = 0u; k < n; ++k) {
        const unsigned b = rd_u8(rd);
        tau[k] = raw ? rd_f64(rd) : b == 255u ? 0.5 : 1.0 + (double)(b * b) / 4.0;
        w[k] = raw ? rd_f64(rd) : (double)(signed char)rd_u8(rd) / 16.0;
    }
    x_rest = raw ? rd_f64(rd) : (double)(signed char)rd_u8(rd) / 8.0;
    /* creep.h's order: the count, then per term its tau, weight and the rest drive */
    if (n < 1u || n > HYST_CREEP_MAX_TERMS) {
        want = HYST_ERR_ARG;
    }
    for (k = 0u; want == HYST_OK && k < n; ++k) {
        if (!(isfinite(tau[k]) && tau[k] >= 1.0)) {
            want = HYST_ERR_ARG;
        } else if (!isfinite(w[k])) {
            want = HYST_ERR_WEIGHTS;
        } else if (!isfinite(x_rest)) {
            want = HYST_ERR_NONFINITE;
        }
    }
    { /* creep.h's drive limit: DBL_MAX / (4 max(1, sum |w|)), x_rest beyond it refused */
        double sum = 0.0;
        for (k = 0u; k < n && k < HYST_CREEP_MAX_TERMS; ++k) sum += fabs(w[k]);
        x_limit = DBL_MAX / (4.0 * (sum > 1.0 ? sum : 1.0));
        if (want == HYST_OK && !(fabs(x_rest) <= x_limit)) want = HYST_ERR_NONFINITE;
    }
    memset(&C, 0x5A, sizeof C);
    memcpy(&keep_c, &C, sizeof C);
    st = hyst_creep_init(&C, n, tau, w, x_rest);
    CHECK(st == want);
    if (st != HYST_OK) {
        CHECK(memcmp(&C, &keep_c, sizeof C) == 0);
        return;
    }
    CHECK(hyst_creep_size(&C) == n && hyst_creep_status(&C) == HYST_OK);
    CHECK(hyst_creep_fit_init(&F, n, tau, x_rest) == HYST_OK);
    for (k = 0u; k < n; ++k) {
        a_ref[k] = 1.0 / tau[k];
        s_ref[k] = x_rest;
    }
    lo_x = hi_x = x_rest;
    for (ops = 0u; ops < MAX_OPS && rd->at < rd->n; ++ops) {
        const unsigned op = rd_u8(rd);
        double x, c_ref = 0.0, m, bound;
        hyst_real_t out, y;
        if (op == 0xF0u) {
            CHECK(hyst_creep_reset(&C, x_rest) == HYST_OK && hyst_creep_events(&C) == 0u);
            for (k = 0u; k < n; ++k) s_ref[k] = x_rest;
            lo_x = hi_x = x_rest;
            continue;
        }
        if (op == 0xF2u) { /* the fit so far: the gradient of its objective at its answer */
            hyst_wide_t wf[HYST_CREEP_MAX_TERMS], off = 0, rms = 0;
            const hyst_status_t fs = hyst_creep_fit_solve(&F, wf, &off, &rms);
            CHECK(fs == HYST_OK || fs == HYST_ERR_SINGULAR);
            { /* the same fit through the hold-out scorer, no hold-out part */
                hyst_creep_holdout_t h;
                const hyst_status_t hs = hyst_creep_fit_holdout(n, tau, x_rest, xs, rs, count, count, &h);
                CHECK(hs == fs || (fs == HYST_OK && hs == HYST_ERR_WEIGHTS));
                if (hs == HYST_OK) {
                    CHECK(memcmp(h.weight, wf, n * sizeof wf[0]) == 0 && h.offset == off &&
                          h.fit_rms == rms && h.holdout_used == 0u);
                }
            }
            if (fs == HYST_OK && count > 0u) {
                /* re-run the lags over the samples fitted, in double */
                double sf[HYST_CREEP_MAX_TERMS], g[HYST_CREEP_MAX_TERMS + 1u];
                double scale[HYST_CREEP_MAX_TERMS + 1u], sq[HYST_CREEP_MAX_TERMS];
                size_t i, j;
                CHECK(isfinite(rms) && rms >= 0);
                for (j = 0u; j < n; ++j) sf[j] = x_rest;
                for (j = 0u; j < n; ++j) sq[j] = 0.0;
                for (j = 0u; j <= n; ++j) g[j] = scale[j] = 0.0;
                for (i = 0u; i < count; ++i) {
                    /* e and the sum of its terms' sizes: the scale its rounding has */
                    double e = rs[i] - off, size_e = fabs(rs[i]) + fabs(off);
                    if (isnan(rs[i])) { /* fed without its equation: the lags move on */
                        for (j = 0u; j < n; ++j) sf[j] += a_ref[j] * (xs[i] - sf[j]);
                        continue;
                    }
                    for (j = 0u; j < n; ++j) {
                        e -= wf[j] * sf[j];
                        size_e += fabs(wf[j] * sf[j]);
                    }
                    g[n] += e;
                    scale[n] += size_e;
                    for (j = 0u; j < n; ++j) {
                        g[j] += e * sf[j];
                        scale[j] += size_e * fabs(sf[j]);
                        sq[j] += sf[j] * sf[j];
                        sf[j] += a_ref[j] * (xs[i] - sf[j]);
                    }
                }
                /* A lag whose squares reach the subnormals (raw drives of 1e-150 and
                 * less) has no relative accuracy left in its co-moments: the
                 * solve's status and finite numbers are all that is checked there. */
                for (j = 0u; j < n; ++j) {
                    if (!(sq[j] >= DBL_MIN / EPS)) break;
                }
                for (i = 0u; j == n && i <= n; ++i) {
                    CLOSE("creep_fit_gradient", fabs(g[i]), 1e-9 * scale[i] + 1e-300);
                }
            }
            continue;
        }
        if (op == 0xF1u) { /* NaN: nothing moves */
            memcpy(&keep_c, &C, sizeof C);
            y = hyst_creep_step(&C, (hyst_real_t)NAN);
            CHECK(hyst_creep_status(&C) == HYST_ERR_NONFINITE);
            CHECK((hyst_creep_events(&C) & HYST_EVENT_NONFINITE) != 0u);
            CHECK(memcmp(C.state, keep_c.state, sizeof C.state) == 0);
            CHECK(isnan(y) || y == hyst_creep_output(&C));
            hyst_creep_clear_events(&C);
            CHECK(hyst_creep_events(&C) == 0u);
            continue;
        }
        if (op == 0xF3u) {
            missing = 1;
            continue;
        }
        if (op == 0xF4u) { /* a snapshot: restored whole into a twin, or refused damaged */
            static hyst_creep_t twin, keep_twin;
            static unsigned char buf[HYST_CREEP_SNAPSHOT_SIZE + 1u];
            const unsigned at = rd_u8(rd), flip = rd_u8(rd) | 1u;
            size_t len = 0u;
            CHECK(hyst_creep_snapshot_save(&C, buf, sizeof buf, &len) == HYST_OK);
            CHECK(len == hyst_creep_snapshot_size(&C) && len <= HYST_CREEP_SNAPSHOT_SIZE);
            CHECK(hyst_creep_init(&twin, n, tau, w, 0.0) == HYST_OK);
            memcpy(&keep_twin, &twin, sizeof twin);
            buf[at % len] = (unsigned char)(buf[at % len] ^ (flip & 0xFFu));
            CHECK(hyst_creep_snapshot_restore(&twin, buf, len) != HYST_OK);
            CHECK(memcmp(&twin, &keep_twin, sizeof twin) == 0);
            buf[at % len] = (unsigned char)(buf[at % len] ^ (flip & 0xFFu));
            CHECK(hyst_creep_snapshot_restore(&twin, buf, len) == HYST_OK);
            CHECK(memcmp(twin.state, C.state, sizeof C.state) == 0);
            CHECK(hyst_creep_status(&twin) == hyst_creep_status(&C) &&
                  hyst_creep_events(&twin) == hyst_creep_events(&C));
            continue;
        }
        x = raw ? rd_f64(rd) : (double)(signed char)rd_u8(rd) / 8.0;
        if (!isfinite(x)) continue;
        if (fabs(x) > x_limit) { /* would overflow a lag or c: refused, nothing moves */
            memcpy(&keep_c, &C, sizeof C);
            out = hyst_creep_output(&C);
            y = hyst_creep_step(&C, x);
            CHECK(memcmp(&out, &y, sizeof y) == 0 || (isnan(out) && isnan(y)));
            CHECK(hyst_creep_status(&C) == HYST_ERR_DOMAIN);
            CHECK(memcmp(C.state, keep_c.state, sizeof C.state) == 0);
            continue;
        }
        lo_x = fmin(lo_x, x);
        hi_x = fmax(hi_x, x);
        out = hyst_creep_output(&C);
        y = hyst_creep_step(&C, x);
        CHECK(memcmp(&out, &y, sizeof y) == 0 || (isnan(out) && isnan(y)));
        CHECK(hyst_creep_status(&C) == HYST_OK);
        for (k = 0u; k < n; ++k) {
            c_ref += w[k] * s_ref[k];
            s_ref[k] += a_ref[k] * (x - s_ref[k]);
        }
        /* creep.h's bound, M the largest |drive| so far, tau below 2 as M doubled */
        m = fmax(fabs(lo_x), fabs(hi_x));
        bound = 0.0;
        for (k = 0u; k < n; ++k) {
            bound += fabs(w[k]) * (tau[k] + 4.0 * (double)n + 12.0) * (tau[k] < 2.0 ? 2.0 : 1.0);
        }
        bound *= m * EPS; /* twice the header's: the reference rounds alike */
        if (isfinite(c_ref) && isfinite(bound)) {
            CLOSE("creep_vs_reference", fabs(y - c_ref), bound + UNDER);
        }
        for (k = 0u; k < n; ++k) { /* the drives' hull */
            const double sk = C.state[k].HYST_R, slack = (tau[k] < 2.0 ? 2.0 : 1.0) * EPS * m;
            CHECK(sk >= lo_x - slack && sk <= hi_x + slack);
        }
        if (count < MAX_OPS && missing) { /* the residual missing: the lags move on */
            CHECK(hyst_creep_fit_feed(&F, x) == HYST_OK);
            xs[count] = x;
            rs[count] = NAN;
            ++count;
        } else if (count < MAX_OPS) { /* a known lag, an offset and noise as the residual */
            const double r = c_ref + 0.25 + ldexp((double)(rd->at & 7u), -12);
            if (isfinite(r) && hyst_creep_fit_add(&F, x, r) == HYST_OK) {
                xs[count] = x;
                rs[count] = r;
                ++count;
            }
        }
        missing = 0;
    }
}

/* ------------------------------------------------------------------ rate --- */

/* The rate term as rate.h states it, in double: r = w v, then
 * v += a ((x - p) - v), p = x. */
typedef struct {
    double a, w, p, v;
} rate_ref_t;

static double rate_ref_step(rate_ref_t *q, double x)
{
    const double out = q->w * q->v;
    q->v += q->a * ((x - q->p) - q->v);
    q->p = x;
    return out;
}

/* rate.h's init checks in its order, for the variant of numbers t_min..t_max
 * (f32: float's, f64: double's), the numbers rounded to it by `round`. */
static hyst_status_t rate_expected(double tau, double w, double x_rest, int f32)
{
    const double t_min = f32 ? (double)FLT_MIN : DBL_MIN, t_max = f32 ? (double)FLT_MAX : DBL_MAX;
    double a, wt, limit;
    if (!(isfinite(tau) && tau >= 1.0)) return HYST_ERR_ARG;
    a = f32 ? (double)(float)(1.0 / tau) : 1.0 / tau;
    if (!(a >= t_min)) return HYST_ERR_ARG;
    wt = f32 ? (double)(float)w : w;
    if (!isfinite(wt)) return HYST_ERR_WEIGHTS;
    limit = t_max / (4.0 * (fabs(wt) > 1.0 ? fabs(wt) : 1.0));
    limit = f32 ? (double)(float)limit : limit;
    if (!isfinite(x_rest) || !(fabs(x_rest) <= limit) || (f32 && !isfinite((double)(float)x_rest))) {
        return HYST_ERR_NONFINITE;
    }
    return HYST_OK;
}

/* rate.h's bound on |r - r_exact|: |w| (tau + 12) ulp(2M) / 2 in the
 * variant's type, M the largest |drive| taken (x_rest included), plus the
 * subnormals' absolute rounding. */
static double rate_bound(double tau, double w, double m, int f32)
{
    const double two_m = 2.0 * m;
    const double ulp = f32 ? (double)(nextafterf((float)two_m, INFINITY) - (float)two_m)
                           : nextafter(two_m, INFINITY) - two_m;
    return fabs(w) * (tau + 12.0) * ulp / 2.0 +
           (tau + 12.0) * (fabs(w) > 1.0 ? fabs(w) : 1.0) * (f32 ? (double)FLT_MIN * FLT_EPSILON : UNDER);
}

/* Config: tau (structured byte: 1 + b^2 / 4 samples, 0 gives 0.5 and 255
 * gives 1e308, both refused; raw: any double), the weight ((signed char) /
 * 16; raw: any double), the rest drive ((signed char) / 8; raw: any
 * double). The term runs in both real variants (the float one from the
 * same numbers, if its init accepts them). Opcodes: 0xF0 reset to the
 * rest drive; 0xF1 a reset refused (byte: NaN, infinite, beyond the drive
 * limit; an instance not initialised, or of the other variant), nothing
 * changed; 0xF2 a NaN sample; 0xF3 a finite sample beyond the drive limit
 * (byte: by how much); 0xF4 a snapshot (two bytes: an octet to damage, a
 * mask) refused damaged by a twin, changing nothing, then restored whole
 * (the twin then runs beside, bit for bit), refused too by a term of
 * another time constant, of the other variant and not initialised; 0xF5
 * clear the events; any other byte a drive sample (structured: (signed
 * char) b2 / 8; raw: a double).
 * Checks: init refuses exactly what rate.h says, in its order, writing
 * nothing; output() is bit for bit the next step's value; each value
 * within twice rate.h's bound of a double reference (the reference rounds
 * alike); a NaN or a drive beyond the limit changes no state, says
 * HYST_ERR_NONFINITE or HYST_ERR_DOMAIN and sets the sticky event until
 * cleared; a restored twin continues bit for bit. */
static void fuzz_rate(reader_t *rd, unsigned flags)
{
    static hyst_rate_t R, F, twin, keep;
    static unsigned char buf[HYST_RATE_SNAPSHOT_SIZE + 1u], keep_buf[HYST_RATE_SNAPSHOT_SIZE + 1u];
    const int raw = (flags & 2u) != 0u;
    const unsigned tb = rd_u8(rd);
    const double tau = raw ? rd_f64(rd) : tb == 0u ? 0.5 : tb == 255u ? 1e308 : 1.0 + (double)(tb * tb) / 4.0;
    const double w = raw ? rd_f64(rd) : (double)(signed char)rd_u8(rd) / 16.0;
    const double x_rest = raw ? rd_f64(rd) : (double)(signed char)rd_u8(rd) / 8.0;
    rate_ref_t q, q32;
    double m, m32, limit;
    hyst_status_t st;
    unsigned ops;
    int f32_on, twin_on = 0;
    /* every variant refuses what rate.h says, writing nothing */
    memset(&R, 0x5A, sizeof R);
    memcpy(&keep, &R, sizeof R);
    CHECK(hyst_f64_rate_init(NULL, tau, w, x_rest) == HYST_ERR_NULL);
    CHECK(hyst_f64_rate_init_(&R, tau, w, x_rest, HYST_LAYOUT ^ 1ul) == HYST_ERR_LAYOUT);
    CHECK(memcmp(&R, &keep, sizeof R) == 0);
    st = hyst_f32_rate_init(&F, tau, w, x_rest);
    CHECK(st == rate_expected(tau, w, x_rest, 1));
    f32_on = st == HYST_OK;
    st = hyst_f64_rate_init(&R, tau, w, x_rest);
    CHECK(st == rate_expected(tau, w, x_rest, 0));
    if (st != HYST_OK) {
        CHECK(memcmp(&R, &keep, sizeof R) == 0);
        return;
    }
    CHECK(hyst_rate_status(&R) == HYST_OK && hyst_rate_events(&R) == 0u && hyst_rate_output(&R) == 0);
    CHECK(hyst_rate_status(NULL) == HYST_ERR_NULL && hyst_rate_events(NULL) == 0u &&
          hyst_rate_output(NULL) == 0 && hyst_rate_step(NULL, 1.0) == 0);
    hyst_rate_clear_events(NULL);
    limit = R.x_limit.f64;
    q.a = 1.0 / tau;
    q.w = w;
    q.p = x_rest;
    q.v = 0.0;
    q32.a = 1.0 / tau;
    q32.w = (double)(float)w;
    q32.p = (double)(float)x_rest;
    q32.v = 0.0;
    m = fabs(x_rest);
    m32 = fabs(q32.p);
    for (ops = 0u; ops < MAX_OPS && rd->at < rd->n; ++ops) {
        const unsigned op = rd_u8(rd);
        double x, r, before;
        if (op == 0xF0u) {
            CHECK(hyst_f64_rate_reset(&R, x_rest) == HYST_OK && hyst_rate_events(&R) == 0u &&
                  hyst_rate_status(&R) == HYST_OK && hyst_rate_output(&R) == 0);
            q.p = x_rest;
            q.v = 0.0;
            if (f32_on) {
                CHECK(hyst_f32_rate_reset(&F, (float)x_rest) == HYST_OK);
                q32.p = (double)(float)x_rest;
                q32.v = 0.0;
            }
            if (twin_on) {
                CHECK(hyst_f64_rate_reset(&twin, x_rest) == HYST_OK);
            }
            continue;
        }
        if (op == 0xF1u) { /* a reset refused: nothing changes */
            const unsigned b = rd_u8(rd) % 5u;
            static hyst_rate_t blank;
            const double bad = b == 0u ? NAN : b == 1u ? -INFINITY : nextafter(limit, INFINITY);
            memcpy(&keep, &R, sizeof R);
            if (b < 3u) {
                CHECK(hyst_f64_rate_reset(&R, bad) == HYST_ERR_NONFINITE);
            } else if (b == 3u) {
                memset(&blank, 0, sizeof blank);
                CHECK(hyst_f64_rate_reset(&blank, 0.0) == HYST_ERR_LAYOUT);
            } else {
                CHECK(hyst_f32_rate_reset(&R, 0.0f) == HYST_ERR_LAYOUT);
            }
            CHECK(memcmp(&R, &keep, sizeof R) == 0);
            continue;
        }
        if (op == 0xF5u) {
            hyst_rate_clear_events(&R);
            CHECK(hyst_rate_events(&R) == 0u);
            if (twin_on) hyst_rate_clear_events(&twin);
            continue;
        }
        if (op == 0xF4u) { /* a snapshot: refused damaged, restored whole into a twin */
            const unsigned at = rd_u8(rd), flip = rd_u8(rd) | 1u;
            static hyst_rate_t other, other32, blank;
            size_t len = 0u;
            CHECK(hyst_rate_snapshot_size(&R) == 44u && hyst_rate_snapshot_size(NULL) == 0u);
            memset(buf, 0xA5, sizeof buf);
            memcpy(keep_buf, buf, sizeof buf);
            CHECK(hyst_rate_snapshot_save(&R, buf, 43u, &len) == HYST_ERR_NOSPACE && len == 0u);
            CHECK(memcmp(buf, keep_buf, sizeof buf) == 0);
            CHECK(hyst_rate_snapshot_save(NULL, buf, sizeof buf, &len) == HYST_ERR_NULL);
            CHECK(hyst_rate_snapshot_save(&R, buf, sizeof buf, &len) == HYST_OK && len == 44u);
            CHECK(hyst_f64_rate_init(&twin, tau, w, 0.0) == HYST_OK);
            memcpy(&keep, &twin, sizeof twin);
            buf[at % len] = (unsigned char)(buf[at % len] ^ (flip & 0xFFu));
            CHECK(hyst_rate_snapshot_restore(&twin, buf, len) != HYST_OK);
            CHECK(memcmp(&twin, &keep, sizeof twin) == 0);
            buf[at % len] = (unsigned char)(buf[at % len] ^ (flip & 0xFFu));
            CHECK(hyst_rate_snapshot_restore(&twin, buf, len - 1u) == HYST_ERR_FORMAT);
            CHECK(hyst_rate_snapshot_restore(NULL, buf, len) == HYST_ERR_NULL);
            memset(&blank, 0, sizeof blank);
            CHECK(hyst_rate_snapshot_restore(&blank, buf, len) == HYST_ERR_ARG);
            if (hyst_f64_rate_init(&other, tau + 1.0, w, 0.0) == HYST_OK && 1.0 / (tau + 1.0) != 1.0 / tau) {
                memcpy(&keep, &other, sizeof other);
                CHECK(hyst_rate_snapshot_restore(&other, buf, len) == HYST_ERR_CURVE);
                CHECK(memcmp(&other, &keep, sizeof other) == 0);
            }
            if (hyst_f32_rate_init(&other32, tau, w, 0.0) == HYST_OK) {
                CHECK(hyst_rate_snapshot_restore(&other32, buf, len) == HYST_ERR_VERSION);
            }
            CHECK(hyst_rate_snapshot_restore(&twin, buf, len) == HYST_OK);
            CHECK(memcmp(&twin.last, &R.last, sizeof R.last) == 0 &&
                  memcmp(&twin.state, &R.state, sizeof R.state) == 0 &&
                  hyst_rate_status(&twin) == hyst_rate_status(&R) &&
                  hyst_rate_events(&twin) == hyst_rate_events(&R));
            twin_on = 1;
            if (f32_on) { /* the float variant's: 36 octets, restored whole */
                static hyst_rate_t twin32;
                CHECK(hyst_rate_snapshot_size(&F) == 36u);
                CHECK(hyst_rate_snapshot_save(&F, buf, sizeof buf, &len) == HYST_OK && len == 36u);
                CHECK(hyst_f32_rate_init(&twin32, tau, w, 0.0) == HYST_OK);
                CHECK(hyst_rate_snapshot_restore(&twin32, buf, len) == HYST_OK);
                CHECK(memcmp(&twin32.last, &F.last, sizeof F.last) == 0 &&
                      memcmp(&twin32.state, &F.state, sizeof F.state) == 0);
            }
            continue;
        }
        if (op == 0xF2u || op == 0xF3u) { /* ignored: NaN, or beyond the drive limit */
            const unsigned b = op == 0xF3u ? rd_u8(rd) : 0u;
            hyst_rate_t copy;
            x = op == 0xF2u ? NAN : (b & 1u ? -1.0 : 1.0) * (b & 2u ? nextafter(limit, INFINITY) : limit * (2.0 + b));
            memcpy(&copy, &R, sizeof R);
            before = hyst_f64_rate_output(&R);
            r = hyst_f64_rate_step(&R, x);
            CHECK(memcmp(&r, &before, sizeof r) == 0);
            CHECK(hyst_rate_status(&R) == (op == 0xF2u || !isfinite(x) ? HYST_ERR_NONFINITE : HYST_ERR_DOMAIN));
            CHECK((hyst_rate_events(&R) & HYST_EVENT_NONFINITE) != 0u);
            CHECK(memcmp(&copy.last, &R.last, sizeof R.last) == 0 && memcmp(&copy.state, &R.state, sizeof R.state) == 0);
            if (twin_on) (void)hyst_f64_rate_step(&twin, x);
            continue;
        }
        x = raw ? rd_f64(rd) : (double)(signed char)rd_u8(rd) / 8.0;
        if (!(fabs(x) <= limit)) continue; /* ops 0xF2 and 0xF3 probe these */
        m = fmax(m, fabs(x));
        before = hyst_f64_rate_output(&R);
        r = hyst_f64_rate_step(&R, x);
        CHECK(memcmp(&r, &before, sizeof r) == 0);
        CHECK(hyst_rate_status(&R) == HYST_OK);
        {
            const double r_ref = rate_ref_step(&q, x), bound = rate_bound(tau, w, m, 0);
            if (isfinite(bound) && isfinite(r_ref)) {
                CLOSE("rate_vs_reference", fabs(r - r_ref), 2.0 * bound);
            }
        }
        if (twin_on) { /* the twin restored from a snapshot: bit for bit */
            const double r2 = hyst_f64_rate_step(&twin, x);
            CHECK(memcmp(&r2, &r, sizeof r) == 0 && hyst_rate_status(&twin) == hyst_rate_status(&R));
        }
        if (f32_on) {
            const float xf = (float)x;
            if (fabs((double)xf) <= (double)F.x_limit.f32) {
                const float bf = hyst_f32_rate_output(&F), rf = hyst_f32_rate_step(&F, xf);
                const double r_ref = rate_ref_step(&q32, (double)xf);
                double bound;
                m32 = fmax(m32, fabs((double)xf));
                bound = rate_bound(tau, (double)(float)w, m32, 1) + rate_bound(tau, w, m32, 0);
                CHECK(memcmp(&rf, &bf, sizeof rf) == 0 && hyst_rate_status(&F) == HYST_OK);
                if (isfinite(bound) && isfinite(r_ref)) {
                    CLOSE("rate_f32_vs_reference", fabs((double)rf - r_ref), bound);
                }
            }
        }
    }
}

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size)
{
    reader_t r = {data, size, 0};
    const unsigned b0 = rd_u8(&r);
    /* 252..255: the creep module, 248..251 the rate term; below, the others
     * (as before they came) */
    const unsigned module = b0 >= 252u ? 4u : b0 >= 248u ? 5u : b0 % 4u;
    const unsigned flags = rd_u8(&r);
    g_raw = (int)(flags & 2u);
    { /* every status has a distinct, non-empty name; unknown codes one too */
        const int code = (int)(signed char)flags % 24;
        const char *name = hyst_status_str(code);
        CHECK(name != NULL && name[0] != '\0');
        CHECK(code == 0 || strcmp(name, hyst_status_str(0)) != 0);
    }
    switch (module) {
    case 0: fuzz_pi(&r, flags); break;
    case 1: fuzz_pwl(&r, flags); break;
    case 2: fuzz_inverse(&r, flags); break;
    case 3: fuzz_ident(&r, flags); break;
    case 4: fuzz_creep(&r, flags); break;
    default: fuzz_rate(&r, flags); break;
    }
    return 0;
}
