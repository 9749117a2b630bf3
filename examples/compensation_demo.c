/* SPDX-License-Identifier: MIT */
/* Feedforward compensation with the inverse TCM (docs/theory.md, the inverse model).
 *
 * Plant: a Prandtl-Ishlinskii model with 50 play operators on 0..100 V whose
 * loading curve follows h(v) = 0.05 v + 1.2e-3 v^2 - 6e-6 v^3 um (about
 * 11 um of stroke), driven through a 12-bit DAC. The compensator knows none
 * of this: it is identified from the plant's major ascending curve, sampled
 * at 21 inputs (every 5 V) after a reset, and used as a piecewise-linear f0;
 * the compensator is the same TCM engine on the inverse curve.
 *
 * A multi-amplitude reference (the paper's shrinking/growing triangle in
 * output units, then triangles of 10 % to 90 % of the stroke around moving
 * centres) is tracked
 *   (a) open loop, by a plain linear scaling from displacement to voltage;
 *   (b) through the inverse TCM on that piecewise-linear f0 (exact inverse);
 *   (c) through the inverse TCM on a cubic f0 fitted by hyst_ident to two
 *       full-range triangle cycles of the plant (polynomial inverse).
 * Prints the RMS and maximum tracking errors and the ratios to (a); exits
 * non-zero unless (b) and (c) beat (a) on both. Host and QEMU. */
#include "hyst/hyst.h"
#include "hyst_port.h"
#include "support.h"

#include <stdio.h>

#define N_OPS 50
#define V_MAX 100.0
#define N_ID 21        /* identification points on the major ascending curve */
#define DAC_CODES 4096 /* 12-bit DAC */
#define MAX_SAMPLES 16384L

static hyst_real_t plant_r[N_OPS], plant_w[N_OPS], plant_z[N_OPS];
static hyst_pi_t plant;
static hyst_real_t id_x[N_ID], id_y[N_ID]; /* kept by the curves: static */
HYST_DEFINE_INVERSE(comp, DAC_CODES);

static double loading(double v)
{
    return v * (0.05 + v * (1.2e-3 - v * 6e-6));
}

/* Weights so that f_PI interpolates h at the thresholds 0, 2, ..., 98 V (and 100 V). */
static void make_plant(void)
{
    double slope_prev = 0.0;
    int i;
    for (i = 0; i < N_OPS; ++i) {
        const double a = V_MAX * i / N_OPS, b = V_MAX * (i + 1) / N_OPS;
        const double slope = (loading(b) - loading(a)) / (b - a);
        plant_r[i] = (hyst_real_t)a;
        plant_w[i] = (hyst_real_t)(slope - slope_prev);
        slope_prev = slope;
    }
}

/* The drive as it reaches the plant: clamped and quantised by the DAC. */
static hyst_real_t dac(double v)
{
    long code = (long)(v / V_MAX * (DAC_CODES - 1) + 0.5);
    code = code < 0 ? 0 : (code > DAC_CODES - 1 ? DAC_CODES - 1 : code);
    return (hyst_real_t)(V_MAX * (double)code / (DAC_CODES - 1));
}

/* Identification: a rising sweep from reset, sampled every 5 V. */
static void identify(void)
{
    int k;
    hyst_pi_reset(&plant);
    for (k = 0; k < N_ID; ++k) {
        id_x[k] = dac(V_MAX * k / (N_ID - 1));
        id_y[k] = hyst_pi_step(&plant, id_x[k]);
    }
}

typedef struct {
    double rms, max;
} errors_t;

/* Identification for (c): a cubic fitted to two full-range triangle cycles. */
static int identify_cubic(hyst_poly_t *f0)
{
    static hyst_ident_t id; /* about 0.9 KB: static, off the stack */
    hyst_ident_result_t res;
    const hyst_ident_config_t cfg = {3u, HYST_IDENT_JOINT, 0.0, V_MAX, 0u, 0u};
    int cycle, k;
    if (hyst_ident_init(&id, &cfg) != HYST_OK) {
        return 0;
    }
    hyst_pi_reset(&plant);
    for (cycle = 0; cycle < 2; ++cycle) {
        for (k = 0; k < 800; ++k) { /* 0 -> 100 V -> 0 in 0.25 V steps */
            const hyst_real_t v = dac(V_MAX * (k < 400 ? k : 800 - k) / 400.0);
            (void)hyst_ident_add(&id, (hyst_wide_t)v, (hyst_wide_t)hyst_pi_step(&plant, v));
        }
    }
    if (hyst_ident_solve(&id, &res) != HYST_OK || !res.increasing) {
        return 0;
    }
    f0->degree = 3u;
    f0->lo = 0;
    f0->hi = (hyst_real_t)V_MAX;
    for (k = 0; k <= 3; ++k) {
        f0->coeffs[k] = (hyst_real_t)res.coeffs[k];
    }
    printf("# identified cubic f0 = %.4g v^3 + %.4g v^2 + %.4g v + %.4g um (fit RMS %.2g um)\n",
           (double)f0->coeffs[0], (double)f0->coeffs[1], (double)f0->coeffs[2],
           (double)f0->coeffs[3], (double)res.rms);
    return 1;
}

/* Tracks ref[0..n): open loop if !compensated, else through comp. */
static errors_t track(const hyst_real_t *ref, long n, int compensated)
{
    const double y_lo = (double)id_y[0], y_hi = (double)id_y[N_ID - 1];
    errors_t e = {0.0, 0.0};
    long i;
    hyst_pi_reset(&plant);
    hyst_reset(&comp);
    for (i = 0; i < n; ++i) {
        const double drive = compensated ? (double)hyst_step(&comp, ref[i])
                                         : ((double)ref[i] - y_lo) * V_MAX / (y_hi - y_lo);
        const double y = (double)hyst_pi_step(&plant, dac(drive));
        const double err = y - (double)ref[i];
        e.rms += err * err;
        e.max = (err < 0 ? -err : err) > e.max ? (err < 0 ? -err : err) : e.max;
    }
    e.rms = n > 0 ? e.rms / (double)n : 0.0;
    /* square root without libm: a few Newton steps from a safe start */
    {
        double s = e.rms > 1.0 ? e.rms : 1.0;
        int k;
        for (k = 0; k < 60 && e.rms > 0.0; ++k) {
            s = 0.5 * (s + e.rms / s);
        }
        e.rms = e.rms > 0.0 ? s : 0.0;
    }
    return e;
}

int main(void)
{
    static hyst_real_t ref[MAX_SAMPLES];
    static const double tri[] = {0.10, 0.90, 0.30, 0.70, 0.45, 0.55, 0.20, 0.80,
                                 0.60, 0.95, 0.05, 0.40, 0.35, 0.65, 0.50};
    double levels[64];
    hyst_curve_t f0, f0_inv;
    hyst_poly_t cubic;
    double y_lo, y_hi, span;
    errors_t open, closed, closed_poly;
    long n;
    int n_levels, k, st;

    hyst_port_init();
    make_plant();
    if (hyst_pi_init(&plant, plant_r, plant_w, plant_z, N_OPS) != HYST_OK) {
        printf("plant init failed\n");
        return 1;
    }
    identify();
    st = hyst_curve_from_pwl(&f0, id_x, id_y, N_ID);
    if (st == HYST_OK) {
        st = hyst_curve_inverse(&f0_inv, &f0);
    }
    if (st == HYST_OK) {
        st = hyst_init_curve(&comp, &f0_inv, comp_xltp, comp_yltp, comp_xrtp, comp_yrtp,
                             HYST_CAPACITY(DAC_CODES));
    }
    if (st != HYST_OK) {
        printf("compensator init failed: %s\n", hyst_status_str(st));
        return 1;
    }
    y_lo = (double)id_y[0];
    y_hi = (double)id_y[N_ID - 1];
    span = y_hi - y_lo;

    /* reference: the paper's signal inside 5..95 % of the stroke, then triangles */
    n_levels = paper_levels(y_lo + 0.05 * span, y_lo + 0.95 * span, levels);
    for (k = 0; k < (int)(sizeof tri / sizeof tri[0]); ++k) {
        levels[n_levels++] = y_lo + tri[k] * span;
    }
    levels[n_levels++] = y_lo;
    n = ramp_path(y_lo, levels, n_levels, 0.002 * span, ref, MAX_SAMPLES);

    printf("# hyst compensation demo: plant = PI, %d operators, 0..%g V, stroke %.3f um, "
           "12-bit DAC, %ld reference samples\n", N_OPS, V_MAX, span, n);
    open = track(ref, n, 0);
    closed = track(ref, n, 1);
    printf("# (b) PWL f0 from %d samples of the major ascending curve; events 0x%x\n", N_ID,
           hyst_events(&comp));
    if (!identify_cubic(&cubic) || HYST_INIT_INVERSE(comp, &cubic) != HYST_OK) {
        printf("cubic identification or its inverse failed\n");
        return 1;
    }
    closed_poly = track(ref, n, 1);
    printf("# (c) events 0x%x (desired outputs outside [f0(lo), f0(hi)] are clamped, "
           "flag 0x%x)\n", hyst_events(&comp), HYST_EVENT_CLAMPED);
    printf("(a) open loop, linear scaling:  RMS %.4f um, max %.4f um\n", open.rms, open.max);
    printf("(b) inverse TCM, PWL f0:        RMS %.4f um, max %.4f um, ratio (a)/(b): RMS %.1f, max %.1f\n",
           closed.rms, closed.max, open.rms / closed.rms, open.max / closed.max);
    printf("(c) inverse TCM, cubic f0:      RMS %.4f um, max %.4f um, ratio (a)/(c): RMS %.1f, max %.1f\n",
           closed_poly.rms, closed_poly.max, open.rms / closed_poly.rms,
           open.max / closed_poly.max);
    return closed.rms < open.rms && closed.max < open.max && closed_poly.rms < open.rms &&
                   closed_poly.max < open.max
               ? 0
               : 2;
}
