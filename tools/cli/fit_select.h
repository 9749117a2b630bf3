/* SPDX-License-Identifier: MIT */
/* Model selection for `hyst fit` without --degree (fit_select.c). */
#ifndef HYST_CLI_FIT_SELECT_H
#define HYST_CLI_FIT_SELECT_H

#include "hyst/hyst.h"

#include <stddef.h>

/* Delays tried when --delay is not given: 0 .. FIT_MAX_DELAY samples. */
#define FIT_MAX_DELAY 8u

/* A drive's period in samples over this is searched for delays up to period /
 * FIT_DELAY_PERIOD_FRACTION (at least FIT_MAX_DELAY, at most FIT_MAX_SCALED_DELAY):
 * first with one cheap model at every delay, then every candidate at the
 * delays next to the best. */
#define FIT_DELAY_PERIOD_FRACTION 64u
#define FIT_MAX_SCALED_DELAY 1000u
/* Fractions of a sample tried after the choice (sub-sample delay), at the
 * chosen delay and one below: 1/FIT_FRACTIONS steps. */
#define FIT_FRACTIONS 4u

/* A model at a sub-sample delay enters the comparison when it lowers the
 * hold-out error of the same model at its best whole delay by more than
 * this fraction: the fractions add many options (each candidate at each),
 * whose best is biased low by the hold-out's noise. It then counts one
 * parameter more (the fraction is chosen on the data too): a model that
 * takes a half-sample misalignment in as loop shape does not win over the
 * plant's own model at the plant's delay by it. */
#define FIT_FRACTION_GAIN 0.05
/* Parameters a sub-sample delay adds: its fraction. */
#define FIT_FRACTION_PARAMETERS 1u

/* Hold-out splits every candidate is scored on: the last third predicted by
 * the model fitted on the first two thirds, then the middle third by the
 * model fitted on the first and the last (the fit takes the middle's inputs
 * in without their outputs, so its turning points are the record's), the
 * model run from rest at the start each time; the score is the root of their
 * mean square. One split alone lets a record's last third decide (its drift,
 * or inputs beyond the part fitted: a delay that suits the extrapolation is
 * chosen, wrong at other rates). A third split, the first third, is
 * implemented but not used: a creep term's weight is not determined without
 * the lag's rise from rest that it holds out. */
#define FIT_SPLITS 2
/* Fewer samples than this in a third: the last third alone is scored. */
#define FIT_SPLIT_MIN 100u

/* Delays around the cheap search's best at which every candidate is fitted. */
#define FIT_DELAY_AROUND 4u

/* Parameters a creep term adds: its weight and its time constant (chosen
 * from a series, but chosen on the data all the same). */
#define FIT_CREEP_PARAMETERS 2u

/* A candidate within this fraction of the lowest hold-out error counts as
 * as good: the fewest parameters among them win. */
#define FIT_PARSIMONY 0.01

/* Hold-out errors below this fraction of the output's range are all as good
 * as exact and count as that resolution: a record computed by a model is
 * fitted down to its own rounding (float: 4e-8 of the largest output;
 * nine printed digits: 3e-10), where FIT_PARSIMONY would compare digits of
 * rounding and keep terms the plant lacks. No sensor resolves a millionth
 * of its range. */
#define FIT_RESOLUTION 1e-6

/* Two hold-out errors this close (a fraction of the larger) differ only in
 * rounding: between as many parameters of the same kind's preference, the
 * widened candidate wins then (it predicts where the other clamps), not the
 * last digits. */
#define FIT_TIE 1e-9

/* The asymmetric kind is also fitted on a domain wider than the inputs' range
 * by this fraction of the range on each side: E continued beyond the inputs
 * it was identified on (monotone on the whole wider triangle, as the library
 * requires), so later inputs outside that range are predicted, not clamped. */
#define FIT_WIDEN 1.0

/* A second record of the same actuator the choice is scored on instead of
 * the hold-out splits (validation data, `hyst fit --validate OTHER`): each
 * candidate fitted on the whole record (after its skip), then run from rest
 * at row skip of this one over every row after it, scored by its RMS error
 * there. x is not const: fit_search() and fit_given_delay() interpolate it
 * in place with the record's own drive when they choose a sub-sample delay.
 * NULL everywhere a function takes one: the hold-out splits. */
typedef struct fit_validation {
    double *x;       /* its inputs */
    const double *y; /* its outputs */
    size_t n;        /* rows */
    size_t skip;     /* rows before the model starts from rest */
} fit_validation_t;

/* FIT_RESOLUTION of the range of the finite outputs a candidate at `delay`
 * is scored on (0 if none): v's from its skip + delay, or (v NULL) those of
 * the record y[skip + delay .. n). */
double fit_resolution(const double *y, size_t n, size_t skip, size_t delay,
                      const fit_validation_t *v);

/* The first finite entry of x[from .. to) (NaN if none): the record's first
 * input, a missing one (NaN) skipped. */
double fit_first_input(const double *x, size_t from, size_t to);

/* The domain of a widened candidate from the range [lo, hi] of the inputs
 * fitted: FIT_WIDEN of it on each side, but lo kept when the record's first
 * input `first` is within 1 % of the range of it (the model starts at rest
 * at its domain's lo: a record that starts at its lowest input starts
 * there, not lower). */
void fit_widened_domain(double lo, double hi, double first, double *wide_lo, double *wide_hi);


/* Kinds of model a candidate may be (see below); FIT_CANDIDATES_PER_DELAY:
 * the most fit_select() adds at one delay (poly, everett and spline ones also
 * widened). */
#define FIT_CANDIDATES_PER_DELAY                                                             \
    (2u * (HYST_MAX_DEGREE + FIT_EVERETT_CANDIDATES + FIT_SPLINE_CANDIDATES) + FIT_GRID_CANDIDATES)

/* Kinds of model a candidate may be (a mask for fit_select()): the
 * symmetric TCM's polynomial f0, the asymmetric kind's E, E on a grid and
 * the symmetric TCM's f0 a cubic spline. */
enum { FIT_POLY = 1, FIT_EVERETT = 2, FIT_GRID = 4, FIT_SPLINE = 8 };

/* Grid candidates of each delay (FIT_GRID, the asymmetric kind on a grid):
 * FIT_GRID_INTERVALS(i) knot intervals, i < FIT_GRID_CANDIDATES (the
 * candidate's degree is its number of intervals). */
#define FIT_GRID_CANDIDATES 2u
#define FIT_GRID_INTERVALS(i) (4u + 2u * (i))

/* Spline candidates of each delay (FIT_SPLINE, f0 a cubic spline on uniform
 * knots): FIT_SPLINE_INTERVALS(i) knot intervals, i < FIT_SPLINE_CANDIDATES
 * (the candidate's degree is its number of intervals): 2..16. */
#define FIT_SPLINE_CANDIDATES 15u
#define FIT_SPLINE_INTERVALS(i) (2u + (i))

/* fit_select(): every t-degree of each everett degree. */
#define FIT_ANY_T_DEGREE 99u

/* Everett candidates of each delay: (degree d, t-degree 0..d - 1), d = 1..4. */
#define FIT_EVERETT_CANDIDATES (HYST_EVERETT_MAX_DEGREE * (HYST_EVERETT_MAX_DEGREE + 1u) / 2u)

/* The creep term of a candidate (fit_creep.c): one lag of time constant
 * tau samples (0: none), its weight and the offset it needs, fitted on the
 * training part of the model's residual; the model with it scored on the
 * hold-out part (NaN: not scored). */
typedef struct fit_creep {
    double tau, weight, offset;
    double holdout_rms, fit_rms;
    double max_abs; /* the largest error of the model with it, over every sample */
    double last_third_rms; /* its hold-out on the last third alone (split 0) */
    /* a rate term fitted with it (hyst/rate.h; rate_tau 0: none): on entry
     * to the hold-out, its time constant (tau 0 then: no creep lag, the
     * rate term alone); its weight fitted with the lag's and the offset */
    double rate_tau, rate_weight;
} fit_creep_t;

/* The creep lags' states of the series (fit_creep_score()) over one run's
 * inputs from one rest, kept for the next run that takes the same inputs
 * from the same rest, as most candidates of a delay do: FIT_LAG_RUNS runs,
 * the one used longest ago replaced, while they fit in FIT_LAG_BYTES
 * (records of up to about 460 000 samples; longer ones compute them for
 * each run). Zeroed before use, then fit_lags_free(). */
#define FIT_LAG_RUNS 4u
#define FIT_LAG_BYTES (128u * 1024u * 1024u)
typedef struct fit_lag_run {
    double *u;          /* the inputs (a copy), NULL: none kept */
    double *s;          /* the states, the series' lags side by side */
    size_t len;
    double x_rest;
    unsigned long used; /* when last used: the one with the lowest goes */
} fit_lag_run_t;
typedef struct fit_lags {
    fit_lag_run_t run[FIT_LAG_RUNS];
    unsigned long clock;
} fit_lags_t;

/* Frees the runs *lags keeps (zeroed after). */
void fit_lags_free(fit_lags_t *lags);

/* The creep on a model's run: u[k] its inputs, r[k] the measurement minus
 * its prediction (NaN where missing), k < len; fitted on k < train, scored
 * on the rest. tau > 0: that time constant; 0: each of a 1-2-5 series from
 * 100 samples up to len, the lowest hold-out error into *best (its tau 0
 * if none could be fitted, e.g. train == len leaves no hold-out). */
void fit_creep_score(const double *u, const double *r, size_t len, size_t train, double x_rest,
                     double tau, fit_creep_t *best);

/* fit_creep_score() on a part held out inside the run: fitted on [0, len)
 * but [from, to) (the lags fed through it), scored on [from, to) from
 * score_from on; the series' states kept in lags (may be NULL). */
void fit_creep_score_part(const double *u, const double *r, size_t len, size_t from, size_t to,
                          size_t score_from, double x_rest, double tau, fit_lags_t *lags,
                          fit_creep_t *best);

/* The rate term with the creep lag (creep_tau > 0) or alone (0), on a part
 * held out as fit_creep_score_part(): their weights and the offset by least
 * squares on the residual outside [from, to), the terms run from rest,
 * scored on [from, to) from score_from on (into *out; holdout_rms NaN when
 * the weights are not determined). */
void fit_terms_part(const double *u, const double *r, size_t len, size_t from, size_t to,
                    size_t score_from, double x_rest, double creep_tau, double rate_tau,
                    fit_creep_t *out);

/* The creep lag (creep_tau > 0; 0: each of the series, the best on the
 * other record) or the rate term with it or alone (rate_tau > 0, as
 * fit_terms_part()), fitted on the whole residual r[0 .. len) of a model's
 * run over the record fitted (u its inputs as the model took them), then
 * run from rest over another record's run (u2, r2[0 .. len2)) and scored
 * there (out->holdout_rms, NaN if nothing could be fitted or scored). */
void fit_terms_other(const double *u, const double *r, size_t len, const double *u2,
                     const double *r2, size_t len2, double x_rest, double creep_tau,
                     double rate_tau, fit_creep_t *out);

/* Parameters a rate term adds: its weight and its time constant. */
#define FIT_RATE_PARAMETERS 2u
/* Time constants a rate term is tried at: 1 sample, and 1/256 and 1/64 of
 * the drive's period (fit_rate_taus()). */
#define FIT_RATE_TAUS 3u

/* The rate term's time constants for the drive x[from .. to) into taus
 * (FIT_RATE_TAUS at most, increasing, each >= 1): their count. */
size_t fit_rate_taus(const double *x, size_t from, size_t to, double *taus);

/* The first sample of x[from .. to) within 1 % of the range of an end of
 * that range: where a model run from rest has the record's own state
 * whatever came before (an extreme wipes the rest out); from itself when
 * that sample lies beyond the first third (or there is none). */
size_t fit_settled(const double *x, size_t from, size_t to);

typedef struct fit_candidate {
    int kind;                 /* FIT_POLY, FIT_EVERETT, FIT_GRID or FIT_SPLINE */
    unsigned degree;
    unsigned t_degree;        /* everett: the highest power of t fitted (< degree) */
    size_t delay;
    double fraction;          /* a sub-sample delay's fraction of a sample (0: a whole delay) */
    int widened;              /* poly, everett, spline: its domain the inputs' range widened
                               * by FIT_WIDEN (fit_select()) */
    hyst_status_t status;     /* of the training fit (everett: or of its curve) */
    hyst_ident_result_t fit;  /* poly: on the first two thirds */
    double fit_rms;           /* residual of the training fit (poly: fit.rms) */
    double holdout_rms;       /* model's RMS error over the FIT_SPLITS; NaN: not scored */
    double last_third_rms;    /* on the last third alone (split 0) */
    fit_creep_t creep;        /* the model with a creep term (creep.tau 0: none) */
} fit_candidate_t;

/* The asymmetric kind fitted on a record (fit_everett.c). */
typedef struct fit_everett_result {
    hyst_everett_t e;
    hyst_everett_grid_t grid;   /* FIT_GRID: its grid (e unused) */
    hyst_spline_t spline;       /* FIT_SPLINE: its f0 (e unused) */
    hyst_status_t curve_status; /* the library's curve of it (fit_result_curve()) */
    double rms, max_abs;        /* the model run over the samples fitted (NaN if refused) */
    double ls_rms;              /* the least-squares residual (hyst_everett_fit_solve()) */
    size_t used;                /* samples fitted */
    int determined;             /* FIT_GRID: the record determines every mass
                                   (hyst_everett_grid_fit_determined()) */
} fit_everett_result_t;

/* The longest delay worth searching for a drive x[from .. to): a fraction
 * of its period (from its reversals, moves below 1 % of its range ignored). */
size_t fit_max_delay(const double *x, size_t from, size_t to);

/* Reversals of the drive x[from .. to) (moves back from an extreme by less
 * than 1 % of [lo, hi] ignored): the count, and into *inner those whose
 * extreme lies more than 2 % of [lo, hi] inside it (the turning points of
 * minor loops). */
size_t fit_reversals(const double *x, size_t from, size_t to, double lo, double hi,
                     size_t *inner);

/* A hold-out part whose inputs span less than this fraction of the record's
 * range is warned about: the choice was not tested over the rest. */
#define FIT_HOLDOUT_MIN_SPAN 0.5

/* What the hold-out's last third tests a choice on (fit_holdout_excitation()): the
 * front ends print it, and warn when it spans less than
 * FIT_HOLDOUT_MIN_SPAN of the record's range or holds no minor loop. */
typedef struct fit_excitation {
    double fitted_lo, fitted_hi; /* the range of the first two thirds' inputs */
    size_t holdout_n;            /* samples in the last third */
    size_t beyond;               /* of them, inputs outside [fitted_lo, fitted_hi] */
    double span;                 /* the last third's input range over the record's */
    size_t minor;                /* its reversals inside the record's range (minor loops) */
    double noise;                /* its outputs' noise floor (fit_noise_floor()); NaN: none */
} fit_excitation_t;

/* The excitation of the inputs x[skip .. end) split as the hold-out splits
 * them (the first two thirds fitted, the last third scored), the output of
 * input k being y[k + delay]. */
void fit_holdout_excitation(const double *x, const double *y, size_t skip, size_t end,
                            size_t delay, fit_excitation_t *e);

/* The same for a validation record v (the output `delay` rows after the
 * input): fitted_lo, fitted_hi the range of x[skip .. end), the record
 * fitted; holdout_n v's rows scored, beyond those outside that range, span
 * their range over it, minor v's reversals inside it, noise its outputs'. */
void fit_validation_excitation(const double *x, size_t skip, size_t end,
                               const fit_validation_t *v, size_t delay, fit_excitation_t *e);

/* fit_noise_floor(): its estimates of order 3 and 4 agree within this fraction. */
#define FIT_NOISE_AGREE 0.05

/* The white noise of the outputs y[from .. to), as an RMS, estimated without
 * a model (the output of the drive's x[k] being y[k + delay], x of nx
 * samples): for white noise of deviation s the k-th difference of the
 * samples has mean square C(2k, k) s^2, while a signal sampled finely enough
 * cancels in it; the differences whose samples answer a turn of the drive
 * (where the output's slope jumps) are left out. The order 4 estimate where
 * the order 3 one agrees with it within FIT_NOISE_AGREE; NaN where it does
 * not (a record sampled too coarsely to tell its noise from its signal) or no
 * difference is left. No prediction of those outputs from the drive scores
 * below it, the noise being independent of it. */
double fit_noise_floor(const double *x, size_t nx, const double *y, size_t from, size_t to,
                       size_t delay);

/* The delay in [0, max_delay] at which the cheap model (f0 of degree 3 on
 * base's skip and domain, no creep) predicts the hold-out (or v) best. */
size_t fit_cheap_delay(const hyst_ident_config_t *base, const double *x, const double *y,
                       size_t n, const fit_validation_t *v, size_t max_delay);

/* The range of the finite entries of x[from .. to) widened by `widen` times
 * it on each side (NaN if none is finite). */
void fit_input_range(const double *x, size_t from, size_t to, double widen, double *lo,
                     double *hi);

/* Real numbers a model of this kind and degree identifies: poly the
 * degree + 1 coefficients, everett E's terms w^i t^j with j <= t_degree
 * and y_lo (t_degree ignored for the other kinds), everett_grid of degree K
 * intervals y_lo, the cells' masses and the inner knots, spline of K
 * intervals y_lo and its K + 2 weights (K + 3). */
unsigned fit_parameters(int kind, unsigned degree, unsigned t_degree);

/* The name of a candidate's kind (FIT_POLY, FIT_EVERETT, FIT_GRID or
 * FIT_SPLINE) in a model file's key `kind`: "poly", "everett",
 * "everett_grid" or "spline". */
const char *fit_kind_name(int kind);

/* The TCM (f0, or when f0 is NULL the prepared curve) run from rest over
 * x[skip .. n - delay) against y[k + delay]: the RMS error over the samples
 * from index `from` on (returned; NaN if none, or if the model cannot run),
 * over those before it (*before_rms, may be NULL) and the largest error of
 * all (*max_abs, may be NULL). */
double fit_model_run(const hyst_poly_t *f0, const hyst_curve_t *curve, const double *x,
                     const double *y, size_t n, size_t skip, size_t delay, size_t from,
                     double *before_rms, double *max_abs);

/* fit_model_run() and, creep not NULL, the creep term fitted to its residual
 * on the samples before `from` and scored after (fit_creep_score(); creep->tau
 * on entry: the time constant, 0 to choose one). */
double fit_model_run_creep(const hyst_poly_t *f0, const hyst_curve_t *curve, const double *x,
                           const double *y, size_t n, size_t skip, size_t delay, size_t from,
                           double *before_rms, double *max_abs, fit_creep_t *creep);

/* The TCM of cfg (degree, delay, skip...) scored on the FIT_SPLITS (fitted
 * on the rest of the record, run over all of it from rest): the root of
 * the mean square of its RMS errors (NaN if a fit failed, *status, or f0 is
 * not increasing), *fit the training fit of the last third's split, and
 * *last_third (may be NULL) its error on that third alone; creep (may be
 * NULL): as fit_model_run_creep(), on the same splits. */
double fit_tcm_holdout(const hyst_ident_config_t *cfg, const double *x, const double *y,
                       size_t n, hyst_status_t *status, hyst_ident_result_t *fit,
                       fit_creep_t *creep, double *last_third);

/* E of degree cfg->degree, its terms w^i t^j with j <= t_degree, fitted to x[k] with y[k + delay], skip <= k <
 * n - delay (the model from rest at sample skip), on [cfg->lo, cfg->hi]
 * (samples outside ignored), or the range of those inputs when lo == hi;
 * then the curve checked and, if the library accepts it, the model run over
 * the same samples (res->rms, max_abs). HYST_OK, or the fit's status. */
hyst_status_t fit_everett_record(const hyst_ident_config_t *cfg, unsigned t_degree,
                                 const double *x, const double *y, size_t n,
                                 fit_everett_result_t *res);

/* E of t-degree 0 (no term of t) is the symmetric model: its f0, in powers
 * of x, is y_lo + sum e[i-1][0] ((x - lo) / (hi - lo))^i on [lo, hi]
 * (docs/identification.md). Into *f0 and 1 when E has no term of t, the
 * expansion agrees with that sum within FIT_POLY_AGREEMENT of f0's span at
 * FIT_POLY_CHECK_POINTS + 1 points of the domain (powers of x far from 0
 * cancel) and f0 increases; else 0 and *f0 untouched. */
#define FIT_POLY_CHECK_POINTS 64u
#define FIT_POLY_AGREEMENT 1e-9
int fit_poly_from_everett(const hyst_everett_t *e, hyst_poly_t *f0);

/* x[i] with y[i] (i < n) added to an everett fit started from rest at x[0],
 * as the front ends fit E (Python's fit(kind="everett"), Octave's
 * hyst_fit): each input clamped to [lo, hi] as the model clamps it, the
 * outputs fitted from fit_settled() on (before it the model's state is not
 * the record's: those inputs move the fit's turning points only). *used
 * the rows added. HYST_OK, or HYST_ERR_NOSPACE (the fit's workspace holds
 * fewer turning points than the record stacks). */
hyst_status_t fit_everett_add_clamped(hyst_everett_fit_t *fit, const double *x, const double *y,
                                      size_t n, double lo, double hi, size_t *used);

/* The asymmetric kind on a grid of k knot intervals fitted as
 * fit_everett_record() fits E (fit_grid.c): the knots where the output
 * steps, refined; res->grid, its curve's status, the model's run. */
hyst_status_t fit_grid_record(const hyst_ident_config_t *cfg, unsigned k, const double *x,
                              const double *y, size_t n, fit_everett_result_t *res);

/* The symmetric TCM with f0 a monotone cubic spline of k uniform knot
 * intervals (fit_spline.c): f0 fitted by hyst_spline_fit_*() to x[i] with
 * y[i + delay], skip <= i < n - delay, along every branch of the record
 * (minor loops included; outputs from fit_settled() on, the model from rest
 * at sample skip, as 'hyst sim --model' runs it), on [cfg->lo, cfg->hi]
 * (samples outside ignored) or the range of those inputs when lo == hi;
 * res->spline, its curve's status (hyst_f64_curve_from_spline()), the
 * model's run over the same samples (res->rms, max_abs), res->ls_rms and
 * res->used. HYST_OK, or the fit's status (HYST_ERR_ARG: no sample or k
 * outside 1..HYST_SPLINE_MAX_INTERVALS; HYST_ERR_DOMAIN: the inputs span
 * no range). */
hyst_status_t fit_spline_record(const hyst_ident_config_t *cfg, unsigned k, const double *x,
                                const double *y, size_t n, fit_everett_result_t *res);

/* The prepared curve of a fitted result of kind FIT_EVERETT (ev->e),
 * FIT_GRID (ev->grid) or FIT_SPLINE (ev->spline), as the library's
 * constructor answers; a grid's or a spline's table is static, one per
 * kind: the curve holds until the next call for its kind. */
hyst_status_t fit_result_curve(int kind, const fit_everett_result_t *ev, hyst_curve_t *curve);

/* A fit of x[k] with y[k + delay], skip <= k < n - delay (cfg: skip, delay,
 * domain), begun: *res cleared (rms and max_abs NaN, curve_status
 * HYST_ERR_ARG) and [*lo, *hi] the domain, cfg's or the range of those
 * inputs when it is empty. HYST_OK, or HYST_ERR_ARG (no sample). */
hyst_status_t fit_record_start(const hyst_ident_config_t *cfg, const double *x, size_t n,
                               fit_everett_result_t *res, double *lo, double *hi);

/* The same fit ended, st the fit's status: st when it failed (but
 * HYST_ERR_NOT_MONOTONE, a fit returned all the same), else HYST_OK with
 * res->curve_status fit_result_curve()'s and, if the library accepts the
 * curve, the model run from rest over the samples fitted (res->rms,
 * res->max_abs). */
hyst_status_t fit_record_finish(int kind, const hyst_ident_config_t *cfg, const double *x,
                                const double *y, size_t n, hyst_status_t st,
                                fit_everett_result_t *res);

/* What the front ends say of a grid whose masses the record does not
 * determine (fit_everett_result_t's determined 0). */
extern const char fit_grid_undetermined[];

/* fit_tcm_holdout() for the asymmetric kind: NaN if the fit failed or the
 * library refused E (*status says which). */
double fit_everett_holdout(const hyst_ident_config_t *cfg, unsigned t_degree, const double *x,
                           const double *y, size_t n, hyst_status_t *status,
                           fit_everett_result_t *fit, fit_creep_t *creep, double *last_third);

/* The same for the asymmetric kind on a grid of cfg->degree intervals. */
double fit_grid_holdout(const hyst_ident_config_t *cfg, const double *x, const double *y,
                        size_t n, hyst_status_t *status, fit_everett_result_t *fit,
                        fit_creep_t *creep, double *last_third);

/* The same for the PI model of cfg (operators, skip, delay; the thresholds
 * uniform over the training part's inputs unless given): r, w its N
 * thresholds and weights. NaN if the fit failed (*status) or its weights
 * have w1 = 0, which hyst_pi_init() refuses. */
double fit_pi_holdout(const hyst_pi_fit_config_t *cfg, const double *x, const double *y,
                      size_t n, hyst_status_t *status, hyst_pi_fit_result_t *fit, double *r,
                      double *w);

/* Candidate c (kind, degree, t_degree, delay, widened set) fitted on the
 * first two thirds of x, y (base: method, domain, skip) and scored on the
 * last third (the hold-out splits; v not NULL: fitted on the whole of x, y
 * and scored on v, c->holdout_rms its RMS error there, last_third_rms NaN);
 * with a creep term too unless creep_tau < 0 (0: its time constant chosen). */
void fit_score(const hyst_ident_config_t *base, const double *x, const double *y, size_t n,
               const fit_validation_t *v, double creep_tau, fit_candidate_t *c);

/* The drive a fraction f of a sample later, into xf: (1 - f) x[k] + f x[k - 1]
 * (xf[0] = x[0]); xf may be x (done in place). */
void fit_delay_fraction(const double *x, size_t n, double f, double *xf);

/* A candidate's two options: the model alone, or with its creep term
 * (with_creep): the hold-out RMS (NaN: not scored) and the parameters (the
 * creep term's weight and time constant are FIT_CREEP_PARAMETERS more). */
double fit_option_rms(const fit_candidate_t *c, int with_creep);
unsigned fit_option_parameters(const fit_candidate_t *c, int with_creep);
/* The option's hold-out on the last third alone (what PI-10 is compared on). */
double fit_option_last_third(const fit_candidate_t *c, int with_creep);

/* The domain candidate c is fitted on over the whole record x[skip .. n)
 * once chosen, into *lo, *hi when it is a widened one (returns 1; 0 and
 * nothing written otherwise): the inputs' range, fit_widened_domain(). */
int fit_chosen_domain(const fit_candidate_t *c, const double *x, size_t skip, size_t n,
                      double *lo, double *hi);

/* Fits each kind of the mask `kinds` (poly degree 1..HYST_MAX_DEGREE,
 * everett degree 1..HYST_EVERETT_MAX_DEGREE with each t-degree 0..degree - 1;
 * everett_degree, when not 0, the only everett degree, t_degree, when not
 * FIT_ANY_T_DEGREE, the only t-degree; max_parameters, when not 0, the
 * most a model may have, fit_parameters(): the others are not fitted) at
 * each delay from base->delay to max_delay (base: method, domain, skip)
 * into cand[0..max_cand), each also
 * with a creep term unless creep_tau < 0 (0: its time constant chosen,
 * fit_creep_score()); returns the count, *best the index chosen and
 * *with_creep its option: the fewest parameters within FIT_PARSIMONY of the
 * lowest hold-out RMS of all options; between as many parameters the
 * symmetric kind (its compensator is a table, the asymmetric kind's
 * solves), then the lower RMS, the widened one at a tie (FIT_TIE)
 * ((size_t)-1: none could be scored). */
size_t fit_select(const hyst_ident_config_t *base, int kinds, unsigned everett_degree,
                  unsigned t_degree, unsigned max_parameters, double creep_tau, const double *x, const double *y,
                  size_t n, const fit_validation_t *v, size_t max_delay,
                  fit_candidate_t *cand, size_t max_cand, size_t *best, int *with_creep);

/* The choice among cand[0..count) (scored), as fit_select() makes it:
 * *best ((size_t)-1: none scored) and *with_creep its option; creep_tau < 0
 * compares the candidates alone, > 0 with their creep terms only, 0 both. */
void fit_choose(const fit_candidate_t *cand, size_t count, double creep_tau, size_t *best,
                int *with_creep);

/* The automatic choice as `hyst fit` without --degree, Python's
 * fit(degree=None) and Octave's hyst_fit make it (fit_search()). */
typedef struct fit_found {
    size_t max_delay;       /* choose_delay: delays searched 0..max_delay (fit_max_delay()) */
    size_t cheap_delay;     /* max_delay > FIT_MAX_DELAY: f0 of degree 3's best delay */
    size_t count;           /* candidates scored into cand[] */
    size_t best;            /* the choice ((size_t)-1: none) */
    int with_creep;         /* chosen with its creep term */
    double delay_fraction;  /* the sub-sample delay's fraction (0: none) */
    size_t integer_delay;   /* the choice's whole delay (before its fraction) */
    double integer_holdout; /* the chosen model's hold-out error there */
} fit_found_t;

/* Candidates fit_search() may score: every one of a delay, at the
 * FIT_MAX_DELAY + 1 = 2 FIT_DELAY_AROUND + 1 delays searched alike. */
#define FIT_SEARCH_CANDIDATES (FIT_CANDIDATES_PER_DELAY * (FIT_MAX_DELAY + 1u))

/* fit_select() of the kinds, each t-degree or t_degree, on cand[0..max_cand),
 * at base->delay only, or with choose_delay at delays scaled to the drive
 * (0..fit_max_delay(); beyond FIT_MAX_DELAY, f0 of degree 3 at each, then
 * every candidate at FIT_DELAY_AROUND each side of its best), then at a
 * fraction of a sample (1/FIT_FRACTIONS steps, at the chosen delay and one
 * below): each model there more than FIT_FRACTION_GAIN better than at its
 * best whole delay joins the whole delays' candidates, with one parameter
 * more, and fit_choose()'s rule picks among them all; a model at a fraction
 * replaces the same model at its whole delay in cand (x then the drive
 * interpolated, in place, as the model file's delay makes sim interpolate
 * it, and v's x too). Every candidate scored on the hold-out splits, or (v not NULL) on
 * v (fit_score()). HYST_OK, or HYST_ERR_NOSPACE (out of memory). */
hyst_status_t fit_search(const hyst_ident_config_t *base, int kinds, unsigned t_degree,
                         double creep_tau, int choose_delay, double *x, const double *y,
                         size_t n, const fit_validation_t *v, fit_candidate_t *cand,
                         size_t max_cand, fit_found_t *out);

/* A model of one kind and degree (base->degree; t_degree: everett's), no
 * creep term: its delay by the same hold-out, each whole delay up to
 * fit_max_delay() (a single model each), then a fraction of a sample at the
 * best and one below, kept when more than FIT_FRACTION_GAIN better (x then
 * the drive interpolated in place, and v's x). *delay the whole delay
 * chosen (0 when nothing could be scored); out's max_delay, integer_delay,
 * integer_holdout and delay_fraction set, its best (size_t)-1. Scored on v
 * instead of the hold-out when v is not NULL. HYST_OK, or HYST_ERR_NOSPACE
 * (out of memory). */
hyst_status_t fit_given_delay(const hyst_ident_config_t *base, int kind, unsigned t_degree,
                              double *x, const double *y, size_t n, const fit_validation_t *v,
                              size_t *delay, fit_found_t *out);

/* The chosen candidate (kind, degree, delay, its creep option) scored again
 * with a rate term of each of fit_rate_taus() (rate_tau 0; > 0: that time
 * constant alone; < 0: none), its weight fitted with the creep lag's on the
 * same hold-out splits: 1 when the best of them errs less than the choice by
 * more than FIT_PARSIMONY, or rate_tau > 0 and it could be scored (*out the
 * candidate with it: out->creep holds the terms and their hold-out), else 0
 * (*out the best tried, its creep.rate_tau 0 if none could be scored). */
int fit_rate_search(const hyst_ident_config_t *base, const double *x, const double *y, size_t n,
                    const fit_validation_t *v, const fit_candidate_t *chosen, int with_creep,
                    double rate_tau, fit_candidate_t *out);

/* A response whose correlation with its drive is below this clearly falls
 * as the drive rises: every kind's branches rise with the input, so no
 * model fits it (a sensor of the opposite sign is the usual cause). */
#define FIT_FALLING_CORRELATION (-0.5)

/* What fit_record_check() finds wrong with a record: the first of these. */
enum {
    FIT_RECORD_OK = 0,
    FIT_RECORD_INFINITE_INPUT,  /* x[at] is infinite (NaN is a missing sample) */
    FIT_RECORD_INFINITE_OUTPUT, /* y[at] is */
    FIT_RECORD_NO_SAMPLE,       /* skip and delay leave no pair */
    FIT_RECORD_CONSTANT_INPUT,  /* the pairs' inputs, missing ones aside, one number or none */
    FIT_RECORD_CONSTANT_OUTPUT, /* their outputs alike */
    FIT_RECORD_FALLING          /* correlation below FIT_FALLING_CORRELATION */
};

/* A record as fit_record_check() finds it. */
typedef struct fit_record {
    int fault;          /* FIT_RECORD_OK, or what is wrong */
    size_t pairs;       /* (x[skip + i], y[skip + delay + i]), i < pairs */
    size_t at;          /* FIT_RECORD_INFINITE_*: the sample's index */
    double value;       /* infinite: the sample; constant: the number (NaN: every one missing) */
    double correlation; /* of the pairs with both samples (NaN: not determined) */
    size_t minor;       /* the pairs' drive's reversals inside its range (fit_reversals()) */
} fit_record_t;

/* The record x[0..nx), y[0..ny) as hyst fit, Python's fit() and Octave's
 * hyst_fit check it before fitting (x[skip + i] with y[skip + delay + i]; a
 * NaN sample is missing: skipped in the sums): into *r, its fault the first
 * of an infinite sample (x's, then y's), no pair left, a constant input, a
 * constant output, an output that falls as the input rises. Columns of
 * different lengths are checked for infinite samples only (the library
 * refuses them: HYST_ERR_ARG). Returns r->fault. */
int fit_record_check(const double *x, size_t nx, const double *y, size_t ny, size_t skip,
                     size_t delay, fit_record_t *r);

/* The fault's name as Python's and Octave's front ends take it: "ok",
 * "infinite_input", "infinite_output", "no_sample", "constant_input",
 * "constant_output" or "falling". */
const char *fit_record_fault_name(int fault);

#endif
