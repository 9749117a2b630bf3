/* SPDX-License-Identifier: MIT */
/* hyst fit without --degree: degree and delay chosen by hold-out. Each
 * candidate (degree, delay) is fitted on the first two thirds of the record,
 * then the model (the TCM in double, with that f0 and that delay) runs over
 * the whole record and is scored by its RMS prediction error on the last
 * third, which the fit never saw: a degree that fits noise predicts worse
 * there, so the criterion does not reward it. Of the candidates within
 * FIT_PARSIMONY of the lowest error, the one with the fewest parameters is
 * chosen: a gain below that is not worth a coefficient (between as many,
 * the symmetric kind: its compensator costs less). The candidates are
 * of both kinds, the symmetric TCM's f0 and the asymmetric kind's E (each
 * degree with each power of t up to it: major loops determine E linear in
 * t, not E of full degree 3 or 4), scored alike. */
#include "fit_select.h"

#include "cli.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void fit_input_range(const double *x, size_t from, size_t to, double widen, double *lo,
                     double *hi)
{
    size_t k;
    double a = INFINITY, b = -INFINITY;
    for (k = from; k < to; ++k) {
        if (isfinite(x[k])) { /* a missing (NaN) input is no end of the range */
            a = x[k] < a ? x[k] : a;
            b = x[k] > b ? x[k] : b;
        }
    }
    if (!(a <= b)) { /* no finite input in [from, to) */
        a = b = NAN;
    }
    *lo = a - widen * (b - a);
    *hi = b + widen * (b - a);
}

double fit_first_input(const double *x, size_t from, size_t to)
{
    for (; from < to; ++from) {
        if (isfinite(x[from])) {
            return x[from];
        }
    }
    return NAN;
}

double fit_resolution(const double *y, size_t n, size_t skip, size_t delay,
                      const fit_validation_t *v)
{
    double lo, hi;
    if (v != NULL) {
        fit_input_range(v->y, v->skip + delay, v->n, 0.0, &lo, &hi);
    } else {
        fit_input_range(y, skip + delay, n, 0.0, &lo, &hi);
    }
    return isfinite(hi - lo) ? FIT_RESOLUTION * (hi - lo) : 0.0;
}

/* A hold-out error as the choice compares it: e, or the resolution where e
 * is below it (NaN stays NaN). */
static double resolved(double e, double resolution)
{
    return e < resolution ? resolution : e;
}

void fit_widened_domain(double lo, double hi, double first, double *wide_lo, double *wide_hi)
{
    *wide_lo = first <= lo + 0.01 * (hi - lo) ? lo : lo - FIT_WIDEN * (hi - lo);
    *wide_hi = hi + FIT_WIDEN * (hi - lo);
}

int fit_chosen_domain(const fit_candidate_t *c, const double *x, size_t skip, size_t n,
                      double *lo, double *hi)
{
    double a, b;
    if (!c->widened || n <= skip + c->delay) {
        return 0;
    }
    fit_input_range(x, skip, n - c->delay, 0.0, &a, &b);
    fit_widened_domain(a, b, fit_first_input(x, skip, n - c->delay), lo, hi);
    return 1;
}

size_t fit_settled(const double *x, size_t from, size_t to)
{
    double lo, hi;
    size_t k;
    fit_input_range(x, from, to, 0.0, &lo, &hi);
    for (k = from; k < to; ++k) {
        if (x[k] <= lo + 0.01 * (hi - lo) || x[k] >= hi - 0.01 * (hi - lo)) {
            break;
        }
    }
    /* a later first extreme (excursions growing from a rest in the middle)
     * would leave most of the record unfitted: fitting the head instead
     * makes the model carry the branch from rest to the actuator's state */
    return k - from <= (to - from) / 3u ? k : from;
}

size_t fit_reversals(const double *x, size_t from, size_t to, double lo, double hi,
                     size_t *inner)
{
    const double step = 0.01 * (hi - lo), edge = 0.02 * (hi - lo);
    double ext;
    size_t k, count = 0u;
    int dir = 0;
    *inner = 0u;
    while (from < to && !isfinite(x[from])) { /* a missing input is no extreme */
        ++from;
    }
    if (to <= from) {
        return 0u;
    }
    ext = x[from];
    for (k = from + 1u; k < to; ++k) {
        if (dir >= 0 && x[k] > ext) {
            ext = x[k];
            dir = 1;
        } else if (dir <= 0 && x[k] < ext) {
            ext = x[k];
            dir = -1;
        } else if ((dir > 0 && x[k] < ext - step) || (dir < 0 && x[k] > ext + step)) {
            ++count;
            *inner += ext > lo + edge && ext < hi - edge ? 1u : 0u;
            dir = -dir;
            ext = x[k];
        }
    }
    return count;
}

/* Whether the drive x[0 .. n) turns (reverses, or starts or stops moving) at
 * an index in [lo, hi]: where the output's slope jumps. */
static int turns_within(const double *x, size_t n, size_t lo, size_t hi)
{
    size_t i;
    for (i = lo < 1u ? 1u : lo; i <= hi && i + 1u < n; ++i) {
        const double before = x[i] - x[i - 1u], after = x[i + 1u] - x[i];
        if (before * after <= 0.0 && (before != 0.0 || after != 0.0)) {
            return 1;
        }
    }
    return 0;
}

double fit_noise_floor(const double *x, size_t nx, const double *y, size_t from, size_t to,
                       size_t delay)
{
    /* the k-th differences' weights (k = 3, 4) and C(2k, k) */
    static const double weight[2][5] = {{-1.0, 3.0, -3.0, 1.0, 0.0}, {1.0, -4.0, 6.0, -4.0, 1.0}};
    static const double central[2] = {20.0, 70.0};
    double s[2];
    size_t order;
    for (order = 0u; order < 2u; ++order) {
        const size_t width = order + 4u; /* samples in a difference */
        double ss = 0.0;
        size_t used = 0u, k, j;
        for (k = from < delay + 1u ? delay + 1u : from; k + width <= to; ++k) {
            double d = 0.0;
            if (turns_within(x, nx, k - delay - 1u, k + width - delay)) {
                continue;
            }
            for (j = 0u; j < width; ++j) {
                d += weight[order][j] * y[k + j];
            }
            if (isfinite(d)) {
                ss += d * d;
                ++used;
            }
        }
        if (used == 0u) {
            return NAN;
        }
        s[order] = sqrt(ss / (double)used / central[order]);
    }
    return fabs(s[0] - s[1]) <= FIT_NOISE_AGREE * s[1] ? s[1] : NAN;
}

void fit_holdout_excitation(const double *x, const double *y, size_t skip, size_t end,
                            size_t delay, fit_excitation_t *e)
{
    const size_t train = end > skip ? (2u * (end - skip)) / 3u : 0u;
    double lo, hi, hold_lo, hold_hi;
    size_t k;
    memset(e, 0, sizeof *e);
    e->noise = NAN;
    if (end <= skip) {
        return;
    }
    e->noise = fit_noise_floor(x, end, y, skip + train + delay, end + delay, delay);
    fit_input_range(x, skip, skip + train, 0.0, &e->fitted_lo, &e->fitted_hi);
    e->holdout_n = end - skip - train;
    for (k = skip + train; k < end; ++k) {
        e->beyond += x[k] < e->fitted_lo || x[k] > e->fitted_hi ? 1u : 0u;
    }
    fit_input_range(x, skip, end, 0.0, &lo, &hi);
    fit_input_range(x, skip + train, end, 0.0, &hold_lo, &hold_hi);
    e->span = hi > lo && hold_hi >= hold_lo ? (hold_hi - hold_lo) / (hi - lo) : 0.0;
    (void)fit_reversals(x, skip + train, end, lo, hi, &e->minor);
}

void fit_validation_excitation(const double *x, size_t skip, size_t end,
                               const fit_validation_t *v, size_t delay, fit_excitation_t *e)
{
    const size_t v_end = v->n > v->skip + delay ? v->n - delay : v->skip;
    double lo, hi;
    size_t k;
    memset(e, 0, sizeof *e);
    e->noise = NAN;
    if (end <= skip || v_end <= v->skip) {
        return;
    }
    e->noise = fit_noise_floor(v->x, v->n, v->y, v->skip + delay, v->n, delay);
    fit_input_range(x, skip, end, 0.0, &e->fitted_lo, &e->fitted_hi);
    e->holdout_n = v_end - v->skip;
    for (k = v->skip; k < v_end; ++k) {
        e->beyond += v->x[k] < e->fitted_lo || v->x[k] > e->fitted_hi ? 1u : 0u;
    }
    fit_input_range(v->x, v->skip, v_end, 0.0, &lo, &hi);
    e->span = e->fitted_hi > e->fitted_lo && hi >= lo
                  ? (hi - lo) / (e->fitted_hi - e->fitted_lo)
                  : 0.0;
    (void)fit_reversals(v->x, v->skip, v_end, e->fitted_lo, e->fitted_hi, &e->minor);
}

size_t fit_max_delay(const double *x, size_t from, size_t to)
{
    double lo, hi;
    size_t reversals, inner, d;
    if (to <= from + 1u) {
        return FIT_MAX_DELAY;
    }
    fit_input_range(x, from, to, 0.0, &lo, &hi);
    reversals = fit_reversals(x, from, to, lo, hi, &inner);
    d = reversals > 0u ? 2u * (to - from) / reversals / FIT_DELAY_PERIOD_FRACTION : 0u;
    return d < FIT_MAX_DELAY ? FIT_MAX_DELAY : d > FIT_MAX_SCALED_DELAY ? FIT_MAX_SCALED_DELAY : d;
}

/* f0's first pass at HYST_MAX_DEGREE over one split of the record (the
 * part fitted: its domain, method, skip and delay, which with the split
 * decide its samples), from which the fit of every lower degree is lowered
 * (hyst_ident_lower_degree(): the same f0 bit for bit) instead of passing
 * over the record once per degree. */
typedef struct poly_pass {
    int valid;
    hyst_ident_config_t part; /* as the candidate gave it, its degree aside */
    hyst_status_t status;     /* of the pass: HYST_OK, or why no degree fits */
    hyst_ident_t id;
} poly_pass_t;

/* What the candidates of one record share (one fit_select() call): f0's
 * passes, one per split and widening, and the creep lags' states of the
 * runs they make. */
typedef struct reuse {
    poly_pass_t pass[FIT_SPLITS][2];
    fit_lags_t lags;
} reuse_t;

static double holdout(const hyst_ident_config_t *cfg, int kind, unsigned t_degree, int widened,
                      const double *x, const double *y, size_t n, const fit_validation_t *v,
                      reuse_t *reuse, hyst_status_t *status, hyst_ident_result_t *poly,
                      fit_everett_result_t *ev, fit_creep_t *creep, double *last_third);

size_t fit_cheap_delay(const hyst_ident_config_t *base, const double *x, const double *y,
                       size_t n, const fit_validation_t *v, size_t max_delay)
{
    size_t d, best = 0u;
    double lowest = NAN;
    for (d = 0u; d <= max_delay && n > base->skip + d; ++d) {
        hyst_ident_config_t cfg = *base;
        hyst_ident_result_t fit;
        fit_everett_result_t unused;
        hyst_status_t st;
        double e;
        cfg.degree = 3u;
        cfg.delay = d;
        e = holdout(&cfg, FIT_POLY, 0u, 0, x, y, n, v, NULL, &st, &fit, &unused, NULL, NULL);
        if (isfinite(e) && !(lowest <= e)) {
            lowest = e;
            best = d;
        }
    }
    return best;
}

const char *fit_kind_name(int kind)
{
    return kind == FIT_EVERETT ? "everett"
           : kind == FIT_GRID  ? "everett_grid"
           : kind == FIT_SPLINE ? "spline"
                               : "poly";
}

unsigned fit_parameters(int kind, unsigned degree, unsigned t_degree)
{
    unsigned i, count = 1u; /* y_lo */
    if (kind == FIT_GRID) { /* y_lo, the cells' masses, the inner knots */
        return count + degree * (degree + 1u) / 2u + degree - 1u;
    }
    if (kind == FIT_SPLINE) { /* y_lo and the K + 2 weights */
        return count + degree + 2u;
    }
    if (kind != FIT_EVERETT) {
        return degree + 1u;
    }
    for (i = 1u; i <= degree; ++i) { /* w^i t^j, j = 0 .. min(degree - i, t_degree) */
        count += (degree - i < t_degree ? degree - i : t_degree) + 1u;
    }
    return count;
}

double fit_model_run(const hyst_poly_t *f0, const hyst_curve_t *curve, const double *x,
                     const double *y, size_t n, size_t skip, size_t delay, size_t from,
                     double *before_rms, double *max_abs)
{
    return fit_model_run_creep(f0, curve, x, y, n, skip, delay, from, before_rms, max_abs, NULL);
}

/* The model's run from rest at skip over x[skip .. n - delay) against
 * y[k + delay]: u[k - skip] the input as the model took
 * it (clamped; the last one for NaN), r[k - skip] the output minus the
 * model's (NaN where missing). 0, or 1 when out of memory. */
static int model_residual(const hyst_poly_t *f0, const hyst_curve_t *curve, const double *x,
                          const double *y, size_t n, size_t skip, size_t delay, double *u,
                          double *r)
{
    hyst_tcm_t S;
    const size_t cap = n > delay + skip ? (n - delay - skip) / 2u + 2u : 2u;
    double *mem = (double *)malloc(4u * cap * sizeof(double));
    hyst_status_t st;
    size_t k;
    if (mem == NULL) {
        return 1;
    }
    st = f0 != NULL ? hyst_f64_init(&S, f0, mem, mem + cap, mem + 2u * cap, mem + 3u * cap, cap)
                    : hyst_f64_init_curve(&S, curve, mem, mem + cap, mem + 2u * cap,
                                          mem + 3u * cap, cap);
    for (k = skip; st == HYST_OK && k + delay < n; ++k) {
        const double ym = hyst_f64_step(&S, x[k]);
        u[k - skip] = hyst_f64_input(&S);
        r[k - skip] = isfinite(x[k]) && isfinite(y[k + delay]) ? y[k + delay] - ym : NAN;
    }
    free(mem);
    return st != HYST_OK;
}

/* The model run from rest at skip over x[skip .. n - delay) against
 * y[k + delay]: the RMS error over [from, to) from score_from on (returned)
 * and before `from` (*before_rms); creep (may be NULL) fitted to its
 * residual before `from` and scored from it on (part 0), or fitted on every
 * sample but [from, to) and scored there (part 1), from score_from on. */
static double model_run(const hyst_poly_t *f0, const hyst_curve_t *curve, const double *x,
                        const double *y, size_t n, size_t skip, size_t delay, size_t from,
                        size_t to, int part, size_t score_from, double *before_rms,
                        double *max_abs, fit_creep_t *creep, fit_lags_t *lags)
{
    const size_t len = n > delay + skip ? n - delay - skip : 0u;
    double *u, *r, ss = 0.0, ss_before = 0.0, worst = 0.0;
    size_t k, used = 0u, before = 0u;
    const double tau = creep != NULL ? creep->tau : 0.0;
    const double rate_tau = creep != NULL ? creep->rate_tau : 0.0;
    if (before_rms != NULL) {
        *before_rms = NAN;
    }
    if (max_abs != NULL) {
        *max_abs = NAN;
    }
    if (creep != NULL) {
        memset(creep, 0, sizeof *creep);
        creep->holdout_rms = NAN;
        creep->fit_rms = NAN;
        if (len == 0u) {
            return NAN;
        }
    }
    /* the model's inputs and residuals (for the creep fitted to them) */
    if ((u = (double *)malloc((2u * len + 1u) * sizeof(double))) == NULL) {
        return NAN;
    }
    r = u + len;
    if (model_residual(f0, curve, x, y, n, skip, delay, u, r) != 0) {
        free(u);
        return NAN;
    }
    for (k = skip; k + delay < n; ++k) {
        if (!isnan(r[k - skip])) {
            const double e = -r[k - skip];
            if (k >= from && k < to) {
                if (k >= score_from) {
                    ss += e * e;
                    ++used;
                }
            } else if (k < from) {
                ss_before += e * e;
                ++before;
            }
            worst = fabs(e) > worst ? fabs(e) : worst;
        }
    }
    if (creep != NULL) {
        const double x_rest = f0 != NULL ? (double)f0->lo : curve->lo.f64;
        const size_t at = from > skip ? from - skip : 0u;
        if (rate_tau > 0) { /* with a rate term: tau the creep lag's, or none */
            fit_terms_part(u, r, len, at, part ? (to > skip ? to - skip : 0u) : len,
                           part ? (score_from > skip ? score_from - skip : 0u) : at, x_rest, tau,
                           rate_tau, creep);
        } else { /* part: held out inside the run (fit_creep_score()'s the rest) */
            fit_creep_score_part(u, r, len, at, part ? (to > skip ? to - skip : 0u) : len,
                                 part ? (score_from > skip ? score_from - skip : 0u) : at, x_rest,
                                 tau, lags, creep);
        }
    }
    free(u);
    if (before_rms != NULL && before > 0u) {
        *before_rms = sqrt(ss_before / (double)before);
    }
    if (max_abs != NULL) {
        *max_abs = worst;
    }
    return used > 0u ? sqrt(ss / (double)used) : NAN;
}

double fit_model_run_creep(const hyst_poly_t *f0, const hyst_curve_t *curve, const double *x,
                           const double *y, size_t n, size_t skip, size_t delay, size_t from,
                           double *before_rms, double *max_abs, fit_creep_t *creep)
{
    return model_run(f0, curve, x, y, n, skip, delay, from, n, 0, from, before_rms, max_abs,
                     creep, NULL);
}

/* Samples of the training part: the first two thirds of those the model sees. */
static size_t train_count(size_t n, size_t skip, size_t delay)
{
    return (2u * (n - skip - delay)) / 3u;
}

hyst_status_t fit_result_curve(int kind, const fit_everett_result_t *ev, hyst_curve_t *curve)
{
    static double grid_table[HYST_EVERETT_GRID_TABLE_LEN(HYST_EVERETT_GRID_MAX_INTERVALS)];
    static double spline_table[HYST_SPLINE_TABLE_LEN(HYST_SPLINE_MAX_INTERVALS)];
    if (kind == FIT_GRID) {
        return hyst_f64_curve_from_everett_grid(curve, &ev->grid, grid_table,
                                                sizeof grid_table / sizeof grid_table[0]);
    }
    if (kind == FIT_SPLINE) {
        return hyst_f64_curve_from_spline(curve, &ev->spline, spline_table,
                                          sizeof spline_table / sizeof spline_table[0]);
    }
    return hyst_f64_curve_from_everett(curve, &ev->e);
}

hyst_status_t fit_record_start(const hyst_ident_config_t *cfg, const double *x, size_t n,
                               fit_everett_result_t *res, double *lo, double *hi)
{
    memset(res, 0, sizeof *res);
    res->rms = NAN;
    res->max_abs = NAN;
    res->curve_status = HYST_ERR_ARG;
    if (n <= cfg->skip + cfg->delay) {
        return HYST_ERR_ARG;
    }
    *lo = (double)cfg->lo;
    *hi = (double)cfg->hi;
    if (!(*lo < *hi)) { /* the range of the inputs used, as hyst_ident_fit() takes it */
        fit_input_range(x, cfg->skip, n - cfg->delay, 0.0, lo, hi);
    }
    return HYST_OK;
}

hyst_status_t fit_record_finish(int kind, const hyst_ident_config_t *cfg, const double *x,
                                const double *y, size_t n, hyst_status_t st,
                                fit_everett_result_t *res)
{
    hyst_curve_t curve;
    /* HYST_ERR_NOT_MONOTONE: the fit is returned all the same; the curve's
     * own refusal says why (curve_status) */
    if (st != HYST_OK && st != HYST_ERR_NOT_MONOTONE) {
        return st;
    }
    res->curve_status = fit_result_curve(kind, res, &curve);
    if (res->curve_status == HYST_OK) {
        (void)fit_model_run(NULL, &curve, x, y, n, cfg->skip, cfg->delay, n - cfg->delay,
                            &res->rms, &res->max_abs);
    }
    return HYST_OK;
}

/* The fits of two parts differ in nothing but their degree. */
static int same_part(const hyst_ident_config_t *a, const hyst_ident_config_t *b)
{
    return a->method == b->method && a->lo == b->lo && a->hi == b->hi && a->skip == b->skip &&
           a->delay == b->delay;
}

/* hyst_ident_fit() of part, its first pass lowered from *pass, the pass at
 * HYST_MAX_DEGREE over this split's samples, made first unless *pass holds
 * it for a part that differs in nothing but its degree. */
static hyst_status_t poly_fit_lowered(const hyst_ident_config_t *part, const double *x,
                                      const double *y, size_t count, poly_pass_t *pass,
                                      hyst_ident_t *work, hyst_ident_result_t *res)
{
    hyst_status_t st;
    size_t i;
    if (!pass->valid || !same_part(&pass->part, part)) {
        hyst_ident_config_t high = *part;
        high.degree = HYST_MAX_DEGREE;
        pass->part = high;
        pass->valid = 1;
        pass->status = part->skip >= count || part->delay >= count - part->skip ? HYST_ERR_ARG
                                                                             : HYST_OK;
        if (pass->status == HYST_OK && high.lo == high.hi) { /* as hyst_ident_fit() takes it */
            pass->status = hyst_ident_domain(x + high.skip, count - high.skip - high.delay,
                                             &high.lo, &high.hi);
        }
        if (pass->status == HYST_OK) {
            pass->status = hyst_ident_init(&pass->id, &high);
        }
        for (i = high.skip; pass->status == HYST_OK && i + high.delay < count; ++i) {
            (void)hyst_ident_add(&pass->id, x[i], y[i + high.delay]);
        }
    }
    if (pass->status != HYST_OK) {
        return pass->status;
    }
    st = hyst_ident_lower_degree(&pass->id, part->degree, work);
    if (st == HYST_OK) {
        st = hyst_ident_solve(work, res);
    }
    if (st != HYST_OK) {
        return st;
    }
    for (i = part->skip; i + part->delay < count; ++i) {
        (void)hyst_ident_check(work, x[i], y[i + part->delay]);
    }
    return hyst_ident_residuals(work, res);
}

/* The model of kind `kind` fitted to x[k] with y[k + delay], part->skip <= k
 * < count - delay (part: degree, delay, domain, method): f0 into *f0
 * (FIT_POLY; lowered from *pass when not NULL, which holds the same samples'
 * pass or gets it) or the curve into *curve (its grid's table static). 0,
 * or 1 when the fit failed, f0 is not increasing or the library refused E
 * (*status says which). */
static int model_fit(const hyst_ident_config_t *part, int kind, unsigned t_degree,
                     const double *x, const double *y, size_t count, poly_pass_t *pass,
                     hyst_status_t *status, hyst_ident_result_t *poly, fit_everett_result_t *ev,
                     hyst_poly_t *f0, hyst_curve_t *curve)
{
    unsigned i;
    if (kind != FIT_POLY) {
        *status = kind == FIT_GRID     ? fit_grid_record(part, part->degree, x, y, count, ev)
                  : kind == FIT_SPLINE ? fit_spline_record(part, part->degree, x, y, count, ev)
                                       : fit_everett_record(part, t_degree, x, y, count, ev);
        if (*status == HYST_OK) {
            *status = ev->curve_status;
        }
        return *status != HYST_OK || fit_result_curve(kind, ev, curve) != HYST_OK;
    }
    {
        hyst_ident_t work;
        *status = pass != NULL ? poly_fit_lowered(part, x, y, count, pass, &work, poly)
                               : hyst_ident_fit(part, x, y, count, &work, poly);
        if (*status != HYST_OK || !poly->increasing) {
            return 1;
        }
        memset(f0, 0, sizeof *f0);
        f0->degree = poly->degree;
        f0->lo = (double)poly->lo;
        f0->hi = (double)poly->hi;
        for (i = 0u; i <= poly->degree; ++i) {
            f0->coeffs[i] = (double)poly->coeffs[i];
        }
    }
    return 0;
}

/* One split of the hold-out (FIT_SPLITS) of the samples the model sees:
 * 0 fits the first two thirds and scores the last third; 1 and 2 score the
 * middle and the first third, fitted on the rest with the outputs of that
 * third left out (the fit takes its inputs in: the turning points are the
 * record's), from `settle` on (fit_settled()). The model runs from rest at
 * cfg->skip over the whole record each time; kind FIT_EVERETT with t_degree;
 * its domain widened by FIT_WIDEN about the inputs fitted when `widened`;
 * creep (may be NULL) as fit_model_run_creep(), fitted and scored on the
 * same parts. */
static double holdout_split(const hyst_ident_config_t *cfg, int kind, unsigned t_degree,
                            int widened, const double *x, const double *y, size_t n, int split,
                            size_t settle, reuse_t *reuse, hyst_status_t *status,
                            hyst_ident_result_t *poly, fit_everett_result_t *ev,
                            fit_creep_t *creep)
{
    const size_t len = n > cfg->skip + cfg->delay ? n - cfg->skip - cfg->delay : 0u;
    const size_t train = len > 0u ? train_count(n, cfg->skip, cfg->delay) : 0u;
    const size_t from = cfg->skip + (split == 0 ? train : split == 2 ? 0u : len / 3u);
    const size_t to = split == 0 ? n : cfg->skip + (split == 2 ? len / 3u : train);
    const size_t count = split == 0 ? from + cfg->delay : n; /* the samples fitted end here */
    hyst_ident_config_t part = *cfg;
    poly_pass_t *pass = NULL;
    double *masked = NULL;
    const double *yf = y;
    hyst_curve_t curve;
    hyst_poly_t f0;
    size_t k;
    double before, e;
    if (len == 0u || from >= to || (split != 0 && settle >= to)) {
        *status = HYST_ERR_ARG;
        return NAN;
    }
    if (split != 0) { /* the held-out third's outputs left out of the fit */
        if ((masked = (double *)malloc(n * sizeof(double))) == NULL) {
            *status = HYST_ERR_NOSPACE;
            return NAN;
        }
        memcpy(masked, y, n * sizeof(double));
        for (k = from; k < to; ++k) {
            masked[k + cfg->delay] = NAN;
        }
        yf = masked;
    }
    if (kind == FIT_EVERETT) {
        memset(ev, 0, sizeof *ev);
    }
    if (widened) { /* about the inputs whose outputs are fitted */
        double lo, hi, lo2, hi2;
        if (split == 0) {
            fit_input_range(x, cfg->skip, from, 0.0, &lo, &hi);
        } else {
            fit_input_range(x, to < n - cfg->delay ? to : from, n - cfg->delay, 0.0, &lo, &hi);
            if (from > cfg->skip) {
                fit_input_range(x, cfg->skip, from, 0.0, &lo2, &hi2);
                lo = lo2 < lo ? lo2 : lo;
                hi = hi2 > hi ? hi2 : hi;
            }
        }
        fit_widened_domain(lo, hi, fit_first_input(x, cfg->skip, n - cfg->delay), &lo, &hi);
        part.lo = lo;
        part.hi = hi;
    }
    if (reuse != NULL && kind == FIT_POLY) {
        pass = &reuse->pass[split][widened != 0];
    }
    if (model_fit(&part, kind, t_degree, x, yf, count, pass, status, poly, ev, &f0, &curve) != 0) {
        free(masked);
        return NAN;
    }
    free(masked);
    e = model_run(kind != FIT_POLY ? NULL : &f0, kind != FIT_POLY ? &curve : NULL, x, y, n,
                  cfg->skip, cfg->delay, from, to, split != 0,
                  split != 0 && settle > from ? settle : from, &before, NULL, creep,
                  reuse != NULL ? &reuse->lags : NULL);
    return e;
}

/* A candidate scored on the validation record v: fitted on the whole of x,
 * y from cfg->skip on (widened as fit_chosen_domain() widens the model
 * chosen: the model the choice saves), then run from rest over v: the RMS
 * error over every row of v it predicts (NaN if the fit failed, *status, or
 * none could be scored); creep (may be NULL): its
 * terms fitted on the model's residual over x, y, scored on v
 * (fit_terms_other()). */
static double validated(const hyst_ident_config_t *cfg, int kind, unsigned t_degree,
                        int widened, const double *x, const double *y, size_t n,
                        const fit_validation_t *v, hyst_status_t *status,
                        hyst_ident_result_t *poly, fit_everett_result_t *ev, fit_creep_t *creep)
{
    const double creep_tau = creep != NULL ? creep->tau : 0.0;
    const double rate_tau = creep != NULL ? creep->rate_tau : 0.0;
    hyst_ident_config_t whole = *cfg;
    hyst_curve_t curve;
    hyst_poly_t f0;
    const hyst_poly_t *fp;
    const hyst_curve_t *cp;
    double *u, *r, *u2, *r2, ss = 0.0;
    size_t len, len2, k, used = 0u;
    memset(ev, 0, sizeof *ev);
    if (creep != NULL) {
        memset(creep, 0, sizeof *creep);
        creep->holdout_rms = NAN;
        creep->fit_rms = NAN;
    }
    if (n <= cfg->skip + cfg->delay || v->n <= v->skip + cfg->delay) {
        *status = HYST_ERR_ARG;
        return NAN;
    }
    if (widened) {
        double lo, hi;
        fit_input_range(x, cfg->skip, n - cfg->delay, 0.0, &lo, &hi);
        fit_widened_domain(lo, hi, fit_first_input(x, cfg->skip, n - cfg->delay), &whole.lo,
                           &whole.hi);
    }
    if (model_fit(&whole, kind, t_degree, x, y, n, NULL, status, poly, ev, &f0, &curve) != 0) {
        return NAN;
    }
    fp = kind == FIT_POLY ? &f0 : NULL;
    cp = kind == FIT_POLY ? NULL : &curve;
    len = n - cfg->skip - cfg->delay;
    len2 = v->n - v->skip - cfg->delay;
    if ((u = (double *)malloc(2u * (len + len2) * sizeof(double))) == NULL) {
        *status = HYST_ERR_NOSPACE;
        return NAN;
    }
    r = u + len;
    u2 = r + len;
    r2 = u2 + len2;
    if (model_residual(fp, cp, v->x, v->y, v->n, v->skip, cfg->delay, u2, r2) != 0 ||
        (creep != NULL && model_residual(fp, cp, x, y, n, cfg->skip, cfg->delay, u, r) != 0)) {
        free(u);
        *status = HYST_ERR_NOSPACE;
        return NAN;
    }
    for (k = 0u; k < len2; ++k) {
        if (isfinite(r2[k])) {
            ss += r2[k] * r2[k];
            ++used;
        }
    }
    if (creep != NULL && used > 0u) {
        fit_terms_other(u, r, len, u2, r2, len2, fp != NULL ? (double)fp->lo : cp->lo.f64,
                        creep_tau, rate_tau, creep);
    }
    free(u);
    return used > 0u ? sqrt(ss / (double)used) : NAN;
}

/* The hold-out of every split (FIT_SPLITS): their mean square's root; the
 * training fit's results and the creep's time constant those of split 0,
 * the creep's hold-out over every split at that time constant. */
static double holdout(const hyst_ident_config_t *cfg, int kind, unsigned t_degree, int widened,
                      const double *x, const double *y, size_t n, const fit_validation_t *v,
                      reuse_t *reuse, hyst_status_t *status, hyst_ident_result_t *poly,
                      fit_everett_result_t *ev, fit_creep_t *creep, double *last_third)
{
    hyst_ident_result_t poly_other;
    fit_everett_result_t ev_other;
    fit_creep_t creep_other;
    hyst_status_t st;
    double e, ss, ss_creep = 0.0;
    int split, splits = 1;
    const size_t settle =
        n > cfg->skip + cfg->delay ? fit_settled(x, cfg->skip, n - cfg->delay) : cfg->skip;
    const double resolution = fit_resolution(y, n, cfg->skip, cfg->delay, v);
    if (v != NULL) { /* instead of the splits: no third of the record held out */
        if (last_third != NULL) {
            *last_third = NAN;
        }
        e = validated(cfg, kind, t_degree, widened, x, y, n, v, status, poly, ev, creep);
        if (creep != NULL) {
            creep->holdout_rms = resolved(creep->holdout_rms, resolution);
            creep->last_third_rms = NAN;
        }
        return resolved(e, resolution);
    }
    e = holdout_split(cfg, kind, t_degree, widened, x, y, n, 0, settle, reuse, status, poly, ev,
                      creep);
    ss = e * e;
    if (last_third != NULL) {
        *last_third = e;
    }
    if (creep != NULL) {
        ss_creep = creep->holdout_rms * creep->holdout_rms;
        creep->last_third_rms = creep->holdout_rms;
    }
    for (split = 1; split < FIT_SPLITS && isfinite(ss); ++split) {
        const size_t len = n - cfg->skip - cfg->delay;
        if (len / 3u < FIT_SPLIT_MIN ||
            settle >= cfg->skip + (split == 2 ? len / 3u : train_count(n, cfg->skip, cfg->delay))) {
            continue; /* too short, or it ends before the model's state is the record's */
        }
        const int terms = creep != NULL && (creep->tau > 0 || creep->rate_tau > 0);
        creep_other.tau = creep != NULL ? creep->tau : 0.0;
        creep_other.rate_tau = creep != NULL ? creep->rate_tau : 0.0;
        e = holdout_split(cfg, kind, t_degree, widened, x, y, n, split, settle, reuse, &st,
                          &poly_other, &ev_other, terms ? &creep_other : NULL);
        ss += e * e;
        ++splits;
        if (terms) {
            ss_creep += creep_other.holdout_rms * creep_other.holdout_rms;
        }
        if (*status == HYST_OK && !isfinite(e)) {
            *status = st; /* the reason this split could not be scored */
        }
    }
    if (creep != NULL) {
        creep->holdout_rms = resolved(sqrt(ss_creep / (double)splits), resolution);
        creep->last_third_rms = resolved(creep->last_third_rms, resolution);
    }
    if (last_third != NULL) {
        *last_third = resolved(*last_third, resolution);
    }
    return resolved(sqrt(ss / (double)splits), resolution);
}

double fit_tcm_holdout(const hyst_ident_config_t *cfg, const double *x, const double *y,
                       size_t n, hyst_status_t *status, hyst_ident_result_t *fit,
                       fit_creep_t *creep, double *last_third)
{
    fit_everett_result_t unused;
    return holdout(cfg, FIT_POLY, 0u, 0, x, y, n, NULL, NULL, status, fit, &unused, creep,
                   last_third);
}

double fit_everett_holdout(const hyst_ident_config_t *cfg, unsigned t_degree, const double *x,
                           const double *y, size_t n, hyst_status_t *status,
                           fit_everett_result_t *fit, fit_creep_t *creep, double *last_third)
{
    hyst_ident_result_t unused;
    return holdout(cfg, FIT_EVERETT, t_degree, 0, x, y, n, NULL, NULL, status, &unused, fit, creep,
                   last_third);
}

double fit_grid_holdout(const hyst_ident_config_t *cfg, const double *x, const double *y,
                        size_t n, hyst_status_t *status, fit_everett_result_t *fit,
                        fit_creep_t *creep, double *last_third)
{
    hyst_ident_result_t unused;
    return holdout(cfg, FIT_GRID, 0u, 0, x, y, n, NULL, NULL, status, &unused, fit, creep,
                   last_third);
}

double fit_pi_holdout(const hyst_pi_fit_config_t *cfg, const double *x, const double *y,
                      size_t n, hyst_status_t *status, hyst_pi_fit_result_t *fit, double *r,
                      double *w)
{
    static double work[HYST_PI_FIT_WORK(HYST_PI_FIT_MAX_OPERATORS)];
    static double z[HYST_PI_FIT_MAX_OPERATORS];
    hyst_pi_t P;
    double ss = 0.0;
    size_t train, k, used = 0u;
    if (n <= cfg->skip + cfg->delay) {
        *status = HYST_ERR_ARG;
        return NAN;
    }
    train = train_count(n, cfg->skip, cfg->delay);
    *status = hyst_pi_fit_record(cfg, x, y, cfg->skip + train + cfg->delay, work,
                                 sizeof work / sizeof work[0], r, w, fit);
    /* hyst_pi_init() refuses w1 = 0 (a flat start of the loading curve) */
    if (*status != HYST_OK || hyst_f64_pi_init(&P, r, w, z, cfg->operators) != HYST_OK) {
        return NAN;
    }
    /* the model from reset at the first sample used, scored on the last third */
    for (k = cfg->skip; k + cfg->delay < n; ++k) {
        const double e = hyst_f64_pi_step(&P, x[k]) + (double)fit->offset - y[k + cfg->delay];
        if (k >= cfg->skip + train) {
            ss += e * e;
            ++used;
        }
    }
    return used > 0u ? sqrt(ss / (double)used) : NAN;
}

/* fit_score(), with what the candidates of one delay share in *reuse (may be NULL). */
static void score(const hyst_ident_config_t *base, const double *x, const double *y, size_t n,
                  const fit_validation_t *v, reuse_t *reuse, double creep_tau,
                  fit_candidate_t *c)
{
    hyst_ident_config_t cfg = *base;
    fit_creep_t *creep = creep_tau >= 0 ? &c->creep : NULL;
    cfg.degree = c->degree;
    cfg.delay = c->delay;
    c->creep.tau = creep_tau >= 0 ? creep_tau : 0.0;
    c->creep.holdout_rms = NAN;
    if (c->kind == FIT_EVERETT || c->kind == FIT_GRID || c->kind == FIT_SPLINE) {
        fit_everett_result_t ev;
        hyst_ident_result_t unused;
        c->holdout_rms = holdout(&cfg, c->kind, c->t_degree, c->widened, x, y, n, v, reuse,
                                 &c->status, &unused, &ev, creep, &c->last_third_rms);
        c->fit_rms = ev.rms;
    } else {
        fit_everett_result_t unused;
        c->holdout_rms = holdout(&cfg, FIT_POLY, 0u, c->widened, x, y, n, v, reuse, &c->status,
                                 &c->fit, &unused, creep, &c->last_third_rms);
        c->fit_rms = (double)c->fit.rms;
    }
    if (!isfinite(c->holdout_rms)) {
        c->creep.tau = 0.0; /* the model itself could not be scored */
        c->creep.holdout_rms = NAN;
    }
}

/* Candidate c fitted and scored: kind, degree (t_degree) and delay set by
 * the caller; with a creep term too unless creep_tau < 0 (0: its time
 * constant chosen). */
void fit_score(const hyst_ident_config_t *base, const double *x, const double *y, size_t n,
               const fit_validation_t *v, double creep_tau, fit_candidate_t *c)
{
    score(base, x, y, n, v, NULL, creep_tau, c);
}

void fit_delay_fraction(const double *x, size_t n, double f, double *xf)
{
    size_t k;
    for (k = n; k-- > 1u;) { /* from the end: in place, x[k - 1] not yet replaced */
        xf[k] = (1.0 - f) * x[k] + f * x[k - 1u];
    }
    if (n > 0u) {
        xf[0] = x[0];
    }
}

double fit_option_rms(const fit_candidate_t *c, int with_creep)
{
    return with_creep ? (c->creep.tau > 0 ? c->creep.holdout_rms : NAN) : c->holdout_rms;
}

double fit_option_last_third(const fit_candidate_t *c, int with_creep)
{
    return with_creep ? (c->creep.tau > 0 ? c->creep.last_third_rms : NAN) : c->last_third_rms;
}

unsigned fit_option_parameters(const fit_candidate_t *c, int with_creep)
{
    return fit_parameters(c->kind, c->degree, c->t_degree) +
           (with_creep ? FIT_CREEP_PARAMETERS : 0u) +
           (c->fraction > 0.0 ? FIT_FRACTION_PARAMETERS : 0u);
}

/* Adds candidate (kind, degree, t_degree, delay), scored, at cand[*count]
 * unless cand is full or the model has more than max_parameters (when not
 * 0). */
static void add(const hyst_ident_config_t *base, const double *x, const double *y, size_t n,
                const fit_validation_t *v, reuse_t *reuse, double creep_tau,
                unsigned max_parameters, int kind, unsigned degree, unsigned t_degree,
                size_t delay, int widened, fit_candidate_t *cand, size_t max_cand, size_t *count)
{
    fit_candidate_t *c = &cand[*count];
    if (*count >= max_cand ||
        (max_parameters != 0u && fit_parameters(kind, degree, t_degree) > max_parameters)) {
        return;
    }
    memset(c, 0, sizeof *c);
    c->kind = kind;
    c->degree = degree;
    c->t_degree = t_degree;
    c->delay = delay;
    c->widened = widened;
    score(base, x, y, n, v, reuse, creep_tau, c);
    ++*count;
}

size_t fit_select(const hyst_ident_config_t *base, int kinds, unsigned everett_degree,
                  unsigned t_degree, unsigned max_parameters, double creep_tau, const double *x, const double *y,
                  size_t n, const fit_validation_t *v, size_t max_delay,
                  fit_candidate_t *cand, size_t max_cand, size_t *best, int *with_creep)
{
    reuse_t reuse;
    size_t count = 0u, d;
    unsigned deg, k;
    int widen = 0, w;
    size_t i;
    /* widened candidates only where they make a difference: the hold-out
     * part's inputs leave the range of the part fitted (and no --domain).
     * Each kind whose branches continue beyond the inputs on a wider domain:
     * f0 a polynomial (where it stays increasing: else the fit refuses it),
     * E (monotone on the whole wider triangle), f0 a spline (a straight line
     * at its last slope above its inputs). Not the grid: its cells beyond
     * the inputs see no data, and their masses 0 hold the output as
     * clamping does. */
    memset(&reuse, 0, sizeof reuse);
    if (v != NULL && !(base->lo < base->hi) && n > base->skip + base->delay) {
        fit_excitation_t e; /* the validation record's inputs leave the record's range */
        fit_validation_excitation(x, base->skip, n - base->delay, v, base->delay, &e);
        widen = e.beyond > 0u;
    } else if (!(base->lo < base->hi) && n > base->skip + base->delay) {
        const size_t from = base->skip, end = n - base->delay;
        const size_t train = train_count(n, base->skip, base->delay);
        double lo, hi;
        fit_input_range(x, from, from + train, 0.0, &lo, &hi);
        for (i = from + train; i < end && !widen; ++i) {
            widen = x[i] < lo || x[i] > hi;
        }
    }
    for (d = base->delay; d <= max_delay; ++d) {
        if (n <= base->skip + d) {
            break;
        }
        for (deg = 1u; (kinds & FIT_POLY) != 0 && deg <= HYST_MAX_DEGREE; ++deg) {
            for (w = 0; w <= widen; ++w) {
                add(base, x, y, n, v, &reuse, creep_tau, max_parameters, FIT_POLY, deg, 0u, d, w,
                    cand, max_cand, &count);
            }
        }
        for (k = 0u; (kinds & FIT_GRID) != 0 && k < FIT_GRID_CANDIDATES; ++k) {
            add(base, x, y, n, v, &reuse, creep_tau, max_parameters, FIT_GRID,
                FIT_GRID_INTERVALS(k), 0u, d, 0, cand, max_cand, &count);
        }
        for (k = 0u; (kinds & FIT_SPLINE) != 0 && k < FIT_SPLINE_CANDIDATES; ++k) {
            for (w = 0; w <= widen; ++w) {
                add(base, x, y, n, v, &reuse, creep_tau, max_parameters, FIT_SPLINE,
                    FIT_SPLINE_INTERVALS(k), 0u, d, w, cand, max_cand, &count);
            }
        }
        for (deg = 1u; (kinds & FIT_EVERETT) != 0 && deg <= HYST_EVERETT_MAX_DEGREE; ++deg) {
            for (k = 0u; k < deg && (everett_degree == 0u || deg == everett_degree); ++k) {
                for (w = 0; w <= widen; ++w) {
                    if (t_degree == FIT_ANY_T_DEGREE || k == t_degree) {
                        add(base, x, y, n, v, &reuse, creep_tau, max_parameters, FIT_EVERETT,
                            deg, k, d, w, cand, max_cand, &count);
                    }
                }
            }
        }
    }
    fit_lags_free(&reuse.lags);
    fit_choose(cand, count, creep_tau, best, with_creep);
    return count;
}

void fit_choose(const fit_candidate_t *cand, size_t count, double creep_tau, size_t *best,
                int *with_creep)
{
    /* the options compared: without creep unless a time constant is given,
     * with it unless creep_tau < 0 */
    const int wc_first = creep_tau > 0 ? 1 : 0, wc_last = creep_tau < 0 ? 0 : 1;
    int wc, low_creep = 0;
    double lowest = NAN;
    size_t i;
    *best = (size_t)-1;
    *with_creep = 0;
    /* every option (a candidate without, or with its creep term): the lowest error */
    for (i = 0u; i < count; ++i) {
        for (wc = wc_first; wc <= wc_last; ++wc) {
            const double e = fit_option_rms(&cand[i], wc);
            if (isfinite(e) && !(lowest <= e)) {
                lowest = e;
                *best = i;
                low_creep = wc;
            }
        }
    }
    *with_creep = low_creep;
    if (*best != (size_t)-1) { /* parsimony: the fewest parameters within 1 % of the best */
        const double limit = lowest * (1.0 + FIT_PARSIMONY);
        for (i = 0u; i < count; ++i) {
            for (wc = wc_first; wc <= wc_last; ++wc) {
                const fit_candidate_t *c = &cand[i], *b = &cand[*best];
                const double ec = fit_option_rms(c, wc), eb = fit_option_rms(b, *with_creep);
                const unsigned pc = fit_option_parameters(c, wc);
                const unsigned pb = fit_option_parameters(b, *with_creep);
                /* between as many parameters: the symmetric kind (its
                 * compensator is a table), then the lower error; at a tie
                 * in rounding, the widened one */
                const int sym_c = c->kind == FIT_POLY, sym_b = b->kind == FIT_POLY;
                const int tie = fabs(ec - eb) <= FIT_TIE * fmax(ec, eb);
                const int better = tie ? c->widened > b->widened : ec < eb;
                if (isfinite(ec) && ec <= limit &&
                    (pc < pb || (pc == pb && (sym_c > sym_b || (sym_c == sym_b && better))))) {
                    *best = i;
                    *with_creep = wc;
                }
            }
        }
    }
}

/* One model's hold-out at delay d (its own kind's, no creep term). */
static double kind_holdout(const hyst_ident_config_t *base, int kind, unsigned t_degree,
                           const double *x, const double *y, size_t n,
                           const fit_validation_t *v, size_t d)
{
    hyst_ident_config_t cfg = *base;
    hyst_status_t st;
    fit_everett_result_t ev;
    hyst_ident_result_t poly;
    cfg.delay = d;
    return holdout(&cfg, kind, t_degree, 0, x, y, n, v, NULL, &st, &poly, &ev, NULL, NULL);
}

/* v with its drive a fraction f of a sample later, in vxf (v's rows) and
 * *vf; NULL if v is. */
static const fit_validation_t *validation_fraction(const fit_validation_t *v, double f,
                                                   double *vxf, fit_validation_t *vf)
{
    if (v == NULL) {
        return NULL;
    }
    *vf = *v;
    fit_delay_fraction(v->x, v->n, f, vxf);
    vf->x = vxf;
    return vf;
}

hyst_status_t fit_given_delay(const hyst_ident_config_t *base, int kind, unsigned t_degree,
                              double *x, const double *y, size_t n, const fit_validation_t *v,
                              size_t *delay, fit_found_t *out)
{
    fit_validation_t vf;
    const size_t end = n > base->skip ? n - base->skip : 0u;
    double lowest = NAN, f, best_f = 0.0, limit;
    double *xf;
    size_t d, best_d = 0u, k;
    unsigned i;
    memset(out, 0, sizeof *out);
    out->best = (size_t)-1;
    out->max_delay = fit_max_delay(x, base->skip, n);
    for (d = 0u; d <= out->max_delay && d + 3u < end; ++d) {
        const double e = kind_holdout(base, kind, t_degree, x, y, n, v, d);
        if (isfinite(e) && !(lowest <= e)) {
            lowest = e;
            best_d = d;
        }
    }
    out->integer_delay = best_d;
    out->integer_holdout = lowest;
    *delay = isfinite(lowest) ? best_d : 0u;
    if (!isfinite(lowest)) {
        return HYST_OK;
    }
    if ((xf = (double *)malloc((n + (v != NULL ? v->n : 0u)) * sizeof(double))) == NULL) {
        return HYST_ERR_NOSPACE;
    }
    limit = lowest * (1.0 - FIT_FRACTION_GAIN);
    for (i = 1u; i < FIT_FRACTIONS; ++i) {
        const fit_validation_t *vt;
        f = (double)i / (double)FIT_FRACTIONS;
        fit_delay_fraction(x, n, f, xf);
        vt = validation_fraction(v, f, xf + n, &vf);
        for (k = 0u; k <= 1u && k <= best_d; ++k) { /* D + f and D - 1 + f */
            const double e = kind_holdout(base, kind, t_degree, xf, y, n, vt, best_d - k);
            if (isfinite(e) && e < limit) {
                limit = e;
                best_f = f;
                *delay = best_d - k;
            }
        }
    }
    if (best_f > 0.0) {
        out->delay_fraction = best_f;
        fit_delay_fraction(x, n, best_f, x);
        if (v != NULL) {
            fit_delay_fraction(v->x, v->n, best_f, v->x);
        }
    }
    free(xf);
    return HYST_OK;
}

/* Do a and b differ only in their delay? */
static int same_model(const fit_candidate_t *a, const fit_candidate_t *b)
{
    return a->kind == b->kind && a->degree == b->degree && a->t_degree == b->t_degree &&
           a->widened == b->widened;
}

/* The lowest error of option wc of c's model among the whole delays'
 * candidates cand[0..count) (NaN if none was scored). */
static double whole_delay_rms(const fit_candidate_t *cand, size_t count,
                              const fit_candidate_t *c, int wc)
{
    double lowest = NAN;
    size_t i;
    for (i = 0u; i < count; ++i) {
        const double e = fit_option_rms(&cand[i], wc);
        if (same_model(&cand[i], c) && isfinite(e) && !(lowest <= e)) {
            lowest = e;
        }
    }
    return lowest;
}

/* The index of c's model at c's whole delay in cand[0..count), or
 * (size_t)-1 if it was not scored there. */
static size_t whole_delay_index(const fit_candidate_t *cand, size_t count, const fit_candidate_t *c)
{
    size_t i;
    for (i = 0u; i < count; ++i) {
        if (same_model(&cand[i], c) && cand[i].delay == c->delay) {
            return i;
        }
    }
    return (size_t)-1;
}

/* The sub-sample delay of fit_search(): every candidate scored again with
 * the drive a fraction of a sample later, at the chosen delay and one
 * below, its fraction counted as FIT_FRACTION_PARAMETERS. An option there
 * is compared with the whole delays' choice when it errs less than its own
 * model at any whole delay by more than FIT_FRACTION_GAIN, and either has
 * fewer parameters than that choice (a model that took a sub-sample
 * misalignment in as loop shape gives way to the plant's own model at the
 * plant's delay), or at most FIT_FRACTION_PARAMETERS more and errs less than
 * the choice by more than FIT_FRACTION_GAIN too (the fraction is not a way to
 * more terms); fit_choose()'s rule picks among them. A model chosen at a
 * fraction replaces the same model at that whole delay in cand (or the
 * whole delays' choice if that one was not scored), and x is interpolated
 * in place. 0, or 1 when out of memory. */
static int search_fraction(const hyst_ident_config_t *cfg, int kinds, unsigned t_degree,
                           double creep_tau, double *x, const double *y, size_t n,
                           const fit_validation_t *v, fit_candidate_t *cand, fit_found_t *out)
{
    const size_t per_fraction = 2u * FIT_CANDIDATES_PER_DELAY;
    const size_t most = 1u + per_fraction * (FIT_FRACTIONS - 1u);
    const fit_candidate_t *b = &cand[out->best];
    const unsigned params = fit_option_parameters(b, out->with_creep);
    const double gain_limit = fit_option_rms(b, out->with_creep) * (1.0 - FIT_FRACTION_GAIN);
    double *xf = (double *)malloc((n + (v != NULL ? v->n : 0u) + 1u) * sizeof(double));
    fit_candidate_t *tried = (fit_candidate_t *)malloc(most * sizeof(fit_candidate_t));
    hyst_ident_config_t base = *cfg;
    fit_validation_t vf;
    size_t total = 1u, best = (size_t)-1, k;
    unsigned i;
    int wc;
    out->integer_holdout = fit_option_rms(b, out->with_creep);
    out->integer_delay = b->delay;
    out->delay_fraction = 0.0;
    if (xf == NULL || tried == NULL) {
        free(xf);
        free(tried);
        return 1;
    }
    tried[0] = *b; /* the whole delays' choice, its other option set aside */
    *(out->with_creep ? &tried[0].holdout_rms : &tried[0].creep.holdout_rms) = NAN;
    base.delay = b->delay > 0u ? b->delay - 1u : 0u; /* D - 1 + f and D + f */
    for (i = 1u; i < FIT_FRACTIONS && isfinite(out->integer_holdout); ++i) {
        const double f = (double)i / (double)FIT_FRACTIONS;
        size_t n_tried;
        fit_delay_fraction(x, n, f, xf);
        /* a model with more parameters than the choice is never kept (below): not fitted */
        n_tried = fit_select(&base, kinds, 0u, t_degree, params, creep_tau, xf, y, n,
                             validation_fraction(v, f, xf + n, &vf), b->delay, tried + total,
                             per_fraction, &best, &wc);
        for (k = total; k < total + n_tried; ++k) {
            tried[k].fraction = f;
            for (wc = 0; wc <= 1; ++wc) {
                const double whole = whole_delay_rms(cand, out->count, &tried[k], wc);
                const unsigned p = fit_option_parameters(&tried[k], wc);
                const double e = fit_option_rms(&tried[k], wc);
                if (!(e < whole * (1.0 - FIT_FRACTION_GAIN) &&
                      (p < params || (p <= params + FIT_FRACTION_PARAMETERS && e < gain_limit)))) {
                    *(wc ? &tried[k].creep.holdout_rms : &tried[k].holdout_rms) = NAN;
                }
            }
        }
        total += n_tried;
    }
    fit_choose(tried, total, creep_tau, &best, &wc);
    if (best != (size_t)-1 && best > 0u) { /* a model at a fraction */
        const double f = tried[best].fraction;
        size_t at = whole_delay_index(cand, out->count, &tried[best]);
        if (at == (size_t)-1) {
            at = out->best;
        }
        out->integer_delay = tried[best].delay;
        out->integer_holdout = fit_option_rms(&cand[at], wc);
        cand[at] = tried[best];
        out->best = at;
        out->with_creep = wc;
        out->delay_fraction = f;
        fit_delay_fraction(x, n, f, x);
        if (v != NULL) {
            fit_delay_fraction(v->x, v->n, f, v->x);
        }
    }
    free(xf);
    free(tried);
    return 0;
}

hyst_status_t fit_search(const hyst_ident_config_t *base, int kinds, unsigned t_degree,
                         double creep_tau, int choose_delay, double *x, const double *y,
                         size_t n, const fit_validation_t *v, fit_candidate_t *cand,
                         size_t max_cand, fit_found_t *out)
{
    hyst_ident_config_t cfg = *base;
    size_t max_delay = base->delay;
    memset(out, 0, sizeof *out);
    out->integer_holdout = NAN;
    out->max_delay = base->delay;
    if (choose_delay) { /* delays scaled to the drive's period */
        cfg.delay = 0u;
        out->max_delay = fit_max_delay(x, cfg.skip, n);
        max_delay = out->max_delay;
        if (max_delay > FIT_MAX_DELAY) { /* the cheap model's best delay, then around it */
            out->cheap_delay = fit_cheap_delay(&cfg, x, y, n, v, max_delay);
            cfg.delay = out->cheap_delay > FIT_DELAY_AROUND ? out->cheap_delay - FIT_DELAY_AROUND
                                                             : 0u;
            max_delay = out->cheap_delay + FIT_DELAY_AROUND;
        }
    }
    out->count = fit_select(&cfg, kinds, 0u, t_degree, 0u, creep_tau, x, y, n, v, max_delay,
                            cand, max_cand, &out->best, &out->with_creep);
    if (out->best != (size_t)-1) {
        out->integer_delay = cand[out->best].delay;
        out->integer_holdout = fit_option_rms(&cand[out->best], out->with_creep);
    }
    if (choose_delay && out->best != (size_t)-1 &&
        search_fraction(&cfg, kinds, t_degree, creep_tau, x, y, n, v, cand, out) != 0) {
        return HYST_ERR_NOSPACE;
    }
    return HYST_OK;
}

/* The first infinite entry of v[0..n) (n if none). */
static size_t first_infinite(const double *v, size_t n)
{
    size_t k;
    for (k = 0u; k < n && !isinf(v[k]); ++k) {
    }
    return k;
}

/* 1 if the entries of v[0..n), NaN aside, are one number or none (*value
 * it, NaN if none). */
static int constant_column(const double *v, size_t n, double *value)
{
    size_t k;
    *value = fit_first_input(v, 0u, n);
    for (k = 0u; k < n; ++k) {
        if (!isnan(v[k]) && v[k] != *value) {
            return 0;
        }
    }
    return 1;
}

/* The correlation of the pairs (x[k], y[k]), k < n, with both present (NaN
 * when fewer than two, a column of them constant or the sums overflow). */
static double record_correlation(const double *x, const double *y, size_t n)
{
    double mx = 0.0, my = 0.0, sxx = 0.0, syy = 0.0, sxy = 0.0;
    size_t k, m = 0u;
    for (k = 0u; k < n; ++k) {
        m += !isnan(x[k]) && !isnan(y[k]) ? 1u : 0u;
    }
    if (m < 2u) {
        return NAN;
    }
    for (k = 0u; k < n; ++k) { /* each over m: the sum itself may overflow */
        if (!isnan(x[k]) && !isnan(y[k])) {
            mx += x[k] / (double)m;
            my += y[k] / (double)m;
        }
    }
    for (k = 0u; k < n; ++k) {
        if (!isnan(x[k]) && !isnan(y[k])) {
            sxx += (x[k] - mx) * (x[k] - mx);
            syy += (y[k] - my) * (y[k] - my);
            sxy += (x[k] - mx) * (y[k] - my);
        }
    }
    return sxx > 0.0 && syy > 0.0 ? sxy / sqrt(sxx) / sqrt(syy) : NAN;
}

int fit_record_check(const double *x, size_t nx, const double *y, size_t ny, size_t skip,
                     size_t delay, fit_record_t *r)
{
    const double *u, *v;
    double lo, hi;
    memset(r, 0, sizeof *r);
    r->value = NAN;
    r->correlation = NAN;
    if ((r->at = first_infinite(x, nx)) < nx) {
        r->value = x[r->at];
        return r->fault = FIT_RECORD_INFINITE_INPUT;
    }
    if ((r->at = first_infinite(y, ny)) < ny) {
        r->value = y[r->at];
        return r->fault = FIT_RECORD_INFINITE_OUTPUT;
    }
    r->at = 0u;
    if (nx != ny) {
        return FIT_RECORD_OK;
    }
    if (nx <= skip || nx - skip <= delay) {
        return r->fault = FIT_RECORD_NO_SAMPLE;
    }
    r->pairs = nx - skip - delay;
    u = x + skip;
    v = y + skip + delay;
    if (constant_column(u, r->pairs, &r->value)) {
        return r->fault = FIT_RECORD_CONSTANT_INPUT;
    }
    if (constant_column(v, r->pairs, &r->value)) {
        return r->fault = FIT_RECORD_CONSTANT_OUTPUT;
    }
    r->value = NAN;
    fit_input_range(u, 0u, r->pairs, 0.0, &lo, &hi);
    (void)fit_reversals(u, 0u, r->pairs, lo, hi, &r->minor);
    r->correlation = record_correlation(u, v, r->pairs);
    if (r->correlation < FIT_FALLING_CORRELATION) {
        return r->fault = FIT_RECORD_FALLING;
    }
    return FIT_RECORD_OK;
}

const char *fit_record_fault_name(int fault)
{
    static const char *const names[] = {"ok",        "infinite_input", "infinite_output",
                                        "no_sample", "constant_input", "constant_output",
                                        "falling"};
    return fault >= 0 && fault <= FIT_RECORD_FALLING ? names[fault] : "unknown";
}
