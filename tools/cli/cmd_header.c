/* SPDX-License-Identifier: MIT */
/* hyst header: the firmware header of a model file. */
#include "cli.h"
#include "hyst/hyst.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
    "usage: hyst header --model MODEL [--dir DIR] [--sealed [--codes LO,HI]]\n"
    "                   [--compensator [--intervals N] [--rows R]] NAME\n"
    "\n"
    "Writes NAME.h (in DIR, default the current directory) declaring\n"
    "'static const hyst_poly_t NAME = {...};', the f0 of the model file MODEL\n"
    "('hyst fit --save'), for firmware: hyst_init(&S, &NAME, ...); for a model\n"
    "of kind everett 'static const hyst_everett_t NAME = {...};', its E (checked\n"
    "as hyst_curve_from_everett() checks it), for hyst_curve_from_everett() then\n"
    "hyst_init_kind(); kind everett_grid and kind spline a hyst_everett_grid_t\n"
    "or hyst_spline_t, for hyst_curve_from_everett_grid() or\n"
    "hyst_curve_from_spline() (with a table, its length in a comment). The file's\n"
    "delay is a property of the sensor, not of the model: it is stated in a\n"
    "comment. NAME.h is replaced whole or not at all.\n"
    "\n"
    "  --model MODEL  the model file (format hyst-model-text 1)\n"
    "  --dir DIR      directory of NAME.h\n"
    "  --sealed       also the prepared curve (kind poly), made and checked here in\n"
    "                 float and in double and sealed: 'NAME_sealed' of the build's\n"
    "                 real type, for hyst_init_sealed(): firmware initialises without\n"
    "                 building the curve (integer checks, no double arithmetic);\n"
    "                 with --compensator also the compensator's curve sealed with\n"
    "                 its table, 'NAME_comp_sealed', for hyst_init_inverse_sealed()\n"
    "  --codes LO,HI  with --sealed: also the q31 model on codes LO..HI,\n"
    "                 'NAME_q31_sealed', for hyst_q31_init_sealed()\n"
    "  --compensator  also the compensator's table, built here in float and in\n"
    "                 double and sealed: 'NAME_table', 'NAME_seal' of the build's\n"
    "                 real type (HYST_USE_DOUBLE), NAME_INTERVALS (and NAME_ROWS),\n"
    "                 for hyst_curve_inverse_table_const() (kind poly) or\n"
    "                 hyst_curve_everett_inverse_table_const() (kind everett):\n"
    "                 firmware takes the table from flash instead of building it;\n"
    "                 kind everett_grid: no table (hyst_curve_everett_grid_inverse()\n"
    "                 solves each branch in closed form), kind spline: none without\n"
    "                 --intervals (hyst_curve_spline_inverse() solves each drive per\n"
    "                 sample), the header says so; with --intervals the table firmware\n"
    "                 builds at init (hyst_curve_spline_inverse_table()), measured here:\n"
    "                 NAME_INTERVALS and the calls, no numbers\n"
    "  --intervals N  with --compensator: the table's intervals (per row), 1..1048576\n"
    "                 or 'default' (" CLI_STR(HYST_INV_TABLE) " for poly and spline, "
    CLI_STR(HYST_EVERETT_INV_INTERVALS) " for everett)\n"
    "  --rows R       with --compensator, kind everett: R + 1 rows per direction,\n"
    "                 3..4096 or 'default' (" CLI_STR(HYST_EVERETT_INV_ROWS) ")\n"
    "  --help         this text\n";

/* --codes LO,HI: two codes, LO < HI <= HYST_CODE_MAX. */
static int codes_of(const cli_args_t *a, const char *v, unsigned long *lo, unsigned long *hi)
{
    char part[32], q[CLI_QUOTE_SIZE];
    const char *comma = strchr(v, ',');
    const size_t n = comma != NULL ? (size_t)(comma - v) : 0u;
    if (comma == NULL || n == 0u || n >= sizeof part) {
        return !cli_fail(a->cmd, "option %s: %s is not two codes LO,HI", a->opt, cli_quote(q, v));
    }
    memcpy(part, v, n);
    part[n] = '\0';
    if (!cli_opt_ulong(a, part, 0ul, (unsigned long)HYST_CODE_MAX, lo) ||
        !cli_opt_ulong(a, comma + 1, 0ul, (unsigned long)HYST_CODE_MAX, hi)) {
        return 0;
    }
    if (*lo >= *hi) {
        return !cli_fail(a->cmd, "option %s: LO must be below HI", a->opt);
    }
    return 1;
}

int cmd_header(int argc, char **argv)
{
    cli_args_t a;
    cli_replace_t h;
    cli_model_t m;
    const char *model = NULL, *dir = NULL, *name = NULL, *pos = NULL;
    char q[CLI_QUOTE_SIZE], path[CLI_PATH_MAX], *text;
    size_t len = 0u, size = 8192u;
    unsigned long intervals = 0ul, rows = 0ul; /* 0: not given */
    unsigned long code_lo = 0ul, code_hi = 0ul;
    hyst_status_t st = HYST_OK;
    int kind, over, compensator = 0, sealed = 0, codes = 0, failed, table;
    cli_args_init(&a, "header", argc, argv);
    while ((kind = cli_args_next(&a, &pos)) != CLI_END) {
        if (kind < 0) {
            return 1;
        }
        if (kind == CLI_POS) {
            if (name != NULL) {
                return cli_fail(a.cmd, "more than one NAME (%s)", cli_quote(q, pos));
            }
            name = pos;
        } else if (cli_is(&a, "--help") || cli_is(&a, "-h")) {
            (void)fputs(help, stdout);
            return 0;
        } else if (cli_is(&a, "--compensator")) {
            compensator = 1;
        } else if (cli_is(&a, "--sealed")) {
            sealed = 1;
        } else if (cli_is(&a, "--codes")) {
            const char *v = cli_value(&a);
            if (v == NULL || !codes_of(&a, v, &code_lo, &code_hi)) {
                return 1;
            }
            codes = 1;
        } else if (cli_is(&a, "--model") || cli_is(&a, "--dir") || cli_is(&a, "--intervals") ||
                   cli_is(&a, "--rows")) {
            const char *v = cli_value(&a);
            if (v == NULL) {
                return 1;
            }
            if (cli_is(&a, "--intervals") || cli_is(&a, "--rows")) {
                const int is_rows = cli_is(&a, "--rows");
                if (!cli_opt_table_size(&a, v, is_rows, is_rows ? &rows : &intervals)) {
                    return 1;
                }
            } else {
                *(cli_is(&a, "--model") ? &model : &dir) = v;
            }
        } else {
            return cli_unknown(&a);
        }
    }
    if (model == NULL) {
        return cli_fail(a.cmd, "--model is required (see 'hyst header --help')");
    }
    if (name == NULL || !cli_c_identifier(name)) {
        return cli_fail(a.cmd, "NAME %s is not a C identifier",
                        name != NULL ? cli_quote(q, name) : "(missing)");
    }
    if (codes && !sealed) {
        return cli_fail(a.cmd, "option --codes needs --sealed (the q31 model it sizes)");
    }
    if (!compensator && (intervals != 0ul || rows != 0ul)) {
        return cli_fail(a.cmd, "option %s needs --compensator (the table it sizes)",
                        intervals != 0ul ? "--intervals" : "--rows");
    }
    if (cli_header_path(a.cmd, "--dir", dir, name, path) != 0 ||
        cli_model_read(a.cmd, model, &m) != 0 || cli_replace_check(&h, a.cmd, "header", path) != 0) {
        return 1;
    }
    if ((m.kind == CLI_MODEL_GRID && (sealed || intervals != 0ul || rows != 0ul)) ||
        (m.kind == CLI_MODEL_SPLINE && sealed)) {
        return cli_fail(a.cmd, "model file %s: kind %s has no %s (%s)", cli_file_name(model),
                        m.kind == CLI_MODEL_SPLINE ? "spline" : "everett_grid",
                        sealed ? "sealed curve" : "compensator table",
                        m.kind == CLI_MODEL_SPLINE
                            ? "firmware builds its curve and its compensator: "
                              "hyst_curve_spline_inverse(), or with --intervals "
                              "hyst_curve_spline_inverse_table()"
                            : "its compensator solves each branch in closed form");
    }
    /* a grid's compensator needs none, a spline's only with --intervals */
    table = compensator && m.kind != CLI_MODEL_GRID &&
            (m.kind != CLI_MODEL_SPLINE || intervals != 0ul);
    if (table && intervals == 0ul) {
        intervals = CLI_TABLE_DEFAULT;
    }
    if (cli_table_sizes(a.cmd, m.kind == CLI_MODEL_EVERETT, &intervals, &rows) != 0) {
        return 1;
    }
    if (table) {
        size += model_text_header_table_size(&m, (size_t)rows, (size_t)intervals);
    }
    if ((text = (char *)malloc(size)) == NULL) {
        return cli_fail(a.cmd, "out of memory for the header's text (%lu bytes)",
                        (unsigned long)size);
    }
    if (m.kind == CLI_MODEL_SPLINE || m.kind == CLI_MODEL_GRID) {
        static double grid_table[CLI_GRID_TABLE_LEN], spline_table[CLI_SPLINE_TABLE_LEN];
        const int spline = m.kind == CLI_MODEL_SPLINE;
        hyst_curve_t curve; /* what firmware's constructor would refuse is refused here */
        if ((spline ? cli_spline_curve(a.cmd, cli_file_name(model), &m, &curve, spline_table)
                    : cli_grid_curve(a.cmd, cli_file_name(model), &m, &curve, grid_table)) != 0) {
            free(text);
            return 1;
        }
        /* the solved compensator's sentence (a spline's table says its own) */
        const char *solved =
            !compensator || table ? ""
            : spline ? "\n * The compensator: hyst_curve_spline_inverse() of that curve,\n * then "
                       "hyst_init_kind() with hyst_kind_spline; each drive solved on\n * its "
                       "cubic piece per sample, no table of its own."
                     : "\n * The compensator: hyst_curve_everett_grid_inverse() of that curve,\n"
                       " * then hyst_init_kind() with hyst_kind_everett_grid_inverse; each\n * "
                       "branch solved in closed form, no table of its own.";
        over = cli_append(text, size, &len,
                          "/* Generated by 'hyst header' from the model file %s:\n"
                          " * %s of %lu knot intervals on [%.9g, %.9g]\n"
                          " * (%s, then\n"
                          " * hyst_init_kind() with %s); the\n"
                          " * measured output follows its input %.17g samples later (a sensor\n"
                          " * delay: the model does not include it).%s */\n",
                          cli_file_name(model),
                          spline ? "symmetric model, f0 a monotone cubic spline\n *"
                                 : "asymmetric model on a grid",
                          (unsigned long)(spline ? m.nvalues : m.nknots) - 1ul, m.lo, m.hi,
                          spline ? "hyst_curve_from_spline()" : "hyst_curve_from_everett_grid()",
                          spline ? "hyst_kind_spline" : "hyst_kind_everett_grid",
                          cli_model_delay(&m), solved);
    } else if (m.kind == CLI_MODEL_EVERETT) {
        hyst_curve_t curve; /* what firmware's init would refuse is refused here */
        if (cli_everett_curve(a.cmd, cli_file_name(model), &m, &curve) != 0) {
            free(text);
            return 1;
        }
        over = cli_append(text, size, &len,
                          "/* Generated by 'hyst header' from the model file %s:\n"
                          " * asymmetric model, branch function E of degree %u on [%.9g, %.9g]\n"
                          " * (hyst_curve_from_everett(), then hyst_init_kind() with\n"
                          " * hyst_kind_everett); the measured\n"
                          " * output follows its input %.17g samples later (a sensor delay: the\n"
                          " * model does not include it). */\n",
                          cli_file_name(model), m.degree, m.lo, m.hi, cli_model_delay(&m));
    } else {
        const double range[2] = {m.lo, m.hi};
        hyst_poly_t f0; /* what firmware's hyst_init() would refuse is refused here */
        if (cli_make_poly(a.cmd, cli_file_name(model), m.coeffs, m.ncoef, range, 2u, &f0) != 0) {
            free(text);
            return 1;
        }
        over = cli_append(text, size, &len,
                          "/* Generated by 'hyst header' from the model file %s:\n"
                          " * f0 of degree %lu on [%.9g, %.9g]; the measured output follows its input\n"
                          " * %.17g samples later (a sensor delay: the model does not include it). */\n",
                          cli_file_name(model), (unsigned long)(m.ncoef - 1u), m.lo, m.hi,
                          cli_model_delay(&m));
    }
    over |= cli_header_open(text, size, &len, name, &m);
    if (over == 0 && table &&
        model_text_header_table(text, size, &len, name, &m, (size_t)rows, (size_t)intervals,
                                sealed, &st) != 0) {
        free(text);
        return st != HYST_OK ? cli_fail(a.cmd, "model file %s: the compensator's table: %s",
                                        cli_file_name(model), hyst_status_str(st))
                             : cli_fail(a.cmd, "%s: header text too long", path);
    }
    if (over == 0 && sealed &&
        cli_header_sealed(a.cmd, cli_file_name(model), text, size, &len, name, &m, codes,
                          code_lo, code_hi) != 0) {
        free(text);
        return 1;
    }
    if (over != 0 || cli_header_close(text, size, &len, name) != 0) {
        free(text);
        return cli_fail(a.cmd, "%s: header text too long", path);
    }
    failed = cli_replace_write(&h, text, len) != 0 || cli_replace_commit(&h) != 0;
    free(text);
    return failed;
}
