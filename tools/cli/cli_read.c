/* SPDX-License-Identifier: MIT */
/* The data file reader of `hyst`, one line at a time: columns separated by
 * blanks, ',' or ';' (with --decimal-comma: blanks or ';', and ',' is the
 * decimal mark); '#' lines and blank lines skipped. Whatever would be read
 * wrongly stops the command with file, line and field: a NUL byte, an empty
 * or missing field, a field that is not a finite number, a decimal comma
 * that would be taken for a column separator. */
#include "cli.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static int is_space(char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f'; }
static int is_digit(char c) { return c >= '0' && c <= '9'; }
/* Column delimiters besides blanks: ',' is the decimal mark with --decimal-comma. */
static int is_delim(char c, int dc) { return c == ';' || (c == ',' && !dc); }

/* Longest line read: memory stays bounded whatever the input (a binary file
 * without newlines). */
#define CLI_MAX_LINE (16ul << 20)

/* One line, ended by LF, CR LF or CR, into *buf (grown); 0 at end of file,
 * -1 out of memory, -2 not shorter than CLI_MAX_LINE. *nul: 0, or the
 * 1-based column of the line's first NUL byte (the line is then cut there as
 * a C string). */
static int read_line(FILE *f, char **buf, size_t *cap, size_t *nul)
{
    size_t len = 0u;
    int c;
    *nul = 0u;
    while ((c = getc_unlocked(f)) != EOF) { /* POSIX; one thread: no lock per byte */
        if (len + 1u >= *cap) {
            const size_t ncap = *cap ? 2u * *cap : 256u;
            char *nb;
            if (ncap > CLI_MAX_LINE) {
                return -2;
            }
            nb = (char *)realloc(*buf, ncap);
            if (nb == NULL) {
                return -1;
            }
            *buf = nb;
            *cap = ncap;
        }
        if (c == '\n') {
            break;
        }
        if (c == '\r') { /* CR LF, or CR alone (an old Mac export), as model files */
            const int next = getc_unlocked(f);
            if (next != '\n' && next != EOF) {
                (void)ungetc(next, f);
            }
            break;
        }
        if (c == '\0' && *nul == 0u) {
            *nul = len + 1u;
        }
        (*buf)[len++] = (char)c;
    }
    if (c == EOF && len == 0u) {
        return 0;
    }
    (*buf)[len] = '\0';
    return 1;
}

/* Splits a data line into fields, in place: runs of blanks separate, and so
 * does one delimiter (',' or ';'; ';' alone when @p dc) with optional blanks
 * around it. Returns the count, or -(k) when field k is empty (two
 * delimiters in a row, or one at an end). */
static long split_fields(char *line, char **field, long max, int dc)
{
    char *p = line;
    long n = 0;
    for (;;) {
        char *start;
        while (is_space(*p)) {
            ++p;
        }
        if (*p == '\0') {
            return (n > 0 && p > line && is_delim(p[-1], dc)) ? -(n + 1) : n;
        }
        if (is_delim(*p, dc)) {
            return -(n + 1);
        }
        start = p;
        while (*p != '\0' && !is_space(*p) && !is_delim(*p, dc)) {
            ++p;
        }
        if (n < max) {
            field[n] = start;
        }
        ++n;
        while (is_space(*p)) {
            *p++ = '\0';
        }
        if (is_delim(*p, dc)) {
            *p++ = '\0';
            while (is_space(*p)) {
                ++p;
            }
            if (*p == '\0' || is_delim(*p, dc)) {
                return -(n + 1);
            }
        } else if (*p != '\0') {
            continue; /* blank-separated */
        }
    }
}

/* ---- decimal commas ----
 *
 * "1,5" is one number in a German spreadsheet and two columns in a CSV file.
 * A field as a spreadsheet writes it (fields separated by blanks and ';'
 * only) is suspect when it holds a comma between two digits and no '.'.
 * Without --decimal-comma, a suspect field stops the command when
 *  - the line also separates fields by ';' or blanks ("1,8;-123,05"), or
 *  - the field cannot be two integers printed by a program ("-0,5", "1,05"),
 *  - the line does not have as many columns as the first data line, and
 *    one of the two has a suspect field ("0" "0,5" "1"), or
 *  - the command reads column 1 only, the line is that field alone, of the
 *    form [+-]digits,digits, and no line of the file has a '.' (checked at
 *    the end: "0,0" then "0.5,1" is `hyst sim --tp` output, not commas).
 * Integer CSV read by `hyst fit` ("1024,3071") stays two columns. */

typedef struct comma_scan {
    long field;      /* 1-based field of the first suspect one, 0 if none */
    const char *tok; /* that field, @p len bytes */
    size_t len;
    int other_sep;   /* ';' or blanks separate fields too */
    int strong;      /* the suspect field cannot be two integers */
    int alone;       /* the line is the suspect field, [+-]digits,digits */
} comma_scan_t;

/* Is [s, e) of the form [+-]digits,digits? */
static int integer_pair(const char *s, const char *e)
{
    const char *p = s + (*s == '-' || *s == '+');
    const char *d = p;
    while (p < e && is_digit(*p)) {
        ++p;
    }
    if (p == d || p == e || *p != ',') {
        return 0;
    }
    d = ++p;
    while (p < e && is_digit(*p)) {
        ++p;
    }
    return p > d && p == e;
}

/* The suspect field [s, e): is a comma in it between digits, and does one
 * of them look like a decimal comma whatever the rest of the file says? */
static int bare_comma(const char *s, const char *e, int *strong)
{
    const char *q;
    int found = 0;
    *strong = 0;
    for (q = s + 1; q + 1 < e; ++q) {
        if (*q == ',' && is_digit(q[-1]) && is_digit(q[1])) {
            const char *b = q;
            found = 1;
            while (b > s && is_digit(b[-1])) {
                --b;
            }
            /* "-0,5": no integer is printed as -0; "1,05": nor with a leading 0 */
            if ((q - b == 1 && *b == '0' && b > s && (b[-1] == '-' || b[-1] == '+')) ||
                (q[1] == '0' && q + 2 < e && is_digit(q[2]))) {
                *strong = 1;
            }
        }
    }
    return found;
}

static void scan_commas(const char *line, comma_scan_t *cs)
{
    const char *p = line;
    char prev_last = ',';
    long k = 0;
    memset(cs, 0, sizeof *cs);
    for (;;) {
        const char *start;
        int strong;
        while (is_space(*p) || *p == ';') {
            cs->other_sep |= *p == ';';
            ++p;
        }
        if (*p == '\0') {
            break;
        }
        start = p;
        while (*p != '\0' && !is_space(*p) && *p != ';') {
            ++p;
        }
        ++k;
        /* blanks between fields, not around a comma: "1,8 2,5", not "1, 2" */
        if (k > 1 && prev_last != ',' && *start != ',') {
            cs->other_sep = 1;
        }
        prev_last = p[-1];
        if (cs->field == 0 && memchr(start, '.', (size_t)(p - start)) == NULL &&
            bare_comma(start, p, &strong)) {
            cs->field = k;
            cs->tok = start;
            cs->len = (size_t)(p - start);
            cs->strong = strong;
            cs->alone = integer_pair(start, p);
        }
    }
    if (k != 1) {
        cs->alone = 0;
    }
}

static int decimal_comma_fail(const cli_reader_t *r, unsigned long line, long field,
                              const char *quoted, const char *extra)
{
    return cli_fail(r->cmd, "%s:%lu: field %ld: %s: decimal comma? convert to '.' or use "
                            "--decimal-comma%s",
                    r->name, line, field, quoted, extra);
}

/* ---- the reader ---- */

int cli_reader_open(cli_reader_t *r, const char *cmd, const char *path,
                    const unsigned long *cols, unsigned ncols, int decimal_comma)
{
    struct stat st;
    unsigned c;
    memset(r, 0, sizeof *r);
    r->cmd = cmd;
    r->name = cli_file_name(path);
    r->own = !(path == NULL || strcmp(path, "-") == 0);
    r->f = r->own ? fopen(path, "r") : stdin;
    for (c = 0u; c < ncols && c < CLI_MAX_COLS; ++c) {
        r->cols[c] = cols[c];
    }
    r->ncols = c;
    r->decimal_comma = decimal_comma;
    if (r->f == NULL) {
        return -cli_fail(cmd, "%s: cannot open: %s", r->name, strerror(errno));
    }
    /* fopen() opens a directory for reading; the first read fails (EISDIR) */
    if (fstat(fileno(r->f), &st) == 0 && S_ISDIR(st.st_mode)) {
        cli_reader_close(r);
        return -cli_fail(cmd, "%s: is a directory", r->name);
    }
    return 0;
}

void cli_reader_close(cli_reader_t *r)
{
    if (r->own && r->f != NULL) {
        (void)fclose(r->f);
    }
    r->f = NULL;
    free(r->line);
    r->line = NULL;
    r->cap = 0u;
}

/* The checks that need the whole file; 0 or -1 after a message. */
static int reader_end(cli_reader_t *r)
{
    if (ferror(r->f)) {
        return -cli_fail(r->cmd, "%s: read error: %s", r->name, strerror(errno));
    }
    if (r->rows == 0u) {
        return -cli_fail(r->cmd, "%s: no data (the file is empty or holds only comments and "
                                 "blank lines)",
                         r->name);
    }
    if (r->alone_line != 0ul && !r->seen_dot) {
        return -decimal_comma_fail(r, r->alone_line, 1, r->alone_tok,
                                   " (no line has a '.'; if ',' separates columns, "
                                   "add a blank after it)");
    }
    return 0;
}

/* A word on the first data line is most often a column's name (a spreadsheet
 * export's first row): the way to keep it, as a hint to a refusal. */
static const char *names_hint(const cli_reader_t *r, const char *field)
{
    const char *p = field[0] == '"' || field[0] == '\'' ? field + 1 : field;
    const int letter = (*p >= 'a' && *p <= 'z') || (*p >= 'A' && *p <= 'Z') || *p == '_';
    char *end;
    if (r->rows != 0u || !letter) {
        return "";
    }
    (void)strtod(p, &end); /* "nan", "inf": numbers, not names */
    return end == p ? " (a line of column names? start it with '#')" : "";
}

int cli_reader_next(cli_reader_t *r, double *v)
{
    size_t nul;
    int got;
    while ((got = read_line(r->f, &r->line, &r->cap, &nul)) != 0) {
        char *field[CLI_MAX_FIELD];
        char q[CLI_QUOTE_SIZE], qtok[CLI_QUOTE_SIZE];
        const char *p = r->line;
        comma_scan_t cs;
        long nf;
        unsigned c;
        ++r->lineno;
        if (got == -2) {
            return -cli_fail(r->cmd, "%s:%lu: line of %lu MB or more (not a text file?)",
                             r->name, r->lineno, CLI_MAX_LINE >> 20);
        }
        if (got < 0) {
            return -cli_fail(r->cmd, "%s:%lu: out of memory", r->name, r->lineno);
        }
        if (nul != 0u) {
            return -cli_fail(r->cmd, "%s:%lu: NUL byte at column %lu (not a text file?)",
                             r->name, r->lineno, (unsigned long)nul);
        }
        if (r->lineno == 1ul && strncmp(r->line, "\xEF\xBB\xBF", 3u) == 0) {
            /* a UTF-8 byte-order mark (a spreadsheet's "CSV UTF-8"): not data */
            memmove(r->line, r->line + 3, strlen(r->line + 3) + 1u);
        }
        while (is_space(*p)) {
            ++p;
        }
        if (*p == '\0' || *p == '#') {
            continue;
        }
        if (!r->decimal_comma && strchr(p, ',') == NULL) {
            cs.field = 0; /* nothing to suspect, and the usual case: skip the scan */
            r->seen_dot |= strchr(p, '.') != NULL;
        } else if (!r->decimal_comma) {
            scan_commas(r->line, &cs);
            r->seen_dot |= strchr(r->line, '.') != NULL;
            if (cs.field != 0) {
                (void)cli_quote_n(qtok, cs.tok, cs.len); /* before split_fields() cuts it */
                if (cs.other_sep || cs.strong) {
                    return -decimal_comma_fail(r, r->lineno, cs.field, qtok, "");
                }
                if (cs.alone && r->ncols == 1u && r->cols[0] == 1ul && r->alone_line == 0ul) {
                    r->alone_line = r->lineno;
                    memcpy(r->alone_tok, qtok, sizeof qtok);
                }
            }
        } else {
            cs.field = 0;
        }
        nf = split_fields(r->line, field, CLI_MAX_FIELD, r->decimal_comma);
        if (nf < 0) {
            return -cli_fail(r->cmd, "%s:%lu: field %ld is empty", r->name, r->lineno, -nf);
        }
        if (r->rows == 0u) {
            r->first_nf = nf;
            if (cs.field != 0) {
                r->first_line = r->lineno;
                r->first_field = cs.field;
                memcpy(r->first_tok, qtok, sizeof qtok);
            }
        } else if (nf != r->first_nf && cs.field != 0) {
            return -decimal_comma_fail(r, r->lineno, cs.field, qtok, "");
        } else if (nf != r->first_nf && r->first_line != 0ul) {
            return -decimal_comma_fail(r, r->first_line, r->first_field, r->first_tok, "");
        }
        for (c = 0u; c < r->ncols; ++c) {
            const unsigned long k = r->cols[c];
            char *f;
            if ((unsigned long)nf < k) {
                return -cli_fail(r->cmd, "%s:%lu: field %lu is missing (the line has %ld field%s)",
                                 r->name, r->lineno, k, nf, nf == 1 ? "" : "s");
            }
            f = field[k - 1u];
            if (r->decimal_comma) {
                char *comma = strchr(f, ',');
                if (strchr(f, '.') != NULL) {
                    return -cli_fail(r->cmd, "%s:%lu: field %lu: %s has a '.', but with "
                                             "--decimal-comma ',' is the decimal mark",
                                     r->name, r->lineno, k, cli_quote(q, f));
                }
                if (comma != NULL) {
                    *comma = '.'; /* strtod of the "C" locale */
                }
                if (!cli_parse_double(f, &v[c])) {
                    if (comma != NULL) {
                        *comma = ',';
                    }
                    return -cli_fail(r->cmd, "%s:%lu: field %lu: %s is not a finite number%s",
                                     r->name, r->lineno, k, cli_quote(q, f), names_hint(r, f));
                }
            } else if (!cli_parse_double(f, &v[c])) {
                return -cli_fail(r->cmd, "%s:%lu: field %lu: %s is not a finite number%s",
                                 r->name, r->lineno, k, cli_quote(q, f), names_hint(r, f));
            }
        }
        ++r->rows;
        return 1;
    }
    return reader_end(r);
}

/* ---- whole columns in memory ---- */

static int table_push(cli_table_t *t, const double *v, unsigned ncols)
{
    unsigned c;
    if (t->n == t->cap) {
        const size_t ncap = t->cap ? 2u * t->cap : 1024u;
        if (ncap > (size_t)-1 / sizeof(double)) {
            return -1;
        }
        for (c = 0u; c < ncols; ++c) {
            double *nb = (double *)realloc(t->col[c], ncap * sizeof(double));
            if (nb == NULL) {
                return -1;
            }
            t->col[c] = nb;
        }
        t->cap = ncap;
    }
    for (c = 0u; c < ncols; ++c) {
        t->col[c][t->n] = v[c];
    }
    ++t->n;
    return 0;
}

void cli_table_free(cli_table_t *t)
{
    unsigned c;
    for (c = 0u; c < CLI_MAX_COLS; ++c) {
        free(t->col[c]);
        t->col[c] = NULL;
    }
    t->n = t->cap = 0u;
}

int cli_read_columns(const char *cmd, const char *path, const unsigned long *cols,
                     unsigned ncols, int decimal_comma, cli_table_t *t)
{
    cli_reader_t r;
    double v[CLI_MAX_COLS];
    int got;
    memset(t, 0, sizeof *t);
    if (cli_reader_open(&r, cmd, path, cols, ncols, decimal_comma) != 0) {
        return -1;
    }
    while ((got = cli_reader_next(&r, v)) > 0) {
        if (table_push(t, v, r.ncols) != 0) {
            got = -cli_fail(cmd, "%s:%lu: out of memory", r.name, r.lineno);
            break;
        }
    }
    cli_reader_close(&r);
    if (got != 0) {
        cli_table_free(t);
        return -1;
    }
    return 0;
}
