/* SPDX-License-Identifier: MIT */
/* Shared by `hyst sim` and `hyst inv`: the same options (--poly, --range,
 * --xcol, --tp, FILE) and the same engine, forward or on the inverse curve. */
#include "cli.h"
#include "hyst/hyst.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct tcm_run {
    const hyst_poly_t *f0;
    const hyst_curve_t *curve; /* an everett model's curve (sim) or its inverse (inv), else NULL */
    int inverse;
    const char *cmd;
    hyst_real_t *mem; /* the four turning-point arrays, cap entries each */
    size_t cap;
    hyst_t S;
    hyst_curve_t inv; /* the compensator's curve, kept by S */
    double *late;     /* sim --model with a delay: the last `delay` outputs, a ring */
    unsigned long delay, at;
    double fraction;  /* sim --model: the delay's fraction of a sample (0: none) */
    double previous;  /* the input before, for the fraction (NaN before the first) */
    /* its creep term (model->ncreep > 0) or rate term (model->has_rate), or NULL */
    const cli_model_t *model;
    hyst_creep_t creep;       /* lags of the model's input (sim) or of the drive (inv) */
    hyst_rate_t rate;         /* the low-pass of the same input's change */
    double lo, hi;            /* inv with creep: the range the engine clamps its input to */
} tcm_run_t;

/* Longest delay a model file may give sim (outputs held in memory). */
#define TCM_MAX_DELAY 1000000ul

/* Turning points the engine starts with; doubled whenever one array is
 * nearly full, so it never has to merge loops (the output is the full
 * model's) and holds what the trajectory needs, not one per sample. */
#define TCM_CAP0 256u

int cli_make_poly(const char *cmd, const char *model_path, const double *coeffs, size_t ncoef,
                  const double *range, size_t nrange, hyst_poly_t *f0)
{
    hyst_curve_t curve;
    hyst_status_t st;
    size_t i;
    if (ncoef == 0u) {
        return cli_fail(cmd, "--poly is required (see 'hyst %s --help')", cmd);
    }
    if (nrange == 0u) {
        return cli_fail(cmd, "--range is required (see 'hyst %s --help')", cmd);
    }
    if (!(range[0] < range[1])) {
        return cli_fail(cmd, "option --range: LO must be below HI");
    }
    f0->degree = (unsigned)(ncoef - 1u);
    f0->lo = (hyst_real_t)range[0];
    f0->hi = (hyst_real_t)range[1];
    for (i = 0u; i <= HYST_MAX_DEGREE; ++i) {
        f0->coeffs[i] = i < ncoef ? (hyst_real_t)coeffs[i] : 0;
    }
    st = hyst_curve_from_poly(&curve, f0);
    if (st == HYST_ERR_NOT_INCREASING) {
        hyst_wide_t c[HYST_MAX_DEGREE + 1], turn = 0;
        for (i = 0u; i < ncoef; ++i) {
            c[i] = (hyst_wide_t)coeffs[i];
        }
        (void)hyst_poly_is_increasing(c, f0->degree, range[0], range[1], &turn);
        return cli_fail(cmd, "%s%s: f0 is not increasing on [%g, %g] (slope negative at x = %.6g)",
                        model_path != NULL ? "model file " : "option --poly",
                        model_path != NULL ? model_path : "", range[0], range[1], (double)turn);
    }
    if (st != HYST_OK) {
        return cli_fail(cmd, "%s%s: %s", model_path != NULL ? "model file " : "options --poly/--range",
                        model_path != NULL ? model_path : "", hyst_status_str(st));
    }
    return 0;
}

/* r->S on fresh arrays of @p cap entries, into r->mem (the caller frees the old). */
static hyst_status_t tcm_init(tcm_run_t *r, size_t cap)
{
    hyst_real_t *mem;
    hyst_status_t st;
    if (cap > (size_t)-1 / (4u * sizeof(hyst_real_t)) ||
        (mem = (hyst_real_t *)malloc(4u * cap * sizeof(hyst_real_t))) == NULL) {
        return HYST_ERR_NOSPACE;
    }
    st = r->curve != NULL
             ? hyst_init_curve(&r->S, r->curve, mem, mem + cap, mem + 2u * cap, mem + 3u * cap, cap)
         : r->inverse
             ? hyst_init_inverse_exact(&r->S, &r->inv, r->f0, mem, mem + cap, mem + 2u * cap,
                                 mem + 3u * cap, cap)
             : hyst_init(&r->S, r->f0, mem, mem + cap, mem + 2u * cap, mem + 3u * cap, cap);
    if (st != HYST_OK) {
        free(mem);
        return st;
    }
    r->mem = mem;
    r->cap = cap;
    return HYST_OK;
}

static int tcm_begin(void *ctx)
{
    tcm_run_t *r = (tcm_run_t *)ctx;
    unsigned long i;
    const hyst_status_t st = tcm_init(r, TCM_CAP0);
    if (st == HYST_ERR_NOSPACE) {
        return cli_fail(r->cmd, "out of memory");
    }
    if (st != HYST_OK) {
        return cli_fail(r->cmd, "%s", hyst_status_str(st));
    }
    if (r->model != NULL && r->model->ncreep > 0u) { /* at rest at the drive's low end, as
                                                        the fit assumed */
        hyst_wide_t tau[CLI_CREEP_MAX_TERMS], w[CLI_CREEP_MAX_TERMS];
        hyst_status_t cst;
        for (i = 0u; i < r->model->ncreep; ++i) {
            tau[i] = (hyst_wide_t)r->model->creep_tau[i];
            w[i] = (hyst_wide_t)r->model->creep_weight[i];
        }
        cst = hyst_creep_init(&r->creep, r->model->ncreep, tau, w, (hyst_wide_t)r->model->lo);
        if (cst != HYST_OK) {
            return cli_fail(r->cmd, "the model's creep term: %s", hyst_status_str(cst));
        }
    }
    if (r->model != NULL && r->model->has_rate) {
        const hyst_status_t rst =
            hyst_rate_init(&r->rate, (hyst_wide_t)r->model->rate_tau,
                           (hyst_wide_t)r->model->rate_weight, (hyst_wide_t)r->model->lo);
        if (rst != HYST_OK) {
            return cli_fail(r->cmd, "the model's rate term: %s", hyst_status_str(rst));
        }
    }
    if (r->delay > 0u) { /* before the first input arrives: the model at rest, f0(lo) */
        if ((r->late = (double *)malloc(r->delay * sizeof(double))) == NULL) {
            return cli_fail(r->cmd, "out of memory");
        }
        for (i = 0u; i < r->delay; ++i) {
            r->late[i] = (double)hyst_output(&r->S);
        }
    }
    return 0;
}

/* Twice the turning-point memory, the state carried over bit for bit by a
 * snapshot (hyst/snapshot.h: the capacity may differ on restore). */
static int tcm_grow(tcm_run_t *r)
{
    hyst_real_t *old = r->mem;
    const size_t old_cap = r->cap;
    const size_t size = hyst_snapshot_size(&r->S);
    unsigned char *snap = (unsigned char *)malloc(size);
    hyst_status_t st =
        snap != NULL ? hyst_snapshot_save(&r->S, snap, size, NULL) : HYST_ERR_NOSPACE;
    if (st == HYST_OK) {
        st = tcm_init(r, 2u * old_cap); /* on error r->S and r->mem are untouched */
        if (st == HYST_OK) {
            st = hyst_snapshot_restore(&r->S, snap, size);
            free(old);
        }
    }
    free(snap);
    if (st == HYST_ERR_NOSPACE) {
        return cli_fail(r->cmd, "out of memory (%lu turning points stored)",
                        (unsigned long)hyst_tp_count(&r->S));
    }
    return st == HYST_OK ? 0 : cli_fail(r->cmd, "growing the turning-point memory: %s",
                                        hyst_status_str(st));
}

/* The model's creep and rate terms at the next sample (known before it). */
static double terms_output(const tcm_run_t *r)
{
    return (r->model->ncreep > 0u ? (double)hyst_creep_output(&r->creep) : 0.0) +
           (r->model->has_rate ? (double)hyst_rate_output(&r->rate) : 0.0);
}

/* Both terms take the input x in: their contribution, as terms_output(). */
static double terms_step(tcm_run_t *r, hyst_real_t x)
{
    return (r->model->ncreep > 0u ? (double)hyst_creep_step(&r->creep, x) : 0.0) +
           (r->model->has_rate ? (double)hyst_rate_step(&r->rate, x) : 0.0);
}

/* Whether a term refused its last input (beyond its drive limit). */
static int terms_refused(const tcm_run_t *r)
{
    return (r->model->ncreep > 0u && hyst_creep_status(&r->creep) != HYST_OK) ||
           (r->model->has_rate && hyst_rate_status(&r->rate) != HYST_OK);
}

static int tcm_step(void *ctx, double x, double *y, int *clamped)
{
    tcm_run_t *r = (tcm_run_t *)ctx;
    /* a sample stores at most one turning point: grow before an array is full */
    if ((hyst_ltp_count(&r->S) + 2u >= r->cap || hyst_rtp_count(&r->S) + 1u >= r->cap) &&
        tcm_grow(r) != 0) {
        return 1;
    }
    if (r->fraction > 0.0) { /* sim: the drive a fraction of a sample later */
        const double now = x;
        x = isnan(r->previous) ? x : (1.0 - r->fraction) * x + r->fraction * r->previous;
        r->previous = now;
    }
    if (r->model != NULL && r->inverse) { /* the desired output less the terms' share */
        const double v = x - terms_output(r);
        const double drive = (double)hyst_step(&r->S, (hyst_real_t)v);
        (void)terms_step(r, (hyst_real_t)drive);
        *y = drive;
        /* clamped beyond the rounding of a printed x (cli_map_samples() tests
         * x itself for the others) */
        const double tol = CLI_PRINT_TOL * fmax(fabs(x), fmax(fabs(r->lo), fabs(r->hi)));
        *clamped = hyst_status(&r->S) == HYST_WARN_CLAMPED && (v < r->lo - tol || v > r->hi + tol);
    } else if (r->model != NULL) { /* the terms of the input as the model took it */
        *y = (double)hyst_step(&r->S, (hyst_real_t)x);
        *y += terms_step(r, hyst_input(&r->S));
    } else {
        *y = (double)hyst_step(&r->S, (hyst_real_t)x);
    }
    if (r->late != NULL) { /* the sensor's reading now is the output `delay` samples ago */
        const double now = *y;
        *y = r->late[r->at];
        r->late[r->at] = now;
        r->at = r->at + 1u == r->delay ? 0u : r->at + 1u;
    }
    if ((hyst_events(&r->S) & HYST_EVENT_FULL) != 0u) {
        return cli_fail(r->cmd, "internal error: turning-point memory full");
    }
    if (r->model != NULL && (terms_refused(r) || !isfinite(*y))) {
        /* inv printed the previous drive and exited 0 where sim refused */
        return cli_fail(r->cmd, "the model's %s term overflows at drive %.9g (its weights "
                                "are too large for the drives)",
                        r->model->ncreep > 0u ? "creep" : "rate", hyst_input(&r->S));
    }
    if (r->model == NULL || !r->inverse) {
        *clamped = hyst_status(&r->S) == HYST_WARN_CLAMPED;
    }
    return 0;
}

static unsigned long tcm_tp(void *ctx)
{
    return (unsigned long)hyst_tp_count(&((tcm_run_t *)ctx)->S);
}

/* inv --intervals N [--rows R]: the firmware's tabulated compensator, its
 * table allocated here (firmware gives a static array of the same length):
 * kind poly hyst_curve_inverse_table() of f0's curve (what
 * hyst_init_inverse_table() does before attaching the instance), kind
 * everett hyst_curve_everett_inverse_table() of E's curve @p fwd, kind
 * spline hyst_curve_spline_inverse_table() of f0's curve @p fwd. The
 * curve into *tab, its table into *table (the caller frees it). */
static int tabulate(const char *cmd, const char *model_path, int kind, const hyst_poly_t *f0,
                    const hyst_curve_t *fwd, unsigned long intervals, unsigned long rows,
                    double **table, hyst_curve_t *tab)
{
    const int everett = kind == CLI_MODEL_EVERETT;
    const char *opts = everett ? "options --rows/--intervals" : "option --intervals";
    const double n = everett ? 2.0 * ((double)rows + 1.0) * 4.0 * ((double)intervals + 1.0)
                             : 4.0 * ((double)intervals + 1.0);
    hyst_curve_t poly;
    hyst_status_t st;
    *table = NULL;
    if (n * (double)sizeof(double) >= (double)(size_t)-1 ||
        (*table = (double *)malloc((size_t)n * sizeof(double))) == NULL) {
        return cli_fail(cmd, "%s: out of memory for a table of %.0f numbers (%.3g MB)", opts, n,
                        n * (double)sizeof(double) / 1e6);
    }
    if (everett) {
        st = hyst_curve_everett_inverse_table(tab, fwd, *table, (size_t)rows, (size_t)intervals);
    } else if (kind == CLI_MODEL_SPLINE) {
        st = hyst_curve_spline_inverse_table(tab, fwd, *table, (size_t)intervals);
    } else {
        st = hyst_curve_from_poly(&poly, f0);
        if (st == HYST_OK) {
            st = hyst_curve_inverse_table(tab, &poly, *table, (size_t)intervals);
        }
    }
    if (st != HYST_OK) {
        free(*table);
        *table = NULL;
        return cli_fail(cmd, "%s%s: %s",
                        model_path != NULL ? "model file " : "options --poly/--range",
                        model_path != NULL ? model_path : "", hyst_status_str(st));
    }
    return 0;
}

/* What init measured, on stderr after the results (stdout stays one drive
 * per line): the table's size, the intervals it left to exact evaluation and
 * hyst_curve_inverse_error(), a fraction of the drive range, and in drive
 * units. */
static void report_table(const char *cmd, const hyst_curve_t *tab, int everett,
                         unsigned long intervals, unsigned long rows)
{
    const double lo = tab->y_lo.f64, hi = tab->y_hi.f64; /* the inverse's values: the drive */
    const double err = (double)hyst_curve_inverse_error(tab);
    if (everett) {
        (void)fprintf(stderr, "hyst %s: tabulated compensator, %lu rows of %lu intervals (%lu of "
                              "the %lu intervals of both directions solved instead): ",
                      cmd, rows, intervals, (unsigned long)tab->u.everett.exact, 2ul * intervals);
    } else {
        (void)fprintf(stderr, "hyst %s: tabulated compensator, %lu interval%s (%lu of them "
                              "evaluated exactly): ",
                      cmd, intervals, intervals == 1ul ? "" : "s",
                      (unsigned long)tab->u.inv_table.exact);
    }
    (void)fprintf(stderr, "init's worst measured error %.9g of the drive range [%.9g, %.9g], "
                          "%.9g\n",
                  err, lo, hi, err * (hi - lo));
}

/* inv --model on the asymmetric kind: the compensator is the engine on the
 * inverse of its curve (hyst_curve_inverse(), curve.h), in place. */
static int everett_compensator(const char *cmd, const char *model_path, hyst_curve_t *curve)
{
    const hyst_status_t st = hyst_curve_inverse(curve, curve);
    return st == HYST_OK ? 0 : cli_fail(cmd, "model file %s: %s", model_path, hyst_status_str(st));
}

int cli_tcm_command(int argc, char **argv, const char *cmd, const char *help, int inverse)
{
    cli_args_t a;
    cli_samples_t s;
    cli_map_t m;
    tcm_run_t r;
    const char *v;
    double coeffs[HYST_MAX_DEGREE + 1], range[2];
    size_t ncoef = 0u, nrange = 0u;
    cli_model_t model;
    const char *model_path = NULL;
    int tp = 0, kind, rc;
    unsigned long digits = 9ul;
    hyst_poly_t f0;
    hyst_curve_t everett; /* a model of kind everett, everett_grid or spline */
    /* inv --intervals / --rows: 0 when not given (the library's defaults with "default") */
    unsigned long intervals = 0ul, rows = 0ul;
    hyst_curve_t tab; /* the tabulated compensator's curve */
    double *table = NULL;

    cli_args_init(&a, cmd, argc, argv);
    cli_samples_init(&s);
    while ((kind = cli_samples_next(&a, &s, help)) == CLI_OPT) {
        if (cli_is(&a, "--tp")) {
            tp = 1;
        } else if (cli_is(&a, "--poly")) {
            if ((v = cli_value(&a)) == NULL ||
                !cli_opt_list(&a, v, coeffs, 2u, HYST_MAX_DEGREE + 1u, &ncoef)) {
                return 1;
            }
        } else if (cli_is(&a, "--range")) {
            if ((v = cli_value(&a)) == NULL || !cli_opt_list(&a, v, range, 2u, 2u, &nrange)) {
                return 1;
            }
        } else if (cli_is(&a, "--digits")) {
            if ((v = cli_value(&a)) == NULL || !cli_opt_ulong(&a, v, 1ul, 17ul, &digits)) {
                return 1;
            }
        } else if (cli_is(&a, "--model")) {
            if ((model_path = cli_value(&a)) == NULL) {
                return 1;
            }
        } else if (inverse && (cli_is(&a, "--intervals") || cli_is(&a, "--rows"))) {
            const int is_rows = cli_is(&a, "--rows");
            if ((v = cli_value(&a)) == NULL ||
                !cli_opt_table_size(&a, v, is_rows, is_rows ? &rows : &intervals)) {
                return 1;
            }
        } else {
            return cli_unknown(&a);
        }
    }
    if (kind != CLI_END) {
        return kind == CLI_HELP ? 0 : 1;
    }
    memset(&model, 0, sizeof model);
    if (model_path != NULL) {
        if (ncoef > 0u || nrange > 0u) {
            return cli_fail(cmd, "--model replaces --poly and --range: give one or the other");
        }
        if (cli_model_read(cmd, model_path, &model) != 0) {
            return 1;
        }
    }
    /* the kind known (else cli_make_poly() says what is missing): --rows is the everett table's */
    if (model_path != NULL || ncoef > 0u) {
        if (cli_table_sizes(cmd, model.kind == CLI_MODEL_EVERETT, &intervals, &rows) != 0) {
            return 1;
        }
        if (rows > 0ul && intervals == 0ul) {
            return cli_fail(cmd, "option --rows needs --intervals (the tabulated compensator)");
        }
    }
    if (model_path != NULL && (model.kind == CLI_MODEL_GRID || model.kind == CLI_MODEL_SPLINE)) {
        static double grid_table[CLI_GRID_TABLE_LEN], spline_table[CLI_SPLINE_TABLE_LEN];
        const int spline = model.kind == CLI_MODEL_SPLINE;
        if (intervals > 0ul && !spline) {
            return cli_fail(cmd, "%s: kind everett_grid has no tabulated compensator (it solves "
                                 "each branch in closed form: inv --model without --intervals)",
                            model_path);
        }
        if ((spline ? cli_spline_curve(cmd, cli_file_name(model_path), &model, &everett,
                                       spline_table)
                    : cli_grid_curve(cmd, cli_file_name(model_path), &model, &everett,
                                     grid_table)) != 0) {
            return 1;
        }
        /* with --intervals the spline's compensator is tabulated from its curve below */
        if (inverse && intervals == 0ul &&
            (spline ? hyst_curve_spline_inverse(&everett, &everett)
                    : hyst_f64_curve_everett_grid_inverse(&everett, &everett)) != HYST_OK) {
            return cli_fail(cmd, "%s: the model has no compensator (%s)", model_path,
                            spline ? "f0 is flat between two knots: no drive there is the inverse"
                                   : "its outputs never rise");
        }
    }
    if (model_path != NULL) {
        size_t i;
        if (model.kind == CLI_MODEL_EVERETT &&
            (cli_everett_curve(cmd, cli_file_name(model_path), &model, &everett) != 0 ||
             (inverse && intervals == 0ul &&
              everett_compensator(cmd, cli_file_name(model_path), &everett) != 0))) {
            return 1;
        }
        if (!inverse && model.delay > TCM_MAX_DELAY) {
            return cli_fail(cmd, "%s: delay %lu above %lu samples", model_path, model.delay,
                            TCM_MAX_DELAY);
        }
        for (i = 0u; i < model.ncoef; ++i) {
            coeffs[i] = model.coeffs[i];
        }
        ncoef = model.ncoef;
        range[0] = model.lo;
        range[1] = model.hi;
        nrange = 2u;
        if (inverse && model.delay > 0u) {
            (void)fprintf(stderr, "hyst %s: %s: the model's delay of %lu samples is not "
                                  "compensated (a pure delay has no causal inverse): line k "
                                  "is the drive for desired output k\n",
                          cmd, model_path, model.delay);
        }
    }
    if (model.kind == CLI_MODEL_EVERETT || model.kind == CLI_MODEL_GRID ||
        model.kind == CLI_MODEL_SPLINE) {
        memset(&f0, 0, sizeof f0);
        r.curve = &everett;
    } else if (cli_make_poly(cmd, model_path, coeffs, ncoef, range, nrange, &f0) != 0) {
        return 1;
    } else {
        r.curve = NULL;
    }
    if (intervals > 0ul) { /* the tabulated compensator, on the engine as a curve */
        if (tabulate(cmd, model_path != NULL ? cli_file_name(model_path) : NULL, model.kind,
                     &f0, &everett, intervals, rows, &table, &tab) != 0) {
            return 1;
        }
        r.curve = &tab;
    }
    r.f0 = &f0;
    r.inverse = inverse;
    r.cmd = cmd;
    r.mem = NULL;
    r.cap = 0u;
    r.late = NULL;
    r.delay = inverse ? 0u : model.delay;
    r.fraction = inverse ? 0.0 : model.delay_fraction;
    r.previous = NAN;
    r.at = 0u;
    r.model = model.ncreep > 0u || model.has_rate ? &model : NULL;
    m.ctx = &r;
    m.begin = tcm_begin;
    m.step = tcm_step;
    m.col2 = tp ? tcm_tp : NULL;
    m.digits = (int)digits;
    m.has_identified = 0;
    if (inverse && model.kind != CLI_MODEL_POLY) {
        /* the inverse's domain: the outputs */
        m.clamp_what = "desired outputs";
        m.lo = intervals > 0ul ? tab.lo.f64 : everett.lo.f64;
        m.hi = intervals > 0ul ? tab.hi.f64 : everett.hi.f64;
    } else if (inverse) {
        m.clamp_what = "desired outputs";
        m.lo = (double)hyst_poly_eval(&f0, f0.lo);
        m.hi = (double)hyst_poly_eval(&f0, f0.hi);
    } else {
        m.clamp_what = "inputs";
        m.lo = range[0];
        m.hi = range[1];
        m.has_identified = model.has_identified;
        m.id_lo = model.id_lo;
        m.id_hi = model.id_hi;
    }
    m.step_checks_range = inverse && r.model != NULL;
    if (m.step_checks_range) {
        m.clamp_what = model.ncreep > 0u && model.has_rate
                           ? "desired outputs less the creep and rate terms"
                       : model.ncreep > 0u ? "desired outputs less the creep term"
                                           : "desired outputs less the rate term";
        r.lo = m.lo;
        r.hi = m.hi;
    }
    rc = cli_map_samples(cmd, &s, &m);
    if (rc == 0 && intervals > 0ul) {
        report_table(cmd, &tab, model.kind == CLI_MODEL_EVERETT, intervals, rows);
    }
    free(r.mem);
    free(r.late);
    free(table);
    return rc;
}
