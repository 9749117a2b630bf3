/* SPDX-License-Identifier: MIT */
/* Bounded memory: a small capacity and the noise deadband against the
 * unbounded double-precision reference (support/ref_tcm.c), on both engines
 * (real inputs and 16-bit codes), over long random and adversarial inputs.
 * Asserted at every sample: |y - y_ref| <= hyst_error_bound() (+ rounding),
 * no jump (|dy| <= max f0' |dx|), and per merge the stated a-priori bounds. */
#include "ref_tcm.h"
#include "support.h"
#include "unity.h"

#include <math.h>
#include <stdlib.h>

#define LO 0.0
#define HI 40.0
#define CODES 65535.0 /* 16-bit codes over [LO, HI] */
#define MAXCAP 64

static ref_tcm_t ref;
static rng_t rng;

/* One engine behind one interface: real inputs or codes. */
typedef struct {
    int code;
    hyst_t f;
    hyst_t c;
    hyst_real_t xf[2][MAXCAP];
    hyst_code_word_t xc[2][MAXCAP];
    hyst_real_t y[2][MAXCAP];
    float yc[2][MAXCAP]; /* the code variant's outputs are float */
} eng_t;

static eng_t E;

/* The curve under test: the paper's Eq. 20 (convex) unless a test swaps in
 * the concave one; cubic coefficients, highest power first. */
static const double concave_coeffs[4] = {0.0, -0.01, 1.0, 0.5};
static const hyst_poly_t concave = {3u, HYST_REAL_C(0.0), HYST_REAL_C(40.0),
                                    {HYST_REAL_C(0.0), HYST_REAL_C(-0.01), HYST_REAL_C(1.0),
                                     HYST_REAL_C(0.5)}};
static const hyst_poly_t *curve_poly = &paper_eq20;
static const double *curve_c = paper_eq20_coeffs;

void setUp(void) { rng_seed(&rng, 777u); }
void tearDown(void) {}

static void eng_init(eng_t *e, int code, size_t cap)
{
    e->code = code;
    if (code) {
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_code_init(&e->c, curve_poly, 0u, (uint_least32_t)CODES,
                                                      e->xc[0], e->yc[0], e->xc[1], e->yc[1], cap));
    } else {
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init(&e->f, curve_poly, e->xf[0], e->y[0], e->xf[1],
                                                 e->y[1], cap));
    }
}

/* The input the engine really gets for x (quantised for codes). */
static double eng_quantise(const eng_t *e, double x)
{
    if (e->code) {
        return (double)(long)(x / HI * CODES + 0.5) * HI / CODES;
    }
    return (double)(hyst_real_t)x;
}

static double eng_step(eng_t *e, double x)
{
    if (e->code) {
        return (double)hyst_code_step(&e->c, (uint_least32_t)(x / HI * CODES + 0.5));
    }
    return (double)hyst_step(&e->f, (hyst_real_t)x);
}

static double eng_bound(const eng_t *e)
{
    return (double)(e->code ? hyst_code_error_bound(&e->c) : hyst_error_bound(&e->f));
}

static int eng_status(const eng_t *e) { return e->code ? e->c.status : e->f.status; }
static size_t eng_nl(const eng_t *e) { return e->code ? e->c.n_ltp : e->f.n_ltp; }
static size_t eng_nr(const eng_t *e) { return e->code ? e->c.n_rtp : e->f.n_rtp; }

/* Stored TP x in volts: side 0 = LTP, 1 = RTP. */
static double eng_x(const eng_t *e, int side, size_t i)
{
    return e->code ? (double)e->xc[side][i] * HI / CODES : (double)e->xf[side][i];
}

static double eng_set_deadband(eng_t *e, double volts)
{
    if (e->code) {
        const long codes = (long)(volts / HI * CODES);
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_code_set_deadband(&e->c, (uint_least32_t)codes));
        return (double)codes * HI / CODES;
    }
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_set_deadband(&e->f, (hyst_real_t)volts));
    return volts;
}

/* Curve facts, from the reference's double coefficients. */
static double g(double d) { return ref_f0(&ref, LO + d) - ref_f0(&ref, LO); }

static double slope_max, slope_min, curv_max, out_range;

static void curve_facts(void)
{
    int k;
    ref_init(&ref, curve_c, 3u, LO, HI);
    slope_max = 0.0;
    slope_min = 1e300;
    curv_max = 0.0;
    for (k = 0; k <= 1000; ++k) {
        const double x = LO + (HI - LO) * k / 1000.0;
        const double c = curve_c[0], b = curve_c[1], a = curve_c[2];
        const double s = 3 * c * x * x + 2 * b * x + a;
        const double s2 = 6 * c * x + 2 * b;
        slope_max = s > slope_max ? s : slope_max;
        slope_min = s < slope_min ? s : slope_min;
        curv_max = (s2 < 0 ? -s2 : s2) > curv_max ? (s2 < 0 ? -s2 : s2) : curv_max;
    }
    out_range = g(HI - LO);
}

/* Arithmetic tolerance of the build's real type. */
/* The code variant's outputs are float in every build. */
static double tol(void) { return 8.0 * (E.code ? 1e-5 : TOL_OF_RANGE) * out_range; }

/* Input generators: a ramp towards target levels, step at most `step`. */
enum { WALK, JUMPS, NESTED, SHRINK_GROW, NOISY, HOLD };

typedef struct {
    int kind;
    double x, target, step, centre;
    long level;
} gen_t;

static double next_level(gen_t *s)
{
    switch (s->kind) {
    case WALK:
        return s->x + rng_range(&rng, -2.0, 2.0);
    case JUMPS:
        return rng_range(&rng, LO, HI);
    case NESTED: { /* mostly strictly inside the last excursion: deep nesting */
        if (rng_below(&rng, 12u) == 0u) {
            return rng_range(&rng, LO, HI);
        }
        return s->x + rng_range(&rng, 0.05, 0.95) * (s->centre - s->x);
    }
    case SHRINK_GROW: { /* 2 x 150 nested levels in, then back out */
        const long k = s->level % 600;
        const long depth = k < 300 ? k / 2 : (599 - k) / 2;
        const double half = 20.0 * (1.0 - (double)depth / 160.0);
        return (k % 2 == 0) ? 20.0 + half : 20.0 - half;
    }
    case HOLD: /* a held command: 20 V + 0.1 V peak-to-peak noise */
        return 20.0 + rng_range(&rng, -0.05, 0.05);
    default: { /* NOISY: slow triangle 5..35 V (0.01 V per level) + 0.1 V noise */
        const long phase = s->level % 6000;
        const double base = 5.0 + 0.01 * (double)(phase < 3000 ? phase : 6000 - phase);
        return base + rng_range(&rng, -0.05, 0.05);
    }
    }
}

static double gen_next(gen_t *s)
{
    if (s->x == s->target) {
        double t;
        const double from = s->x;
        s->level++;
        t = next_level(s);
        t = t < LO ? LO : (t > HI ? HI : t);
        s->centre = from;
        s->target = t;
    }
    if (s->target > s->x) {
        s->x = s->target - s->x > s->step ? s->x + s->step : s->target;
    } else {
        s->x = s->x - s->target > s->step ? s->x - s->step : s->target;
    }
    return s->x;
}

typedef struct {
    long merges;
    double worst_err, worst_bound, worst_ratio;
} stats_t;

/* Runs n samples through E (capacity cap, deadband db volts) and the
 * reference, asserting the bound, continuity and the per-merge bounds. */
static stats_t run(int code, size_t cap, double db, int kind, long n, double step)
{
    gen_t s;
    stats_t st = {0, 0.0, 0.0, 0.0};
    double x_prev = LO, y_prev, dbq = 0.0;
    /* codes: the merged TP is a code, its residual gap <= spread x 1 code */
    const double resid = code ? (slope_max - slope_min) * HI / CODES : 0.0;
    long i;
    eng_init(&E, code, cap);
    if (db > 0.0) {
        dbq = eng_set_deadband(&E, db);
    }
    ref_init(&ref, curve_c, 3u, LO, HI);
    y_prev = ref_f0(&ref, LO);
    s.kind = kind;
    s.x = s.target = s.centre = 20.0;
    s.step = step;
    s.level = 0;
    for (i = 0; i < n; ++i) {
        const double xq = eng_quantise(&E, gen_next(&s));
        const size_t nl = eng_nl(&E), nr = eng_nr(&E);
        const double before = eng_bound(&E);
        /* the stack before the step: P = x_prev, L1/R1 the innermost loop */
        const double xl1 = eng_x(&E, 0, nl - 1u);
        const double xr1 = nr > 0u ? eng_x(&E, 1, nr - 1u) : HI;
        const double y = eng_step(&E, xq);
        const double yr_ = ref_step(&ref, xq);
        const double err = y > yr_ ? y - yr_ : yr_ - y;
        const double bound = eng_bound(&E);
        const double dx = xq > x_prev ? xq - x_prev : x_prev - xq;
        const double dy = y > y_prev ? y - y_prev : y_prev - y;
        if (getenv("TRACE") && i > 1880 && i < 1900) {
            TEST_PRINTF("i %ld x %g y %g yref %g bound %g nl %u nr %u st %d", i, xq, y, yr_, bound, (unsigned)eng_nl(&E), (unsigned)eng_nr(&E), eng_status(&E));
        }
        if (err > bound + tol()) {
            TEST_PRINTF("sample %ld: |y - y_ref| = %g > bound %g", i, err, bound);
            TEST_FAIL_MESSAGE("error exceeds the stated bound");
        }
        if (dy > slope_max * dx + tol()) {
            TEST_PRINTF("sample %ld: jump %g for dx %g", i, dy, dx);
            TEST_FAIL_MESSAGE("output jumped");
        }
        if (bound > before) { /* something forgotten: within its a-priori bound */
            const double inc = bound - before;
            ++st.merges;
            if (eng_status(&E) == HYST_WARN_FULL) { /* merge of L1, R1 and P */
                const double w = xr1 - xl1;
                TEST_ASSERT_EQUAL_UINT(cap, nl);
                TEST_ASSERT_TRUE(inc <= curv_max * w * w / 4.0 + resid + tol());
                TEST_ASSERT_TRUE(inc <= g(w) + resid + tol()); /* height of the loop */
            } else { /* deadband: a reversal within dbq of the current TP skipped */
                const double d = nl == nr ? xr1 - x_prev : x_prev - xl1;
                TEST_ASSERT_TRUE(d < dbq + 1e-9);
                TEST_ASSERT_TRUE(inc <= curv_max * d * d / 4.0 + resid + tol());
            }
        }
        st.worst_err = err > st.worst_err ? err : st.worst_err;
        st.worst_bound = bound > st.worst_bound ? bound : st.worst_bound;
        TEST_ASSERT_TRUE(eng_nl(&E) <= cap && eng_nr(&E) <= cap);
        x_prev = xq;
        y_prev = y;
    }
    return st;
}

static void check_all_kinds(int code)
{
    static const size_t caps[] = {2u, 3u, 4u, 8u, 16u};
    static const int kinds[] = {WALK, JUMPS, NESTED, SHRINK_GROW};
    long merges = 0;
    double worst = 0.0;
    unsigned c, k;
    for (c = 0; c < sizeof caps / sizeof caps[0]; ++c) {
        for (k = 0; k < sizeof kinds / sizeof kinds[0]; ++k) {
            const stats_t st = run(code, caps[c], 0.0, kinds[k], 40000L, 0.25);
            merges += st.merges;
            worst = st.worst_err > worst ? st.worst_err : worst;
        }
    }
    TEST_PRINTF("code=%d: %ld merges, max |y - y_ref| = %g (%g %% of range)", code, merges,
                worst, 100.0 * worst / out_range);
    TEST_ASSERT_TRUE(merges > 1000); /* the bound was really exercised */
    TEST_ASSERT_TRUE(worst > 100.0 * tol());
}

static void test_bound_holds_real_inputs(void) { check_all_kinds(0); }
static void test_bound_holds_codes(void) { check_all_kinds(1); }

/* f0 concave (f0'' < 0: the loops run the other way round): same bounds. */
static void test_bound_holds_on_a_concave_curve(void)
{
    curve_poly = &concave;
    curve_c = concave_coeffs;
    curve_facts();
    check_all_kinds(0);
    check_all_kinds(1);
    curve_poly = &paper_eq20;
    curve_c = paper_eq20_coeffs;
    curve_facts();
}

/* The case the former policy got wrong: A0, R0, L1, R1 stored (capacity 2),
 * reversal at P inside (L1, R1). Dropping L1, R1 and storing P made the
 * output jump by J on reaching R0; the merge keeps it continuous and the
 * error below J everywhere. */
static void test_overflow_is_continuous_where_dropping_jumped(void)
{
    const double xr0 = 36.0, xl1 = 4.0, xr1 = 30.0, xp = 20.0;
    const double jump = g(xr0 - xl1) - g(xr1 - xl1) - g(xr0 - xp) + g(xr1 - xp);
    double x, y_prev, worst = 0.0;
    int fulls = 0;
    eng_init(&E, 0, 2u);
    ref_init(&ref, curve_c, 3u, LO, HI);
    (void)eng_step(&E, xr0);
    (void)ref_step(&ref, xr0);
    (void)eng_step(&E, xl1);
    (void)ref_step(&ref, xl1);
    (void)eng_step(&E, xr1);
    (void)ref_step(&ref, xr1);
    y_prev = eng_step(&E, xp);
    (void)ref_step(&ref, xp);
    TEST_ASSERT_EQUAL_UINT(3u, (unsigned)hyst_tp_count(&E.f));
    for (x = xp + 0.01; x <= HI; x += 0.01) { /* up through R1, R0 to hi */
        const double y = eng_step(&E, x);
        const double yr_ = ref_step(&ref, (double)(hyst_real_t)x);
        const double err = y > yr_ ? y - yr_ : yr_ - y;
        fulls += hyst_status(&E.f) == HYST_WARN_FULL;
        TEST_ASSERT_TRUE(y - y_prev <= slope_max * 0.0101 + tol());
        TEST_ASSERT_TRUE(y >= y_prev);
        TEST_ASSERT_TRUE(err <= (double)hyst_error_bound(&E.f) + tol());
        worst = err > worst ? err : worst;
        y_prev = y;
    }
    TEST_PRINTF("former jump J = %g, merged: max error %g", jump, worst);
    TEST_ASSERT_EQUAL_INT(1, fulls);
    TEST_ASSERT_TRUE(jump > 0.01);               /* a visible step before */
    TEST_ASSERT_TRUE(worst < jump);              /* now smaller, and no step */
    TEST_ASSERT_TRUE(worst > 10.0 * tol());      /* yet something was forgotten */
    TEST_ASSERT_EQUAL_FLOAT(0.0f, (float)hyst_error_bound(&E.f)); /* hi: all closed */
}

/* Saturation closes every loop: after it the bounded model is exact again. */
static void test_reaching_an_end_restores_the_exact_model(void)
{
    int side;
    for (side = 0; side < 2; ++side) {
        const double end = side ? HI : LO;
        stats_t st = run(0, 3u, 0.0, NESTED, 5000L, 0.25);
        int i;
        TEST_ASSERT_TRUE(st.merges > 0);
        TEST_ASSERT_TRUE(hyst_error_bound(&E.f) > 0 || st.worst_bound > 0);
        (void)eng_step(&E, end);
        (void)ref_step(&ref, end);
        TEST_ASSERT_EQUAL_FLOAT(0.0f, (float)hyst_error_bound(&E.f));
        for (i = 0; i < 2000; ++i) { /* exact while nothing new is forgotten */
            const double x = rng_range(&rng, LO, HI);
            const double y = eng_step(&E, x);
            const double yr_ = ref_step(&ref, (double)(hyst_real_t)x);
            if (hyst_events(&E.f) & HYST_EVENT_FULL) {
                hyst_clear_events(&E.f);
            }
            if (hyst_error_bound(&E.f) == 0) {
                TEST_ASSERT_DOUBLE_WITHIN(tol(), yr_, y);
            }
        }
    }
}

/* Noise on a slow command: without a deadband the memory fills with noise
 * loops; with one, few TPs are stored and the error stays within the bound
 * (each merge within deadband x (max f0' - min f0'), asserted in run()). */
static size_t noisy_peak_depth(int code, int kind, double db)
{
    size_t peak = 0;
    long i;
    gen_t s;
    eng_init(&E, code, MAXCAP);
    if (db > 0.0) {
        (void)eng_set_deadband(&E, db);
    }
    s.kind = kind;
    s.x = s.target = s.centre = 20.0;
    s.step = 0.02;
    s.level = 0;
    for (i = 0; i < 30000L; ++i) {
        size_t n;
        (void)eng_step(&E, eng_quantise(&E, gen_next(&s)));
        n = eng_nl(&E) + eng_nr(&E);
        peak = n > peak ? n : peak;
    }
    return peak;
}

static void test_deadband_keeps_noise_out_of_memory(void)
{
    const double db = 0.2; /* V, above the 0.1 V peak-to-peak noise */
    int code, kind;
    for (code = 0; code < 2; ++code) {
        for (kind = NOISY; kind <= HOLD; ++kind) {
            const stats_t with = run(code, MAXCAP, db, kind, 30000L, 0.02);
            const size_t peak_with = noisy_peak_depth(code, kind, db);
            const size_t peak_without = noisy_peak_depth(code, kind, 0.0);
            TEST_PRINTF("code=%d %s: deadband %g V: %ld skips, max error %g um (bound %g), "
                        "peak stack depth %u (without: %u)", code, kind == HOLD ? "hold" : "triangle",
                        db, with.merges, with.worst_err, with.worst_bound, (unsigned)peak_with,
                        (unsigned)peak_without);
            TEST_ASSERT_TRUE(with.merges > 10); /* widest-skip updates */
            /* the stated a-priori bound: max|f0''| db^2 / 4 */
            TEST_ASSERT_TRUE(with.worst_bound <= curv_max * db * db / 4.0 + tol());
            TEST_ASSERT_TRUE(peak_with <= 6u);
            TEST_ASSERT_TRUE(peak_without > peak_with);
        }
    }
}

/* Deadband 0 and a never-full memory: bit-identical to the plain model. */
static void test_zero_deadband_changes_nothing(void)
{
    static hyst_real_t a[4][MAXCAP];
    hyst_t S;
    int i;
    eng_init(&E, 0, MAXCAP);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init(&S, &paper_eq20, a[0], a[1], a[2], a[3], MAXCAP));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_set_deadband(&S, 0));
    for (i = 0; i < 20000; ++i) {
        const hyst_real_t x = (hyst_real_t)rng_range(&rng, LO, HI);
        const hyst_real_t y1 = hyst_step(&S, x);
        const hyst_real_t y2 = hyst_step(&E.f, x);
        TEST_ASSERT_EQUAL_MEMORY(&y2, &y1, sizeof y1);
        TEST_ASSERT_EQUAL_FLOAT(0.0f, (float)hyst_error_bound(&S));
    }
    TEST_ASSERT_EQUAL_UINT(0u, hyst_events(&S) & HYST_EVENT_FULL);
}

/* A deadband narrowed while a skipped excursion is open: the output is
 * still on the branch it moved back along, off the full model by up to the
 * skipped loop's height. A reversal inside that excursion must not store
 * it as a turning point (with the bound then dropped to 0, the error stayed
 * unaccounted for: fuzz_code found it through a deadband request). The
 * bound covers the error at every sample, on real inputs and codes. */
static void test_narrowed_deadband_keeps_the_open_window_bounded(void)
{
    static const double path[] = {20.0, 10.0, 14.0, 13.0, 12.5, 12.0, 11.5, 13.5, 12.0, 10.5,
                                  9.0, 25.0, 18.0, 30.0};
    int code;
    for (code = 0; code < 2; ++code) {
        double worst = 0.0;
        size_t i;
        eng_init(&E, code, MAXCAP);
        curve_facts();
        ref_init(&ref, curve_c, 3u, LO, HI);
        for (i = 0u; i < sizeof path / sizeof path[0]; ++i) {
            const double x = eng_quantise(&E, path[i]);
            double y, yr;
            if (i == 2u) {
                (void)eng_set_deadband(&E, 6.0); /* 14 - 10 = 4: the reversal at 14 is skipped */
            }
            if (i == 4u) {
                (void)eng_set_deadband(&E, 1.0); /* narrower than the open excursion */
            }
            y = eng_step(&E, x);
            yr = ref_step(&ref, x);
            if (i == 3u) {
                TEST_ASSERT_TRUE(eng_bound(&E) > 0.0); /* the window is open */
            }
            TEST_ASSERT_TRUE_MESSAGE(fabs(y - yr) <= eng_bound(&E) + tol(),
                                     "error beyond the stated bound");
            worst = fabs(y - yr) > worst ? fabs(y - yr) : worst;
        }
        TEST_ASSERT_TRUE(worst > 10.0 * tol()); /* the skip did cost something */
        TEST_ASSERT_TRUE(eng_bound(&E) == 0.0); /* 30 wiped it all: exact again */
        TEST_PRINTF("%s: narrowed deadband, worst error %g um within the bound",
                    code ? "codes" : "reals", worst);
    }
}

/* f0 with an inflection near lo, f0 = c (x - 5)^3 + s x (increasing; c =
 * 0.01, s = 0.1), which init accepts: the density g''(a - b) changes sign
 * inside a window of width 10, where a loop's height at its middle,
 * g(10) - 2 g(5), is 0. Nested excursions below the deadband then leave the
 * full model well off the branch moved back along; the stated bound must
 * cover it at every sample, on real inputs and codes. */
static void test_deadband_bound_holds_where_f0_inflects(void)
{
    static const double inflect_coeffs[4] = {0.01, -0.15, 0.85, -1.25};
    static const hyst_poly_t inflect = {3u, HYST_REAL_C(0.0), HYST_REAL_C(40.0),
                                        {HYST_REAL_C(0.01), HYST_REAL_C(-0.15), HYST_REAL_C(0.85),
                                         HYST_REAL_C(-1.25)}};
    static const double path[] = {25.0, 5.0, 15.0, 6.0,  14.0, 10.0, 7.0,  13.0,
                                  9.5,  11.5, 7.5, 14.5, 5.5,  10.0, 39.0};
    int code;
    curve_poly = &inflect;
    curve_c = inflect_coeffs;
    curve_facts();
    for (code = 0; code < 2; ++code) {
        double worst = 0.0, worst_ratio = 0.0;
        size_t i;
        eng_init(&E, code, MAXCAP);
        (void)eng_set_deadband(&E, 10.5);
        ref_init(&ref, curve_c, 3u, LO, HI);
        for (i = 0u; i < sizeof path / sizeof path[0]; ++i) {
            const double x = eng_quantise(&E, path[i]);
            const double y = eng_step(&E, x);
            const double err = fabs(y - ref_step(&ref, x));
            const double bound = eng_bound(&E);
            if (err > bound + tol()) {
                TEST_PRINTF("%s: sample %u at %g: |y - y_full| = %g > bound %g",
                            code ? "codes" : "reals", (unsigned)i, x, err, bound);
                TEST_FAIL_MESSAGE("deadband error beyond the stated bound");
            }
            worst = err > worst ? err : worst;
            worst_ratio = bound > 0.0 && err / bound > worst_ratio ? err / bound : worst_ratio;
        }
        TEST_ASSERT_TRUE(worst > 10.0 * tol()); /* the skips did cost something */
        TEST_ASSERT_TRUE(eng_bound(&E) == 0.0);  /* 39 wiped it all */
        TEST_PRINTF("%s: inflecting f0, worst error %g, at most %g of the bound",
                    code ? "codes" : "reals", worst, worst_ratio);
    }
    curve_poly = &paper_eq20;
    curve_c = paper_eq20_coeffs;
    curve_facts();
}

static void test_deadband_arguments_are_checked(void)
{
    eng_init(&E, 0, 4u);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_set_deadband(NULL, 1));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_set_deadband(&E.f, -1));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_set_deadband(&E.f, (hyst_real_t)NAN));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_set_deadband(&E.f, (hyst_real_t)INFINITY));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_set_deadband(&E.f, 0.5));
    hyst_reset(&E.f);
    TEST_ASSERT_EQUAL_FLOAT(0.5f, (float)E.f.deadband.HYST_R); /* kept by reset */
    eng_init(&E, 1, 4u);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_code_set_deadband(NULL, 1u));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_code_set_deadband(&E.c, 65536u));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_code_set_deadband(&E.c, 65535u));
}

int main(void)
{
    curve_facts();
    UNITY_BEGIN();
    RUN_TEST(test_bound_holds_real_inputs);
    RUN_TEST(test_bound_holds_codes);
    RUN_TEST(test_bound_holds_on_a_concave_curve);
    RUN_TEST(test_overflow_is_continuous_where_dropping_jumped);
    RUN_TEST(test_reaching_an_end_restores_the_exact_model);
    RUN_TEST(test_deadband_keeps_noise_out_of_memory);
    RUN_TEST(test_zero_deadband_changes_nothing);
    RUN_TEST(test_narrowed_deadband_keeps_the_open_window_bounded);
    RUN_TEST(test_deadband_bound_holds_where_f0_inflects);
    RUN_TEST(test_deadband_arguments_are_checked);
    return UNITY_END();
}
