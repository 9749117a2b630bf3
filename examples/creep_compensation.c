/* SPDX-License-Identifier: MIT */
/* Creep compensation in firmware (hyst/creep.h, docs/creep.md).
 *
 * Plant: the paper's Eq. 20 hysteresis on 0..40 V (a TCM) plus creep, two
 * lags of the drive: 2000 samples and 0.02 um/V (16 % of the stroke at a
 * sustained 40 V) and a small fast one, 300 samples and 0.002 um/V, that the
 * firmware's single lag does not have; its sensor adds +-0.005 um of noise.
 * The firmware knows the hysteresis model (as if identified) but not the
 * creep: it records the plant over a
 * full-range triangle with holds, fits a lag to what the hysteresis model
 * leaves, its time constant the best of a 1-2-5 series on the record's last
 * third (hyst_creep_fit_holdout(), what `hyst fit --creep auto` does on a
 * PC), then tracks a staircase of held positions and triangles
 *   (a) through the hysteresis compensator alone (the tabulated inverse of
 *       Eq. 20, HYST_INIT_INVERSE);
 *   (b) through the same compensator on the desired output less the creep's
 *       share, the creep instance fed with the drive (strictly causal);
 *   (c) as (b), with a brown-out half-way: the firmware saves the
 *       compensator's and the creep's snapshots (hyst/snapshot.h) to its
 *       "non-volatile memory", reboots (both instances back at rest),
 *       restores both and goes on, the plant keeping its state.
 * Prints both RMS and maximum tracking errors and their ratio; exits
 * non-zero unless the time constant found is the plant's, (b) cuts the
 * RMS error at least five-fold and (c) tracks exactly as (b): the same
 * drives, bit for bit. Host and QEMU (float). */
#include "hyst/hyst.h"
#include "hyst_port.h"

#include <stdio.h>

#define V_MAX 40.0
#define CAP 512u
#define ID_SAMPLES 12000L   /* the identification record */
#define RUN_SAMPLES 24000L  /* the tracking run */
#define PLANT_TAU 2000.0
#define PLANT_W 0.02

static const hyst_poly_t eq20 = {3u, HYST_REAL_C(0.0), HYST_REAL_C(40.0),
                                 {HYST_REAL_C(-6.1876e-6), HYST_REAL_C(1.1949e-3),
                                  HYST_REAL_C(8.6444e-2), HYST_REAL_C(5.8517e-1)}};
HYST_DEFINE(plant_h, CAP);
HYST_DEFINE(model_h, CAP);
HYST_DEFINE_INVERSE(comp, 4096);
static hyst_creep_t plant_c, comp_c;
static unsigned char nvm[HYST_SNAPSHOT_SIZE(HYST_CAPACITY(4096)) + HYST_CREEP_SNAPSHOT_SIZE];

/* The brown-out of run (c): both snapshots saved, the instances back at
 * rest as after a reboot's init, then both restored. 0 on success. */
static size_t len, creep_len; /* the octets saved */
static int brown_out(void)
{
    if (hyst_snapshot_save(&comp, nvm, sizeof nvm, &len) != HYST_OK ||
        hyst_creep_snapshot_save(&comp_c, nvm + len, sizeof nvm - len, &creep_len) != HYST_OK) {
        return 1;
    }
    hyst_reset(&comp);
    (void)hyst_creep_reset(&comp_c, 0);
    return hyst_snapshot_restore(&comp, nvm, len) != HYST_OK ||
           hyst_creep_snapshot_restore(&comp_c, nvm + len, creep_len) != HYST_OK;
}
static unsigned long lcg = 12345ul;

/* The sensor's noise: +-0.005 um, deterministic (an LCG). */
static double noise(void)
{
    lcg = (lcg * 1103515245ul + 12345ul) & 0x7FFFFFFFul;
    return ((double)lcg / 2147483648.0 - 0.5) * 0.01;
}
static hyst_wide_t id_u[ID_SAMPLES], id_r[ID_SAMPLES];

/* The plant's displacement for drive x (hysteresis plus its creep). */
static double plant_step(hyst_real_t x)
{
    return (double)hyst_step(&plant_h, x) + (double)hyst_creep_step(&plant_c, x);
}

/* A full-range triangle of 2000 samples per cycle with a hold of 1000 at
 * either end: the record the creep is identified from. */
static hyst_real_t id_drive(long k)
{
    const long phase = k % 4000L;
    double v;
    if (phase < 1000L) {
        v = V_MAX * (double)phase / 1000.0;
    } else if (phase < 2000L) {
        v = V_MAX;
    } else if (phase < 3000L) {
        v = V_MAX * (double)(3000L - phase) / 1000.0;
    } else {
        v = 0.0;
    }
    return (hyst_real_t)v;
}

/* The reference: staircase holds of 2000 samples at 10 %, 70 %, 35 %, 90 %,
 * 20 % of the stroke, then triangles between 20 % and 80 %. */
static double reference(long k, double y_lo, double y_hi)
{
    static const double level[5] = {0.1, 0.7, 0.35, 0.9, 0.2};
    const double span = y_hi - y_lo;
    double f;
    if (k < 10000L) {
        f = level[k / 2000L];
    } else {
        const long p = (k - 10000L) % 1000L;
        f = p < 500L ? 0.2 + 0.6 * (double)p / 500.0 : 0.8 - 0.6 * (double)(p - 500L) / 500.0;
    }
    return y_lo + f * span;
}

int main(void)
{
    static const hyst_wide_t taus[] = {500.0, 1000.0, 2000.0, 5000.0, 10000.0};
    const hyst_wide_t plant_tau[2] = {PLANT_TAU, 300.0}, plant_w[2] = {PLANT_W, 0.002};
    hyst_creep_holdout_t best, h;
    hyst_wide_t tau = 0;
    double y_lo, y_hi, ss[3] = {0.0, 0.0, 0.0}, worst[3] = {0.0, 0.0, 0.0}, rms[2];
    long k;
    int way, ok, restored = 0;
    size_t i;
    hyst_port_init();
    if (HYST_INIT(plant_h, &eq20) != HYST_OK || HYST_INIT(model_h, &eq20) != HYST_OK ||
        HYST_INIT_INVERSE(comp, &eq20) != HYST_OK ||
        hyst_creep_init(&plant_c, 2u, plant_tau, plant_w, 0) != HYST_OK) {
        (void)printf("creep_compensation: init failed\n");
        return 1;
    }
    /* identification: the plant's record and the hysteresis model's residual */
    for (k = 0; k < ID_SAMPLES; ++k) {
        const hyst_real_t x = id_drive(k);
        id_u[k] = (hyst_wide_t)x;
        id_r[k] = (hyst_wide_t)(plant_step(x) + noise() - (double)hyst_step(&model_h, x));
    }
    best.holdout_rms = -1;
    for (i = 0u; i < sizeof taus / sizeof taus[0]; ++i) {
        if (hyst_creep_fit_holdout(1u, &taus[i], 0, id_u, id_r, (size_t)ID_SAMPLES,
                                   (size_t)(2L * ID_SAMPLES / 3L), &h) == HYST_OK &&
            (best.holdout_rms < 0 || h.holdout_rms < best.holdout_rms)) {
            best = h;
            tau = taus[i];
        }
    }
    if (!(tau > 0) || hyst_creep_init(&comp_c, 1u, &tau, best.weight, 0) != HYST_OK) {
        (void)printf("creep_compensation: no creep term could be fitted\n");
        return 1;
    }
    (void)printf("identified: tau %g samples, weight %.5f um/V, offset %.2g (plant: %g, %g)\n",
                 (double)tau, (double)best.weight[0], (double)best.offset, PLANT_TAU, PLANT_W);
    y_lo = (double)hyst_poly_eval(&eq20, eq20.lo);
    y_hi = (double)hyst_poly_eval(&eq20, eq20.hi);
    /* tracking: (a) the hysteresis compensator alone, (b) with the creep's share taken off,
     * (c) as (b) through a brown-out */
    for (way = 0; way < 3; ++way) {
        hyst_reset(&plant_h);
        hyst_reset(&comp);
        (void)hyst_creep_reset(&plant_c, 0);
        (void)hyst_creep_reset(&comp_c, 0);
        for (k = 0; k < RUN_SAMPLES; ++k) {
            const double yd = reference(k, y_lo, y_hi);
            double c, e;
            hyst_real_t x;
            if (way == 2 && k == RUN_SAMPLES / 2L) {
                restored = brown_out() == 0;
            }
            c = way > 0 ? (double)hyst_creep_output(&comp_c) : 0.0;
            x = hyst_step(&comp, (hyst_real_t)(yd - c));
            e = plant_step(x) - yd;
            if (way > 0) {
                (void)hyst_creep_step(&comp_c, x);
            }
            ss[way] += e * e;
            worst[way] = e < 0 ? (-e > worst[way] ? -e : worst[way]) : (e > worst[way] ? e : worst[way]);
        }
        if (way < 2) {
            rms[way] = ss[way] / (double)RUN_SAMPLES;
        }
    }
    for (way = 0; way < 2; ++way) {
        double r = rms[way], s = r > 0 ? r : 0; /* square root by Newton: no libm on the target */
        for (i = 0u; i < 60u && s > 0; ++i) {
            s = 0.5 * (s + r / s);
        }
        rms[way] = s;
        (void)printf("%s: RMS %.4f um, max %.4f um (stroke %.2f um)\n",
                     way == 0 ? "hysteresis compensator alone" : "with creep compensation",
                     rms[way], worst[way], y_hi - y_lo);
    }
    (void)printf("through a brown-out at sample %ld (snapshots of %lu + %lu octets): %s\n",
                 RUN_SAMPLES / 2L, (unsigned long)len, (unsigned long)creep_len,
                 restored && ss[2] == ss[1] && worst[2] == worst[1] ? "the same tracking, bit for bit"
                                                                    : "FAILED");
    ok = tau == plant_tau[0] && rms[1] * 5.0 <= rms[0] && restored && ss[2] == ss[1] &&
         worst[2] == worst[1];
    (void)printf("creep compensation cuts the RMS tracking error %.1f-fold: %s\n",
                 rms[1] > 0 ? rms[0] / rms[1] : 0.0, ok ? "ok" : "FAILED");
    return ok ? 0 : 1;
}
