/* SPDX-License-Identifier: MIT */
/* Shared by the subcommands of `hyst`: messages, option parsing, number
 * parsing and the sample-to-line runner (the data file reader is cli_read.c). */
#include "cli.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

int cli_fail(const char *cmd, const char *fmt, ...)
{
    va_list ap;
    (void)fflush(stdout);
    (void)fprintf(stderr, "hyst %s: ", cmd);
    va_start(ap, fmt);
    (void)vfprintf(stderr, fmt, ap);
    va_end(ap);
    (void)fputc('\n', stderr);
    return 1;
}

const char *cli_quote_n(char *buf, const char *s, size_t len)
{
    return model_text_quote(buf, s, len);
}

const char *cli_quote(char *buf, const char *s) { return cli_quote_n(buf, s, strlen(s)); }

const char *cli_file_name(const char *path)
{
    static char buf[4u * 200u + 8u];
    const char *p;
    char *out = buf;
    if (path == NULL || strcmp(path, "-") == 0) {
        return "<stdin>";
    }
    for (p = path; *p != '\0' && *p != '\\' && (unsigned char)*p >= 0x20u &&
                   (unsigned char)*p < 0x7fu;
         ++p) {
    }
    if (*p == '\0') {
        return path; /* nothing to escape */
    }
    for (p = path; *p != '\0' && p - path < 200; ++p) {
        if (*p == '\'') {
            *out++ = *p; /* the name is not quoted: no need to escape a quote */
        } else {
            out = model_text_escape(out, (unsigned char)*p);
        }
    }
    (void)strcpy(out, *p != '\0' ? "..." : "");
    return buf;
}

/* ---- options ---- */

void cli_args_init(cli_args_t *a, const char *cmd, int argc, char **argv)
{
    a->cmd = cmd;
    a->argc = argc;
    a->argv = argv;
    a->i = 1; /* argv[0] is the subcommand */
    a->only_pos = 0;
    a->opt[0] = '\0';
    a->inline_v = NULL;
    a->value_taken = 1;
}

int cli_args_next(cli_args_t *a, const char **pos)
{
    const char *arg, *eq;
    size_t len;
    if (!a->value_taken && a->inline_v != NULL) {
        char q[CLI_QUOTE_SIZE];
        return -cli_fail(a->cmd, "option %s takes no value (got %s)", a->opt,
                         cli_quote(q, a->inline_v));
    }
    a->opt[0] = '\0';
    a->inline_v = NULL;
    a->value_taken = 1;
    if (a->i >= a->argc) {
        return CLI_END;
    }
    arg = a->argv[a->i++];
    if (!a->only_pos && strcmp(arg, "--") == 0) {
        a->only_pos = 1;
        return cli_args_next(a, pos);
    }
    if (a->only_pos || arg[0] != '-' || arg[1] == '\0') {
        *pos = arg;
        return CLI_POS;
    }
    eq = strchr(arg, '=');
    len = eq != NULL ? (size_t)(eq - arg) : strlen(arg);
    if (len >= sizeof a->opt) {
        len = sizeof a->opt - 1u;
    }
    memcpy(a->opt, arg, len);
    a->opt[len] = '\0';
    a->inline_v = eq != NULL ? eq + 1 : NULL;
    a->value_taken = 0;
    return CLI_OPT;
}

int cli_is(const cli_args_t *a, const char *name) { return strcmp(a->opt, name) == 0; }

const char *cli_value(cli_args_t *a)
{
    a->value_taken = 1;
    if (a->inline_v != NULL) {
        return a->inline_v;
    }
    if (a->i >= a->argc) {
        (void)cli_fail(a->cmd, "option %s needs a value", a->opt);
        return NULL;
    }
    return a->argv[a->i++];
}

int cli_unknown(const cli_args_t *a)
{
    char q[CLI_QUOTE_SIZE];
    return cli_fail(a->cmd, "unknown option %s (see 'hyst %s --help')", cli_quote(q, a->opt),
                    a->cmd);
}

int cli_parse_double(const char *s, double *out)
{
    char *end;
    double v;
    while (*s == ' ' || *s == '\t') {
        ++s;
    }
    if (*s == '\0') {
        return 0;
    }
    errno = 0;
    v = strtod(s, &end);
    while (*end == ' ' || *end == '\t') {
        ++end;
    }
    /* strtod sets ERANGE on underflow too, for denormals (1e-320) and values
     * that round to 0: those are finite numbers. Overflow gives HUGE_VAL. */
    if (end == s || *end != '\0' || !isfinite(v)) {
        return 0;
    }
    *out = v;
    return 1;
}

int cli_opt_ulong(const cli_args_t *a, const char *v, unsigned long min, unsigned long max,
                  unsigned long *out)
{
    char *end;
    unsigned long u;
    errno = 0;
    u = (v[0] >= '0' && v[0] <= '9') ? strtoul(v, &end, 10) : 0ul;
    if (!(v[0] >= '0' && v[0] <= '9') || *end != '\0' || errno == ERANGE || u < min || u > max) {
        char q[CLI_QUOTE_SIZE];
        return !cli_fail(a->cmd, "option %s: %s is not an integer in %lu..%lu", a->opt,
                         cli_quote(q, v), min, max);
    }
    *out = u;
    return 1;
}

int cli_opt_list(const cli_args_t *a, const char *v, double *out, size_t min, size_t max,
                 size_t *n)
{
    char item[128], q[CLI_QUOTE_SIZE];
    const char *p = v;
    size_t count = 0u;
    for (;;) {
        const char *comma = strchr(p, ',');
        const size_t len = comma != NULL ? (size_t)(comma - p) : strlen(p);
        if (count == max) {
            return !cli_fail(a->cmd, "option %s: more than %lu numbers in %s", a->opt,
                             (unsigned long)max, cli_quote(q, v));
        }
        /* a number of 128 characters or more is not one either */
        if (len < sizeof item) {
            memcpy(item, p, len);
            item[len] = '\0';
        }
        if (len >= sizeof item || !cli_parse_double(item, &out[count])) {
            return !cli_fail(a->cmd, "option %s: item %lu %s is not a finite number", a->opt,
                             (unsigned long)count + 1ul, cli_quote_n(q, p, len));
        }
        ++count;
        if (comma == NULL) {
            break;
        }
        p = comma + 1;
    }
    if (count < min) {
        return !cli_fail(a->cmd, "option %s: %s has %lu numbers, needs at least %lu", a->opt,
                         cli_quote(q, v), (unsigned long)count, (unsigned long)min);
    }
    *n = count;
    return 1;
}

void cli_c_number(char *buf, size_t len, double v, int digits)
{
    model_text_c_number(buf, len, v, digits);
}

void cli_c_literal(char *buf, size_t len, double v) { cli_c_number(buf, len, v, 17); }

int cli_opt_table_size(const cli_args_t *a, const char *v, int rows, unsigned long *out)
{
    if (strcmp(v, "default") == 0) {
        *out = CLI_TABLE_DEFAULT;
        return 1;
    }
    return rows ? cli_opt_ulong(a, v, CLI_TABLE_MIN_ROWS, CLI_TABLE_MAX_ROWS, out)
                : cli_opt_ulong(a, v, 1ul, CLI_TABLE_MAX_INTERVALS, out);
}

int cli_table_sizes(const char *cmd, int everett, unsigned long *intervals, unsigned long *rows)
{
    if (*rows > 0ul && !everett) {
        return cli_fail(cmd, "option --rows applies to kind everett only: the compensators of "
                             "kinds poly and spline tabulate f0^-1 in one row (--intervals "
                             "alone)");
    }
    if (*intervals == CLI_TABLE_DEFAULT) {
        *intervals = everett ? HYST_EVERETT_INV_INTERVALS : HYST_INV_TABLE;
    }
    if (*intervals > 0ul && (*rows == 0ul || *rows == CLI_TABLE_DEFAULT)) {
        *rows = HYST_EVERETT_INV_ROWS;
    }
    return 0;
}

/* ---- sample streams ---- */

void cli_samples_init(cli_samples_t *s)
{
    s->file = NULL;
    s->xcol = 1ul;
    s->decimal_comma = 0;
}

int cli_samples_next(cli_args_t *a, cli_samples_t *s, const char *help)
{
    const char *pos = NULL, *v;
    int kind;
    while ((kind = cli_args_next(a, &pos)) != CLI_END) {
        if (kind < 0) {
            return -1;
        }
        if (kind == CLI_POS) {
            if (s->file != NULL) {
                char q1[CLI_QUOTE_SIZE], q2[CLI_QUOTE_SIZE];
                return -cli_fail(a->cmd, "more than one input file (%s, %s)",
                                 cli_quote(q1, s->file), cli_quote(q2, pos));
            }
            s->file = pos;
        } else if (cli_is(a, "--help") || cli_is(a, "-h")) {
            (void)fputs(help, stdout);
            return CLI_HELP;
        } else if (cli_is(a, "--decimal-comma")) {
            s->decimal_comma = 1;
        } else if (cli_is(a, "--xcol")) {
            if ((v = cli_value(a)) == NULL ||
                !cli_opt_ulong(a, v, 1ul, CLI_MAX_FIELD, &s->xcol)) {
                return -1;
            }
        } else {
            return CLI_OPT;
        }
    }
    return CLI_END;
}

int cli_map_samples(const char *cmd, const cli_samples_t *s, const cli_map_t *m)
{
    cli_reader_t rd;
    cli_spool_t sp;
    size_t nclamped = 0u, nbeyond = 0u;
    unsigned long first = 0ul, first_beyond = 0ul;
    double x, y;
    int rc, got = 0;
    if (cli_reader_open(&rd, cmd, s->file, &s->xcol, 1u, s->decimal_comma) != 0) {
        return 1;
    }
    cli_spool_init(&sp, cmd);
    rc = m->begin != NULL ? m->begin(m->ctx) : 0;
    while (rc == 0 && (got = cli_reader_next(&rd, &x)) > 0) {
        char out[64];
        int clamped = 0, len;
        if ((rc = m->step(m->ctx, x, &y, &clamped)) != 0) {
            break;
        }
        if (!isfinite(y)) {
            rc = cli_fail(cmd, "%s:%lu: the output is not finite (%g): the numbers are too "
                               "large, rescale them",
                          rd.name, rd.lineno, y);
            break;
        }
        /* A bound printed with 9 digits (sim's f0(lo) fed to inv) may land just
         * outside: rounding, not an unreachable target, so not warned. */
        if (clamped &&
            (m->step_checks_range || x < m->lo - CLI_PRINT_TOL * fabs(m->lo) ||
             x > m->hi + CLI_PRINT_TOL * fabs(m->hi)) &&
            nclamped++ == 0u) {
            first = rd.lineno;
        }
        if (m->has_identified && (x < m->id_lo || x > m->id_hi) && nbeyond++ == 0u) {
            first_beyond = rd.lineno;
        }
        len = m->col2 != NULL ? sprintf(out, "%.*g,%lu\n", m->digits, y, m->col2(m->ctx))
                              : sprintf(out, "%.*g\n", m->digits, y);
        rc = cli_spool_write(&sp, out, (size_t)len);
    }
    if (got < 0) {
        rc = 1;
    }
    cli_reader_close(&rd);
    if (rc == 0 && nclamped == rd.rows) {
        /* not one sample in the domain: a wrong range or column, not data */
        rc = cli_fail(cmd, "%s: all %lu %s are outside [%.9g, %.9g] (all clamped): check --range "
                           "and --xcol",
                      rd.name, (unsigned long)nclamped, m->clamp_what, m->lo, m->hi);
    }
    if (rc == 0) {
        rc = cli_spool_copy(&sp, stdout);
    }
    if (rc == 0 && nclamped > 0u) {
        (void)fprintf(stderr,
                      "hyst %s: warning: %s: %lu %s outside [%.9g, %.9g] were clamped to it "
                      "(first at line %lu)\n",
                      cmd, cli_file_name(s->file), (unsigned long)nclamped, m->clamp_what,
                      m->lo, m->hi, first);
    }
    if (rc == 0 && nbeyond > 0u) {
        (void)fprintf(stderr,
                      "hyst %s: note: %s: %lu of %lu %s outside [%.9g, %.9g], the range the "
                      "model was identified on (first at line %lu): predicted by its branches "
                      "continued beyond it%s\n",
                      cmd, cli_file_name(s->file), (unsigned long)nbeyond,
                      (unsigned long)rd.rows, m->clamp_what, m->id_lo, m->id_hi, first_beyond,
                      nclamped > 0u ? " (up to the domain, clamped beyond)" : "");
    }
    cli_spool_free(&sp);
    return rc;
}

/* ---- output held back ---- */

void cli_spool_init(cli_spool_t *sp, const char *cmd)
{
    sp->cmd = cmd;
    sp->buf = NULL;
    sp->len = 0u;
    sp->file = NULL;
}

/* An anonymous temporary file: created in $TMPDIR (or /tmp), unlinked at once. */
static FILE *temp_file(const char *cmd)
{
    const char *dir = getenv("TMPDIR");
    char path[4096];
    int fd;
    FILE *f;
    if (dir == NULL || dir[0] == '\0') {
        dir = "/tmp";
    }
    if (strlen(dir) + sizeof "/hyst-XXXXXX" > sizeof path) {
        (void)cli_fail(cmd, "TMPDIR too long");
        return NULL;
    }
    (void)sprintf(path, "%s/hyst-XXXXXX", dir);
    fd = mkstemp(path);
    if (fd < 0) {
        (void)cli_fail(cmd, "cannot create a temporary file for the output in %s: %s (set TMPDIR)",
                       cli_file_name(dir), strerror(errno));
        return NULL;
    }
    (void)unlink(path); /* gone with the process, whatever happens */
    f = fdopen(fd, "w+b");
    if (f == NULL) {
        (void)cli_fail(cmd, "temporary file: %s", strerror(errno));
        (void)close(fd);
    }
    return f;
}

/* The buffer appended to the temporary file (created on the first call). */
static int spool_spill(cli_spool_t *sp)
{
    if (sp->file == NULL && (sp->file = temp_file(sp->cmd)) == NULL) {
        return 1;
    }
    if (fwrite(sp->buf, 1u, sp->len, sp->file) != sp->len) {
        return cli_fail(sp->cmd, "temporary file: %s", strerror(errno));
    }
    sp->len = 0u;
    return 0;
}

int cli_spool_write(cli_spool_t *sp, const char *s, size_t n)
{
    if (sp->buf == NULL && (sp->buf = (char *)malloc(CLI_SPOOL_MEM)) == NULL) {
        return cli_fail(sp->cmd, "out of memory");
    }
    if (n > CLI_SPOOL_MEM - sp->len) {
        if (spool_spill(sp) != 0) {
            return 1;
        }
        if (n > CLI_SPOOL_MEM) {
            return fwrite(s, 1u, n, sp->file) == n
                       ? 0
                       : cli_fail(sp->cmd, "temporary file: %s", strerror(errno));
        }
    }
    memcpy(sp->buf + sp->len, s, n);
    sp->len += n;
    return 0;
}

int cli_spool_copy(cli_spool_t *sp, FILE *out)
{
    if (sp->file == NULL) {
        if (sp->len > 0u && fwrite(sp->buf, 1u, sp->len, out) != sp->len) {
            return cli_fail(sp->cmd, "write error on standard output: %s", strerror(errno));
        }
    } else {
        size_t n;
        if (spool_spill(sp) != 0) {
            return 1;
        }
        if (fflush(sp->file) != 0 || fseek(sp->file, 0L, SEEK_SET) != 0) {
            return cli_fail(sp->cmd, "temporary file: %s", strerror(errno));
        }
        /* sp->buf is free for the copy: the file holds everything */
        while ((n = fread(sp->buf, 1u, CLI_SPOOL_MEM, sp->file)) > 0u) {
            if (fwrite(sp->buf, 1u, n, out) != n) {
                return cli_fail(sp->cmd, "write error on standard output: %s", strerror(errno));
            }
        }
        if (ferror(sp->file)) {
            return cli_fail(sp->cmd, "temporary file: %s", strerror(errno));
        }
    }
    if (fflush(out) != 0 || ferror(out)) {
        return cli_fail(sp->cmd, "write error on standard output: %s", strerror(errno));
    }
    return 0;
}

void cli_spool_free(cli_spool_t *sp)
{
    if (sp->file != NULL) {
        (void)fclose(sp->file);
        sp->file = NULL;
    }
    free(sp->buf);
    sp->buf = NULL;
    sp->len = 0u;
}
