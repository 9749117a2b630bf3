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
#define STR_(x) #x
#define STR(x) STR_(x)

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

/* Fields of a key's line: the key and 1 to MODEL_MAX_FIELDS - 1 values. */
#define MODEL_MAX_FIELDS \
    (HYST_MAX_DEGREE + 2 > HYST_EVERETT_TERMS + 1 ? HYST_MAX_DEGREE + 2 : HYST_EVERETT_TERMS + 1)

enum {
    K_KIND,
    K_LO,
    K_HI,
    K_COEFFS,
    K_DELAY,
    K_Y_LO,
    K_DEGREE,
    K_TERMS,
    K_CREEP_TAU,
    K_CREEP_WEIGHT,
    K_IDENTIFIED,
    K_COUNT
};
static const char *const keys[K_COUNT] = {"kind",  "lo",   "hi",     "coeffs",    "delay",
                                          "y_lo",  "degree", "terms", "creep_tau",
                                          "creep_weight", "identified"};

/* What a key's line needs: 0 if n fields are right, else a message. */
static int model_count(const char *cmd, const char *path, unsigned long no, int k, size_t n)
{
    size_t least = 2u, most = 2u;
    const char *needs = "one value";
    char text[64];
    if (k == K_COEFFS) {
        least = 3u;
        most = HYST_MAX_DEGREE + 2u;
        needs = "2 to 10 numbers (c_n ... c_0)";
    } else if (k == K_TERMS) {
        most = HYST_EVERETT_TERMS + 1u;
        (void)snprintf(text, sizeof text, "1 to %u numbers (E's coefficients)",
                       (unsigned)HYST_EVERETT_TERMS);
        needs = text;
    } else if (k == K_CREEP_TAU || k == K_CREEP_WEIGHT) {
        most = CLI_CREEP_MAX_TERMS + 1u;
        (void)snprintf(text, sizeof text, "1 to %u numbers (one per creep term)",
                       (unsigned)CLI_CREEP_MAX_TERMS);
        needs = text;
    } else if (k == K_IDENTIFIED) {
        least = most = 3u;
        needs = "two values (LO HI)";
    }
    if (n < least) {
        return cli_fail(cmd, "%s:%lu: field %lu is missing: %s needs %s", path, no,
                        (unsigned long)n + 1ul, keys[k], needs);
    }
    if (n > most) {
        return cli_fail(cmd, "%s:%lu: field %lu: one too many: %s needs %s", path, no,
                        (unsigned long)most + 1ul, keys[k], needs);
    }
    return 0;
}

/* A whole number in [least, most] (degree). */
static int whole(double v, double least, double most)
{
    return v >= least && v <= most && v == (double)(unsigned long)v;
}

/* One value of key k, field i of line no, into m: 0, or 1 after a message. */
static int model_value(const char *cmd, const char *path, unsigned long no, int k, size_t i,
                       const char *field, cli_model_t *m)
{
    char q[CLI_QUOTE_SIZE];
    double v;
    const char *what = "a finite number";
    int ok = cli_parse_double(field, &v);
    if (ok && k == K_DELAY) {
        ok = v >= 0.0 && v <= 1e9;
        what = "a delay of 0 to 1e9 samples";
    } else if (ok && k == K_DEGREE) {
        ok = whole(v, 1.0, (double)HYST_EVERETT_MAX_DEGREE);
        what = "a degree in 1.." STR(HYST_EVERETT_MAX_DEGREE);
    } else if (ok && k == K_CREEP_TAU) {
        ok = v >= 1.0;
        what = "a time constant of at least 1 sample";
    }
    if (!ok) {
        return cli_fail(cmd, "%s:%lu: field %lu: %s is not %s", path, no, (unsigned long)(i + 1u),
                        cli_quote(q, field), what);
    }
    switch (k) {
    case K_LO: m->lo = v; break;
    case K_HI: m->hi = v; break;
    case K_DELAY:
        m->delay = (unsigned long)v;
        m->delay_fraction = v - (double)m->delay; /* exact: v < 2^53 */
        break;
    case K_Y_LO: m->y_lo = v; break;
    case K_DEGREE: m->degree = (unsigned)v; break;
    case K_TERMS: m->terms[i - 1u] = v; break;
    case K_CREEP_TAU: m->creep_tau[i - 1u] = v; break;
    case K_CREEP_WEIGHT: m->creep_weight[i - 1u] = v; break;
    case K_IDENTIFIED: *(i == 1u ? &m->id_lo : &m->id_hi) = v; break;
    default: m->coeffs[i - 1u] = v; break;
    }
    return 0;
}

/* After the last line: each key the kind needs, none of the other kind's,
 * and as many terms as the degree gives. 0, or 1 after a message. */
static int model_complete(const char *cmd, const char *path, const unsigned long *line,
                          const cli_model_t *m)
{
    static const int poly_keys[] = {K_KIND, K_LO, K_HI, K_COEFFS};
    static const int everett_keys[] = {K_KIND, K_LO, K_HI, K_Y_LO, K_DEGREE, K_TERMS};
    const int everett = line[K_KIND] != 0ul && m->kind == CLI_MODEL_EVERETT;
    const int *need = everett ? everett_keys : poly_keys;
    const size_t n_need = everett ? sizeof everett_keys / sizeof everett_keys[0]
                                  : sizeof poly_keys / sizeof poly_keys[0];
    size_t i;
    int k;
    if (line[K_KIND] != 0ul) {
        for (k = 0; k < K_COUNT; ++k) {
            const int of_everett = k == K_Y_LO || k == K_DEGREE || k == K_TERMS;
            if (line[k] != 0ul && (everett ? k == K_COEFFS : of_everett)) {
                return cli_fail(cmd, "%s:%lu: field 1: %s is not a key of kind %s (%s)", path,
                                line[k], keys[k], everett ? "everett" : "poly",
                                everett ? "E is given by degree and terms"
                                        : "y_lo, degree and terms are kind everett's");
            }
        }
    }
    for (i = 0u; i < n_need; ++i) {
        if (line[need[i]] == 0ul) {
            return cli_fail(cmd, "%s: the key %s is missing", path, keys[need[i]]);
        }
    }
    if ((line[K_CREEP_TAU] != 0ul) != (line[K_CREEP_WEIGHT] != 0ul)) {
        const int k_has = line[K_CREEP_TAU] != 0ul ? K_CREEP_TAU : K_CREEP_WEIGHT;
        return cli_fail(cmd, "%s:%lu: field 1: %s needs %s too (creep: both or neither)", path,
                        line[k_has], keys[k_has],
                        keys[k_has == K_CREEP_TAU ? K_CREEP_WEIGHT : K_CREEP_TAU]);
    }
    if (line[K_IDENTIFIED] != 0ul && !(m->lo <= m->id_lo && m->id_lo < m->id_hi &&
                                       m->id_hi <= m->hi)) {
        /* the field at fault: LO (below lo, or not below HI), else HI */
        const int field = m->id_lo < m->lo || !(m->id_lo < m->id_hi) ? 2 : 3;
        return cli_fail(cmd, "%s:%lu: field %d: identified %.17g %.17g is not a range within "
                             "[lo, hi] = [%.17g, %.17g]",
                        path, line[K_IDENTIFIED], field, m->id_lo, m->id_hi, m->lo, m->hi);
    }
    if (m->ncreep != m->ncreep_weights) {
        const int short_w = m->ncreep_weights < m->ncreep; /* else one too many */
        return cli_fail(cmd, "%s:%lu: field %lu%s: creep_weight needs %lu numbers, one per creep_tau",
                        path, line[K_CREEP_WEIGHT],
                        (unsigned long)(short_w ? m->ncreep_weights : m->ncreep) + 2ul,
                        short_w ? " is missing" : ": one too many", (unsigned long)m->ncreep);
    }
    if (everett && m->nterms != cli_everett_terms(m->degree)) {
        const size_t want = cli_everett_terms(m->degree);
        return cli_fail(cmd, "%s:%lu: field %lu%s: terms needs %lu numbers for degree %u", path,
                        line[K_TERMS],
                        (unsigned long)(m->nterms < want ? m->nterms : want) + 2ul,
                        m->nterms < want ? " is missing" : ": one too many", (unsigned long)want,
                        m->degree);
    }
    return 0;
}

int cli_model_parse(const char *cmd, const char *path, FILE *in, cli_model_t *m)
{
    char line[1024], *f[MODEL_MAX_FIELDS + 1];
    char q[CLI_QUOTE_SIZE];
    unsigned long seen[K_COUNT]; /* line of each key */
    unsigned long no = 0ul, nul;
    size_t n, i;
    int k, longer;
    memset(m, 0, sizeof *m);
    memset(seen, 0, sizeof seen);
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
        n = split(line, f, MODEL_MAX_FIELDS);
        if (n == 0u || f[0][0] == '#') {
            continue;
        }
        for (k = 0; k < K_COUNT && strcmp(f[0], keys[k]) != 0; ++k) {
        }
        if (k == K_COUNT || seen[k] != 0ul) {
            return cli_fail(cmd, "%s:%lu: field 1: %s %s", path, no, cli_quote(q, f[0]),
                            k == K_COUNT ? "is not a key (kind, lo, hi, identified, delay, "
                                           "coeffs, creep_tau, creep_weight; kind everett: y_lo, "
                                           "degree, terms)"
                                         : "given twice");
        }
        seen[k] = no;
        if (k == K_KIND) {
            if (n != 2u || (strcmp(f[1], "poly") != 0 && strcmp(f[1], "everett") != 0)) {
                return cli_fail(cmd, "%s:%lu: field 2: kind must be 'poly' or 'everett'", path,
                                no);
            }
            m->kind = strcmp(f[1], "everett") == 0 ? CLI_MODEL_EVERETT : CLI_MODEL_POLY;
            continue;
        }
        if (model_count(cmd, path, no, k, n) != 0) {
            return 1;
        }
        for (i = 1u; i < n; ++i) {
            if (model_value(cmd, path, no, k, i, f[i], m) != 0) {
                return 1;
            }
        }
        if (k == K_COEFFS) {
            m->ncoef = n - 1u;
        } else if (k == K_TERMS) {
            m->nterms = n - 1u;
        } else if (k == K_CREEP_TAU) {
            m->ncreep = n - 1u;
        } else if (k == K_CREEP_WEIGHT) {
            m->ncreep_weights = n - 1u;
        } else if (k == K_IDENTIFIED) {
            m->has_identified = 1;
        }
    }
    if (no == 0ul) {
        return cli_fail(cmd, "%s: empty model file", path);
    }
    return model_complete(cmd, path, seen, m);
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

/* Appends " %.17g" of each of v[0..n) to buf[*len..size); 1 when it did not fit. */
static int append_numbers(char *buf, size_t size, size_t *len, const double *v, size_t n)
{
    size_t i;
    int over = 0;
    for (i = 0u; i < n; ++i) {
        over |= cli_append(buf, size, len, " %.17g", v[i]);
    }
    return over;
}

size_t cli_model_text(const cli_model_t *m, char *buf, size_t size)
{
    size_t len = 0u;
    int over;
    if (m->kind == CLI_MODEL_EVERETT) {
        over = cli_append(buf, size, &len,
                          MAGIC "\n# hyst model: asymmetric, E(a, b) = sum of e[i-1][j] w^i t^j, "
                                "w = (a - b) / (hi - lo), t = (b - lo) / (hi - lo); terms i = "
                                "1..degree, then j = 0..degree - i; the output %.17g samples after "
                                "its input (docs/cli.md)\n"
                                "kind everett\nlo %.17g\nhi %.17g\ny_lo %.17g\ndelay %.17g\n"
                                "degree %u\nterms",
                          cli_model_delay(m), m->lo, m->hi, m->y_lo, cli_model_delay(m),
                          m->degree);
        over |= append_numbers(buf, size, &len, m->terms, m->nterms);
    } else {
        over = cli_append(buf, size, &len,
                          MAGIC "\n# hyst model: f0 on [lo, hi], coefficients highest power "
                                "first, the output %.17g samples after its input (docs/cli.md)\n"
                                "kind poly\nlo %.17g\nhi %.17g\ndelay %.17g\ncoeffs",
                          cli_model_delay(m), m->lo, m->hi, cli_model_delay(m));
        over |= append_numbers(buf, size, &len, m->coeffs, m->ncoef);
    }
    if (m->has_identified) {
        over |= cli_append(buf, size, &len,
                           "\n# identified on inputs in [LO, HI]; the branches continue "
                           "beyond it to [lo, hi]\nidentified %.17g %.17g",
                           m->id_lo, m->id_hi);
    }
    if (m->ncreep > 0u) {
        over |= cli_append(buf, size, &len,
                           "\n# creep: the output plus sum of creep_weight[k] s_k, s_k the "
                           "input lagged with time constant creep_tau[k] samples (from lo at "
                           "rest)\ncreep_tau");
        over |= append_numbers(buf, size, &len, m->creep_tau, m->ncreep);
        over |= cli_append(buf, size, &len, "\ncreep_weight");
        over |= append_numbers(buf, size, &len, m->creep_weight, m->ncreep);
    }
    over |= cli_append(buf, size, &len, "\n");
    return over ? 0u : len;
}

double cli_model_delay(const cli_model_t *m) { return (double)m->delay + m->delay_fraction; }

size_t cli_everett_terms(unsigned degree) { return (size_t)degree * (degree + 1u) / 2u; }

void cli_model_to_everett(const cli_model_t *m, hyst_everett_t *e)
{
    unsigned i, j;
    size_t t = 0u;
    memset(e, 0, sizeof *e);
    e->degree = m->degree;
    e->lo = m->lo;
    e->hi = m->hi;
    e->y_lo = m->y_lo;
    for (i = 1u; i <= m->degree && i <= HYST_EVERETT_MAX_DEGREE; ++i) {
        for (j = 0u; i + j <= m->degree && t < m->nterms; ++j) {
            e->e[i - 1u][j] = m->terms[t++];
        }
    }
}

void cli_model_from_everett(cli_model_t *m, const hyst_everett_t *e, unsigned long delay)
{
    unsigned i, j;
    memset(m, 0, sizeof *m);
    m->kind = CLI_MODEL_EVERETT;
    m->degree = e->degree;
    m->lo = (double)e->lo;
    m->hi = (double)e->hi;
    m->y_lo = (double)e->y_lo;
    m->delay = delay;
    for (i = 1u; i <= e->degree && i <= HYST_EVERETT_MAX_DEGREE; ++i) {
        for (j = 0u; i + j <= e->degree; ++j) {
            m->terms[m->nterms++] = (double)e->e[i - 1u][j];
        }
    }
}

int cli_everett_curve(const char *cmd, const char *path, const cli_model_t *m, hyst_curve_t *c)
{
    hyst_everett_t e;
    hyst_status_t st;
    cli_model_to_everett(m, &e);
    st = hyst_f64_curve_from_everett(c, &e);
    return st == HYST_OK ? 0 : cli_fail(cmd, "model file %s: %s", path, hyst_status_str(st));
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

/* "HYST_REAL_C(v)" for the number v, appended. */
static int append_real(char *buf, size_t size, size_t *len, const char *before, double v)
{
    char lit[40];
    cli_c_literal(lit, sizeof lit, v);
    return cli_append(buf, size, len, "%sHYST_REAL_C(%s)", before, lit);
}

/* The asymmetric kind's initializer: every row of e[][] written out, zeros
 * above the degree, so that no brace is elided. */
static int header_everett(char *buf, size_t size, size_t *len, const char *name,
                          const cli_model_t *m)
{
    hyst_everett_t e;
    unsigned i, j;
    int over;
    cli_model_to_everett(m, &e);
    over = cli_append(buf, size, len, "static const hyst_everett_t %s = {\n    %uu,", name,
                      m->degree);
    over |= append_real(buf, size, len, " ", m->lo);
    over |= append_real(buf, size, len, ", ", m->hi);
    over |= append_real(buf, size, len, ", ", m->y_lo);
    over |= cli_append(buf, size, len, ",\n    {");
    for (i = 0u; i < HYST_EVERETT_MAX_DEGREE; ++i) {
        over |= cli_append(buf, size, len, "%s{", i ? ",\n     " : "");
        for (j = 0u; j < HYST_EVERETT_MAX_DEGREE; ++j) {
            over |= append_real(buf, size, len, j ? ", " : "", (double)e.e[i][j]);
        }
        over |= cli_append(buf, size, len, "}");
    }
    return over | cli_append(buf, size, len, "}};\n");
}

/* The creep term, if any: its count, time constants and weights, for
 * hyst_creep_init() with the domain's lo as the rest drive. */
static int header_creep(char *buf, size_t size, size_t *len, const char *name,
                        const cli_model_t *m)
{
    size_t i;
    int over;
    if (m->ncreep == 0u) {
        return 0;
    }
    over = cli_append(buf, size, len,
                      "\n/* creep: add hyst_creep_step() of the model's input to its output\n"
                      " * (hyst/creep.h): hyst_creep_init(&creep, %s_CREEP_TERMS,\n"
                      " * %s_creep_tau, %s_creep_weight, lo) */\n#define %s_CREEP_TERMS %luu\n"
                      "static const hyst_wide_t %s_creep_tau[%s_CREEP_TERMS] = {",
                      name, name, name, name, (unsigned long)m->ncreep, name, name);
    for (i = 0u; i < m->ncreep; ++i) {
        over |= append_real(buf, size, len, i ? ", " : "", m->creep_tau[i]);
    }
    over |= cli_append(buf, size, len, "};\nstatic const hyst_wide_t %s_creep_weight[%s_CREEP_TERMS] = {",
                       name, name);
    for (i = 0u; i < m->ncreep; ++i) {
        over |= append_real(buf, size, len, i ? ", " : "", m->creep_weight[i]);
    }
    return over | cli_append(buf, size, len, "};\n");
}

/* The include guard of NAME.h: NAME in capitals, then _H. */
static void guard_of(const char *name, char *guard, size_t size)
{
    size_t i;
    for (i = 0u; name[i] != '\0' && i + 3u < size; ++i) {
        guard[i] = (char)toupper((unsigned char)name[i]);
    }
    memcpy(guard + i, "_H", 3u);
}

int cli_header_open(char *buf, size_t size, size_t *len, const char *name, const cli_model_t *m)
{
    char guard[256];
    size_t i;
    int over;
    guard_of(name, guard, sizeof guard);
    over = cli_append(buf, size, len, "#ifndef %s\n#define %s\n\n#include \"hyst/curve.h\"\n%s\n",
                      guard, guard, m->ncreep > 0u ? "#include \"hyst/creep.h\"\n" : "");
    if (m->kind == CLI_MODEL_EVERETT) {
        return over | header_everett(buf, size, len, name, m) | header_creep(buf, size, len, name, m);
    }
    over |= cli_append(buf, size, len, "static const hyst_poly_t %s = {\n    %uu,", name,
                       (unsigned)(m->ncoef - 1u));
    over |= append_real(buf, size, len, " ", m->lo);
    over |= append_real(buf, size, len, ", ", m->hi);
    over |= cli_append(buf, size, len, ",\n    {");
    for (i = 0u; i < m->ncoef; ++i) {
        over |= append_real(buf, size, len, i ? ",\n     " : "", m->coeffs[i]);
    }
    return over | cli_append(buf, size, len, "}};\n") | header_creep(buf, size, len, name, m);
}

int cli_header_close(char *buf, size_t size, size_t *len, const char *name)
{
    char guard[256];
    guard_of(name, guard, sizeof guard);
    return cli_append(buf, size, len, "\n#endif /* %s */\n", guard);
}

int cli_header_model(char *buf, size_t size, size_t *len, const char *name, const cli_model_t *m)
{
    return cli_header_open(buf, size, len, name, m) | cli_header_close(buf, size, len, name);
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
