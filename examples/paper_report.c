/* SPDX-License-Identifier: MIT */
/* The paper's results, computed on the target (Cortex-M4F under QEMU, or the
 * host) and printed as sections that tools/report.py turns into a report:
 *   @section <name>      starts a section
 *   @value <key> <num>   a scalar result
 *   @table <name> <cols> a CSV table follows, one row per line
 *   @end                 ends the section
 * Every number is computed here; the host only draws. */
#include "hyst/hyst.h"
#include "hyst_port.h"
#include "piezo_data.h"
#include "plant_bw.h"
#include "plant_everett.h"
#include "signals.h"
#include "support.h"

#include <math.h>
#include <stdio.h>

#ifndef HYST_DATA_DIR
#define HYST_DATA_DIR "tests/data"
#endif

#define NU 4096u /* 12-bit DAC, the paper's sizing */
HYST_DEFINE_INVERSE(model, NU); /* model, then the compensator */
HYST_DEFINE(asym_model, NU);    /* the asymmetric kind, then its compensator */
static hyst_curve_t asym_curve, asym_inverse;
/* its compensator's table, when tabulated (the library's default size) */
static hyst_real_t asym_inv_table[HYST_EVERETT_INV_TABLE_LEN(HYST_EVERETT_INV_ROWS,
                                                             HYST_EVERETT_INV_INTERVALS)];

static int failures;

static void section(const char *name) { printf("@section %s\n", name); }
static void end(void) { printf("@end\n"); }
static void value(const char *key, double v) { printf("@value %s %.9g\n", key, v); }
static void check(int ok, const char *what)
{
    if (!ok) {
        printf("@value failed_%s 1\n", what);
        ++failures;
    }
}

/* Gaussian noise, Box-Muller on the tests' seeded generator. */
static double gauss(rng_t *r)
{
    const double u1 = 1.0 - rng_unit(r); /* (0, 1] */
    const double u2 = rng_unit(r);
    return sqrt(-2.0 * log(u1)) * cos(6.283185307179586 * u2);
}

static void print_fit(const char *prefix, const hyst_ident_result_t *res)
{
    char key[48];
    unsigned k;
    for (k = 0u; k <= res->degree; ++k) {
        (void)snprintf(key, sizeof key, "%s_c%u", prefix, res->degree - k);
        value(key, (double)res->coeffs[k]);
    }
    (void)snprintf(key, sizeof key, "%s_rms", prefix);
    value(key, (double)res->rms);
}

/* Simulation Example 1: f0 = x^2 on [0, 1], a full-range sine through the
 * model, output noise 0.5 % of the range; both estimators, degree 2. */
static void example1(void)
{
    static const hyst_poly_t sq = {2u, HYST_REAL_C(0.0), HYST_REAL_C(1.0),
                                   {HYST_REAL_C(1.0), HYST_REAL_C(0.0), HYST_REAL_C(0.0)}};
    static const int methods[2] = {HYST_IDENT_REFLECT, HYST_IDENT_JOINT};
    static const char *names[2] = {"reflect", "joint"};
    static hyst_ident_t id;
    hyst_ident_result_t res;
    int m;
    section("example1");
    value("noise_sigma", 0.005);
    for (m = 0; m < 2; ++m) {
        hyst_ident_config_t cfg = {0};
        rng_t r;
        long i;
        cfg.degree = 2u;
        cfg.method = methods[m];
        cfg.lo = 0.0;
        cfg.hi = 1.0;
        rng_seed(&r, 777u);
        check(HYST_INIT(model, &sq) == HYST_OK, "example1_init");
        check(hyst_ident_init(&id, &cfg) == HYST_OK, "example1_ident");
        for (i = 0; i < 2000; ++i) { /* 10 periods of 200 samples */
            const double x = 0.5 - 0.5 * cos(6.283185307179586 * (double)i / 200.0);
            const double y = (double)hyst_step(&model, (hyst_real_t)x) + 0.005 * gauss(&r);
            (void)hyst_ident_add(&id, x, y);
        }
        check(hyst_ident_solve(&id, &res) == HYST_OK, "example1_solve");
        print_fit(names[m], &res);
        check(fabs((double)res.coeffs[0] - 1.0) < 0.005 && fabs((double)res.coeffs[1]) < 0.005 &&
                  fabs((double)res.coeffs[2]) < 0.005,
              "example1_tolerance");
    }
    end();
}

/* Simulation Example 2: TCM with f0 = the PI loading curve reproduces the
 * PI model of Table 1 (10 operators on [0, 1]). */
static void example2(void)
{
    static const hyst_real_t w[10] = {
        HYST_REAL_C(0.0789), HYST_REAL_C(0.2268), HYST_REAL_C(0.1928), HYST_REAL_C(0.2019),
        HYST_REAL_C(0.1995), HYST_REAL_C(0.2001), HYST_REAL_C(0.2000), HYST_REAL_C(0.2000),
        HYST_REAL_C(0.1999), HYST_REAL_C(0.2005)};
    static const hyst_real_t r[10] = {
        HYST_REAL_C(0.0), HYST_REAL_C(0.1), HYST_REAL_C(0.2), HYST_REAL_C(0.3), HYST_REAL_C(0.4),
        HYST_REAL_C(0.5), HYST_REAL_C(0.6), HYST_REAL_C(0.7), HYST_REAL_C(0.8), HYST_REAL_C(0.9)};
    static hyst_real_t bx[11], by[11], z[10], xs[20000];
    static hyst_pi_t pi;
    static const char *const keys[SIG_KINDS] = {"walk", "jumps", "paper_triangle"};
    hyst_curve_t f_pi;
    double range;
    int kind;
    section("example2");
    check(hyst_pi_loading_curve(&f_pi, r, w, 10u, HYST_REAL_C(1.0), bx, by) == HYST_OK,
          "example2_curve");
    range = (double)(f_pi.y_hi.HYST_R - f_pi.y_lo.HYST_R);
    value("range", range);
    for (kind = 0; kind < SIG_KINDS; ++kind) {
        const long n = 20000;
        double worst = 0.0;
        char key[48];
        rng_t rng;
        long i;
        rng_seed(&rng, 99u + (uint32_t)kind);
        fill_signal(kind, &rng, 0.0, 1.0, xs, n);
        check(hyst_pi_init(&pi, r, w, z, 10u) == HYST_OK, "example2_pi");
        check(hyst_init_curve(&model, &f_pi, model_xltp, model_yltp, model_xrtp, model_yrtp,
                              HYST_CAPACITY(NU)) == HYST_OK,
              "example2_tcm");
        if (kind == SIG_PAPER) {
            printf("@table trace x,y_pi,y_tcm\n");
        }
        for (i = 0; i < n; ++i) {
            const double yp = (double)hyst_pi_step(&pi, xs[i]);
            const double yt = (double)hyst_step(&model, xs[i]);
            worst = fabs(yp - yt) > worst ? fabs(yp - yt) : worst;
            if (kind == SIG_PAPER && i < 2000) {
                printf("%.5f,%.7f,%.7f\n", (double)xs[i], yp, yt);
            }
        }
        (void)snprintf(key, sizeof key, "%s_samples", keys[kind]);
        value(key, (double)n);
        (void)snprintf(key, sizeof key, "%s_max_diff", keys[kind]);
        value(key, worst);
        check(worst <= 2e-6 * range, "example2_equivalence");
    }
    end();
}

/* Excitation: 5 triangles 0..40..0 V in 0.1 V steps; returns the samples. */
static long triangle_cycles(hyst_real_t *x, long max)
{
    double levels[10];
    int k;
    for (k = 0; k < 5; ++k) {
        levels[2 * k] = 40.0;
        levels[2 * k + 1] = 0.0;
    }
    return ramp_path(0.0, levels, 10, 0.1, x, max);
}

/* The experiment: identify f0 from a simulated piezo (Bouc-Wen, not a TCM),
 * then predict its response to the paper's test signal. */
static hyst_poly_t plant_f0; /* identified in experiment(), used by compensation() */

static void experiment(void)
{
    static hyst_real_t xs[8192];
    static hyst_ident_t id;
    static const char *names[2] = {"reflect", "joint"};
    static const int methods[2] = {HYST_IDENT_REFLECT, HYST_IDENT_JOINT};
    hyst_ident_result_t fit[2];
    double levels[32];
    plant_bw_t plant;
    hyst_poly_t f0;
    double ss = 0.0, max_err = 0.0, y_min = 1e30, y_max = -1e30;
    size_t max_tp = 0u;
    long n, i;
    int m;

    section("experiment");
    for (m = 0; m < 2; ++m) {
        hyst_ident_config_t cfg = {0};
        cfg.degree = 3u;
        cfg.method = methods[m];
        cfg.lo = 0.0;
        cfg.hi = 40.0;
        plant_bw_init_piezo(&plant);
        check(hyst_ident_init(&id, &cfg) == HYST_OK, "experiment_ident");
        n = triangle_cycles(xs, 8192);
        for (i = 0; i < n; ++i) {
            const double y = plant_bw_step(&plant, (double)xs[i]);
            if (i >= n / 5) { /* the first cycle settles */
                (void)hyst_ident_add(&id, (double)xs[i], y);
            }
        }
        check(hyst_ident_solve(&id, &fit[m]) == HYST_OK, "experiment_solve");
        print_fit(names[m], &fit[m]);
    }
    check(hyst_ident_poly(&fit[1], &f0) == HYST_OK && HYST_INIT(model, &f0) == HYST_OK,
          "experiment_model");
    plant_f0 = f0;
    n = ramp_path(0.0, levels, paper_levels(0.0, 40.0, levels), 0.1, xs, 8192);
    printf("@table prediction i,x_V,y_plant_um,y_model_um,tp\n");
    for (i = 0; i < n; ++i) { /* the plant is where the excitation left it: x = 0 */
        const double yp = plant_bw_step(&plant, (double)xs[i]);
        const double ym = (double)hyst_step(&model, xs[i]);
        const double e = ym - yp;
        const size_t tp = hyst_tp_count(&model);
        ss += e * e;
        max_err = fabs(e) > max_err ? fabs(e) : max_err;
        y_min = yp < y_min ? yp : y_min;
        y_max = yp > y_max ? yp : y_max;
        max_tp = tp > max_tp ? tp : max_tp;
        printf("%ld,%.3f,%.6f,%.6f,%u\n", i, (double)xs[i], yp, ym, (unsigned)tp);
    }
    value("samples", (double)n);
    value("max_error_um", max_err);
    value("rms_error_um", sqrt(ss / (double)n));
    value("max_error_pct", 100.0 * max_err / (y_max - y_min));
    value("max_tp", (double)max_tp);
    check(max_tp == 14u, "experiment_tp");
    end();
}

/* Measured data: fit on the first half of the cycles after settling,
 * predict the second half (rows as in tests/test_ident.c). */
static void measured(void)
{
    static double xs[8100], ys[8100];
    static hyst_ident_t work;
    static const char *names[2] = {"reflect", "joint"};
    static const int methods[2] = {HYST_IDENT_REFLECT, HYST_IDENT_JOINT};
    const size_t skip = 350u, split = 4150u, stop = 7950u, delay = 1u;
    const long n = piezo_data_load(HYST_DATA_DIR "/piezo_major_loop.dat", xs, ys, 8100u);
    int m;
    section("measured");
    value("rows", (double)n);
    check(n == 8027, "measured_load");
    if (n != 8027) {
        end();
        return;
    }
    for (m = 0; m < 2; ++m) {
        hyst_ident_config_t cfg = {0};
        hyst_ident_result_t res;
        hyst_poly_t f0;
        double ss = 0.0, max_err = 0.0;
        char key[48];
        size_t i;
        cfg.degree = 3u;
        cfg.method = methods[m];
        cfg.skip = skip;
        cfg.delay = delay;
        check(hyst_ident_fit(&cfg, xs, ys, split + delay, &work, &res) == HYST_OK, "measured_fit");
        print_fit(names[m], &res);
        check(hyst_ident_poly(&res, &f0) == HYST_OK && HYST_INIT(model, &f0) == HYST_OK,
              "measured_model");
        if (m == 1) {
            printf("@table prediction i,x_V,y_measured,y_model\n");
        }
        for (i = split; i < stop; ++i) {
            const double ym = (double)hyst_step(&model, (hyst_real_t)xs[i]);
            const double e = ym - ys[i + delay];
            ss += e * e;
            max_err = fabs(e) > max_err ? fabs(e) : max_err;
            if (m == 1) {
                printf("%u,%.6f,%.6f,%.6f\n", (unsigned)i, xs[i], ys[i + delay], ym);
            }
        }
        (void)snprintf(key, sizeof key, "%s_predict_rms", names[m]);
        value(key, sqrt(ss / (double)(stop - split)));
        (void)snprintf(key, sizeof key, "%s_predict_max", names[m]);
        value(key, max_err);
    }
    end();
}

/* A plant's step, whatever its type. */
typedef double (*plant_step_t)(void *plant, double x);
static double bw_step(void *plant, double x) { return plant_bw_step((plant_bw_t *)plant, x); }
static double everett_step(void *plant, double x)
{
    return plant_everett_step((plant_everett_t *)plant, x);
}

/* Tracking of a desired displacement, the test signal's levels xs[0..n)
 * (0..40) mapped onto 5 %..95 % of [y_lo, y_hi]: one copy of the plant
 * driven open loop by a linear scaling of [y_lo, y_hi] onto 0..40 V, the
 * other through the compensator `comp` (initialised by the caller).
 * Prints open_/comp_ RMS and max errors, their keys prefixed by `tag` if
 * not NULL, else with the tracking table; returns the squared-sum ratio
 * open / compensated. */
static double track(const char *tag, hyst_t *comp, const hyst_real_t *xs, long n, double y_lo,
                    double y_hi, plant_step_t step, void *open_plant, void *comp_plant)
{
    static const char *const keys[4] = {"open_rms", "open_max", "comp_rms", "comp_max"};
    double ss_open = 0.0, ss_comp = 0.0, max_open = 0.0, max_comp = 0.0, figures[4];
    char key[48];
    long i;
    int k;
    if (tag == NULL) {
        printf("@table tracking i,y_ref,y_open,y_comp\n");
    }
    for (i = 0; i < n; ++i) {
        const double y_ref = y_lo + (y_hi - y_lo) * (0.05 + 0.9 * (double)xs[i] / 40.0);
        const double x_open = 40.0 * (y_ref - y_lo) / (y_hi - y_lo);
        const double x_comp = (double)hyst_step(comp, (hyst_real_t)y_ref);
        const double yo = step(open_plant, x_open);
        const double yc = step(comp_plant, x_comp);
        ss_open += (yo - y_ref) * (yo - y_ref);
        ss_comp += (yc - y_ref) * (yc - y_ref);
        max_open = fabs(yo - y_ref) > max_open ? fabs(yo - y_ref) : max_open;
        max_comp = fabs(yc - y_ref) > max_comp ? fabs(yc - y_ref) : max_comp;
        if (tag == NULL) {
            printf("%ld,%.6f,%.6f,%.6f\n", i, y_ref, yo, yc);
        }
    }
    figures[0] = sqrt(ss_open / (double)n);
    figures[1] = max_open;
    figures[2] = sqrt(ss_comp / (double)n);
    figures[3] = max_comp;
    for (k = 0; k < 4; ++k) {
        (void)snprintf(key, sizeof key, "%s%s%s", tag != NULL ? tag : "", tag != NULL ? "_" : "",
                       keys[k]);
        value(key, figures[k]);
    }
    check(ss_comp < ss_open && max_comp < max_open, "compensation_better");
    return ss_open / ss_comp;
}

/* The desired displacement of full major loops only (0..40 twice, the
 * test signal's step), to tell the major loop's fit from minor loops. */
static long major_loops(hyst_real_t *xs, long max)
{
    static const double levels[4] = {40.0, 0.0, 40.0, 0.0};
    return ramp_path(0.0, levels, 4, 0.1, xs, max);
}

/* Feedforward compensation of the same Bouc-Wen plant: the desired
 * displacement (the paper's test signal shape in um) drives the plant
 * (a) through a linear scaling of the major loop's end points and (b) through
 * the inverse TCM of the f0 identified in experiment(). */
static void compensation(void)
{
    static hyst_real_t xs[8192];
    double levels[32];
    plant_bw_t open_plant, comp_plant;
    long n;
    section("compensation");
    check(HYST_INIT_INVERSE(model, &plant_f0) == HYST_OK, "compensation_init");
    plant_bw_init_piezo(&open_plant);
    plant_bw_init_piezo(&comp_plant);
    n = ramp_path(0.0, levels, paper_levels(0.0, 40.0, levels), 0.1, xs, 8192);
    (void)track(NULL, &model, xs, n, (double)hyst_poly_eval(&plant_f0, plant_f0.lo),
                (double)hyst_poly_eval(&plant_f0, plant_f0.hi), bw_step, &open_plant, &comp_plant);
    /* the same compensator along major loops only */
    check(HYST_INIT_INVERSE(model, &plant_f0) == HYST_OK, "compensation_init");
    plant_bw_init_piezo(&open_plant);
    plant_bw_init_piezo(&comp_plant);
    n = major_loops(xs, 8192);
    (void)track("major", &model, xs, n, (double)hyst_poly_eval(&plant_f0, plant_f0.lo),
                (double)hyst_poly_eval(&plant_f0, plant_f0.hi), bw_step, &open_plant, &comp_plant);
    end();
}

/* The asymmetric plant with a lagging sensor (examples/common/plant_everett.h,
 * not a TCM): identified from a record of major loops read through its
 * sensor (noise 0.1 % of the range), the symmetric TCM's degree and delay
 * chosen by hold-out (fit on the first two thirds, score the prediction of
 * the last third; the fewest parameters within 1 % of the best score) and
 * PI-10's weights by NNLS at the same delay; then both predict the sensor's
 * reading of the paper's test signal, and the TCM's inverse drives the
 * actuator along it (tracking error of the actuator itself). */
#define ASYM_CYCLE 400L          /* samples per major loop (1 Hz at 400 Hz) */
#define ASYM_RECORD (6L * ASYM_CYCLE)
#define ASYM_PI_OPERATORS 10u

static hyst_real_t asym_x[ASYM_RECORD]; /* the record's inputs as the model takes them */
static double asym_xr[ASYM_RECORD], asym_yr[ASYM_RECORD];

/* The record's hold-out score of the TCM of degree `degree` fitted at
 * `delay`: RMS of model(x[i]) - y[i + delay] over the last third. */
static int asym_tcm_score(unsigned degree, size_t delay, hyst_poly_t *f0, double *score)
{
    static hyst_ident_t work;
    const size_t skip = (size_t)ASYM_CYCLE, split = (size_t)(2L * ASYM_RECORD / 3L);
    hyst_ident_config_t cfg = {0};
    hyst_ident_result_t res;
    double ss = 0.0;
    size_t i;
    cfg.degree = degree;
    cfg.method = HYST_IDENT_JOINT;
    cfg.lo = 0.0;
    cfg.hi = 40.0;
    cfg.skip = skip;
    cfg.delay = delay;
    if (hyst_ident_fit(&cfg, asym_xr, asym_yr, split + delay, &work, &res) != HYST_OK ||
        hyst_ident_poly(&res, f0) != HYST_OK || HYST_INIT(model, f0) != HYST_OK) {
        return 0; /* not increasing on the domain, or refused */
    }
    for (i = 0u; i + delay < (size_t)ASYM_RECORD; ++i) {
        const double e = (double)hyst_step(&model, asym_x[i]) - asym_yr[i + delay];
        if (i >= split) {
            ss += e * e;
        }
    }
    *score = sqrt(ss / (double)((size_t)ASYM_RECORD - delay - split));
    return 1;
}

/* The same hold-out score for the asymmetric kind of degree `degree`:
 * E fitted on the first two thirds (hyst_everett_fit_*), the model run over
 * the whole record. 0 if the fit is singular or E not monotone. */
/* Identified reals of an E of degree d in the width, k in the lower end:
 * its terms w^i t^j (j <= min(d - i, k)) and y_lo. */
static unsigned everett_params(unsigned d, unsigned k)
{
    unsigned i, n = 1u;
    for (i = 1u; i <= d; ++i) {
        n += (d - i < k ? d - i : k) + 1u;
    }
    return n;
}

static int asym_everett_score(unsigned degree, unsigned t_degree, size_t delay, hyst_everett_t *e,
                              double *score)
{
    static hyst_wide_t work[HYST_EVERETT_FIT_WORK(NU)];
    static hyst_everett_fit_t fit;
    const size_t skip = (size_t)ASYM_CYCLE, split = (size_t)(2L * ASYM_RECORD / 3L);
    double ss = 0.0;
    size_t i;
    if (hyst_everett_fit_init_terms(&fit, degree, t_degree, 0.0, 40.0, work,
                                    sizeof work / sizeof work[0]) != HYST_OK) {
        return 0;
    }
    for (i = 0u; i < split; ++i) { /* the settling cycle moves the input only */
        (void)hyst_everett_fit_add(&fit, asym_xr[i], i >= skip ? asym_yr[i + delay] : (hyst_wide_t)NAN);
    }
    if (hyst_everett_fit_solve(&fit, e, NULL) != HYST_OK ||
        hyst_curve_from_everett(&asym_curve, e) != HYST_OK ||
        HYST_INIT_CURVE(asym_model, &asym_curve) != HYST_OK) {
        return 0;
    }
    for (i = 0u; i + delay < (size_t)ASYM_RECORD; ++i) {
        const double err = (double)hyst_step(&asym_model, asym_x[i]) - asym_yr[i + delay];
        if (i >= split) {
            ss += err * err;
        }
    }
    *score = sqrt(ss / (double)((size_t)ASYM_RECORD - delay - split));
    return 1;
}

/* The compensator identified directly (the axes swapped): E of the drive
 * as a function of the reading, fitted as asym_everett_score() fits the
 * model, on input asym_yr[i + delay] (the actuator's output at i, read
 * through the lagging sensor), output asym_xr[i], domain [lo, hi]; its
 * hold-out score in drive units. Its samples cost what the forward kind's
 * do. 0 if the fit is singular or E not monotone. */
static hyst_curve_t asym_direct;

static int asym_direct_score(unsigned degree, unsigned t_degree, size_t delay, double lo, double hi,
                             hyst_everett_t *e, double *score)
{
    static hyst_wide_t work[HYST_EVERETT_FIT_WORK(NU)];
    static hyst_everett_fit_t fit;
    const size_t skip = (size_t)ASYM_CYCLE, split = (size_t)(2L * ASYM_RECORD / 3L);
    double ss = 0.0;
    size_t i;
    if (hyst_everett_fit_init_terms(&fit, degree, t_degree, lo, hi, work,
                                    sizeof work / sizeof work[0]) != HYST_OK) {
        return 0;
    }
    for (i = 0u; i < split; ++i) {
        (void)hyst_everett_fit_add(&fit, asym_yr[i + delay], i >= skip ? asym_xr[i] : (hyst_wide_t)NAN);
    }
    if (hyst_everett_fit_solve(&fit, e, NULL) != HYST_OK ||
        hyst_curve_from_everett(&asym_direct, e) != HYST_OK ||
        HYST_INIT_CURVE(asym_model, &asym_direct) != HYST_OK) {
        return 0;
    }
    for (i = 0u; i + delay < (size_t)ASYM_RECORD; ++i) {
        const double err = (double)hyst_step(&asym_model, (hyst_real_t)asym_yr[i + delay]) - asym_xr[i];
        if (i >= split) {
            ss += err * err;
        }
    }
    *score = sqrt(ss / (double)((size_t)ASYM_RECORD - delay - split));
    return 1;
}

/* Degree and t-degree of the direct compensator by the model's rule (the
 * fewest parameters within 1 % of the best hold-out score); its curve in
 * asym_direct. 0 if none fits. */
static int asym_direct_choose(size_t delay, double lo, double hi)
{
    double s[HYST_EVERETT_MAX_DEGREE + 1][HYST_EVERETT_MAX_DEGREE], best = 1e300;
    hyst_everett_t e;
    unsigned d, t, params = 1000u, cd = 0u, ct = 0u;
    for (d = 1u; d <= (unsigned)HYST_EVERETT_MAX_DEGREE; ++d) {
        for (t = 0u; t < d; ++t) {
            s[d][t] = asym_direct_score(d, t, delay, lo, hi, &e, &s[d][t]) ? s[d][t] : -1.0;
            best = s[d][t] >= 0.0 && s[d][t] < best ? s[d][t] : best;
        }
    }
    for (d = 1u; d <= (unsigned)HYST_EVERETT_MAX_DEGREE; ++d) {
        for (t = 0u; t < d; ++t) {
            if (s[d][t] >= 0.0 && s[d][t] <= 1.01 * best && everett_params(d, t) < params) {
                params = everett_params(d, t);
                cd = d;
                ct = t;
            }
        }
    }
    if (cd == 0u || !asym_direct_score(cd, ct, delay, lo, hi, &e, &best)) {
        return 0;
    }
    value("direct_degree", (double)cd);
    value("direct_t_degree", (double)ct);
    value("direct_params", (double)params);
    value("direct_holdout_rms", best);
    return 1;
}

static void asymmetric(void)
{
    static hyst_wide_t pi_work[HYST_PI_FIT_WORK(ASYM_PI_OPERATORS)];
    static hyst_wide_t pi_rw[ASYM_PI_OPERATORS], pi_ww[ASYM_PI_OPERATORS];
    static hyst_real_t pi_r[ASYM_PI_OPERATORS], pi_w[ASYM_PI_OPERATORS];
    static hyst_real_t xs[8192];
    static double score[7][7];
    HYST_PI_DEFINE(pi, ASYM_PI_OPERATORS);
    const size_t split = (size_t)(2L * ASYM_RECORD / 3L);
    plant_everett_t plant;
    hyst_pi_fit_config_t pcfg = {0};
    hyst_pi_fit_result_t pres;
    hyst_poly_t f0, best_f0;
    double levels[32], best = 1e300, ss_tcm = 0.0, ss_pi = 0.0, max_tcm = 0.0, max_pi = 0.0;
    double pi_score = 0.0;
    unsigned degree, best_degree = 0u;
    size_t delay, best_delay = 0u, i;
    rng_t rng;
    long n, k;
    section("asymmetric");
    plant_everett_init_piezo(&plant);
    rng_seed(&rng, 2024u);
    for (k = 0; k < ASYM_RECORD; ++k) {
        const double x = 20.0 - 20.0 * cos(6.283185307179586 * (double)k / (double)ASYM_CYCLE);
        (void)plant_everett_step(&plant, x);
        asym_x[k] = (hyst_real_t)x;
        asym_xr[k] = (double)asym_x[k];
        asym_yr[k] = plant_everett_sensor(&plant) + 0.0049 * gauss(&rng);
    }
    /* every candidate scored; the best, then the fewest parameters within 1 % */
    printf("@table candidates degree,delay,holdout_rms\n");
    for (degree = 1u; degree <= 6u; ++degree) {
        for (delay = 0u; delay <= 6u; ++delay) {
            score[degree][delay] = asym_tcm_score(degree, delay, &f0, &score[degree][delay])
                                       ? score[degree][delay]
                                       : -1.0;
            printf("%u,%u,%.6g\n", degree, (unsigned)delay, score[degree][delay]);
            if (score[degree][delay] >= 0.0 && score[degree][delay] < best) {
                best = score[degree][delay];
            }
        }
    }
    for (degree = 1u; degree <= 6u && best_degree == 0u; ++degree) {
        for (delay = 0u; delay <= 6u; ++delay) {
            if (score[degree][delay] >= 0.0 && score[degree][delay] <= 1.01 * best) {
                best_degree = degree;
                best_delay = delay;
                break;
            }
        }
    }
    check(best_degree > 0u && asym_tcm_score(best_degree, best_delay, &best_f0, &best),
          "asymmetric_tcm");
    value("tcm_degree", (double)best_degree);
    value("tcm_delay", (double)best_delay);
    value("tcm_params", (double)(best_degree + 1u));
    value("tcm_holdout_rms", best);
    /* PI-10 at the same delay, its hold-out score the same way */
    pcfg.operators = ASYM_PI_OPERATORS;
    pcfg.skip = (size_t)ASYM_CYCLE;
    pcfg.delay = best_delay;
    check(hyst_pi_fit_record(&pcfg, asym_xr, asym_yr, split + best_delay, pi_work,
                             sizeof pi_work / sizeof pi_work[0], pi_rw, pi_ww, &pres) == HYST_OK,
          "asymmetric_pi_fit");
    for (i = 0u; i < ASYM_PI_OPERATORS; ++i) {
        pi_r[i] = (hyst_real_t)pi_rw[i];
        pi_w[i] = (hyst_real_t)pi_ww[i];
    }
    check(HYST_PI_INIT(pi, pi_r, pi_w) == HYST_OK, "asymmetric_pi_init");
    for (i = 0u; i + best_delay < (size_t)ASYM_RECORD; ++i) {
        const double e = pres.offset + (double)hyst_pi_step(&pi, asym_x[i]) - asym_yr[i + best_delay];
        if (i >= split) {
            pi_score += e * e;
        }
    }
    value("pi_params", (double)(ASYM_PI_OPERATORS + 1u));
    value("pi_holdout_rms", sqrt(pi_score / (double)((size_t)ASYM_RECORD - best_delay - split)));
    /* the asymmetric kind at the same delay: degree d in the width and k in
     * the lower end (k < d; k = d - 1 is every term of total degree d), by
     * the same rule: the fewest parameters within 1 % of the best score.
     * Major loops alone determine E linear in t (k <= 1) at any d, not the
     * full degree 3 or 4 (singular: ident.h). */
    {
        double a_score[HYST_EVERETT_MAX_DEGREE + 1][HYST_EVERETT_MAX_DEGREE], a_best = 1e300;
        double chosen = 0.0;
        hyst_everett_t e;
        unsigned d, t, a_degree = 0u, a_t = 0u, params = 0u, best_params = 1000u;
        printf("@table everett_candidates degree,t_degree,params,holdout_rms\n");
        for (d = 1u; d <= (unsigned)HYST_EVERETT_MAX_DEGREE; ++d) {
            for (t = 0u; t < d; ++t) {
                a_score[d][t] = asym_everett_score(d, t, best_delay, &e, &a_score[d][t])
                                    ? a_score[d][t]
                                    : -1.0;
                printf("%u,%u,%u,%.6g\n", d, t, everett_params(d, t), a_score[d][t]);
                a_best = a_score[d][t] >= 0.0 && a_score[d][t] < a_best ? a_score[d][t] : a_best;
            }
        }
        for (d = 1u; d <= (unsigned)HYST_EVERETT_MAX_DEGREE; ++d) {
            for (t = 0u; t < d; ++t) {
                params = everett_params(d, t);
                if (a_score[d][t] >= 0.0 && a_score[d][t] <= 1.01 * a_best && params < best_params) {
                    best_params = params;
                    a_degree = d;
                    a_t = t;
                }
            }
        }
        { /* the best of at most 6 parameters, for the goal stated that way */
            double six = 1e300;
            unsigned six_d = 0u, six_t = 0u;
            for (d = 1u; d <= (unsigned)HYST_EVERETT_MAX_DEGREE; ++d) {
                for (t = 0u; t < d; ++t) {
                    if (a_score[d][t] >= 0.0 && a_score[d][t] < six && everett_params(d, t) <= 6u) {
                        six = a_score[d][t];
                        six_d = d;
                        six_t = t;
                    }
                }
            }
            value("everett6_degree", (double)six_d);
            value("everett6_t_degree", (double)six_t);
            value("everett6_params", (double)everett_params(six_d, six_t));
            value("everett6_holdout_rms", six);
        }
        check(a_degree > 0u && asym_everett_score(a_degree, a_t, best_delay, &e, &chosen),
              "asymmetric_everett");
        value("everett_degree", (double)a_degree);
        value("everett_t_degree", (double)a_t);
        value("everett_params", (double)best_params);
        value("everett_holdout_rms", chosen);
    }
    /* the paper's test signal: the sensor's reading predicted (delay applied) */
    plant_everett_init_piezo(&plant);
    check(HYST_INIT(model, &best_f0) == HYST_OK && HYST_PI_INIT(pi, pi_r, pi_w) == HYST_OK,
          "asymmetric_models");
    hyst_reset(&asym_model);
    n = ramp_path(0.0, levels, paper_levels(0.0, 40.0, levels), 0.1, xs, 8192);
    {
        static double y_tcm[8192], y_pi[8192], y_sensor[8192], y_ev[8192];
        double ss_ev = 0.0, max_ev = 0.0;
        printf("@table prediction i,x_V,y_sensor,y_tcm,y_pi,y_everett\n");
        for (k = 0; k < n; ++k) {
            (void)plant_everett_step(&plant, (double)xs[k]);
            y_sensor[k] = plant_everett_sensor(&plant);
            y_tcm[k] = (double)hyst_step(&model, xs[k]);
            y_pi[k] = pres.offset + (double)hyst_pi_step(&pi, xs[k]);
            y_ev[k] = (double)hyst_step(&asym_model, xs[k]);
        }
        for (k = 0; k + (long)best_delay < n; ++k) {
            const double ys = y_sensor[k + (long)best_delay];
            ss_tcm += (y_tcm[k] - ys) * (y_tcm[k] - ys);
            ss_pi += (y_pi[k] - ys) * (y_pi[k] - ys);
            max_tcm = fabs(y_tcm[k] - ys) > max_tcm ? fabs(y_tcm[k] - ys) : max_tcm;
            max_pi = fabs(y_pi[k] - ys) > max_pi ? fabs(y_pi[k] - ys) : max_pi;
            ss_ev += (y_ev[k] - ys) * (y_ev[k] - ys);
            max_ev = fabs(y_ev[k] - ys) > max_ev ? fabs(y_ev[k] - ys) : max_ev;
            printf("%ld,%.3f,%.6f,%.6f,%.6f,%.6f\n", k, (double)xs[k], ys, y_tcm[k], y_pi[k],
                   y_ev[k]);
        }
        value("everett_predict_rms", sqrt(ss_ev / (double)(n - (long)best_delay)));
        value("everett_predict_max", max_ev);
        value("tcm_predict_rms", sqrt(ss_tcm / (double)(n - (long)best_delay)));
        value("tcm_predict_max", max_tcm);
        value("pi_predict_rms", sqrt(ss_pi / (double)(n - (long)best_delay)));
        value("pi_predict_max", max_pi);
    }
    /* compensation of the actuator along the test signal's shape, 5..95 %:
     * the symmetric TCM's inverse, then the asymmetric kind's (the chosen
     * model: its hold-out score is the better) */
    {
        plant_everett_t open_plant, comp_plant;
        const double y_lo = (double)hyst_poly_eval(&best_f0, best_f0.lo);
        const double y_hi = (double)hyst_poly_eval(&best_f0, best_f0.hi);
        check(HYST_INIT_INVERSE(model, &best_f0) == HYST_OK, "asymmetric_inverse");
        plant_everett_init_piezo(&open_plant);
        plant_everett_init_piezo(&comp_plant);
        value("symmetric_comp_rms_ratio", sqrt(track("symmetric", &model, xs, n, y_lo, y_hi,
                                                     everett_step, &open_plant, &comp_plant)));
        check(hyst_curve_inverse(&asym_inverse, &asym_curve) == HYST_OK &&
                  HYST_INIT_CURVE(asym_model, &asym_inverse) == HYST_OK,
              "asymmetric_compensator");
        plant_everett_init_piezo(&open_plant);
        plant_everett_init_piezo(&comp_plant);
        value("comp_rms_ratio", sqrt(track(NULL, &asym_model, xs, n, y_lo, y_hi, everett_step,
                                           &open_plant, &comp_plant)));
        n = major_loops(xs, 8192);
        check(HYST_INIT_INVERSE(model, &best_f0) == HYST_OK, "asymmetric_inverse");
        plant_everett_init_piezo(&open_plant);
        plant_everett_init_piezo(&comp_plant);
        (void)track("symmetric_major", &model, xs, n, y_lo, y_hi, everett_step, &open_plant,
                    &comp_plant);
        hyst_reset(&asym_model);
        plant_everett_init_piezo(&open_plant);
        plant_everett_init_piezo(&comp_plant);
        (void)track("major", &asym_model, xs, n, y_lo, y_hi, everett_step, &open_plant,
                    &comp_plant);
        /* the asymmetric compensator as firmware runs it by default: tabulated */
        n = ramp_path(0.0, levels, paper_levels(0.0, 40.0, levels), 0.1, xs, 8192);
        check(hyst_curve_everett_inverse_table(&asym_inverse, &asym_curve, asym_inv_table,
                                               HYST_EVERETT_INV_ROWS,
                                               HYST_EVERETT_INV_INTERVALS) == HYST_OK &&
                  HYST_INIT_CURVE(asym_model, &asym_inverse) == HYST_OK,
              "asymmetric_table_compensator");
        value("table_inverse_error", (double)hyst_curve_inverse_error(&asym_inverse));
        plant_everett_init_piezo(&open_plant);
        plant_everett_init_piezo(&comp_plant);
        value("comp_table_rms_ratio", sqrt(track("table", &asym_model, xs, n, y_lo, y_hi,
                                                 everett_step, &open_plant, &comp_plant)));
        /* the compensator identified directly from the same record, its axes
         * swapped: a forward asymmetric TCM from reading to drive, at the
         * forward kind's cost per sample */
        {
            double r_lo = asym_yr[0], r_hi = asym_yr[0];
            for (i = 0u; i < (size_t)ASYM_RECORD; ++i) {
                r_lo = asym_yr[i] < r_lo ? asym_yr[i] : r_lo;
                r_hi = asym_yr[i] > r_hi ? asym_yr[i] : r_hi;
            }
            check(asym_direct_choose(best_delay, r_lo, r_hi) &&
                      HYST_INIT_CURVE(asym_model, &asym_direct) == HYST_OK,
                  "asymmetric_direct_compensator");
            plant_everett_init_piezo(&open_plant);
            plant_everett_init_piezo(&comp_plant);
            value("comp_direct_rms_ratio", sqrt(track("direct", &asym_model, xs, n, y_lo, y_hi,
                                                      everett_step, &open_plant, &comp_plant)));
        }
    }
    end();
}

/* Table 2 analogue: RAM of one instance sized for Nu = 2^bits codes. */
static void memory(void)
{
    static const unsigned bits[4] = {12u, 16u, 18u, 24u};
    int k;
    section("memory");
    value("instance_bytes", (double)sizeof(hyst_t));
    value("real_bytes", (double)sizeof(hyst_real_t));
    printf("@table ram bits,nu,entries_per_array,bytes\n");
    for (k = 0; k < 4; ++k) {
        const unsigned long nu = 1ul << bits[k];
        const unsigned long entries = (unsigned long)HYST_CAPACITY(nu);
        const unsigned long bytes = 4ul * entries * (unsigned long)sizeof(hyst_real_t) +
                                    (unsigned long)sizeof(hyst_t);
        printf("%u,%lu,%lu,%lu\n", bits[k], nu, entries, bytes);
    }
    end();
}

int main(void)
{
    hyst_port_init();
    printf("@report hyst %d.%d.%d real=%s\n", HYST_VERSION_MAJOR, HYST_VERSION_MINOR,
           HYST_VERSION_PATCH, sizeof(hyst_real_t) == 4u ? "float" : "double");
    example1();
    example2();
    experiment();
    compensation();
    asymmetric();
    measured();
    memory();
    printf("@failures %d\n", failures);
    return failures == 0 ? 0 : 1;
}
