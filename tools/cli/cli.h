/* The `hyst` host tool: subcommands and the helpers they share.
 *
 * A subcommand is a function cmd_<name>(argc, argv) (argv[0] is its name)
 * listed in main.c's table; it reads its input completely and checks it
 * before printing anything, reports errors through cli_fail() and returns
 * the process exit status (0 success, 1 bad input or option). */
#ifndef HYST_CLI_H
#define HYST_CLI_H

#include <stddef.h>

/* Subcommands (one file each). */
int cmd_fit(int argc, char **argv);
int cmd_sim(int argc, char **argv);

/* ---- messages ---- */

/* "hyst <cmd>: <message>\n" on stderr. Returns 1, the exit status of bad input. */
int cli_fail(const char *cmd, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* ---- options: --name VALUE, --name=VALUE, -- ends them, - is a file ---- */

enum { CLI_END = 0, CLI_OPT = 1, CLI_POS = 2 };

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

/* Unknown option or stray argument: message, returns 1. */
int cli_unknown(const cli_args_t *a);

/* Whole string as a finite double; 1 on success. */
int cli_parse_double(const char *s, double *out);

/* ---- data files: columns separated by whitespace, ',' or ';' ---- */

#define CLI_MAX_COLS 2
#define CLI_MAX_FIELD 64 /* highest column number accepted */

typedef struct cli_table {
    double *col[CLI_MAX_COLS]; /* requested columns, n entries each */
    size_t n;                  /* data lines read */
    size_t cap;
} cli_table_t;

/* Reads the 1-based columns cols[0..ncols) of every data line of @p path
 * ("-" = standard input); lines starting with '#' and blank lines are
 * skipped. 0 on success; on error a message naming file, line and field,
 * and -1 (the table is then empty). */
int cli_read_columns(const char *cmd, const char *path, const unsigned long *cols,
                     unsigned ncols, cli_table_t *t);

void cli_table_free(cli_table_t *t);

/* Name of @p path for messages: "<stdin>" for "-". */
const char *cli_file_name(const char *path);

/* A number printed as a C floating literal (always a '.' or an exponent). */
void cli_c_literal(char *buf, size_t len, double v);

#endif /* HYST_CLI_H */
