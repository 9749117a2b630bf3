/* SPDX-License-Identifier: MIT */
/* Model files, format hyst-model-text 1 (docs/cli.md, "Model files"): the
 * same text the MATLAB/Octave functions read and write. */
#include "cli.h"
#include "hyst/hyst.h"

#include <ctype.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAGIC "hyst-model-text 1"

/* Number of blank-separated fields of s into f (pointers into s, which is
 * cut at the blanks); at most max. */
static size_t split(char *s, char **f, size_t max)
{
    size_t n = 0u;
    char *p = s;
    for (;;) {
        while (*p == ' ' || *p == '\t' || *p == '\r') {
            *p++ = '\0';
        }
        if (*p == '\0' || *p == '\n') {
            *p = '\0';
            return n;
        }
        if (n == max) {
            return max + 1u;
        }
        f[n++] = p;
        while (*p != '\0' && *p != ' ' && *p != '\t' && *p != '\r' && *p != '\n') {
            ++p;
        }
    }
}

/* Reads one line, its '\n' dropped, into line[0..size): 1, or 0 at the end
 * of the file. *nul: 1-based column of the line's first NUL byte (0: none),
 * which would otherwise end the line early, silently; *longer: more than
 * size - 2 bytes (the rest of the line is read and dropped). */
static int model_line(FILE *in, char *line, size_t size, unsigned long *nul, int *longer)
{
    size_t len = 0u;
    unsigned long col = 0ul;
    int c;
    *nul = 0ul;
    *longer = 0;
    while ((c = getc(in)) != EOF && c != '\n') {
        ++col;
        if (c == '\0' && *nul == 0ul) {
            *nul = col;
        }
        if (len + 2u < size) {
            line[len++] = (char)c;
        } else {
            *longer = 1;
        }
    }
    line[len] = '\0';
    return c != EOF || col > 0ul;
}

/* 1-based field of line that holds its 1-based column col (a NUL byte is not
 * a blank, so it is in a field). */
static unsigned long field_at(const char *line, unsigned long col)
{
    unsigned long i, field = 0ul;
    int blank = 1;
    for (i = 0ul; i < col; ++i) {
        const char c = line[i];
        const int b = c == ' ' || c == '\t' || c == '\r';
        field += blank && !b ? 1ul : 0ul;
        blank = b;
    }
    return field;
}

/* What a key's line needs: 0 if n fields are right, else a message. */
static int model_count(const char *cmd, const char *path, unsigned long no, const char *key,
                       int coeffs, size_t n)
{
    const size_t most = coeffs ? HYST_MAX_DEGREE + 2u : 2u;
    const size_t least = coeffs ? 3u : 2u;
    const char *needs = coeffs ? "2 to 10 numbers (c_n ... c_0)" : "one value";
    if (n < least) {
        return cli_fail(cmd, "%s:%lu: field %lu is missing: %s needs %s", path, no,
                        (unsigned long)n + 1ul, key, needs);
    }
    if (n > most) {
        return cli_fail(cmd, "%s:%lu: field %lu: one too many: %s needs %s", path, no,
                        (unsigned long)most + 1ul, key, needs);
    }
    return 0;
}

int cli_model_parse(const char *cmd, const char *path, FILE *in, cli_model_t *m)
{
    enum { K_KIND, K_LO, K_HI, K_COEFFS, K_DELAY, K_COUNT };
    static const char *const keys[K_COUNT] = {"kind", "lo", "hi", "coeffs", "delay"};
    char line[1024], *f[HYST_MAX_DEGREE + 3];
    char q[CLI_QUOTE_SIZE];
    int seen[K_COUNT] = {0, 0, 0, 0, 0};
    unsigned long no = 0ul, nul;
    size_t n, i;
    int k, longer;
    memset(m, 0, sizeof *m);
    while (model_line(in, line, sizeof line, &nul, &longer)) {
        ++no;
        if (longer) {
            return cli_fail(cmd, "%s:%lu: line longer than %u bytes", path, no,
                            (unsigned)sizeof line - 2u);
        }
        if (nul != 0ul) {
            return cli_fail(cmd, "%s:%lu: field %lu: NUL byte at column %lu (not a text file?)",
                            path, no, field_at(line, nul), nul);
        }
        if (no == 1ul) {
            line[strcspn(line, "\r")] = '\0';
            if (strcmp(line, MAGIC) != 0) {
                return cli_fail(cmd, "%s:1: %s is not '" MAGIC "' (another format or version)",
                                path, cli_quote(q, line));
            }
            continue;
        }
        n = split(line, f, HYST_MAX_DEGREE + 2u);
        if (n == 0u || f[0][0] == '#') {
            continue;
        }
        for (k = 0; k < K_COUNT && strcmp(f[0], keys[k]) != 0; ++k) {
        }
        if (k == K_COUNT || seen[k]) {
            return cli_fail(cmd, "%s:%lu: field 1: %s %s", path, no, cli_quote(q, f[0]),
                            k == K_COUNT ? "is not a key (kind, lo, hi, coeffs, delay)"
                                         : "given twice");
        }
        seen[k] = 1;
        if (k == K_KIND) {
            if (n != 2u || strcmp(f[1], "poly") != 0) {
                return cli_fail(cmd, "%s:%lu: field 2: kind must be 'poly'", path, no);
            }
            continue;
        }
        if (model_count(cmd, path, no, keys[k], k == K_COEFFS, n) != 0) {
            return 1;
        }
        for (i = 1u; i < n; ++i) {
            double v;
            if (!cli_parse_double(f[i], &v) ||
                (k == K_DELAY && !(v >= 0.0 && v <= 1e9 && v == (double)(unsigned long)v))) {
                return cli_fail(cmd, "%s:%lu: field %lu: %s is not %s", path, no,
                                (unsigned long)(i + 1u), cli_quote(q, f[i]),
                                k == K_DELAY ? "a whole number of samples" : "a finite number");
            }
            if (k == K_LO) {
                m->lo = v;
            } else if (k == K_HI) {
                m->hi = v;
            } else if (k == K_DELAY) {
                m->delay = (unsigned long)v;
            } else {
                m->coeffs[i - 1u] = v;
            }
        }
        if (k == K_COEFFS) {
            m->ncoef = n - 1u;
        }
    }
    if (no == 0ul) {
        return cli_fail(cmd, "%s: empty model file", path);
    }
    for (k = 0; k < K_DELAY; ++k) {
        if (!seen[k]) {
            return cli_fail(cmd, "%s: the key %s is missing", path, keys[k]);
        }
    }
    return 0;
}

int cli_model_read(const char *cmd, const char *path, cli_model_t *m)
{
    int rc;
    FILE *in = fopen(path, "r");
    if (in == NULL) {
        return cli_fail(cmd, "%s: cannot open the model file", path);
    }
    rc = cli_model_parse(cmd, path, in, m);
    if (rc == 0 && ferror(in)) {
        rc = cli_fail(cmd, "%s: read error", path);
    }
    (void)fclose(in);
    return rc;
}

size_t cli_model_text(const cli_model_t *m, char *buf, size_t size)
{
    size_t len;
    unsigned i;
    int w = snprintf(buf, size,
                     MAGIC "\n# hyst model: f0 on [lo, hi], coefficients highest power first, "
                           "the output %lu samples after its input (docs/cli.md)\n"
                           "kind poly\nlo %.17g\nhi %.17g\ndelay %lu\ncoeffs",
                     m->delay, m->lo, m->hi, m->delay);
    if (w < 0 || (size_t)w >= size) {
        return 0u;
    }
    len = (size_t)w;
    for (i = 0u; i < m->ncoef; ++i) {
        w = snprintf(buf + len, size - len, " %.17g", m->coeffs[i]);
        if (w < 0 || (size_t)w >= size - len) {
            return 0u;
        }
        len += (size_t)w;
    }
    if (len + 2u > size) {
        return 0u;
    }
    buf[len++] = '\n';
    buf[len] = '\0';
    return len;
}

int cli_append(char *buf, size_t size, size_t *len, const char *fmt, ...)
{
    va_list ap;
    int n;
    va_start(ap, fmt);
    n = vsnprintf(buf + *len, size - *len, fmt, ap);
    va_end(ap);
    if (n < 0 || (size_t)n >= size - *len) {
        return 1;
    }
    *len += (size_t)n;
    return 0;
}

int cli_header_poly(char *buf, size_t size, size_t *len, const char *name, const cli_model_t *m)
{
    char lit[40], guard[256];
    size_t i;
    int over;
    for (i = 0u; name[i] != '\0' && i + 3u < sizeof guard; ++i) {
        guard[i] = (char)toupper((unsigned char)name[i]);
    }
    memcpy(guard + i, "_H", 3u);
    over = cli_append(buf, size, len, "#ifndef %s\n#define %s\n\n#include \"hyst/curve.h\"\n\n",
                      guard, guard);
    over |= cli_append(buf, size, len, "static const hyst_poly_t %s = {\n    %uu, ", name,
                       (unsigned)(m->ncoef - 1u));
    cli_c_literal(lit, sizeof lit, m->lo);
    over |= cli_append(buf, size, len, "HYST_REAL_C(%s), ", lit);
    cli_c_literal(lit, sizeof lit, m->hi);
    over |= cli_append(buf, size, len, "HYST_REAL_C(%s),\n    {", lit);
    for (i = 0u; i < m->ncoef; ++i) {
        cli_c_literal(lit, sizeof lit, m->coeffs[i]);
        over |= cli_append(buf, size, len, "%sHYST_REAL_C(%s)", i ? ",\n     " : "", lit);
    }
    over |= cli_append(buf, size, len, "}};\n\n#endif /* %s */\n", guard);
    return over;
}

int cli_c_identifier(const char *s)
{
    size_t i;
    if (!(isalpha((unsigned char)s[0]) || s[0] == '_')) {
        return 0;
    }
    for (i = 1u; s[i] != '\0'; ++i) {
        if (!(isalnum((unsigned char)s[i]) || s[i] == '_')) {
            return 0;
        }
    }
    return i < 200u;
}
