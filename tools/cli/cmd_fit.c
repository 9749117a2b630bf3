/* SPDX-License-Identifier: MIT */
/* hyst fit: identify f0 from measured input/output columns. */
#include "cli.h"
#include "fit_pi.h"
#include "fit_select.h"
#include "hyst/hyst.h"

#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Longest --header-dir accepted (the header's path is built in a fixed buffer). */
#define CLI_HEADER_DIR_MAX 4096u

/* The highest --degree of any kind (each kind's own bound checked once
 * --kind is known): f0's degree, E's, the grid's or the spline's intervals. */
#define FIT_MOST_DEGREE_(a, b) ((a) > (b) ? (a) : (b))
#define FIT_MOST_DEGREE                                                                      \
    FIT_MOST_DEGREE_(FIT_MOST_DEGREE_(HYST_MAX_DEGREE, HYST_EVERETT_GRID_MAX_INTERVALS),     \
                     HYST_SPLINE_MAX_INTERVALS)

/* --kind pi without --operators: the size of the paper's Table 1 model. */
#define FIT_PI_DEFAULT_OPERATORS 10u

static const char help[] =
    "usage: hyst fit [--kind tcm|everett|everett_grid|spline] [--degree N]\n"
    "                [--t-degree K] [--skip S] [--delay D] [--xcol I --ycol J]\n"
    "                [--method joint|reflect|branches]\n"
    "                [--domain LO,HI] [--creep none|auto|TAU] [--rate none|auto|TAU]\n"
    "                [--header NAME] [--header-dir DIR] [--save MODEL]\n"
    "                [--validate OTHER] [--compare-pi N] [--decimal-comma] FILE\n"
    "       hyst fit --kind pi [--operators N] [--skip S] [--delay D]\n"
    "                [--xcol I --ycol J] [--decimal-comma] FILE\n"
    "\n"
    "Fits the major ascending curve f0 (polynomial of degree N) of the symmetric\n"
    "TCM, or the branch function E of the asymmetric kind (everett, degree N), to\n"
    "the input/output record in FILE ('-' = standard input), excited by a\n"
    "full-range periodic wave. Columns are separated by blanks, ',' or ';'; '#'\n"
    "lines and blank lines are skipped.\n"
    "\n"
    "  --degree N     polynomial degree, 1..9 (--kind everett: E's, 1..4;\n"
    "                 --kind everett_grid: the grid's knot intervals, 1..12;\n"
    "                 --kind spline: the spline's knot intervals, 1..32). Without\n"
    "                 it, the kind (unless --kind is given), the degree and the\n"
    "                 delay (unless --delay is given) are chosen by hold-out: each\n"
    "                 f0 of degree 1..9 and each E of degree 1..4 in each t-degree\n"
    "                 0..N-1, at each delay (0..8, or up to 1/64 of the drive's\n"
    "                 period, and a fraction of a sample), is fitted on the first two\n"
    "                 thirds of the record and the model predicts the last third,\n"
    "                 then (thirds of 100 samples or more) fitted on the first and\n"
    "                 last thirds and predicts the middle one (the RMS of both);\n"
    "                 of the candidates within 1 % of the lowest RMS prediction\n"
    "                 error, the one with the fewest parameters wins (every\n"
    "                 candidate is printed as a '# candidate' line). With N or\n"
    "                 --kind tcm, f0 on a drive with minor loops is biased: a\n"
    "                 warning says so\n"
    "  --t-degree K   --kind everett: fit only E's terms w^i t^j with j <= K\n"
    "                 (0..N-1; the others 0). Default: with --degree, N-1 (all\n"
    "                 terms); without, every K is a candidate. Major loops alone\n"
    "                 determine E of t-degree 1 at most\n"
    "  --skip S       drop the first S data lines (settling; default 0)\n"
    "  --delay D      the output lags the input by D samples (default: chosen by\n"
    "                 the same hold-out, with --degree too)\n"
    "  --xcol I       input column, 1-based (default 1)\n"
    "  --ycol J       output column, 1-based (default 2)\n"
    "  --method M     estimator of f0: joint (default): both branches in one\n"
    "                 least-squares problem; reflect: the paper's Eq. 14; branches:\n"
    "                 along every branch the record takes, minor loops included\n"
    "                 (E of t-degree 0, written as f0; degree 1..4)\n"
    "  --domain LO,HI domain of the model (default: the range of the inputs used);\n"
    "                 samples outside it are ignored\n";

/* More of the help text (one literal would pass the length C99 promises). */
static const char help_more[] =
    "  --creep C      a creep term (docs/creep.md): the output plus a weight\n"
    "                 times a lag of the input, for a drift under a sustained\n"
    "                 drive. auto (default): each candidate is scored alone and\n"
    "                 with one lag, its time constant the best of 100, 200, 500,\n"
    "                 ..., 20000 samples on the hold-out and its weight one\n"
    "                 parameter more, by the same rule; none: no creep term;\n"
    "                 TAU: a lag of TAU samples (1..1e9), always\n"
    "  --validate OTHER  a second record of the same actuator (validation data,\n"
    "                 the same columns and --skip): every choice above (kind,\n"
    "                 degree, delay, creep) is made on it instead of the hold-out:\n"
    "                 each candidate fitted on the whole of FILE, run from rest\n"
    "                 over OTHER and scored by its RMS error there. A record at\n"
    "                 another drive rate tells the dead time from a lag that\n"
    "                 imitates the loop's shape at FILE's rate\n"
    "  --rate R       a rate term (docs/rate.md), without --degree: the output\n"
    "                 plus a weight times a low-pass of the input's change per\n"
    "                 sample. none (default): no rate term; auto: the choice\n"
    "                 scored again with one of time constant 1 sample, 1/256\n"
    "                 and 1/64 of the drive's period, kept if it lowers the\n"
    "                 hold-out error by more than 1 %; TAU: of TAU samples,\n"
    "                 always (a hold-out at one rate cannot tell how the loops\n"
    "                 change at another)\n"
    "  --decimal-comma ',' is the decimal mark (1,5 is 1.5); fields are then\n"
    "                 separated by blanks or ';'\n"
    "  --header NAME  also write NAME.h holding\n"
    "                 'static const hyst_poly_t NAME = {...};' (kind everett:\n"
    "                 'static const hyst_everett_t NAME = {...};', kind spline:\n"
    "                 'static const hyst_spline_t NAME = {...};') for firmware\n"
    "                 (in the current directory, or in DIR with --header-dir)\n"
    "  --header-dir DIR  directory of NAME.h (an existing directory; needs --header)\n"
    "  --save MODEL   also write the model file MODEL (format hyst-model-text 1:\n"
    "                 the kind, f0 or E, the domain, the delay and the creep), which\n"
    "                 'hyst sim --model' and 'hyst header --model' read\n"
    "  --compare-pi N also fit a Prandtl-Ishlinskii model of N operators (see\n"
    "                 --kind pi) on the same first two thirds, with the same skip\n"
    "                 and delay, and print both models' hold-out RMS on the last\n"
    "                 third as a '# compare' line\n"
    "  --kind K       not given: tcm, everett, everett_grid and spline compared as\n"
    "                 above;\n"
    "                 tcm: f0 only; everett_grid: E on a grid (docs/theory.md);\n"
    "                 spline: f0 a monotone cubic spline on uniform knots, fitted\n"
    "                 along every branch (minor loops included; 2..16 intervals\n"
    "                 compared without --degree);\n"
    "                 everett: E only (least squares along the record, the model\n"
    "                 from rest at the first sample used); pi: the weights\n"
    "                 w1..wN >= 0 and an output offset of a\n"
    "                 Prandtl-Ishlinskii model of N one-sided play operators with\n"
    "                 thresholds r_i = (i - 1) (max - min) / N over the inputs'\n"
    "                 range, by non-negative least squares\n"
    "  --operators N  --kind pi: the number of operators, 1..64 (default 10)\n"
    "  --help         this text\n";

/* The rest of the help text. */
static const char help_output[] =
    "\n"
    "Output: line 1 the coefficients cN,...,c0 (highest power first; kind everett:\n"
    "E's terms; kind everett_grid: the cells' masses; kind spline: f0 at the\n"
    "knots), line 2 LO,HI, line 3 the RMS and max residual against the fitted\n"
    "major loop (kind everett, and f0 fitted along every branch: of the model run\n"
    "over the record; output units),\n"
    "then '#' comment lines. --kind pi: line 1 the weights, line 2 the thresholds,\n"
    "line 3 the offset, line 4 the RMS and max residual, then '#' comment lines,\n"
    "one of them the 'hyst pi' options that run the model.\n"
    "Exit status: 0 success; 1 bad option or input (nothing printed); 2 the fitted\n"
    "f0 is not increasing, the library refuses the fitted E (results printed, no\n"
    "header or model file written) or the PI weight w1 is 0 ('hyst pi' refuses it).\n";

/* --kind: not given (the automatic choice compares both TCM kinds), tcm
 * (the symmetric f0), everett (the asymmetric E) or pi. */
enum { FIT_KIND_AUTO, FIT_KIND_TCM, FIT_KIND_EVERETT, FIT_KIND_PI, FIT_KIND_GRID, FIT_KIND_SPLINE };

typedef struct fit_opts {
    hyst_ident_config_t cfg;
    unsigned long cols[2];
    const char *file;
    const char *header;
    const char *header_dir; /* NULL: the current directory */
    const char *save;       /* model file, or NULL */
    int have_degree;
    const char *degree_text; /* --degree as given */
    int have_t_degree;    /* --t-degree given */
    unsigned t_degree;    /* kind everett: --t-degree, or that of the model fitted */
    int have_delay;
    int decimal_comma;
    int kind;             /* --kind: FIT_KIND_AUTO (not given), _TCM, _EVERETT, _PI, _GRID
                             or _SPLINE */
    int final_kind;       /* of the model fitted: FIT_POLY, FIT_EVERETT, FIT_GRID or FIT_SPLINE */
    int as_poly;          /* E of t-degree 0 chosen with kind poly compared, or --method
                             branches: to be written as f0; once fitted, whether it was */
    int have_method;      /* --method given */
    int branches;         /* --method branches: f0 as E of t-degree 0, fitted along every branch */
    size_t operators;     /* --operators, 0 when not given */
    size_t compare_pi;    /* --compare-pi N, 0 when not given */
    double creep_tau;     /* --creep: -1 none, 0 auto (default), > 0 that time constant */
    int with_creep;       /* the model fitted has a creep term, of time constant creep.tau */
    fit_creep_t creep;    /* its hold-out figures (training fit) */
    double rate_tau;      /* --rate: -1 none (default), 0 auto, > 0 that time constant */
    int with_rate;        /* and a rate term, of time constant rate.rate_tau */
    fit_creep_t rate;     /* the best rate term tried (rate_tau 0: none) with the creep lag */
    double rate_without;  /* the choice's hold-out RMS without a rate term */
    double holdout;       /* the model's hold-out RMS without it (NaN: not scored) */
    double last_third;    /* the same on the last third alone (what PI-10 is compared on) */
    double resolution;    /* hold-out errors below it count as it (fit_resolution()) */
    char tcm_only[64];    /* an option given that --kind pi does not take, or "" */
    fit_excitation_t excitation; /* what the hold-out tested the choice on */
    size_t runner_up;     /* the best option of another model than the chosen ((size_t)-1: none) */
    int runner_up_creep;
    double pi10;          /* PI-10's hold-out RMS at the chosen delay (NaN: not scored) */
    double delay_fraction; /* the delay's fraction of a sample, chosen (0: none) */
    double integer_holdout; /* the choice's hold-out error at a whole delay */
    size_t integer_delay;   /* that delay */
    size_t max_delay;     /* delays searched 0..max_delay (scaled to the drive's period) */
    size_t cheap_delay;   /* max_delay > FIT_MAX_DELAY: the cheap model's best delay */
    const char *validate; /* --validate OTHER, or NULL */
    char vname[256];      /* its name in messages */
    const fit_validation_t *v; /* the record read from it, or NULL: the hold-out */
} fit_opts_t;

/* 0 on success, 1 after a message, -1 after --help. */
static int parse(fit_opts_t *o, int argc, char **argv)
{
    cli_args_t a;
    const char *pos = NULL, *v;
    char q[CLI_QUOTE_SIZE];
    unsigned long u;
    double dom[2];
    size_t nd;
    int kind;
    memset(o, 0, sizeof *o);
    o->rate_tau = -1.0; /* no rate term unless asked for */
    o->cols[0] = 1ul;
    o->cols[1] = 2ul;
    o->cfg.method = HYST_IDENT_JOINT;
    cli_args_init(&a, "fit", argc, argv);
    while ((kind = cli_args_next(&a, &pos)) != CLI_END) {
        if (kind < 0) {
            return 1;
        }
        if (kind == CLI_POS) {
            if (o->file != NULL) {
                char q2[CLI_QUOTE_SIZE];
                return cli_fail(a.cmd, "more than one input file (%s, %s)", cli_quote(q, o->file),
                                cli_quote(q2, pos));
            }
            o->file = pos;
            continue;
        }
        if (cli_is(&a, "--help") || cli_is(&a, "-h")) {
            (void)fputs(help, stdout);
            (void)fputs(help_more, stdout);
            (void)fputs(help_output, stdout);
            return -1;
        }
        if (cli_is(&a, "--decimal-comma")) {
            o->decimal_comma = 1;
            continue;
        }
        if ((v = cli_value(&a)) == NULL) {
            return 1;
        }
        if (!cli_is(&a, "--skip") && !cli_is(&a, "--delay") && !cli_is(&a, "--xcol") &&
            !cli_is(&a, "--ycol") && !cli_is(&a, "--kind") && !cli_is(&a, "--operators")) {
            (void)snprintf(o->tcm_only, sizeof o->tcm_only, "%s", a.opt);
        }
        if (cli_is(&a, "--kind")) {
            if (strcmp(v, "everett_grid") == 0 || strcmp(v, "spline") == 0) {
                o->kind = v[0] == 's' ? FIT_KIND_SPLINE : FIT_KIND_GRID;
            } else if (strcmp(v, "tcm") == 0 || strcmp(v, "everett") == 0 || strcmp(v, "pi") == 0) {
                o->kind = v[0] == 't' ? FIT_KIND_TCM : v[0] == 'e' ? FIT_KIND_EVERETT : FIT_KIND_PI;
            } else {
                return cli_fail(a.cmd, "option --kind: %s is neither tcm nor pi nor everett nor "
                                       "everett_grid nor spline",
                                cli_quote(q, v));
            }
        } else if (cli_is(&a, "--operators") || cli_is(&a, "--compare-pi")) {
            if (!cli_opt_ulong(&a, v, 1ul, HYST_PI_FIT_MAX_OPERATORS, &u)) {
                return 1;
            }
            *(cli_is(&a, "--operators") ? &o->operators : &o->compare_pi) = (size_t)u;
        } else if (cli_is(&a, "--degree")) {
            /* each kind's own bound is checked below, once --kind is known */
            if (!cli_opt_ulong(&a, v, 1ul, FIT_MOST_DEGREE, &u)) {
                return 1;
            }
            o->cfg.degree = (unsigned)u;
            o->have_degree = 1;
            o->degree_text = v;
        } else if (cli_is(&a, "--t-degree")) {
            if (!cli_opt_ulong(&a, v, 0ul, HYST_EVERETT_MAX_DEGREE - 1ul, &u)) {
                return 1;
            }
            o->t_degree = (unsigned)u;
            o->have_t_degree = 1;
        } else if (cli_is(&a, "--skip") || cli_is(&a, "--delay")) {
            if (!cli_opt_ulong(&a, v, 0ul, 1000000000ul, &u)) {
                return 1;
            }
            *(cli_is(&a, "--skip") ? &o->cfg.skip : &o->cfg.delay) = (size_t)u;
            o->have_delay |= cli_is(&a, "--delay");
        } else if (cli_is(&a, "--xcol") || cli_is(&a, "--ycol")) {
            if (!cli_opt_ulong(&a, v, 1ul, CLI_MAX_FIELD, &u)) {
                return 1;
            }
            o->cols[cli_is(&a, "--xcol") ? 0 : 1] = u;
        } else if (cli_is(&a, "--method")) {
            o->have_method = 1;
            if (strcmp(v, "joint") == 0) {
                o->cfg.method = HYST_IDENT_JOINT;
            } else if (strcmp(v, "reflect") == 0) {
                o->cfg.method = HYST_IDENT_REFLECT;
            } else if (strcmp(v, "branches") == 0) {
                o->branches = 1;
            } else {
                return cli_fail(a.cmd, "option --method: %s is not joint, reflect or branches",
                                cli_quote(q, v));
            }
        } else if (cli_is(&a, "--domain")) {
            if (!cli_opt_list(&a, v, dom, 2u, 2u, &nd)) {
                return 1;
            }
            if (!(dom[0] < dom[1])) {
                return cli_fail(a.cmd, "option --domain: LO must be below HI in %s",
                                cli_quote(q, v));
            }
            o->cfg.lo = dom[0];
            o->cfg.hi = dom[1];
        } else if (cli_is(&a, "--header")) {
            if (!cli_c_identifier(v)) {
                return cli_fail(a.cmd, "option --header: %s is not a C identifier",
                                cli_quote(q, v));
            }
            o->header = v;
        } else if (cli_is(&a, "--save")) {
            if (strcmp(v, "-") == 0) { /* standard input's name: not a file to create */
                return cli_fail(a.cmd, "option --save: '-' is not a model file name (standard "
                                       "output holds the results; name a file, or ./- for one "
                                       "called -)");
            }
            o->save = v;
        } else if (cli_is(&a, "--rate")) {
            double tau;
            if (strcmp(v, "none") == 0 || strcmp(v, "auto") == 0) {
                o->rate_tau = v[0] == 'n' ? -1.0 : 0.0;
            } else if (!cli_parse_double(v, &tau) || !(tau >= 1.0) || !(tau <= 1e9)) {
                return cli_fail(a.cmd, "option --rate: %s is not none, auto or a time constant "
                                       "of 1 to 1e9 samples",
                                cli_quote(q, v));
            } else {
                o->rate_tau = tau;
            }
        } else if (cli_is(&a, "--creep")) {
            double tau;
            if (strcmp(v, "none") == 0 || strcmp(v, "auto") == 0) {
                o->creep_tau = v[0] == 'n' ? -1.0 : 0.0;
            } else if (!cli_parse_double(v, &tau) || !(tau >= 1.0) || !(tau <= 1e9)) {
                return cli_fail(a.cmd, "option --creep: %s is not none, auto or a time constant "
                                       "of 1 to 1e9 samples",
                                cli_quote(q, v));
            } else {
                o->creep_tau = tau;
            }
        } else if (cli_is(&a, "--validate")) {
            o->validate = v;
        } else if (cli_is(&a, "--header-dir")) {
            if (v[0] == '\0' || strlen(v) > CLI_HEADER_DIR_MAX) {
                return cli_fail(a.cmd, "option --header-dir: %s is empty or longer than %u bytes",
                                cli_quote(q, v), (unsigned)CLI_HEADER_DIR_MAX);
            }
            o->header_dir = v;
        } else {
            return cli_unknown(&a);
        }
    }
    if (o->file == NULL) {
        return cli_fail(a.cmd, "no input FILE (use '-' for standard input)");
    }
    if (o->header_dir != NULL && o->header == NULL) {
        return cli_fail(a.cmd, "option --header-dir needs --header NAME");
    }
    if (o->cols[0] == o->cols[1]) { /* an identity fitted exactly: never what was meant */
        return cli_fail(a.cmd, "options --xcol and --ycol both name column %lu: the output would "
                               "be the input",
                        o->cols[0]);
    }
    if (o->validate != NULL && o->compare_pi != 0u) {
        return cli_fail(a.cmd, "option --compare-pi compares on the last third of FILE: it does "
                               "not combine with --validate");
    }
    if (o->validate != NULL && strcmp(o->validate, "-") == 0 && strcmp(o->file, "-") == 0) {
        return cli_fail(a.cmd, "option --validate: '-' and FILE '-' both name standard input "
                               "(it holds one record)");
    }
    if (o->have_degree && o->rate_tau >= 0.0) {
        return cli_fail(a.cmd, "option --rate applies to the automatic choice (without --degree)");
    }
    if (o->kind == FIT_KIND_PI && o->tcm_only[0] != '\0') {
        return cli_fail(a.cmd, "option %s does not apply to --kind pi", o->tcm_only);
    }
    if (o->kind == FIT_KIND_EVERETT && o->have_method) {
        return cli_fail(a.cmd, "option --method does not apply to --kind everett (it chooses "
                               "the estimator of the symmetric f0)");
    }
    if (o->kind != FIT_KIND_GRID && o->kind != FIT_KIND_SPLINE && o->kind != FIT_KIND_EVERETT &&
        o->have_degree && o->cfg.degree > HYST_MAX_DEGREE) {
        return cli_fail(a.cmd, "option --degree: %u is above %u, the highest degree of f0 "
                               "(--kind everett_grid: intervals up to %u; --kind spline: up to "
                               "%u)",
                        o->cfg.degree, (unsigned)HYST_MAX_DEGREE,
                        (unsigned)HYST_EVERETT_GRID_MAX_INTERVALS,
                        (unsigned)HYST_SPLINE_MAX_INTERVALS);
    }
    if ((o->kind == FIT_KIND_GRID || o->kind == FIT_KIND_SPLINE) && o->have_degree) {
        const unsigned most = o->kind == FIT_KIND_GRID ? HYST_EVERETT_GRID_MAX_INTERVALS
                                                       : HYST_SPLINE_MAX_INTERVALS;
        if (o->cfg.degree > most) { /* as cli_opt_ulong() says it */
            return cli_fail(a.cmd, "option --degree: %s is not an integer in 1..%u",
                            cli_quote(q, o->degree_text), most);
        }
    }
    if (o->kind == FIT_KIND_EVERETT && o->have_degree && o->cfg.degree > HYST_EVERETT_MAX_DEGREE) {
        return cli_fail(a.cmd, "option --degree: %u is above %u, the highest degree of --kind "
                               "everett",
                        o->cfg.degree, (unsigned)HYST_EVERETT_MAX_DEGREE);
    }
    if (o->have_t_degree && o->kind != FIT_KIND_EVERETT) {
        return cli_fail(a.cmd, "option --t-degree needs --kind everett");
    }
    if (o->kind == FIT_KIND_EVERETT && o->have_degree && o->have_t_degree &&
        o->t_degree >= o->cfg.degree) {
        return cli_fail(a.cmd, "option --t-degree: %u is not below --degree %u", o->t_degree,
                        o->cfg.degree);
    }
    if (o->kind == FIT_KIND_EVERETT && o->have_degree && !o->have_t_degree) {
        o->t_degree = o->cfg.degree - 1u; /* all of E's terms */
    }
    if ((o->kind == FIT_KIND_GRID || o->kind == FIT_KIND_SPLINE) && o->have_method) {
        return cli_fail(a.cmd, "option --method does not apply to --kind %s",
                        o->kind == FIT_KIND_GRID ? "everett_grid"
                                                 : "spline (fitted along every branch)");
    }
    if (o->branches && o->have_degree && o->cfg.degree > HYST_EVERETT_MAX_DEGREE) {
        return cli_fail(a.cmd, "option --degree: %u is above %u, the highest degree --method "
                               "branches fits (f0 as E of t-degree 0)",
                        o->cfg.degree, (unsigned)HYST_EVERETT_MAX_DEGREE);
    }
    if (o->branches) { /* the symmetric kind fitted as E of the width alone, written as f0 */
        o->t_degree = 0u;
        o->have_t_degree = 1;
        o->as_poly = 1;
    }
    o->final_kind = o->kind == FIT_KIND_EVERETT || o->branches ? FIT_EVERETT
                    : o->kind == FIT_KIND_GRID                 ? FIT_GRID
                    : o->kind == FIT_KIND_SPLINE               ? FIT_SPLINE
                                                               : FIT_POLY;
    if (o->kind != FIT_KIND_PI && o->operators != 0u) {
        return cli_fail(a.cmd, "option --operators needs --kind pi (or use --compare-pi N)");
    }
    if (o->operators == 0u) {
        o->operators = FIT_PI_DEFAULT_OPERATORS;
    }
    return 0;
}

static const char *method_name(int m) { return m == HYST_IDENT_REFLECT ? "reflect" : "joint"; }

/* ---- the automatic choice (fit_select.c) ---- */

#define MAX_CANDIDATES FIT_SEARCH_CANDIDATES
static fit_candidate_t candidates[MAX_CANDIDATES];
static size_t n_candidates, best_candidate;

/* The kinds the automatic choice compares: every one unless --kind names one. */
static int candidate_kinds(const fit_opts_t *o)
{
    return o->branches                   ? FIT_EVERETT
           : o->kind == FIT_KIND_TCM     ? FIT_POLY
           : o->kind == FIT_KIND_EVERETT ? FIT_EVERETT
           : o->kind == FIT_KIND_GRID    ? FIT_GRID
           : o->kind == FIT_KIND_SPLINE  ? FIT_SPLINE
                                         : FIT_POLY | FIT_EVERETT | FIT_GRID | FIT_SPLINE;
}

/* Why an E fit is singular: its terms are not determined by the turning
 * points the record visits. Major loops alone (every branch starts at lo or
 * hi) determine E linear in t at most. */
static const char everett_singular[] =
    "the record's turning points do not determine E of this degree; major loops alone "
    "determine t-degree 1 at most";

static void rank_others(fit_opts_t *o, const cli_table_t *t);

/* Sets o->final_kind, o->cfg.degree and .delay by hold-out: 0, or 1 after a message. */
static int choose(fit_opts_t *o, const char *name, cli_table_t *t)
{
    fit_found_t found;
    if (fit_search(&o->cfg, candidate_kinds(o), o->have_t_degree ? o->t_degree : FIT_ANY_T_DEGREE,
                   o->creep_tau, !o->have_delay, t->col[0], t->col[1], t->n, o->v, candidates,
                   MAX_CANDIDATES, &found) != HYST_OK) {
        return cli_fail("fit", "%s: out of memory", name);
    }
    n_candidates = found.count;
    best_candidate = found.best;
    o->with_creep = found.with_creep;
    if (!o->have_delay) {
        o->max_delay = found.max_delay;
        o->cheap_delay = found.cheap_delay;
        o->delay_fraction = found.delay_fraction;
        o->integer_delay = found.integer_delay;
        o->integer_holdout = found.integer_holdout;
    }
    if (best_candidate == (size_t)-1) {
        return cli_fail("fit", "%s: no candidate degree gave %s that could predict %s (give "
                               "--degree)",
                        name, o->v != NULL ? o->vname : "the last third of the record",
                        o->kind == FIT_KIND_EVERETT               ? "an E the library accepts"
                        : o->kind == FIT_KIND_TCM || o->branches ? "an increasing f0"
                        : o->kind == FIT_KIND_SPLINE             ? "a spline f0 the library "
                                                                   "accepts"
                                                                 : "an increasing f0 or an E the "
                                                                   "library accepts");
    }
    { /* a rate term, scored on the choice's hold-out (the drive and domain it was fitted on) */
        fit_candidate_t with_rate;
        o->with_rate = fit_rate_search(&o->cfg, t->col[0], t->col[1], t->n, o->v,
                                       &candidates[best_candidate], o->with_creep, o->rate_tau,
                                       &with_rate);
        o->rate = with_rate.creep;
        o->rate_without = fit_option_rms(&candidates[best_candidate], o->with_creep);
    }
    o->final_kind = candidates[best_candidate].kind;
    o->cfg.degree = candidates[best_candidate].degree;
    o->t_degree = candidates[best_candidate].t_degree;
    o->cfg.delay = candidates[best_candidate].delay;
    o->as_poly = o->final_kind == FIT_EVERETT && o->t_degree == 0u &&
                 ((candidate_kinds(o) & FIT_POLY) != 0 || o->branches);
    o->resolution = fit_resolution(t->col[1], t->n, o->cfg.skip, o->cfg.delay, o->v);
    { /* a widened one: the domain of the model fitted on it all */
        double lo, hi;
        if (fit_chosen_domain(&candidates[best_candidate], t->col[0], o->cfg.skip, t->n, &lo,
                              &hi)) {
            o->cfg.lo = lo;
            o->cfg.hi = hi;
        }
    }
    o->creep = candidates[best_candidate].creep;
    /* at the chosen delay: the hold-out's inputs beyond the part fitted
     * (predicted by branches continued beyond it, or clamped), its range and
     * minor loops */
    if (o->v != NULL) { /* OTHER's inputs against the whole record's */
        fit_validation_excitation(t->col[0], o->cfg.skip, t->n - o->cfg.delay, o->v,
                                  o->cfg.delay, &o->excitation);
    } else {
        fit_holdout_excitation(t->col[0], t->col[1], o->cfg.skip, t->n - o->cfg.delay,
                               o->cfg.delay, &o->excitation);
    }
    rank_others(o, t);
    o->holdout = candidates[best_candidate].holdout_rms;
    o->last_third = candidates[best_candidate].last_third_rms;
    return 0;
}

/* --degree given: the creep term of the model as given, scored by the same
 * hold-out, or on OTHER (with it only if the model without it errs by more
 * than FIT_PARSIMONY over it; always with --creep TAU). */
static void choose_creep(fit_opts_t *o, const cli_table_t *t)
{
    fit_candidate_t c;
    memset(&c, 0, sizeof c);
    c.kind = o->final_kind;
    c.degree = o->cfg.degree;
    c.t_degree = o->t_degree;
    c.delay = o->cfg.delay;
    fit_score(&o->cfg, t->col[0], t->col[1], t->n, o->v, o->creep_tau, &c);
    o->holdout = c.holdout_rms;
    o->last_third = c.last_third_rms;
    if (o->creep_tau >= 0) {
        o->creep = c.creep;
    }
    o->with_creep = o->creep_tau >= 0 && o->creep.tau > 0 && isfinite(o->creep.holdout_rms) &&
                    (o->creep_tau > 0 ||
                     !(o->holdout <= o->creep.holdout_rms * (1.0 + FIT_PARSIMONY)));
}

/* On stderr: what the hold-out part did not test the choice on. */
static void warn_excitation(const fit_opts_t *o, const char *name)
{
    if (o->v != NULL) { /* the validation record against the record fitted */
        if (o->excitation.span < FIT_HOLDOUT_MIN_SPAN) {
            (void)fprintf(stderr, "hyst fit: warning: %s: its inputs span %.3g %% of the range "
                                  "of %s's: the choice was not tested over the rest of it\n",
                          o->vname, 100.0 * o->excitation.span, name);
        }
        if (o->excitation.minor == 0u) {
            (void)fprintf(stderr, "hyst fit: warning: %s holds no minor loop (every reversal "
                                  "at an end of %s's inputs' range or beyond): the choice was "
                                  "not tested on minor loops\n",
                          o->vname, name);
        }
        return;
    }
    if (o->excitation.span < FIT_HOLDOUT_MIN_SPAN) {
        (void)fprintf(stderr, "hyst fit: warning: %s: the last third's inputs span %.3g %% of "
                              "the record's range: the choice was not tested over the rest of "
                              "it\n",
                      name, 100.0 * o->excitation.span);
    }
    if (o->excitation.minor == 0u) {
        (void)fprintf(stderr, "hyst fit: warning: %s: the last third holds no minor loop (every "
                              "reversal at an end of the inputs' range): the choice was not "
                              "tested on minor loops\n",
                      name);
    }
}

/* On stderr: f0 of a given degree, or of the degree chosen among f0 alone
 * (--kind tcm), fitted on a drive with minor loops (reversals inside its
 * range), whose samples lie on neither major branch although the estimator
 * takes each for one of them. */
static void warn_minor_loops(const fit_opts_t *o, const char *name, size_t minor)
{
    char what[32];
    (void)snprintf(what, sizeof what, o->have_degree ? "of --degree %u" : "of every degree",
                   o->cfg.degree);
    (void)fprintf(stderr, "hyst fit: warning: %s: the drive has %lu reversal%s inside its "
                          "range (minor loops): f0 %s is biased, its fit taking every rising "
                          "sample for the major ascending branch and every falling one for the "
                          "descending; leave out %s, or fit --method branches (f0 along every "
                          "branch)\n",
                  name, (unsigned long)minor, minor == 1u ? "" : "s", what,
                  o->have_degree ? "--degree to let fit choose"
                                 : "--kind tcm to let fit compare E too");
}

/* The same model (kind, degree, t-degree, domain, creep option) at any delay. */
static int same_model(const fit_candidate_t *a, int a_creep, const fit_candidate_t *b, int b_creep)
{
    return a->kind == b->kind && a->degree == b->degree && a->t_degree == b->t_degree &&
           a->widened == b->widened && a_creep == b_creep;
}

/* Into o: the runner-up, the lowest hold-out error of another model than
 * the chosen, and PI-10 on the same split at the chosen delay. */
static void rank_others(fit_opts_t *o, const cli_table_t *t)
{
    const fit_candidate_t *b = &candidates[best_candidate];
    double lowest = NAN, r[HYST_PI_FIT_MAX_OPERATORS], w[HYST_PI_FIT_MAX_OPERATORS];
    hyst_pi_fit_config_t cfg;
    hyst_pi_fit_result_t res;
    hyst_status_t st;
    size_t i;
    int wc;
    o->runner_up = (size_t)-1;
    o->runner_up_creep = 0;
    for (i = 0u; i < n_candidates; ++i) {
        for (wc = 0; wc <= 1; ++wc) {
            const double e = fit_option_rms(&candidates[i], wc);
            if (isfinite(e) && !same_model(&candidates[i], wc, b, o->with_creep) &&
                !(lowest <= e)) {
                lowest = e;
                o->runner_up = i;
                o->runner_up_creep = wc;
            }
        }
    }
    memset(&cfg, 0, sizeof cfg);
    cfg.operators = FIT_PI_DEFAULT_OPERATORS;
    cfg.skip = o->cfg.skip;
    cfg.delay = o->cfg.delay;
    /* PI's hold-out is the last third: against a choice made on OTHER, none */
    o->pi10 = o->v != NULL ? NAN : fit_pi_holdout(&cfg, t->col[0], t->col[1], t->n, &st, &res, r, w);
}

/* A candidate's name in the printout into name[0..size). */
static void candidate_name(const fit_candidate_t *c, char *name, size_t size)
{
    const char *widened = c->widened ? " widened" : "";
    if (c->kind == FIT_GRID || c->kind == FIT_SPLINE) {
        (void)snprintf(name, size, "%s intervals %u%s", fit_kind_name(c->kind), c->degree,
                       widened);
    } else if (c->kind == FIT_EVERETT) {
        (void)snprintf(name, size, "everett degree %u t-degree %u%s", c->degree, c->t_degree,
                       widened);
    } else {
        (void)snprintf(name, size, "degree %u%s", c->degree, widened);
    }
}

/* --degree without --delay: the delay by the same hold-out (fit_given_delay()).
 * 0, or 1 when out of memory. */
static int choose_delay(fit_opts_t *o, cli_table_t *t)
{
    fit_found_t found;
    size_t delay;
    if (fit_given_delay(&o->cfg, o->final_kind, o->t_degree, t->col[0], t->col[1], t->n, o->v,
                        &delay, &found) != HYST_OK) {
        return 1;
    }
    o->cfg.delay = delay;
    o->max_delay = found.max_delay;
    o->integer_delay = found.integer_delay;
    o->integer_holdout = found.integer_holdout;
    o->delay_fraction = found.delay_fraction;
    return 0;
}

/* The kinds the automatic choice compared, in words. */
static const char *kinds_compared(const fit_opts_t *o)
{
    if (o->branches) {
        return "poly, f0 fitted along every branch (E of t-degree 0)";
    }
    return candidate_kinds(o) == (FIT_POLY | FIT_EVERETT | FIT_GRID | FIT_SPLINE)
               ? "poly, everett, everett_grid, spline"
               : fit_kind_name(candidate_kinds(o));
}

/* The delays the automatic choice searched, when scaled to the drive. */
static void print_delays_searched(const fit_opts_t *o)
{
    if (o->max_delay > FIT_MAX_DELAY) {
        (void)printf("# delays searched 0..%lu (1/%u of the drive's period): f0 of degree 3 "
                     "predicts best at %lu; every candidate at %lu..%lu\n",
                     (unsigned long)o->max_delay, (unsigned)FIT_DELAY_PERIOD_FRACTION,
                     (unsigned long)o->cheap_delay,
                     (unsigned long)(o->cheap_delay > FIT_DELAY_AROUND
                                         ? o->cheap_delay - FIT_DELAY_AROUND
                                         : 0u),
                     (unsigned long)(o->cheap_delay + FIT_DELAY_AROUND));
    }
}

/* The choice in words into buf: "degree N, delay D (kind K, [t-degree T, ]
 * [creep, ][rate, ]P parameters". */
static void chosen_words(const fit_opts_t *o, char *buf, size_t size)
{
    char t_deg[32] = "";
    if (o->final_kind == FIT_EVERETT) {
        (void)snprintf(t_deg, sizeof t_deg, "t-degree %u, ", o->t_degree);
    }
    (void)snprintf(buf, size, "degree %u, delay %lu (kind %s, %s%s%u parameters",
                   o->cfg.degree, (unsigned long)o->cfg.delay, fit_kind_name(o->final_kind),
                   t_deg,
                   o->with_creep ? (o->with_rate ? "creep, rate, " : "creep, ")
                   : o->with_rate ? "rate, " : "",
                   fit_option_parameters(&candidates[best_candidate], o->with_creep) +
                       (o->with_rate ? FIT_RATE_PARAMETERS : 0u));
}

/* The lines of what the choice was tested on (`what`: hold-out or
 * validation) against the range of the `fitted` part or record. */
static void print_excitation(const fit_opts_t *o, const char *what, const char *fitted)
{
    (void)printf("# %s: %lu of its %lu inputs outside [%.9g, %.9g], the range of the %s "
                 "fitted%s\n",
                 what, (unsigned long)o->excitation.beyond, (unsigned long)o->excitation.holdout_n,
                 o->excitation.fitted_lo, o->excitation.fitted_hi, fitted,
                 o->excitation.beyond > 0u ? " (predicted by the branches continued beyond it: "
                                             "poly, everett and spline widened; the grid "
                                             "clamps them)"
                                           : "");
    (void)printf("# %s excitation: its inputs span %.3g %% of the record's range, %lu reversals "
                 "inside it (minor loops)\n",
                 what, 100.0 * o->excitation.span, (unsigned long)o->excitation.minor);
    if (isfinite(o->excitation.noise)) {
        (void)printf("# %s noise floor: rms %.6g, the white noise of its outputs (from their "
                     "third and fourth differences away from the drive's turns, no model): no "
                     "prediction scores below it\n",
                     what, o->excitation.noise);
    } else {
        (void)printf("# %s noise floor: not resolved (its outputs' third and fourth differences "
                     "away from the drive's turns disagree, or none is: sampled too coarsely to "
                     "tell their noise from their signal)\n",
                     what);
    }
}

/* --validate: what the choice was scored on, and the lines of its inputs. */
static void print_validated(const fit_opts_t *o)
{
    char chosen[128];
    chosen_words(o, chosen, sizeof chosen);
    (void)printf("# chosen on %s: %s: the fewest within 1 %% of the lowest RMS error on its %lu "
                 "samples, each candidate fitted on the whole record and run from rest over it; "
                 "kinds compared: %s): validation rms %.6g\n",
                 o->vname, chosen, (unsigned long)o->excitation.holdout_n, kinds_compared(o),
                 o->with_rate ? o->rate.holdout_rms
                              : fit_option_rms(&candidates[best_candidate], o->with_creep));
    print_excitation(o, "validation", "record");
    print_delays_searched(o);
}

/* Without --validate: what the choice was scored on, and the hold-out's inputs. */
static void print_holdout(const fit_opts_t *o)
{
    char chosen[128];
    chosen_words(o, chosen, sizeof chosen);
    (void)printf("# chosen by hold-out: %s: the fewest within 1 %% of the lowest RMS prediction "
                 "error on the last third of the record, fitted on the first two thirds, and on "
                 "the middle third, fitted on the others, when each third holds %u samples or "
                 "more; kinds compared: %s)\n",
                 chosen, (unsigned)FIT_SPLIT_MIN, kinds_compared(o));
    print_delays_searched(o);
    print_excitation(o, "hold-out", "part");
}

static void print_candidates(const fit_opts_t *o)
{
    const char *score = o->v != NULL ? "validation rms" : "hold-out rms";
    size_t i;
    if (o->v != NULL) {
        print_validated(o);
    } else {
        print_holdout(o);
    }
    if (o->as_poly) {
        (void)printf("# written as kind poly: E of t-degree 0 is the symmetric model, the f0 of "
                     "line 1, whose compensator is a table (hyst inv)\n");
    }
    {
        const double chosen = fit_option_rms(&candidates[best_candidate], o->with_creep);
        char name[48];
        if (o->runner_up != (size_t)-1) {
            const fit_candidate_t *r = &candidates[o->runner_up];
            candidate_name(r, name, sizeof name);
            (void)printf("# runner-up: %s delay %lu%s (%u parameters): %s %.6g, the chosen "
                         "%.6g\n",
                         name, (unsigned long)r->delay, o->runner_up_creep ? " with creep" : "",
                         fit_option_parameters(r, o->runner_up_creep), score,
                         fit_option_rms(r, o->runner_up_creep), chosen);
        }
        if (chosen <= o->resolution) {
            (void)printf("# %s %.6g is the record's resolution (a millionth of its output's "
                         "range): errors below it count as it, the candidates there fit "
                         "the record to its rounding alike and the fewest parameters win\n",
                         score, o->resolution);
        }
        if (isfinite(o->pi10)) { /* PI's fit takes no outputs left out: the last third */
            const double third = fit_option_last_third(&candidates[best_candidate], o->with_creep);
            (void)printf("# PI-10 on the same split (the last third, delay %lu, 11 parameters): "
                         "hold-out rms %.6g, the chosen %.6g; PI-10 / chosen %.3g\n",
                         (unsigned long)o->cfg.delay, o->pi10, third, o->pi10 / third);
        }
    }
    for (i = 0u; i < n_candidates; ++i) {
        const fit_candidate_t *c = &candidates[i];
        char name[48];
        candidate_name(c, name, sizeof name);
        if (isfinite(c->holdout_rms)) {
            char creep[96] = "";
            if (c->creep.tau > 0 && isfinite(c->creep.holdout_rms)) {
                (void)snprintf(creep, sizeof creep, "; with creep tau %.6g: %.6g", c->creep.tau,
                               c->creep.holdout_rms);
            }
            /* the chosen one at its sub-sample delay, if one was chosen */
            (void)printf("# candidate %s delay %.9g: %s %.6g, fit rms %.6g%s%s\n", name,
                         (double)c->delay + (i == best_candidate ? o->delay_fraction : 0.0),
                         score, c->holdout_rms, c->fit_rms, creep,
                         i != best_candidate ? ""
                         : o->with_creep     ? " (chosen, with creep)"
                                             : " (chosen)");
        } else {
            (void)printf("# candidate %s delay %lu: not scored (%s)\n", name,
                         (unsigned long)c->delay,
                         c->kind == FIT_EVERETT && c->status == HYST_ERR_SINGULAR
                             ? everett_singular
                         : c->status != HYST_OK ? hyst_status_str(c->status)
                                                : "f0 not increasing");
        }
    }
}

/* ---- the model fitted on the whole record ---- */

typedef struct fit_final {
    cli_model_t model;       /* what --save and --header write */
    hyst_ident_result_t r;   /* FIT_POLY */
    fit_everett_result_t ev; /* FIT_EVERETT, FIT_GRID, FIT_SPLINE */
    double rms, max_abs;     /* the residual printed on line 3 */
    int usable;              /* f0 increasing, or E or the spline accepted by the library */
    int from_everett;        /* kind poly written from ev.e, E of t-degree 0 (as_poly()) */
} fit_final_t;

/* 1 after a message if a number of the result overflowed (the library sums
 * squared residuals: outputs near 1e154 are enough; a coefficient of x^k is
 * about y / x^k: inputs spanning 1e-100 or less are enough too). */
static int not_finite(const char *name, const fit_final_t *f)
{
    static const char *const names[4] = {"domain LO", "domain HI", "RMS residual",
                                         "max residual"};
    const cli_model_t *m = &f->model;
    const double more[4] = {m->lo, m->hi, f->rms, f->max_abs};
    char advice[96] = "the numbers are too large, rescale them";
    size_t k;
    if (m->hi - m->lo < 1e-100) {
        (void)snprintf(advice, sizeof advice,
                       "the inputs span only %g: the numbers are too small, rescale them",
                       m->hi - m->lo);
    }
    for (k = 0u; k < m->ncoef; ++k) {
        if (!isfinite(m->coeffs[k])) {
            return cli_fail("fit", "%s: the result is not finite (coefficient c%lu %g): %s", name,
                            (unsigned long)(m->ncoef - 1u - k), m->coeffs[k], advice);
        }
    }
    for (k = 0u; k < m->nterms; ++k) {
        if (!isfinite(m->terms[k])) {
            return cli_fail("fit", "%s: the result is not finite (term %lu of E %g): %s", name,
                            (unsigned long)k + 1ul, m->terms[k], advice);
        }
    }
    for (k = 0u; k < m->nvalues; ++k) {
        if (!isfinite(m->values[k]) || !isfinite(m->slopes[k])) {
            return cli_fail("fit", "%s: the result is not finite (f0 at knot %lu %g, its slope "
                                   "%g): %s",
                            name, (unsigned long)k, m->values[k], m->slopes[k], advice);
        }
    }
    if (!isfinite(m->y_lo)) {
        return cli_fail("fit", "%s: the result is not finite (y_lo %g): %s", name, m->y_lo,
                        advice);
    }
    for (k = 0u; k < 4u; ++k) {
        /* the max of a refused E is not known: the model could not run */
        if (!isfinite(more[k]) && (k < 3u || f->usable || m->kind == CLI_MODEL_POLY)) {
            return cli_fail("fit", "%s: the result is not finite (%s %g): %s", name, names[k],
                            more[k], advice);
        }
    }
    return 0;
}

/* A domain wider than the inputs fitted (a widened candidate, or --domain):
 * the range the model was identified on, recorded in its file. */
static void record_identified(const fit_opts_t *o, const cli_table_t *t, cli_model_t *m)
{
    double id_lo, id_hi;
    fit_input_range(t->col[0], o->cfg.skip, t->n - o->cfg.delay, 0.0, &id_lo, &id_hi);
    if (m->lo < id_lo || id_hi < m->hi) {
        m->has_identified = 1;
        m->id_lo = id_lo > m->lo ? id_lo : m->lo;
        m->id_hi = id_hi < m->hi ? id_hi : m->hi;
    }
}

/* The chosen kind fitted on the whole record into f: 0, or 1 after a message. */
static int fit_final(const fit_opts_t *o, const char *name, const cli_table_t *t, size_t pairs,
                     fit_final_t *f)
{
    hyst_ident_t work;
    hyst_status_t st = HYST_ERR_ARG;
    const int everett = o->final_kind == FIT_EVERETT, grid = o->final_kind == FIT_GRID;
    const int spline = o->final_kind == FIT_SPLINE;
    unsigned k;
    memset(f, 0, sizeof *f);
    if (pairs > 0u) {
        st = grid      ? fit_grid_record(&o->cfg, o->cfg.degree, t->col[0], t->col[1], t->n,
                                         &f->ev)
             : spline  ? fit_spline_record(&o->cfg, o->cfg.degree, t->col[0], t->col[1], t->n,
                                           &f->ev)
             : everett ? fit_everett_record(&o->cfg, o->t_degree, t->col[0], t->col[1], t->n,
                                            &f->ev)
                       : hyst_ident_fit(&o->cfg, t->col[0], t->col[1], t->n, &work, &f->r);
    }
    switch (st) {
    case HYST_OK:
        break;
    case HYST_ERR_ARG:
        return cli_fail("fit", "%s: --skip %lu and --delay %lu leave no sample of the %lu read",
                        name, (unsigned long)o->cfg.skip, (unsigned long)o->cfg.delay,
                        (unsigned long)t->n);
    case HYST_ERR_SINGULAR:
        if (everett) {
            return cli_fail("fit", "%s: everett degree %u t-degree %u: %s", name,
                            o->cfg.degree, o->t_degree, everett_singular);
        }
        if (spline) {
            return cli_fail("fit", "%s: too few distinct inputs for a spline of %u intervals",
                            name, o->cfg.degree);
        }
        return cli_fail("fit", "%s: too few distinct inputs for degree %u", name, o->cfg.degree);
    case HYST_ERR_DOMAIN:
        return cli_fail("fit", "%s: the inputs do not span a range (all equal?)", name);
    default:
        return cli_fail("fit", "%s: %s", name, hyst_status_str(st));
    }
    if (grid || spline || everett) {
        if (grid) {
            model_text_from_grid(&f->model, &f->ev.grid, (unsigned long)o->cfg.delay);
        } else if (spline) {
            model_text_from_spline(&f->model, &f->ev.spline, (unsigned long)o->cfg.delay);
        } else {
            cli_model_from_everett(&f->model, &f->ev.e, (unsigned long)o->cfg.delay);
        }
        f->model.delay_fraction = o->delay_fraction;
        if (!grid) {
            record_identified(o, t, &f->model);
        }
        f->usable = f->ev.curve_status == HYST_OK;
        f->rms = f->usable ? f->ev.rms : f->ev.ls_rms;
        f->max_abs = f->ev.max_abs;
    } else {
        f->model.kind = CLI_MODEL_POLY;
        f->model.ncoef = f->r.degree + 1u;
        for (k = 0u; k < f->model.ncoef; ++k) {
            f->model.coeffs[k] = (double)f->r.coeffs[k];
        }
        f->model.lo = (double)f->r.lo;
        f->model.hi = (double)f->r.hi;
        f->model.delay = (unsigned long)o->cfg.delay;
        f->model.delay_fraction = o->delay_fraction;
        record_identified(o, t, &f->model);
        f->usable = f->r.increasing;
        f->rms = (double)f->r.rms;
        f->max_abs = (double)f->r.max_abs;
    }
    return not_finite(name, f);
}

/* The creep and rate terms of the model fitted on the whole record (either
 * or both): their weights and offset fitted to that model's residual over
 * every sample (the offset folded into the model: f0's constant, or E's
 * y_lo); the residual printed then is the model's with them. 0, or 1 after
 * a message. */
static int fit_final_creep(const fit_opts_t *o, const char *name, const cli_table_t *t,
                           fit_final_t *f)
{
    cli_model_t *m = &f->model;
    fit_creep_t c;
    hyst_poly_t f0;
    hyst_curve_t curve;
    unsigned k;
    const size_t end = t->n - o->cfg.delay; /* every sample before it: no hold-out */
    memset(&c, 0, sizeof c);
    c.tau = o->with_creep ? o->creep.tau : 0.0;
    c.rate_tau = o->with_rate ? o->rate.rate_tau : 0.0;
    if (m->kind != CLI_MODEL_POLY) {
        if (fit_result_curve(o->final_kind, &f->ev, &curve) != HYST_OK) {
            return 0; /* refused: reported as such, nothing written */
        }
        (void)fit_model_run_creep(NULL, &curve, t->col[0], t->col[1], t->n, o->cfg.skip,
                                  o->cfg.delay, end, NULL, NULL, &c);
    } else {
        memset(&f0, 0, sizeof f0);
        f0.degree = f->r.degree;
        f0.lo = (double)f->r.lo;
        f0.hi = (double)f->r.hi;
        for (k = 0u; k <= f->r.degree; ++k) {
            f0.coeffs[k] = (double)f->r.coeffs[k];
        }
        (void)fit_model_run_creep(&f0, NULL, t->col[0], t->col[1], t->n, o->cfg.skip,
                                  o->cfg.delay, end, NULL, NULL, &c);
    }
    if (!(c.tau > 0 || c.rate_tau > 0) || !isfinite(c.weight) || !isfinite(c.offset) ||
        !isfinite(c.rate_weight)) {
        return cli_fail("fit", "%s: the %s term of time constant %g samples could not be "
                               "fitted to the model's residual (a drive that never moves?)",
                        name, o->with_creep ? "creep" : "rate",
                        o->with_creep ? o->creep.tau : o->rate.rate_tau);
    }
    if (c.tau > 0) {
        m->ncreep = 1u;
        m->creep_tau[0] = c.tau;
        m->creep_weight[0] = c.weight;
    }
    if (c.rate_tau > 0) {
        m->has_rate = 1;
        m->rate_tau = c.rate_tau;
        m->rate_weight = c.rate_weight;
    }
    if (m->kind == CLI_MODEL_EVERETT || m->kind == CLI_MODEL_GRID) {
        m->y_lo += c.offset;
    } else if (m->kind == CLI_MODEL_SPLINE) { /* f0 moved as a whole */
        for (k = 0u; k < m->nvalues; ++k) {
            m->values[k] += c.offset;
        }
    } else {
        m->coeffs[m->ncoef - 1u] += c.offset;
    }
    f->rms = c.fit_rms;
    f->max_abs = c.max_abs;
    return 0;
}

/* The chosen E of t-degree 0 written as the model it is, the symmetric one
 * (kind poly, whose compensator is a table), its f0 fit_poly_from_everett()'s;
 * kept as E where that refuses it. */
static void as_poly(fit_final_t *f)
{
    cli_model_t *m = &f->model;
    hyst_poly_t f0;
    unsigned k;
    f->ev.e.y_lo = m->y_lo; /* the E the model file holds: the creep term's offset included */
    if (!fit_poly_from_everett(&f->ev.e, &f0)) {
        return;
    }
    m->kind = CLI_MODEL_POLY;
    m->ncoef = f0.degree + 1u;
    for (k = 0u; k < m->ncoef; ++k) {
        m->coeffs[k] = (double)f0.coeffs[k];
    }
    m->degree = 0u;
    m->y_lo = 0.0;
    m->nterms = 0u;
    f->from_everett = 1;
}

/* The --compare-pi line into line[0..size). */
static void compare_line(const fit_opts_t *o, const cli_table_t *t, char *line, size_t size)
{
    char tcm[96];
    const double holdout = o->with_rate    ? o->rate.last_third_rms
                           : o->with_creep ? o->creep.last_third_rms
                                           : o->last_third;
    const char *terms = o->with_creep ? (o->with_rate ? " with creep and rate" : " with creep")
                        : o->with_rate ? " with rate"
                                       : "";
    if (o->final_kind == FIT_GRID) {
        (void)snprintf(tcm, sizeof tcm, "asymmetric TCM on a grid of %u intervals%s",
                       o->cfg.degree, terms);
    } else if (o->final_kind == FIT_SPLINE) {
        (void)snprintf(tcm, sizeof tcm, "TCM, f0 a spline of %u intervals%s", o->cfg.degree,
                       terms);
    } else if (o->as_poly) {
        (void)snprintf(tcm, sizeof tcm, "TCM degree %u, f0 along every branch%s", o->cfg.degree,
                       terms);
    } else if (o->final_kind == FIT_EVERETT) {
        (void)snprintf(tcm, sizeof tcm, "asymmetric (everett) TCM degree %u t-degree %u%s",
                       o->cfg.degree, o->t_degree, terms);
    } else {
        (void)snprintf(tcm, sizeof tcm, "TCM degree %u%s", o->cfg.degree, terms);
    }
    fit_pi_compare(t, o->compare_pi, o->cfg.skip, o->cfg.delay, tcm,
                   fit_parameters(o->final_kind, o->cfg.degree, o->t_degree) +
                       (o->with_creep ? FIT_CREEP_PARAMETERS : 0u) +
                       (o->with_rate ? FIT_RATE_PARAMETERS : 0u),
                   holdout, line, size);
}

/* Lines 1 to 3 and the line that says what they are. */
static void print_result(const fit_final_t *f, unsigned t_degree, size_t pairs)
{
    const cli_model_t *m = &f->model;
    const double *v = m->kind == CLI_MODEL_GRID      ? m->weights
                      : m->kind == CLI_MODEL_SPLINE  ? m->values
                      : m->kind == CLI_MODEL_EVERETT ? m->terms
                                                     : m->coeffs;
    const size_t n = m->kind == CLI_MODEL_GRID      ? m->nweights
                     : m->kind == CLI_MODEL_SPLINE  ? m->nvalues
                     : m->kind == CLI_MODEL_EVERETT ? m->nterms
                                                    : m->ncoef;
    size_t k;
    for (k = 0u; k < n; ++k) {
        (void)printf("%s%.15g", k ? "," : "", v[k]);
    }
    (void)printf("\n%.15g,%.15g\n%.6g,%.6g\n", m->lo, m->hi, f->rms, f->max_abs);
    if (m->kind == CLI_MODEL_GRID) {
        (void)printf("# residual rms,max above: the asymmetric model on a grid (kind "
                     "everett_grid, %lu intervals, y_lo %.15g%s) run over the record, %lu of %lu "
                     "samples used%s; line 1 the cells' masses (i, j), j <= i; knots",
                     (unsigned long)m->nknots - 1ul, m->y_lo,
                     m->ncreep > 0u ? ", with its creep term" : "", (unsigned long)f->ev.used,
                     (unsigned long)pairs,
                     f->usable ? "" : " (least-squares residual: the model cannot run)");
        for (k = 0u; k < m->nknots; ++k) {
            (void)printf(" %.9g", m->knots[k]);
        }
        (void)printf("\n");
        if (!f->ev.determined) {
            (void)printf("# %s\n", fit_grid_undetermined);
        }
    } else if (m->kind == CLI_MODEL_SPLINE) {
        (void)printf("# residual rms,max above: the symmetric model with f0 a monotone cubic "
                     "spline (kind spline, %lu intervals%s) run over the record, %lu of %lu "
                     "samples used%s, f0 fitted along every branch; line 1 f0 at the knots "
                     "lo + k (hi - lo) / %lu, k = 0..%lu; slopes",
                     (unsigned long)m->nvalues - 1ul, m->ncreep > 0u ? ", with its creep term" : "",
                     (unsigned long)f->ev.used, (unsigned long)pairs,
                     f->usable ? "" : " (least-squares residual: the model cannot run)",
                     (unsigned long)m->nvalues - 1ul, (unsigned long)m->nvalues - 1ul);
        for (k = 0u; k < m->nslopes; ++k) {
            (void)printf(" %.15g", m->slopes[k]);
        }
        (void)printf("\n");
    } else if (m->kind == CLI_MODEL_EVERETT) {
        (void)printf("# residual rms,max above: the asymmetric model (kind everett, degree %u, "
                     "t-degree %u, y_lo %.15g%s) run over the record, %lu of %lu samples used%s; "
                     "line 1 E's terms e[i-1][j] of w^i t^j, i = 1..%u, j = 0..%u - i (0 above "
                     "the t-degree)\n",
                     m->degree, t_degree, m->y_lo, m->ncreep > 0u ? ", with its creep term" : "",
                     (unsigned long)f->ev.used, (unsigned long)pairs,
                     f->usable ? "" : " (least-squares residual: the model cannot run)",
                     m->degree, m->degree);
    } else if (f->from_everett) {
        (void)printf("# residual rms,max above: the symmetric model (kind poly, degree %u%s) run "
                     "over the record, %lu of %lu samples used; f0 fitted as E of t-degree 0 "
                     "along every branch, f0(x) = y_lo + sum e[i-1][0] ((x - lo) / (hi - lo))^i "
                     "with y_lo %.15g, line 1 its coefficients in powers of x\n",
                     f->ev.e.degree, m->ncreep > 0u ? ", with its creep term" : "",
                     (unsigned long)f->ev.used, (unsigned long)pairs, (double)f->ev.e.y_lo);
    } else {
        (void)printf("# residual rms,max above%s; %s estimator, degree %u, %lu of %lu samples "
                     "used (%lu rising, %lu falling)\n",
                     m->ncreep > 0u ? " (the model with its creep term, run over the record)" : "",
                     method_name(f->r.method), f->r.degree, (unsigned long)f->r.used,
                     (unsigned long)pairs, (unsigned long)f->r.rising,
                     (unsigned long)f->r.falling);
    }
}

/* The last comment line: whether the library takes the model. */
static void print_usable(const fit_final_t *f)
{
    const cli_model_t *m = &f->model;
    if (m->kind != CLI_MODEL_POLY) { /* the library's curve of E, the grid or the spline */
        const int grid = m->kind == CLI_MODEL_GRID, spline = m->kind == CLI_MODEL_SPLINE;
        if (f->usable) {
            (void)printf("# %s [%.9g, %.9g]%s\n",
                         grid     ? "every cell's mass >= 0: E increases in a and decreases in b on"
                         : spline ? "f0 increases on"
                                  : "E increases in a and decreases in b on lo <= b <= a <= hi,",
                         m->lo, m->hi,
                         spline ? " (every slope >= 0, every piece increasing)" : "");
        } else {
            (void)printf("# %s NOT accepted by the library: %s\n",
                         grid ? "the grid" : spline ? "the spline" : "E",
                         hyst_status_str(f->ev.curve_status));
        }
        return;
    }
    if (!f->from_everett && f->r.method == HYST_IDENT_REFLECT) {
        (void)printf("# y(lo), y(hi) measured for Eq. 14: %.9g, %.9g\n", (double)f->r.y_lo_est,
                     (double)f->r.y_hi_est);
    }
    if (f->usable) {
        (void)printf("# f0 increases on [%.9g, %.9g]\n", m->lo, m->hi);
    } else {
        (void)printf("# f0 NOT increasing: slope negative at x = %.9g\n", (double)f->r.turn);
    }
}

/* ---- the header and the model file: replaced whole, or not at all ----
 *
 * NAME.h is written to a temporary file beside it (NAME.h.XXXXXX), synced and
 * closed, each step checked; the results are printed; only then is it renamed
 * over NAME.h (an atomic replacement on POSIX file systems). Any failure
 * before the rename removes the temporary file and leaves NAME.h as it was. */

/* The header's text into buf; its length, or 0 if it did not fit. */
static size_t header_text(const fit_opts_t *o, const fit_final_t *f, char *buf, size_t size)
{
    char source[1024];
    const char *name = cli_file_name(o->file);
    const cli_model_t *m = &f->model;
    size_t i, j, len = 0u;
    int over;
    /* the file name goes into a comment: "*" "/" in it would end the comment */
    for (i = j = 0u; name[i] != '\0' && j + 3u < sizeof source; ++i) {
        source[j++] = name[i];
        if (name[i] == '*' && name[i + 1u] == '/') {
            source[j++] = ' ';
        }
    }
    source[j] = '\0';
    if (m->kind == CLI_MODEL_GRID || m->kind == CLI_MODEL_SPLINE) {
        const int spline = m->kind == CLI_MODEL_SPLINE;
        char y_lo[48] = "";
        if (!spline) {
            (void)snprintf(y_lo, sizeof y_lo, ", y_lo %.9g", m->y_lo);
        }
        over = cli_append(buf, size, &len,
                          "/* Generated by 'hyst fit': %s identified\n"
                          " * from %s (x column %lu, y column %lu, skip %lu, delay %lu),\n"
                          " * %lu knot intervals, domain [%.9g, %.9g]%s; for\n"
                          " * %s, then hyst_init_curve().\n"
                          " * Residual of the model over %lu samples:\n"
                          " * RMS %.4g, max %.4g (output units). */\n",
                          spline ? "symmetric model with f0 a monotone cubic\n * spline, "
                                   "along every branch,"
                                 : "asymmetric model on a grid",
                          source, o->cols[0], o->cols[1], (unsigned long)o->cfg.skip,
                          (unsigned long)o->cfg.delay,
                          (unsigned long)(spline ? m->nvalues : m->nknots) - 1ul, m->lo, m->hi,
                          y_lo,
                          spline ? "hyst_curve_from_spline()" : "hyst_curve_from_everett_grid()",
                          (unsigned long)f->ev.used, f->rms, f->max_abs);
    } else if (m->kind == CLI_MODEL_EVERETT) {
        over = cli_append(buf, size, &len,
                          "/* Generated by 'hyst fit': asymmetric model (branch function E)\n"
                          " * identified from %s (x column %lu, y column %lu, skip %lu,\n"
                          " * delay %lu), degree %u, domain [%.9g, %.9g], y_lo %.9g; for\n"
                          " * hyst_curve_from_everett(), then hyst_init_curve().\n"
                          " * Residual of the model over %lu samples:\n"
                          " * RMS %.4g, max %.4g (output units). */\n",
                          source, o->cols[0], o->cols[1], (unsigned long)o->cfg.skip,
                          (unsigned long)o->cfg.delay, m->degree, m->lo, m->hi, m->y_lo,
                          (unsigned long)f->ev.used, f->rms, f->max_abs);
    } else if (f->from_everett) {
        over = cli_append(buf, size, &len,
                          "/* Generated by 'hyst fit': major ascending curve f0 identified from\n"
                          " * %s (x column %lu, y column %lu, skip %lu, delay %lu),\n"
                          " * degree %u, fitted as E of t-degree 0 along every branch,\n"
                          " * domain [%.9g, %.9g]. Residual of the model over %lu samples:\n"
                          " * RMS %.4g, max %.4g (output units). */\n",
                          source, o->cols[0], o->cols[1], (unsigned long)o->cfg.skip,
                          (unsigned long)o->cfg.delay, f->ev.e.degree, m->lo, m->hi,
                          (unsigned long)f->ev.used, f->rms, f->max_abs);
    } else {
        over = cli_append(buf, size, &len,
                          "/* Generated by 'hyst fit': major ascending curve f0 identified from\n"
                          " * %s (x column %lu, y column %lu, skip %lu, delay %lu),\n"
                          " * degree %u, %s estimator, domain [%.9g, %.9g].\n"
                          " * Residual against the major loop over %lu samples:\n"
                          " * RMS %.4g, max %.4g (output units). */\n",
                          source, o->cols[0], o->cols[1], (unsigned long)o->cfg.skip,
                          (unsigned long)o->cfg.delay, f->r.degree, method_name(f->r.method),
                          (double)f->r.lo, (double)f->r.hi, (unsigned long)f->r.used,
                          (double)f->r.rms, (double)f->r.max_abs);
    }
    over |= cli_header_model(buf, size, &len, o->header, m);
    return over ? 0u : len;
}

/* Before anything is computed or printed: a NAME.h that cannot be replaced. */
static int header_check(const fit_opts_t *o, cli_replace_t *h)
{
    char path[CLI_PATH_MAX];
    return cli_header_path("fit", "--header-dir", o->header_dir, o->header, path) != 0 ||
           cli_replace_check(h, "fit", "header", path) != 0;
}

/* The model file into its temporary file: 0, or 1 after a message. */
static int model_write(const fit_final_t *f, cli_replace_t *ms)
{
    char text[8192];
    const size_t len = cli_model_text(&f->model, text, sizeof text);
    if (len == 0u) {
        return cli_fail("fit", "%s: model text too long", ms->path);
    }
    return cli_replace_write(ms, text, len);
}

/* The header into its temporary file: 0, or 1 after a message. */
static int header_write(const fit_opts_t *o, const fit_final_t *f, cli_replace_t *h)
{
    char text[16384];
    const size_t len = header_text(o, f, text, sizeof text);
    if (len == 0u) {
        return cli_fail("fit", "%s: header text too long", h->path);
    }
    return cli_replace_write(h, text, len);
}

/* 1 after a message if fewer than two of the @p n inputs x lie in --domain
 * (the others are ignored): the fit would blame the degree. */
static int domain_empty(const fit_opts_t *o, const char *name, const double *x, size_t n)
{
    double lo, hi;
    size_t i, inside = 0u;
    for (i = 0u; i < n; ++i) {
        inside += x[i] >= o->cfg.lo && x[i] <= o->cfg.hi;
    }
    if (inside >= 2u) {
        return 0;
    }
    fit_input_range(x, 0u, n, 0.0, &lo, &hi);
    return cli_fail("fit", "%s: option --domain: %lu of the %lu inputs used lie in [%.9g, %.9g] "
                           "(the inputs span [%.9g, %.9g]): too few to fit",
                    name, (unsigned long)inside, (unsigned long)n, (double)o->cfg.lo,
                    (double)o->cfg.hi, lo, hi);
}

/* 1 after a message if the record is refused before fitting
 * (fit_record_check(): a constant column, nothing to fit and the fit would
 * only report a flat curve's slope; an output that clearly falls as the
 * input rises, which no model fits though the choice would pick the least
 * bad); *rec what it found. */
static int record_refused(const fit_opts_t *o, const char *name, const cli_table_t *t,
                          fit_record_t *rec)
{
    int out;
    (void)fit_record_check(t->col[0], t->n, t->col[1], t->n, o->cfg.skip, o->cfg.delay, rec);
    out = rec->fault == FIT_RECORD_CONSTANT_OUTPUT;
    switch (rec->fault) {
    case FIT_RECORD_OK:
        return 0;
    case FIT_RECORD_NO_SAMPLE:
        return cli_fail("fit", "%s: --skip %lu and --delay %lu leave no sample of the %lu read",
                        name, (unsigned long)o->cfg.skip, (unsigned long)o->cfg.delay,
                        (unsigned long)t->n);
    case FIT_RECORD_CONSTANT_INPUT:
    case FIT_RECORD_CONSTANT_OUTPUT:
        return cli_fail("fit", "%s: column %lu is constant (%.9g on every one of the %lu lines "
                               "used): choose the %s column with %s",
                        name, o->cols[out], rec->value, (unsigned long)rec->pairs,
                        out ? "output" : "input", out ? "--ycol" : "--xcol");
    case FIT_RECORD_FALLING:
        return cli_fail("fit", "%s: the output (column %lu) falls as the input (column %lu) "
                               "rises (correlation %.3g): every model of hyst rises with its "
                               "input; negate the output column",
                        name, o->cols[1], o->cols[0], rec->correlation);
    default: /* an infinite sample: the reader refuses it */
        return cli_fail("fit", "%s: a sample is not finite", name);
    }
}

/* --validate OTHER read into *tv and *v (the same columns and --skip as
 * FILE), its rows checked as FILE's are: 0, or 1 after a message (nothing
 * left to free). */
static int read_validation(fit_opts_t *o, cli_table_t *tv, fit_validation_t *v)
{
    fit_record_t rec;
    size_t pairs;
    if (cli_read_columns("fit", o->validate, o->cols, 2u, o->decimal_comma, tv) != 0) {
        return 1;
    }
    pairs = tv->n > o->cfg.skip ? tv->n - o->cfg.skip : 0u;
    if (pairs < 2u) {
        (void)cli_fail("fit", "option --validate: %s: %lu rows after --skip %lu (of the %lu "
                              "read): a validation record needs two or more",
                       o->vname, (unsigned long)pairs, (unsigned long)o->cfg.skip,
                       (unsigned long)tv->n);
        cli_table_free(tv);
        return 1;
    }
    if (record_refused(o, o->vname, tv, &rec)) {
        cli_table_free(tv);
        return 1;
    }
    v->x = tv->col[0];
    v->y = tv->col[1];
    v->n = tv->n;
    v->skip = o->cfg.skip;
    return 0;
}

int cmd_fit(int argc, char **argv)
{
    fit_opts_t o;
    cli_table_t t, tv;
    fit_validation_t validation;
    fit_final_t f;
    cli_replace_t h, ms;
    fit_record_t rec;
    const char *name, *score;
    size_t pairs;
    char compare[512] = "";
    int rc = parse(&o, argc, argv);
    if (rc != 0) {
        return rc < 0 ? 0 : rc;
    }
    if (o.header != NULL && header_check(&o, &h) != 0) {
        return 1;
    }
    if (o.save != NULL && cli_replace_check(&ms, "fit", "model file", o.save) != 0) {
        return 1;
    }
    if (cli_outputs_distinct("fit", o.file, o.header != NULL ? h.path : NULL, o.save) != 0 ||
        (o.validate != NULL &&
         cli_outputs_distinct("fit", o.validate, o.header != NULL ? h.path : NULL, o.save) != 0)) {
        return 1;
    }
    if (o.validate != NULL) { /* a copy: the name below may share its buffer */
        (void)snprintf(o.vname, sizeof o.vname, "%s", cli_file_name(o.validate));
    }
    name = cli_file_name(o.file);
    if (cli_read_columns("fit", o.file, o.cols, 2u, o.decimal_comma, &t) != 0) {
        return 1;
    }
    pairs = t.n > o.cfg.skip + o.cfg.delay ? t.n - o.cfg.skip - o.cfg.delay : 0u;
    if (pairs == 1u) { /* not a column to choose again, as the constant check would say */
        (void)cli_fail("fit", "%s: one sample to fit (of the %lu read, after --skip %lu and "
                              "--delay %lu): a fit needs a record",
                       name, (unsigned long)t.n, (unsigned long)o.cfg.skip,
                       (unsigned long)o.cfg.delay);
        cli_table_free(&t);
        return 1;
    }
    if (pairs > 1u && o.cfg.lo < o.cfg.hi && domain_empty(&o, name, t.col[0] + o.cfg.skip, pairs)) {
        cli_table_free(&t);
        return 1;
    }
    if (record_refused(&o, name, &t, &rec)) {
        cli_table_free(&t);
        return 1;
    }
    if (o.kind == FIT_KIND_PI) {
        rc = fit_pi_report(name, &t, o.operators, o.cfg.skip, o.cfg.delay);
        cli_table_free(&t);
        return rc;
    }
    memset(&tv, 0, sizeof tv);
    if (o.validate != NULL) {
        if (read_validation(&o, &tv, &validation) != 0) {
            cli_table_free(&t);
            return 1;
        }
        o.v = &validation;
    }
    if (pairs > 0u && !o.have_degree) {
        if (choose(&o, name, &t) != 0) {
            cli_table_free(&t);
            cli_table_free(&tv);
            return 1;
        }
        pairs = t.n - o.cfg.skip - o.cfg.delay; /* at the chosen delay (fit_select() left samples) */
    } else if (pairs > 0u) {
        if (!o.have_delay && choose_delay(&o, &t) != 0) {
            cli_table_free(&t);
            cli_table_free(&tv);
            return cli_fail("fit", "%s: out of memory", name);
        }
        pairs = t.n > o.cfg.skip + o.cfg.delay ? t.n - o.cfg.skip - o.cfg.delay : 0u;
        /* with --validate, the model given is scored on OTHER even without a creep term */
        if (pairs > 0u && (o.creep_tau >= 0 || o.compare_pi != 0u || o.v != NULL)) {
            choose_creep(&o, &t);
        }
    }
    rc = fit_final(&o, name, &t, pairs, &f);
    if (rc == 0 && o.final_kind == FIT_GRID && !f.ev.determined) {
        (void)fprintf(stderr, "hyst fit: warning: %s: %s\n", name, fit_grid_undetermined);
    }
    if (rc == 0 && (o.with_creep || o.with_rate) && f.usable) {
        rc = fit_final_creep(&o, name, &t, &f);
    }
    if (rc == 0 && o.as_poly && f.usable) {
        as_poly(&f);
    }
    if (rc == 0 && o.branches && f.usable && !f.from_everett) {
        rc = cli_fail("fit", "%s: --method branches: E of degree %u fitted along the branches "
                             "gives no f0 in powers of x on [%.9g, %.9g] (they cancel far from "
                             "0, or f0 falls): shift the inputs, or fit --kind everett "
                             "--t-degree 0",
                      name, o.cfg.degree, f.model.lo, f.model.hi);
    }
    o.as_poly = f.from_everett;
    if (rc == 0 && o.compare_pi != 0u) {
        compare_line(&o, &t, compare, sizeof compare);
    }
    cli_table_free(&t);
    cli_table_free(&tv);
    if (rc != 0) {
        return 1;
    }
    if (f.usable && o.header != NULL) {
        if (header_write(&o, &f, &h) != 0) {
            return 1;
        }
        /* a closed pipe must not kill the process with the temporary file left */
        (void)signal(SIGPIPE, SIG_IGN);
    }
    if (f.usable && o.save != NULL) {
        if (model_write(&f, &ms) != 0) {
            if (o.header != NULL) {
                cli_replace_discard(&h);
            }
            return 1;
        }
        (void)signal(SIGPIPE, SIG_IGN);
    }
    score = o.v != NULL ? "validation rms" : "hold-out rms";
    print_result(&f, o.t_degree, pairs);
    if (!o.have_degree) {
        print_candidates(&o);
    }
    if (o.delay_fraction > 0.0) {
        (void)printf("# delay %.9g samples (sub-sample: the drive interpolated; %s at delay "
                     "%lu: %.6g)\n",
                     (double)o.cfg.delay + o.delay_fraction, score,
                     (unsigned long)o.integer_delay, o.integer_holdout);
    } else {
        (void)printf("# delay %lu samples\n", (unsigned long)o.cfg.delay);
    }
    if (o.have_degree && !o.have_delay && isfinite(o.integer_holdout)) {
        (void)printf("# delay chosen %s among 0..%lu samples (without --delay)\n",
                     o.v != NULL ? "on the validation record" : "by hold-out",
                     (unsigned long)o.max_delay);
    }
    if (o.have_degree && o.v != NULL) {
        (void)printf("# validation on %s: rms %.6g (the model fitted on the whole record, run "
                     "from rest over its %lu samples)\n",
                     o.vname, o.with_creep ? o.creep.holdout_rms : o.holdout,
                     (unsigned long)(o.v->n > o.v->skip + o.cfg.delay
                                         ? o.v->n - o.v->skip - o.cfg.delay
                                         : 0u));
    }
    if (o.with_creep && f.model.ncreep > 0u) {
        (void)printf("# creep: tau %.6g samples, weight %.9g (%s %.6g; without it %.6g)\n",
                     f.model.creep_tau[0], f.model.creep_weight[0], score, o.creep.holdout_rms,
                     o.holdout);
    } else if (o.creep_tau >= 0 && o.creep.tau > 0 && isfinite(o.creep.holdout_rms)) {
        (void)printf("# creep: none (%s %.6g; with the best creep term, tau %.6g samples, "
                     "%.6g)\n",
                     score, o.holdout, o.creep.tau, o.creep.holdout_rms);
    }
    if (o.with_rate && f.model.has_rate) {
        (void)printf("# rate: tau %.6g samples, weight %.9g (%s %.6g; without it %.6g)\n",
                     f.model.rate_tau, f.model.rate_weight, score, o.rate.holdout_rms,
                     o.rate_without);
    } else if (!o.have_degree && o.rate.rate_tau > 0 && isfinite(o.rate.holdout_rms)) {
        (void)printf("# rate: none (%s %.6g; with the best rate term, tau %.6g samples, "
                     "%.6g)\n",
                     score, o.rate_without, o.rate.rate_tau, o.rate.holdout_rms);
    }
    (void)printf("# parameters %u\n", fit_parameters(o.final_kind, o.cfg.degree, o.t_degree) +
                                          (o.with_creep && f.model.ncreep > 0u ? FIT_CREEP_PARAMETERS : 0u) +
                                          (o.with_rate && f.model.has_rate ? FIT_RATE_PARAMETERS : 0u));
    (void)fputs(compare, stdout);
    print_usable(&f);
    if (fflush(stdout) != 0 || ferror(stdout)) {
        const int err = errno;
        if (o.header != NULL) {
            cli_replace_discard(&h);
        }
        if (o.save != NULL) {
            cli_replace_discard(&ms);
        }
        return cli_fail("fit", "write error on standard output: %s%s", strerror(err),
                        (o.header != NULL || o.save != NULL) && f.usable
                            ? " (no header or model file written)"
                            : "");
    }
    if (f.usable && o.header != NULL && cli_replace_commit(&h) != 0) {
        if (o.save != NULL) {
            cli_replace_discard(&ms);
        }
        return 1;
    }
    if (f.usable && o.save != NULL && cli_replace_commit(&ms) != 0) {
        return 1;
    }
    if (!o.have_degree) {
        warn_excitation(&o, name);
    }
    if ((o.have_degree || o.kind == FIT_KIND_TCM) && o.final_kind == FIT_POLY && rec.minor > 0u) {
        warn_minor_loops(&o, name, rec.minor);
    }
    if (!f.usable) {
        const char *nothing =
            o.header != NULL || o.save != NULL ? "; no header or model file written" : "";
        if (o.final_kind == FIT_EVERETT || o.final_kind == FIT_GRID ||
            o.final_kind == FIT_SPLINE) {
            (void)fprintf(stderr, "hyst fit: %s: the fitted %s is refused by the library: %s: "
                                  "try another %s%s\n",
                          name, o.final_kind == FIT_SPLINE ? "spline f0" : "E",
                          hyst_status_str(f.ev.curve_status),
                          o.final_kind == FIT_SPLINE ? "number of intervals" : "degree", nothing);
        } else {
            (void)fprintf(stderr,
                          "hyst fit: %s: the fitted f0 is not increasing on [%.9g, %.9g] (slope "
                          "negative at x = %.9g): try another degree%s\n",
                          name, (double)f.r.lo, (double)f.r.hi, (double)f.r.turn, nothing);
        }
        return 2;
    }
    return 0;
}
