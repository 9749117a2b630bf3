/* SPDX-License-Identifier: MIT */
/* The `hyst` host tool: subcommands and the helpers they share.
 *
 * A subcommand is a function cmd_<name>(argc, argv) (argv[0] is its name)
 * listed in main.c's table; it reads its input completely and checks it
 * before printing anything (sim, inv and pi one line at a time, holding their
 * output back in a cli_spool_t), reports errors through cli_fail() and
 * returns the process exit status (0 success, 1 bad input or option). */
#ifndef HYST_CLI_H
#define HYST_CLI_H

#include "hyst/curve.h"
#include "model_text.h"

#include <stddef.h>
#include <stdio.h>

/* Subcommands (one file each). */
int cmd_fit(int argc, char **argv);
int cmd_sim(int argc, char **argv);
int cmd_inv(int argc, char **argv);
int cmd_pi(int argc, char **argv);
int cmd_header(int argc, char **argv);

/* ---- messages ---- */

/* "hyst <cmd>: <message>\n" on stderr. Returns 1, the exit status of bad input. */
int cli_fail(const char *cmd, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* Text from input or arguments, made safe for a message: in single quotes,
 * bytes other than printable ASCII as \xNN (\\ and \' for those two), and
 * beyond the first CLI_QUOTE_MAX bytes "..." and the length in bytes:
 * '7777...' (1048577 bytes). cli_quote_n() takes @p len bytes of @p s, NULs
 * included. Both write into @p buf (CLI_QUOTE_SIZE chars) and return it. */
#define CLI_QUOTE_MAX MODEL_TEXT_QUOTE_MAX
#define CLI_QUOTE_SIZE MODEL_TEXT_QUOTE_SIZE
const char *cli_quote(char *buf, const char *s);
const char *cli_quote_n(char *buf, const char *s, size_t len);

/* ---- options: --name VALUE, --name=VALUE, -- ends them, - is a file ---- */

enum { CLI_END = 0, CLI_OPT = 1, CLI_POS = 2, CLI_HELP = 3 };

typedef struct cli_args {
    const char *cmd;      /* subcommand name, for messages */
    int argc;
    char **argv;
    int i;                /* next argv index */
    int only_pos;         /* after "--" */
    char opt[64];         /* current option name, without "=value" */
    const char *inline_v; /* value given as --name=value, or NULL */
    int value_taken;      /* the current option's value was read */
} cli_args_t;

void cli_args_init(cli_args_t *a, const char *cmd, int argc, char **argv);

/* Next argument: CLI_OPT (name in a->opt), CLI_POS (*pos set) or CLI_END.
 * Returns -1 (message printed) for "--name=value" on a flag. */
int cli_args_next(cli_args_t *a, const char **pos);

/* Is the current option @p name? */
int cli_is(const cli_args_t *a, const char *name);

/* The current option's value; NULL with a message if there is none. */
const char *cli_value(cli_args_t *a);

/* Value parsers: 1 on success, 0 with a message naming the option. */
int cli_opt_ulong(const cli_args_t *a, const char *v, unsigned long min, unsigned long max,
                  unsigned long *out);
int cli_opt_list(const cli_args_t *a, const char *v, double *out, size_t min, size_t max,
                 size_t *n);

/* A compensator table's size (inv --intervals/--rows, header --compensator
 * --intervals/--rows): the counts the library accepts (curve.h), and a
 * constant spelled out in a help text. */
#define CLI_TABLE_MAX_INTERVALS (1ul << 20)
#define CLI_TABLE_MIN_ROWS 3ul
#define CLI_TABLE_MAX_ROWS 4096ul
#define CLI_TABLE_DEFAULT ((unsigned long)-1) /* "default": the kind's, once known */
#define CLI_STR_(x) #x
#define CLI_STR(x) CLI_STR_(x)
/* --intervals N (rows 0) or --rows R (rows 1): a count in range, or
 * "default" (CLI_TABLE_DEFAULT); as cli_opt_ulong(). */
int cli_opt_table_size(const cli_args_t *a, const char *v, int rows, unsigned long *out);
/* The sizes once the model's kind is known (0: not given): --rows refused
 * for kind poly; "default" intervals the kind's, and the rows of a table
 * (intervals given) HYST_EVERETT_INV_ROWS unless given. 0, or 1 after a
 * message. */
int cli_table_sizes(const char *cmd, int everett, unsigned long *intervals, unsigned long *rows);

/* Unknown option or stray argument: message, returns 1. */
int cli_unknown(const cli_args_t *a);

/* Whole string as a finite double (denormals included: only overflow to
 * infinity and NaN are refused); 1 on success. */
int cli_parse_double(const char *s, double *out);

/* ---- files replaced whole, or not at all (cli_replace.c) ---- */

/* Longest path of a file the tool writes. */
#define CLI_PATH_MAX 4352u

typedef struct cli_replace {
    const char *cmd;  /* for messages */
    const char *what; /* "header", "model file": for messages */
    char path[CLI_PATH_MAX];
    char tmp[CLI_PATH_MAX + 8u]; /* path.XXXXXX, "" when there is none */
    char dir[CLI_PATH_MAX];      /* synced after the rename */
} cli_replace_t;

/* A header's path, [DIR/]NAME.h, into path (CLI_PATH_MAX chars): DIR, if
 * not NULL, must be an existing directory. 0, or 1 after a message naming
 * @p option. */
int cli_header_path(const char *cmd, const char *option, const char *dir, const char *name,
                    char *path);
/* Before anything is computed or printed: a target that cannot be replaced
 * (too long a path, a directory). 0, or 1 after a message. */
int cli_replace_check(cli_replace_t *r, const char *cmd, const char *what, const char *path);
/* Before anything is read: the files a command writes (header, save: NULL
 * when not written) are neither its input (NULL or "-": standard input)
 * nor each other (checked by inode where they exist, else by directory and
 * name). 0, or 1 after a message naming the options. */
int cli_outputs_distinct(const char *cmd, const char *input, const char *header, const char *save);
/* The text into the temporary file, synced and closed: 0, or 1 after a
 * message (and no temporary file left). */
int cli_replace_write(cli_replace_t *r, const char *text, size_t len);
/* The temporary file renamed over the target: 0, or 1 after a message. */
int cli_replace_commit(cli_replace_t *r);
/* Removes the temporary file, if any. */
void cli_replace_discard(cli_replace_t *r);

/* ---- model files, hyst-model-text 1 (model_file.c over tools/model_text) ---- */

/* The format's one implementation, under the tool's names. */
#define CLI_CREEP_MAX_TERMS MODEL_TEXT_CREEP_MAX_TERMS
#define CLI_MODEL_POLY MODEL_TEXT_POLY
#define CLI_MODEL_EVERETT MODEL_TEXT_EVERETT
typedef model_text_t cli_model_t;
#define cli_model_text model_text_write
#define cli_header_open model_text_header_open
#define cli_header_close model_text_header_close
#define cli_everett_terms model_text_everett_terms
#define cli_model_to_everett model_text_to_everett
#define cli_model_from_everett model_text_from_everett
#define cli_c_identifier model_text_identifier
#define cli_append model_text_append
#define cli_model_delay model_text_delay
#define cli_model_poly_as_read model_text_poly_as_read

/* Reads a model file; 0, or 1 after a message naming file, line and field. */
int cli_model_read(const char *cmd, const char *path, cli_model_t *m);
/* The same from an open stream (path names it in messages); not closed. */
int cli_model_parse(const char *cmd, const char *path, FILE *in, cli_model_t *m);
/* Appends the firmware header's declaration of the model (include guard,
 * 'static const hyst_poly_t NAME = {...};' or, for the asymmetric kind,
 * 'static const hyst_everett_t NAME = {...};') to buf[*len..size); 1 when
 * it did not fit. */
int cli_header_model(char *buf, size_t size, size_t *len, const char *name, const cli_model_t *m);
/* header --sealed (header_sealed.c): the model's prepared curve in float
 * and in double (and, with q31, the q31 model on codes code_lo..code_hi),
 * checked and sealed for hyst_*_init_sealed(); appended like the model:
 * 0, or 1 after a message (kind everett, the library's refusal, too long). */
int cli_header_sealed(const char *cmd, const char *model, char *buf, size_t size, size_t *len,
                      const char *name, const cli_model_t *m, int q31, unsigned long code_lo,
                      unsigned long code_hi);

/* The library's curve of an everett model (hyst_f64_curve_from_everett(),
 * which checks that E is monotone on the triangle): 0, or 1 after a message
 * with the library's reason. */
int cli_everett_curve(const char *cmd, const char *path, const cli_model_t *m, hyst_curve_t *c);
/* f0 of --poly/--range or of a poly model (model_path, else NULL), checked as
 * hyst_init() checks it (increasing on [LO, HI]): 0, or 1 after a message
 * naming the option or the model file, and where the slope turns. */
int cli_make_poly(const char *cmd, const char *model_path, const double *coeffs, size_t ncoef,
                  const double *range, size_t nrange, hyst_poly_t *f0);
/* The same for a model of kind everett_grid, its table in table[0..CLI_GRID_TABLE_LEN). */
#define CLI_MODEL_GRID MODEL_TEXT_GRID
#define CLI_GRID_TABLE_LEN HYST_EVERETT_GRID_TABLE_LEN(HYST_EVERETT_GRID_MAX_INTERVALS)
int cli_grid_curve(const char *cmd, const char *path, const cli_model_t *m, hyst_curve_t *c,
                   double *table);
/* The same for a model of kind spline, its table in table[0..CLI_SPLINE_TABLE_LEN). */
#define CLI_MODEL_SPLINE MODEL_TEXT_SPLINE
#define CLI_SPLINE_TABLE_LEN HYST_SPLINE_TABLE_LEN(HYST_SPLINE_MAX_INTERVALS)
int cli_spline_curve(const char *cmd, const char *path, const cli_model_t *m, hyst_curve_t *c,
                     double *table);


/* ---- data files (cli_read.c): columns separated by blanks, ',' or ';' ---- */

#define CLI_MAX_COLS 2
#define CLI_MAX_FIELD 64 /* highest column number accepted */

/* A data file read one line at a time (fields: see cli_read.c). */
typedef struct cli_reader {
    const char *cmd;  /* for messages */
    const char *name; /* cli_file_name() of the path */
    FILE *f;
    int own;          /* f was opened here */
    char *line;       /* the current line, grown to the longest one */
    size_t cap;
    unsigned long lineno; /* of the current line, 1-based */
    unsigned long cols[CLI_MAX_COLS]; /* requested columns, 1-based */
    unsigned ncols;
    int decimal_comma; /* ',' is the decimal mark, ';' and blanks separate */
    size_t rows;       /* data lines read */
    /* decimal comma detection (cli_read.c) */
    long first_nf;               /* fields of the first data line */
    unsigned long first_line;    /* its suspect field, if any */
    long first_field;
    char first_tok[CLI_QUOTE_SIZE];
    int seen_dot;                /* some data line has a '.' */
    unsigned long alone_line;    /* first line that is a suspect field alone */
    char alone_tok[CLI_QUOTE_SIZE];
} cli_reader_t;

/* Opens @p path ("-" or NULL = standard input) to read the 1-based columns
 * cols[0..ncols). 0, or -1 after a message (nothing to close then). */
int cli_reader_open(cli_reader_t *r, const char *cmd, const char *path,
                    const unsigned long *cols, unsigned ncols, int decimal_comma);

/* The requested columns of the next data line into v[0..ncols): 1; lines
 * starting with '#' and blank lines are skipped. 0 at the end of the data,
 * after the checks that need the whole file (no data, ...). -1 after a
 * message naming file, line and field. r->lineno is the line of v. */
int cli_reader_next(cli_reader_t *r, double *v);

void cli_reader_close(cli_reader_t *r);

typedef struct cli_table {
    double *col[CLI_MAX_COLS]; /* requested columns, n entries each */
    size_t n;                  /* data lines read */
    size_t cap;
} cli_table_t;

/* Reads the requested columns of every data line of @p path into @p t, as
 * cli_reader_next() does: 8 bytes per column and line in memory (`hyst fit`
 * only; the other commands stream). 0 on success; on error a message naming
 * file, line and field, and -1 (the table is then empty). */
int cli_read_columns(const char *cmd, const char *path, const unsigned long *cols,
                     unsigned ncols, int decimal_comma, cli_table_t *t);

void cli_table_free(cli_table_t *t);

/* Name of @p path for messages: "<stdin>" for "-"; bytes other than
 * printable ASCII as \xNN (then in a static buffer, cut after 200 bytes). */
const char *cli_file_name(const char *path);

/* A number printed as a C floating literal (always a '.' or an exponent):
 * 17 significant digits (a double read back exactly), or `digits`. */
void cli_c_literal(char *buf, size_t len, double v);
void cli_c_number(char *buf, size_t len, double v, int digits);

/* ---- sample streams: one output line per input sample ---- */

/* Help lines of the options every sample command takes. */
#define CLI_HELP_XCOL                                                                 \
    "  --xcol I          input column, 1-based (default 1); columns are separated\n" \
    "                    by blanks, ',' or ';'; '#' lines and blank lines are skipped\n"
#define CLI_HELP_DECIMAL                                                              \
    "  --decimal-comma   ',' is the decimal mark (1,5 is 1.5): fields are then\n"  \
    "                    separated by blanks or ';'. Without it, a number that\n"  \
    "                    looks written with one is refused\n"
#define CLI_HELP_EXIT                                                                 \
    "Exit status: 0 success, 1 bad option or input (nothing is printed then).\n"

/* Relative rounding of a number printed with 9 significant digits (at most
 * half a unit of the 9th digit: 5e-9 of 1.00000000), with margin: clamping
 * by less than this is not warned. */
#define CLI_PRINT_TOL 1e-8

typedef struct cli_samples {
    const char *file;   /* NULL or "-": standard input */
    unsigned long xcol; /* input column, 1-based */
    int decimal_comma;  /* --decimal-comma */
} cli_samples_t;

void cli_samples_init(cli_samples_t *s);

/* Next option of a sample command, handling the common ones itself (FILE,
 * --xcol, --decimal-comma, --help/-h: prints @p help): CLI_OPT (the caller's,
 * name in a->opt), CLI_END, CLI_HELP (exit 0) or -1 after a message (exit 1). */
int cli_samples_next(cli_args_t *a, cli_samples_t *s, const char *help);

/* What a sample command does per sample. */
typedef struct cli_map {
    void *ctx;
    /* Before the first sample: 0, or 1 after a message. May be NULL. */
    int (*begin)(void *ctx);
    /* One sample: the output into *y, *clamped set if the input was clamped;
     * 0, or 1 after a message (the command stops). */
    int (*step)(void *ctx, double x, double *y, int *clamped);
    /* Second output column ("y,c") after each step, or NULL. */
    unsigned long (*col2)(void *ctx);
    const char *clamp_what; /* for the clamp warning: "inputs", ... */
    double lo, hi;          /* the interval inputs are clamped to */
    /* 1: the step clamps something else than the input (inv with a creep
     * term: the desired output less the creep's share) and sets *clamped
     * only beyond the printing tolerance of [lo, hi] itself */
    int step_checks_range;
    int digits;             /* significant digits printed (9; 17 gives the doubles exactly) */
    /* 1: the inputs outside [id_lo, id_hi], the range the model was
     * identified on, are counted and said (predicted, not clamped, up to
     * [lo, hi]) */
    int has_identified;
    double id_lo, id_hi;
} cli_map_t;

/* Reads the samples one line at a time and runs them through @p m, in
 * constant memory; the output lines (9 significant digits) wait in a
 * cli_spool_t until the whole input was read and checked: a malformed sample
 * stops everything with nothing printed. Clamped inputs are not an error: one
 * warning on stderr gives their count and the first line (those beyond lo/hi
 * by more than CLI_PRINT_TOL relative), and the exit status stays 0, unless
 * every sample was clamped: then it is an error. Returns the exit status. */
int cli_map_samples(const char *cmd, const cli_samples_t *s, const cli_map_t *m);

/* ---- output held back until the command succeeds ---- */

/* A buffer of CLI_SPOOL_MEM bytes in memory; when it overflows, it goes to a
 * temporary file in $TMPDIR (default /tmp), unlinked as soon as it is
 * created, and starts again. */
#define CLI_SPOOL_MEM (1u << 20)

typedef struct cli_spool {
    const char *cmd; /* for messages */
    char *buf;       /* CLI_SPOOL_MEM bytes, allocated on the first write */
    size_t len;      /* bytes in buf, after those in file */
    FILE *file;      /* what came before, once buf overflowed; else NULL */
} cli_spool_t;

void cli_spool_init(cli_spool_t *sp, const char *cmd);

/* Appends @p n bytes: 0, or 1 after a message (temporary file not created,
 * disk full, ...). */
int cli_spool_write(cli_spool_t *sp, const char *s, size_t n);

/* Copies everything to @p out and flushes it: 0, or 1 after a message. */
int cli_spool_copy(cli_spool_t *sp, FILE *out);

void cli_spool_free(cli_spool_t *sp);

/* ---- sim and inv (cli_tcm.c) ---- */

/* The whole of `hyst sim` (inverse = 0) or `hyst inv` (inverse = 1): options
 * --poly, --range, --xcol, --tp, FILE; --help prints @p help. */
int cli_tcm_command(int argc, char **argv, const char *cmd, const char *help, int inverse);

#endif /* HYST_CLI_H */
