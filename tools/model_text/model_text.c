/* SPDX-License-Identifier: MIT */
/* hyst-model-text 1: the reader, the checks, the writer and the header text
 * (model_text.h). Numbers are decimal, read the same whatever the C locale
 * of the process that links this (Octave and Python set theirs). */
#include "model_text.h"

#include <locale.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define STR_(x) #x
#define STR(x) STR_(x)

/* Fields of a key's line: the key and its values, at most. */
#define MAX_FIELDS_ \
    (HYST_MAX_DEGREE + 2 > HYST_EVERETT_TERMS + 1 ? HYST_MAX_DEGREE + 2 : HYST_EVERETT_TERMS + 1)
#define GRID_CELLS_ HYST_EVERETT_GRID_CELLS(HYST_EVERETT_GRID_MAX_INTERVALS)
#define MAX_FIELDS__ (MAX_FIELDS_ > GRID_CELLS_ + 1 ? MAX_FIELDS_ : GRID_CELLS_ + 1)
#define MAX_FIELDS \
    (MAX_FIELDS__ > HYST_SPLINE_MAX_INTERVALS + 2 ? MAX_FIELDS__ : HYST_SPLINE_MAX_INTERVALS + 2)

/* The longest number read without an allocation (a 17-digit number needs
 * 24 characters). */
#define MAX_NUMBER 1023u

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
    K_RATE_TAU,
    K_RATE_WEIGHT,
    K_KNOTS,
    K_WEIGHTS,
    K_VALUES,
    K_SLOPES,
    K_COUNT
};
static const char *const keys[K_COUNT] = {"kind",      "lo",           "hi",        "coeffs",
                                          "delay",     "y_lo",         "degree",    "terms",
                                          "creep_tau", "creep_weight", "identified",
                                          "rate_tau",  "rate_weight",  "knots",     "weights",
                                          "values",    "slopes"};

/* A field of a line: its start and length. */
typedef struct field {
    const char *s;
    size_t n;
} field_t;

/* The reader's state. */
typedef struct reader {
    const char *path;
    char *msg;
    size_t msg_size;
    unsigned long seen[K_COUNT]; /* line of each key, 0: not seen */
    char lo_text[MODEL_TEXT_QUOTE_SIZE], hi_text[MODEL_TEXT_QUOTE_SIZE];
} reader_t;

int model_text_append(char *buf, size_t size, size_t *len, const char *fmt, ...)
{
    va_list ap;
    int n;
    if (*len >= size) {
        return 1;
    }
    va_start(ap, fmt);
    n = vsnprintf(buf + *len, size - *len, fmt, ap);
    va_end(ap);
    if (n < 0 || (size_t)n >= size - *len) {
        return 1;
    }
    *len += (size_t)n;
    return 0;
}

/* The message into r->msg; returns 1. */
static int fail(const reader_t *r, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
static int fail(const reader_t *r, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    (void)vsnprintf(r->msg, r->msg_size, fmt, ap);
    va_end(ap);
    return 1;
}

char *model_text_escape(char *out, unsigned char c)
{
    static const char hex[] = "0123456789abcdef";
    if (c == '\\' || c == '\'') {
        *out++ = '\\';
        *out++ = (char)c;
    } else if (c >= 0x20u && c < 0x7fu) {
        *out++ = (char)c;
    } else {
        *out++ = '\\';
        *out++ = 'x';
        *out++ = hex[c >> 4];
        *out++ = hex[c & 0xfu];
    }
    return out;
}

const char *model_text_quote(char *buf, const char *s, size_t len)
{
    char *out = buf;
    size_t i;
    *out++ = '\'';
    for (i = 0u; i < len && i < MODEL_TEXT_QUOTE_MAX; ++i) {
        out = model_text_escape(out, (unsigned char)s[i]);
    }
    if (len > MODEL_TEXT_QUOTE_MAX) {
        (void)sprintf(out, "...' (%lu bytes)", (unsigned long)len);
    } else {
        *out++ = '\'';
        *out = '\0';
    }
    return buf;
}

static int is_blank(char c) { return c == ' ' || c == '\t'; }

static size_t digits(const char *s, size_t n, size_t i)
{
    while (i < n && s[i] >= '0' && s[i] <= '9') {
        ++i;
    }
    return i;
}

/* A decimal number, the whole of s[0..n): [+-] digits [. digits] [e [+-]
 * digits], at least one digit before the exponent; finite (denormals are:
 * only overflow is refused). Not hexadecimal, not inf or nan, and '.' as
 * the decimal mark whatever the locale. 1 on success. */
static int parse_number(const char *s, size_t n, double *out)
{
    char small[MAX_NUMBER + 1u], *buf = small, *end;
    const struct lconv *lc = localeconv();
    const char point = lc != NULL && lc->decimal_point != NULL && lc->decimal_point[0] != '\0'
                           ? lc->decimal_point[0]
                           : '.';
    size_t i = 0u, mantissa, k;
    double v;
    int ok;
    if (n == 0u) {
        return 0;
    }
    i += s[i] == '+' || s[i] == '-' ? 1u : 0u;
    k = digits(s, n, i);
    mantissa = k - i;
    i = k;
    if (i < n && s[i] == '.') {
        k = digits(s, n, i + 1u);
        mantissa += k - i - 1u;
        i = k;
    }
    if (mantissa == 0u) {
        return 0;
    }
    if (i < n && (s[i] == 'e' || s[i] == 'E')) {
        ++i;
        i += i < n && (s[i] == '+' || s[i] == '-') ? 1u : 0u;
        k = digits(s, n, i);
        if (k == i) {
            return 0;
        }
        i = k;
    }
    if (i != n) {
        return 0;
    }
    if (n > MAX_NUMBER && (buf = (char *)malloc(n + 1u)) == NULL) {
        return 0;
    }
    for (k = 0u; k < n; ++k) {
        buf[k] = s[k] == '.' ? point : s[k];
    }
    buf[n] = '\0';
    v = strtod(buf, &end);
    ok = end == buf + n && isfinite(v);
    if (buf != small) {
        free(buf);
    }
    if (ok) {
        *out = v;
    }
    return ok;
}

/* What key k's line needs: 0 if its n fields (the key's included) are
 * right, else 1 after a message. */
static int check_count(const reader_t *r, unsigned long no, int k, size_t n)
{
    size_t least = 2u, most = 2u;
    const char *needs = "one value";
    char text[64];
    if (k == K_COEFFS) {
        least = 3u;
        most = HYST_MAX_DEGREE + 2u;
        (void)snprintf(text, sizeof text, "2 to %u numbers (c_n ... c_0)",
                       (unsigned)HYST_MAX_DEGREE + 1u);
        needs = text;
    } else if (k == K_TERMS) {
        most = HYST_EVERETT_TERMS + 1u;
        (void)snprintf(text, sizeof text, "1 to %u numbers (E's coefficients)",
                       (unsigned)HYST_EVERETT_TERMS);
        needs = text;
    } else if (k == K_CREEP_TAU || k == K_CREEP_WEIGHT) {
        most = MODEL_TEXT_CREEP_MAX_TERMS + 1u;
        (void)snprintf(text, sizeof text, "1 to %u numbers (one per creep term)",
                       (unsigned)MODEL_TEXT_CREEP_MAX_TERMS);
        needs = text;
    } else if (k == K_IDENTIFIED) {
        least = most = 3u;
        needs = "two values (LO HI)";
    } else if (k == K_KNOTS) {
        least = 3u;
        most = HYST_EVERETT_GRID_MAX_INTERVALS + 2u;
        (void)snprintf(text, sizeof text, "2 to %u numbers (lo ... hi)",
                       (unsigned)HYST_EVERETT_GRID_MAX_INTERVALS + 1u);
        needs = text;
    } else if (k == K_WEIGHTS) {
        most = GRID_CELLS_ + 1u;
        (void)snprintf(text, sizeof text, "1 to %u numbers (the cells' masses)",
                       (unsigned)GRID_CELLS_);
        needs = text;
    } else if (k == K_VALUES || k == K_SLOPES) {
        least = k == K_VALUES ? 3u : 2u;
        most = HYST_SPLINE_MAX_INTERVALS + 2u;
        (void)snprintf(text, sizeof text, "%u to %u numbers (%s at the knots)",
                       (unsigned)least - 1u,
                       (unsigned)HYST_SPLINE_MAX_INTERVALS + 1u,
                       k == K_VALUES ? "f0" : "its slope");
        needs = text;
    }
    if (n < least) {
        return fail(r, "%s:%lu: field %lu is missing: %s needs %s", r->path, no,
                    (unsigned long)n + 1ul, keys[k], needs);
    }
    if (n > most) {
        return fail(r, "%s:%lu: field %lu: one too many: %s needs %s", r->path, no,
                    (unsigned long)most + 1ul, keys[k], needs);
    }
    return 0;
}

/* A whole number in [least, most] (degree). */
static int whole(double v, double least, double most)
{
    return v >= least && v <= most && v == floor(v);
}

/* Value i (field i + 1) of key k into m: 0, or 1 after a message. */
static int read_value(reader_t *r, unsigned long no, int k, size_t i, const field_t *f,
                      model_text_t *m)
{
    char q[MODEL_TEXT_QUOTE_SIZE];
    double v = 0.0;
    const char *what = "a finite number";
    int ok = parse_number(f->s, f->n, &v);
    if (ok && k == K_DELAY) {
        ok = v >= 0.0 && v <= (double)MODEL_TEXT_MAX_DELAY;
        what = "a delay of 0 to 1000000000 samples";
    } else if (ok && k == K_DEGREE) {
        ok = whole(v, 1.0, (double)HYST_EVERETT_MAX_DEGREE);
        what = "a degree in 1.." STR(HYST_EVERETT_MAX_DEGREE);
    } else if (ok && (k == K_CREEP_TAU || k == K_RATE_TAU)) {
        ok = v >= 1.0;
        what = "a time constant of at least 1 sample";
    } else if (ok && k == K_SLOPES) {
        ok = v >= 0.0;
        what = "a slope >= 0 (f0 increases)";
    }
    if (!ok) {
        return fail(r, "%s:%lu: field %lu: %s is not %s%s", r->path, no, (unsigned long)(i + 1u),
                    model_text_quote(q, f->s, f->n), what,
                    memchr(f->s, ',', f->n) != NULL ? " (the decimal mark is '.')" : "");
    }
    switch (k) {
    case K_LO:
        m->lo = v;
        (void)model_text_quote(r->lo_text, f->s, f->n);
        break;
    case K_HI:
        m->hi = v;
        (void)model_text_quote(r->hi_text, f->s, f->n);
        break;
    case K_DELAY:
        m->delay = (unsigned long)v;
        /* exact: v < 2^53; 0, not -0, for "-0" (the file written back says 0) */
        m->delay_fraction = v > (double)m->delay ? v - (double)m->delay : 0.0;
        break;
    case K_Y_LO: m->y_lo = v; break;
    case K_DEGREE: m->degree = (unsigned)v; break;
    case K_TERMS: m->terms[i - 1u] = v; break;
    case K_CREEP_TAU: m->creep_tau[i - 1u] = v; break;
    case K_CREEP_WEIGHT: m->creep_weight[i - 1u] = v; break;
    case K_IDENTIFIED: *(i == 1u ? &m->id_lo : &m->id_hi) = v; break;
    case K_RATE_TAU: m->rate_tau = v; break;
    case K_RATE_WEIGHT: m->rate_weight = v; break;
    case K_KNOTS: m->knots[i - 1u] = v; break;
    case K_WEIGHTS: m->weights[i - 1u] = v; break;
    case K_VALUES: m->values[i - 1u] = v; break;
    case K_SLOPES: m->slopes[i - 1u] = v; break;
    default: m->coeffs[i - 1u] = v; break;
    }
    return 0;
}

/* 1-based field of the line s[0..n) that holds its 1-based column col. */
static unsigned long field_at(const char *s, size_t col)
{
    unsigned long field = 0ul;
    size_t i;
    int blank = 1;
    for (i = 0u; i < col; ++i) {
        const int b = is_blank(s[i]);
        field += blank && !b ? 1ul : 0ul;
        blank = b;
    }
    return field;
}

/* Line no, s[0..n) without its end: 0, or 1 after a message. */
static int read_line(reader_t *r, unsigned long no, const char *s, size_t n, model_text_t *m)
{
    field_t f[MAX_FIELDS + 1];
    char q[MODEL_TEXT_QUOTE_SIZE];
    const char *nul = (const char *)memchr(s, '\0', n);
    size_t count = 0u, i = 0u;
    int k;
    if (nul != NULL) {
        const size_t col = (size_t)(nul - s) + 1u;
        return fail(r, "%s:%lu: field %lu: NUL byte at column %lu (not a text file?)", r->path,
                    no, field_at(s, col), (unsigned long)col);
    }
    if (no == 1ul) {
        while (n > 0u && is_blank(s[n - 1u])) {
            --n;
        }
        if (n != sizeof MODEL_TEXT_MAGIC - 1u || memcmp(s, MODEL_TEXT_MAGIC, n) != 0) {
            return fail(r, "%s:1: %s is not '" MODEL_TEXT_MAGIC "' (another format or version)",
                        r->path, model_text_quote(q, s, n));
        }
        return 0;
    }
    for (;;) {
        while (i < n && is_blank(s[i])) {
            ++i;
        }
        if (i == n) {
            break;
        }
        if (count == MAX_FIELDS + 1u) {
            ++count; /* more than any key takes: check_count() says so */
            break;
        }
        f[count].s = s + i;
        while (i < n && !is_blank(s[i])) {
            ++i;
        }
        f[count].n = (size_t)(s + i - f[count].s);
        ++count;
    }
    if (count == 0u || f[0].s[0] == '#') {
        return 0;
    }
    for (k = 0; k < K_COUNT && !(strlen(keys[k]) == f[0].n && memcmp(f[0].s, keys[k], f[0].n) == 0);
         ++k) {
    }
    if (k == K_COUNT || r->seen[k] != 0ul) {
        return fail(r, "%s:%lu: field 1: %s %s", r->path, no, model_text_quote(q, f[0].s, f[0].n),
                    k == K_COUNT ? "is not a key (kind, lo, hi, identified, delay, coeffs, "
                                   "creep_tau, creep_weight, rate_tau, rate_weight; kind "
                                   "everett: y_lo, degree, terms; kind everett_grid: y_lo, "
                                   "knots, weights; kind spline: values, slopes)"
                                 : "given twice");
    }
    r->seen[k] = no;
    if (k == K_KIND) {
        const int poly = count == 2u && f[1].n == 4u && memcmp(f[1].s, "poly", 4u) == 0;
        const int everett = count == 2u && f[1].n == 7u && memcmp(f[1].s, "everett", 7u) == 0;
        const int grid = count == 2u && f[1].n == 12u && memcmp(f[1].s, "everett_grid", 12u) == 0;
        const int spline = count == 2u && f[1].n == 6u && memcmp(f[1].s, "spline", 6u) == 0;
        if (!poly && !everett && !grid && !spline) {
            return fail(r, "%s:%lu: field 2: kind must be 'poly', 'everett', 'everett_grid' or "
                           "'spline'",
                        r->path, no);
        }
        m->kind = spline    ? MODEL_TEXT_SPLINE
                  : grid    ? MODEL_TEXT_GRID
                  : everett ? MODEL_TEXT_EVERETT
                            : MODEL_TEXT_POLY;
        return 0;
    }
    if (check_count(r, no, k, count) != 0) {
        return 1;
    }
    for (i = 1u; i < count; ++i) {
        if (read_value(r, no, k, i, &f[i], m) != 0) {
            return 1;
        }
    }
    if (k == K_COEFFS) {
        m->ncoef = count - 1u;
    } else if (k == K_TERMS) {
        m->nterms = count - 1u;
    } else if (k == K_CREEP_TAU) {
        m->ncreep = count - 1u;
    } else if (k == K_CREEP_WEIGHT) {
        m->ncreep_weights = count - 1u;
    } else if (k == K_IDENTIFIED) {
        m->has_identified = 1;
    } else if (k == K_RATE_TAU) {
        m->has_rate = 1;
    } else if (k == K_KNOTS) {
        m->nknots = count - 1u;
    } else if (k == K_WEIGHTS) {
        m->nweights = count - 1u;
    } else if (k == K_VALUES) {
        m->nvalues = count - 1u;
    } else if (k == K_SLOPES) {
        m->nslopes = count - 1u;
    }
    return 0;
}

/* After the last line: each key the kind needs, none of the other kind's,
 * as many terms as the degree gives, creep keys paired, lo < hi. 0, or 1
 * after a message. */
static int read_complete(const reader_t *r, const model_text_t *m)
{
    static const int poly_keys[] = {K_KIND, K_LO, K_HI, K_COEFFS};
    static const int everett_keys[] = {K_KIND, K_LO, K_HI, K_Y_LO, K_DEGREE, K_TERMS};
    static const int grid_keys[] = {K_KIND, K_LO, K_HI, K_Y_LO, K_KNOTS, K_WEIGHTS};
    static const int spline_keys[] = {K_KIND, K_LO, K_HI, K_VALUES, K_SLOPES};
    const unsigned long *line = r->seen;
    const int everett = line[K_KIND] != 0ul && m->kind == MODEL_TEXT_EVERETT;
    const int grid = line[K_KIND] != 0ul && m->kind == MODEL_TEXT_GRID;
    const int spline = line[K_KIND] != 0ul && m->kind == MODEL_TEXT_SPLINE;
    const int *need = spline ? spline_keys : grid ? grid_keys : everett ? everett_keys : poly_keys;
    const size_t n_need = spline    ? sizeof spline_keys / sizeof spline_keys[0]
                          : grid    ? sizeof grid_keys / sizeof grid_keys[0]
                          : everett ? sizeof everett_keys / sizeof everett_keys[0]
                                    : sizeof poly_keys / sizeof poly_keys[0];
    size_t i;
    int k;
    if (line[K_KIND] != 0ul) {
        for (k = 0; k < K_COUNT; ++k) {
            const int of_everett = k == K_DEGREE || k == K_TERMS;
            const int of_grid = k == K_KNOTS || k == K_WEIGHTS;
            const int of_spline = k == K_VALUES || k == K_SLOPES;
            const int bad = spline    ? k == K_COEFFS || k == K_Y_LO || of_everett || of_grid
                            : grid    ? k == K_COEFFS || of_everett || of_spline
                            : everett ? k == K_COEFFS || of_grid || of_spline
                                      : k == K_Y_LO || of_everett || of_grid || of_spline;
            if (line[k] != 0ul && bad) {
                return fail(r, "%s:%lu: field 1: %s is not a key of kind %s (%s)", r->path,
                            line[k], keys[k],
                            spline    ? "spline"
                            : grid    ? "everett_grid"
                            : everett ? "everett"
                                      : "poly",
                            spline    ? "f0 is given by values and slopes"
                            : grid    ? "E is given by knots and weights"
                            : everett ? "E is given by degree and terms"
                                      : "y_lo, degree, terms, knots and weights are the "
                                        "asymmetric kinds', values and slopes the spline's");
            }
        }
    }
    for (i = 0u; i < n_need; ++i) {
        if (line[need[i]] == 0ul) {
            return fail(r, "%s: the key %s is missing", r->path, keys[need[i]]);
        }
    }
    if ((line[K_CREEP_TAU] != 0ul) != (line[K_CREEP_WEIGHT] != 0ul)) {
        const int k_has = line[K_CREEP_TAU] != 0ul ? K_CREEP_TAU : K_CREEP_WEIGHT;
        return fail(r, "%s:%lu: field 1: %s needs %s too (creep: both or neither)", r->path,
                    line[k_has], keys[k_has],
                    keys[k_has == K_CREEP_TAU ? K_CREEP_WEIGHT : K_CREEP_TAU]);
    }
    if ((line[K_RATE_TAU] != 0ul) != (line[K_RATE_WEIGHT] != 0ul)) {
        const int k_has = line[K_RATE_TAU] != 0ul ? K_RATE_TAU : K_RATE_WEIGHT;
        return fail(r, "%s:%lu: field 1: %s needs %s too (rate: both or neither)", r->path,
                    line[k_has], keys[k_has],
                    keys[k_has == K_RATE_TAU ? K_RATE_WEIGHT : K_RATE_TAU]);
    }
    if (m->ncreep != m->ncreep_weights) {
        const int short_w = m->ncreep_weights < m->ncreep; /* else one too many */
        return fail(r, "%s:%lu: field %lu%s: creep_weight needs %lu numbers, one per creep_tau",
                    r->path, line[K_CREEP_WEIGHT],
                    (unsigned long)(short_w ? m->ncreep_weights : m->ncreep) + 2ul,
                    short_w ? " is missing" : ": one too many", (unsigned long)m->ncreep);
    }
    if (everett && m->nterms != model_text_everett_terms(m->degree)) {
        const size_t want = model_text_everett_terms(m->degree);
        return fail(r, "%s:%lu: field %lu%s: terms needs %lu numbers for degree %u", r->path,
                    line[K_TERMS], (unsigned long)(m->nterms < want ? m->nterms : want) + 2ul,
                    m->nterms < want ? " is missing" : ": one too many", (unsigned long)want,
                    m->degree);
    }
    if (grid && m->nweights != HYST_EVERETT_GRID_CELLS(m->nknots - 1u)) {
        const size_t want = HYST_EVERETT_GRID_CELLS(m->nknots - 1u);
        return fail(r, "%s:%lu: field %lu%s: weights needs %lu numbers for %lu knots", r->path,
                    line[K_WEIGHTS],
                    (unsigned long)(m->nweights < want ? m->nweights : want) + 2ul,
                    m->nweights < want ? " is missing" : ": one too many", (unsigned long)want,
                    (unsigned long)m->nknots);
    }
    if (spline && m->nslopes != m->nvalues) {
        return fail(r, "%s:%lu: field %lu%s: slopes needs %lu numbers, one per value", r->path,
                    line[K_SLOPES],
                    (unsigned long)(m->nslopes < m->nvalues ? m->nslopes : m->nvalues) + 2ul,
                    m->nslopes < m->nvalues ? " is missing" : ": one too many",
                    (unsigned long)m->nvalues);
    }
    if (grid && (m->knots[0] != m->lo || m->knots[m->nknots - 1u] != m->hi)) {
        return fail(r, "%s:%lu: field %lu: knots must run from lo to hi (%.17g, %.17g)", r->path,
                    line[K_KNOTS], m->knots[0] != m->lo ? 2ul : (unsigned long)m->nknots + 1ul,
                    m->lo, m->hi);
    }
    if (!(m->lo < m->hi)) { /* blamed on the later line of the two */
        const int k_late = line[K_HI] > line[K_LO] ? K_HI : K_LO;
        return fail(r, "%s:%lu: field 2: the domain is empty: hi %s is not above lo %s",
                    r->path, line[k_late], r->hi_text, r->lo_text);
    }
    if (m->has_identified && !(m->lo <= m->id_lo && m->id_lo < m->id_hi && m->id_hi <= m->hi)) {
        /* the field at fault: LO (below lo, or not below HI), else HI */
        const int field = m->id_lo < m->lo || !(m->id_lo < m->id_hi) ? 2 : 3;
        return fail(r, "%s:%lu: field %d: identified %.17g %.17g is not a range within [lo, hi] "
                       "= [%.17g, %.17g]",
                    r->path, line[K_IDENTIFIED], field, m->id_lo, m->id_hi, m->lo, m->hi);
    }
    return 0;
}

int model_text_parse(const char *text, size_t len, const char *path, model_text_t *m, char *msg,
                     size_t msg_size)
{
    reader_t r;
    unsigned long no = 0ul;
    size_t pos = 0u;
    memset(m, 0, sizeof *m);
    memset(&r, 0, sizeof r);
    r.path = path;
    r.msg = msg;
    r.msg_size = msg_size;
    if (msg_size > 0u) {
        msg[0] = '\0';
    }
    if (len > MODEL_TEXT_MAX_BYTES) {
        return fail(&r, "%s: larger than %lu bytes: not a model file", path,
                    (unsigned long)MODEL_TEXT_MAX_BYTES);
    }
    if (len >= 3u && memcmp(text, "\xEF\xBB\xBF", 3u) == 0) {
        pos = 3u; /* a UTF-8 byte-order mark */
    }
    while (pos < len) {
        size_t end = pos;
        while (end < len && text[end] != '\n' && text[end] != '\r') {
            ++end;
        }
        if (read_line(&r, ++no, text + pos, end - pos, m) != 0) {
            return 1;
        }
        pos = end < len && text[end] == '\r' && end + 1u < len && text[end + 1u] == '\n'
                  ? end + 2u
                  : end + 1u;
    }
    if (no == 0ul) {
        return fail(&r, "%s: empty model file", path);
    }
    return read_complete(&r, m);
}

/* 1 if v[0..n) are all finite. */
static int all_finite(const double *v, size_t n)
{
    size_t i;
    for (i = 0u; i < n; ++i) {
        if (!isfinite(v[i])) {
            return 0;
        }
    }
    return 1;
}

int model_text_check(const model_text_t *m, char *msg, size_t msg_size)
{
    size_t i;
    const char *why = NULL;
    if (m->kind != MODEL_TEXT_POLY && m->kind != MODEL_TEXT_EVERETT && m->kind != MODEL_TEXT_GRID &&
        m->kind != MODEL_TEXT_SPLINE) {
        why = "kind must be 'poly', 'everett', 'everett_grid' or 'spline'";
    } else if (m->kind == MODEL_TEXT_SPLINE &&
               (m->nvalues < 2u || m->nvalues > HYST_SPLINE_MAX_INTERVALS + 1u ||
                m->nslopes != m->nvalues || !all_finite(m->values, m->nvalues) ||
                !all_finite(m->slopes, m->nslopes))) {
        why = "values and slopes need as many finite numbers, 2 to " STR(
            HYST_SPLINE_MAX_INTERVALS) " + 1 (one per knot)";
    } else if (m->kind == MODEL_TEXT_GRID &&
               (m->nknots < 2u || m->nknots > HYST_EVERETT_GRID_MAX_INTERVALS + 1u ||
                !all_finite(m->knots, m->nknots) || m->knots[0] != m->lo ||
                m->knots[m->nknots - 1u] != m->hi)) {
        why = "knots needs 2 to " STR(HYST_EVERETT_GRID_MAX_INTERVALS) " + 1 finite numbers from "
              "lo to hi";
    } else if (m->kind == MODEL_TEXT_GRID &&
               (m->nweights != HYST_EVERETT_GRID_CELLS(m->nknots - 1u) ||
                !all_finite(m->weights, m->nweights) || !isfinite(m->y_lo))) {
        why = "weights needs K (K + 1) / 2 finite numbers for K + 1 knots, y_lo a finite number";
    } else if (m->kind == MODEL_TEXT_POLY &&
               (m->ncoef < 2u || m->ncoef > HYST_MAX_DEGREE + 1u ||
                !all_finite(m->coeffs, m->ncoef))) {
        why = "coeffs needs 2 to HYST_MAX_DEGREE + 1 finite numbers (c_n ... c_0)";
    } else if (m->kind == MODEL_TEXT_EVERETT &&
               (m->degree < 1u || m->degree > HYST_EVERETT_MAX_DEGREE)) {
        why = "degree is not a degree in 1.." STR(HYST_EVERETT_MAX_DEGREE);
    } else if (m->kind == MODEL_TEXT_EVERETT &&
               (m->nterms != model_text_everett_terms(m->degree) ||
                !all_finite(m->terms, m->nterms))) {
        why = "terms needs degree (degree + 1) / 2 finite numbers";
    } else if (m->kind == MODEL_TEXT_EVERETT && !isfinite(m->y_lo)) {
        why = "y_lo is not a finite number";
    } else if (!isfinite(m->lo) || !isfinite(m->hi)) {
        why = "lo and hi must be finite numbers";
    } else if (!(m->lo < m->hi)) {
        why = "the domain is empty: hi is not above lo";
    } else if (m->delay > MODEL_TEXT_MAX_DELAY || !(m->delay_fraction >= 0.0) ||
               !(m->delay_fraction < 1.0) ||
               model_text_delay(m) > (double)MODEL_TEXT_MAX_DELAY) {
        why = "delay is not a delay of 0 to 1000000000 samples (its fraction in [0, 1))";
    } else if (m->has_identified &&
               !(m->lo <= m->id_lo && m->id_lo < m->id_hi && m->id_hi <= m->hi)) {
        why = "identified is not a range within [lo, hi]";
    } else if (m->ncreep > MODEL_TEXT_CREEP_MAX_TERMS || m->ncreep != m->ncreep_weights) {
        why = "creep_tau and creep_weight need as many numbers, 1 to " STR(
            MODEL_TEXT_CREEP_MAX_TERMS) " (one per creep term)";
    } else if (!all_finite(m->creep_tau, m->ncreep) || !all_finite(m->creep_weight, m->ncreep)) {
        why = "creep_tau and creep_weight must be finite numbers";
    } else if (m->has_rate && (!(m->rate_tau >= 1.0) || !isfinite(m->rate_tau) ||
                               !isfinite(m->rate_weight))) {
        why = "rate_tau must be a finite time constant of at least 1 sample, rate_weight a "
              "finite number";
    }
    for (i = 0u; why == NULL && i < m->ncreep; ++i) {
        if (!(m->creep_tau[i] >= 1.0)) {
            why = "creep_tau: a time constant is not at least 1 sample";
        }
    }
    for (i = 0u; why == NULL && m->kind == MODEL_TEXT_SPLINE && i < m->nslopes; ++i) {
        if (!(m->slopes[i] >= 0.0)) {
            why = "slopes: a slope is not >= 0 (f0 increases)";
        }
    }
    if (why != NULL) {
        (void)snprintf(msg, msg_size, "%s", why);
        return 1;
    }
    return 0;
}

/* Appends " %.17g" of each of v[0..n) to buf[*len..size); 1 when it did not fit. */
static int append_numbers(char *buf, size_t size, size_t *len, const double *v, size_t n)
{
    size_t i;
    int over = 0;
    for (i = 0u; i < n; ++i) {
        over |= model_text_append(buf, size, len, " %.17g", v[i]);
    }
    return over;
}

size_t model_text_write(const model_text_t *m, char *buf, size_t size)
{
    size_t len = 0u;
    int over;
    if (m->kind == MODEL_TEXT_SPLINE) {
        over = model_text_append(
            buf, size, &len,
            MODEL_TEXT_MAGIC "\n# hyst model: symmetric, f0 a monotone cubic spline on the uniform "
                             "knots x_k = lo + k (hi - lo) / K, k = 0..K: values f0(x_k), slopes "
                             "f0'(x_k) (output units per input unit), a cubic (Hermite) between "
                             "two knots; the output %.17g samples after its input (docs/cli.md)\n"
                             "kind spline\nlo %.17g\nhi %.17g\ndelay %.17g\nvalues",
            model_text_delay(m), m->lo, m->hi, model_text_delay(m));
        over |= append_numbers(buf, size, &len, m->values, m->nvalues);
        over |= model_text_append(buf, size, &len, "\nslopes");
        over |= append_numbers(buf, size, &len, m->slopes, m->nslopes);
    } else if (m->kind == MODEL_TEXT_GRID) {
        over = model_text_append(
            buf, size, &len,
            MODEL_TEXT_MAGIC "\n# hyst model: asymmetric, E(a, b) the mass of b <= b' <= a' <= a "
                             "of a density constant on each cell of the knots' grid, weights "
                             "the cells' masses (i, j), j <= i, in the order i = 0.., j = 0..i; "
                             "the output %.17g samples after its input (docs/cli.md)\n"
                             "kind everett_grid\nlo %.17g\nhi %.17g\ny_lo %.17g\ndelay %.17g\n"
                             "knots",
            model_text_delay(m), m->lo, m->hi, m->y_lo, model_text_delay(m));
        over |= append_numbers(buf, size, &len, m->knots, m->nknots);
        over |= model_text_append(buf, size, &len, "\nweights");
        over |= append_numbers(buf, size, &len, m->weights, m->nweights);
    } else if (m->kind == MODEL_TEXT_EVERETT) {
        over = model_text_append(
            buf, size, &len,
            MODEL_TEXT_MAGIC "\n# hyst model: asymmetric, E(a, b) = sum of e[i-1][j] w^i t^j, "
                             "w = (a - b) / (hi - lo), t = (b - lo) / (hi - lo); terms i = "
                             "1..degree, then j = 0..degree - i; the output %.17g samples after "
                             "its input (docs/cli.md)\n"
                             "kind everett\nlo %.17g\nhi %.17g\ny_lo %.17g\ndelay %.17g\n"
                             "degree %u\nterms",
            model_text_delay(m), m->lo, m->hi, m->y_lo, model_text_delay(m), m->degree);
        over |= append_numbers(buf, size, &len, m->terms, m->nterms);
    } else {
        over = model_text_append(buf, size, &len,
                                 MODEL_TEXT_MAGIC
                                 "\n# hyst model: f0 on [lo, hi], coefficients highest power "
                                 "first, the output %.17g samples after its input (docs/cli.md)\n"
                                 "kind poly\nlo %.17g\nhi %.17g\ndelay %.17g\ncoeffs",
                                 model_text_delay(m), m->lo, m->hi, model_text_delay(m));
        over |= append_numbers(buf, size, &len, m->coeffs, m->ncoef);
    }
    if (m->has_identified) {
        over |= model_text_append(buf, size, &len,
                                  "\n# identified on inputs in [LO, HI]; the branches continue "
                                  "beyond it to [lo, hi]\nidentified %.17g %.17g",
                                  m->id_lo, m->id_hi);
    }
    if (m->ncreep > 0u) {
        over |= model_text_append(buf, size, &len,
                                  "\n# creep: the output plus sum of creep_weight[k] s_k, s_k the "
                                  "input lagged with time constant creep_tau[k] samples (from lo "
                                  "at rest)\ncreep_tau");
        over |= append_numbers(buf, size, &len, m->creep_tau, m->ncreep);
        over |= model_text_append(buf, size, &len, "\ncreep_weight");
        over |= append_numbers(buf, size, &len, m->creep_weight, m->ncreep);
    }
    if (m->has_rate) {
        over |= model_text_append(buf, size, &len,
                                  "\n# rate: the output plus rate_weight v, v the input's change "
                                  "per sample low-passed with time constant rate_tau samples, up "
                                  "to the sample before (0 at rest)\nrate_tau %.17g\nrate_weight "
                                  "%.17g",
                                  m->rate_tau, m->rate_weight);
    }
    over |= model_text_append(buf, size, &len, "\n");
    return over ? 0u : len;
}

double model_text_delay(const model_text_t *m) { return (double)m->delay + m->delay_fraction; }

size_t model_text_everett_terms(unsigned degree) { return (size_t)degree * (degree + 1u) / 2u; }

void model_text_to_grid(const model_text_t *m, hyst_everett_grid_t *g)
{
    size_t i;
    memset(g, 0, sizeof *g);
    g->intervals = m->nknots >= 2u ? (unsigned)(m->nknots - 1u) : 0u;
    for (i = 0u; i < m->nknots && i <= HYST_EVERETT_GRID_MAX_INTERVALS; ++i) {
        g->knots[i] = (hyst_wide_t)m->knots[i];
    }
    for (i = 0u; i < m->nweights && i < GRID_CELLS_; ++i) {
        g->weight[i] = (hyst_wide_t)m->weights[i];
    }
    g->y_lo = (hyst_wide_t)m->y_lo;
}

void model_text_from_grid(model_text_t *m, const hyst_everett_grid_t *g, unsigned long delay)
{
    size_t i;
    memset(m, 0, sizeof *m);
    m->kind = MODEL_TEXT_GRID;
    m->nknots = (size_t)g->intervals + 1u;
    for (i = 0u; i < m->nknots; ++i) {
        m->knots[i] = (double)g->knots[i];
    }
    m->nweights = HYST_EVERETT_GRID_CELLS((size_t)g->intervals);
    for (i = 0u; i < m->nweights; ++i) {
        m->weights[i] = (double)g->weight[i];
    }
    m->lo = m->knots[0];
    m->hi = m->knots[m->nknots - 1u];
    m->y_lo = (double)g->y_lo;
    m->delay = delay;
}

void model_text_to_spline(const model_text_t *m, hyst_spline_t *f0)
{
    size_t i;
    memset(f0, 0, sizeof *f0);
    f0->intervals = m->nvalues >= 2u ? (unsigned)(m->nvalues - 1u) : 0u;
    f0->lo = (hyst_wide_t)m->lo;
    f0->hi = (hyst_wide_t)m->hi;
    for (i = 0u; i < m->nvalues && i <= HYST_SPLINE_MAX_INTERVALS; ++i) {
        f0->value[i] = (hyst_wide_t)m->values[i];
        f0->slope[i] = i < m->nslopes ? (hyst_wide_t)m->slopes[i] : 0;
    }
}

void model_text_from_spline(model_text_t *m, const hyst_spline_t *f0, unsigned long delay)
{
    size_t i;
    memset(m, 0, sizeof *m);
    m->kind = MODEL_TEXT_SPLINE;
    m->nvalues = m->nslopes = (size_t)f0->intervals + 1u;
    for (i = 0u; i < m->nvalues && i <= HYST_SPLINE_MAX_INTERVALS; ++i) {
        m->values[i] = (double)f0->value[i];
        m->slopes[i] = (double)f0->slope[i];
    }
    m->lo = (double)f0->lo;
    m->hi = (double)f0->hi;
    m->delay = delay;
}

void model_text_to_everett(const model_text_t *m, hyst_everett_t *e)
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

void model_text_from_everett(model_text_t *m, const hyst_everett_t *e, unsigned long delay)
{
    unsigned i, j;
    memset(m, 0, sizeof *m);
    m->kind = MODEL_TEXT_EVERETT;
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

void model_text_c_number(char *buf, size_t len, double v, int digits_)
{
    (void)snprintf(buf, len, "%.*g", digits_, v);
    if (strpbrk(buf, ".eEn") == NULL && strlen(buf) + 3u < len) {
        strcat(buf, ".0");
    }
}

/* "HYST_REAL_C(v)" for the number v, appended. */
static int append_real(char *buf, size_t size, size_t *len, const char *before, double v)
{
    char lit[40];
    model_text_c_number(lit, sizeof lit, v, 17);
    return model_text_append(buf, size, len, "%sHYST_REAL_C(%s)", before, lit);
}

/* The asymmetric kind's initializer: every row of e[][] written out, zeros
 * above the degree, so that no brace is elided. */
static int header_everett(char *buf, size_t size, size_t *len, const char *name,
                          const model_text_t *m)
{
    hyst_everett_t e;
    unsigned i, j;
    int over;
    model_text_to_everett(m, &e);
    over = model_text_append(buf, size, len, "static const hyst_everett_t %s = {\n    %uu,", name,
                             m->degree);
    over |= append_real(buf, size, len, " ", m->lo);
    over |= append_real(buf, size, len, ", ", m->hi);
    over |= append_real(buf, size, len, ", ", m->y_lo);
    over |= model_text_append(buf, size, len, ",\n    {");
    for (i = 0u; i < HYST_EVERETT_MAX_DEGREE; ++i) {
        over |= model_text_append(buf, size, len, "%s{", i ? ",\n     " : "");
        for (j = 0u; j < HYST_EVERETT_MAX_DEGREE; ++j) {
            over |= append_real(buf, size, len, j ? ", " : "", (double)e.e[i][j]);
        }
        over |= model_text_append(buf, size, len, "}");
    }
    return over | model_text_append(buf, size, len, "}};\n");
}

/* The grid kind's initializer: the knots and every cell's mass written
 * out, zeros beyond the grid's. */
static int header_grid(char *buf, size_t size, size_t *len, const char *name,
                       const model_text_t *m)
{
    size_t i;
    int over = model_text_append(
        buf, size, len,
        "/* hyst_curve_from_everett_grid(&curve, &%s, table, HYST_EVERETT_GRID_TABLE_LEN(%luu)) */\n"
        "static const hyst_everett_grid_t %s = {\n    %luu,\n    {",
        name, (unsigned long)m->nknots - 1ul, name, (unsigned long)m->nknots - 1ul);
    for (i = 0u; i < HYST_EVERETT_GRID_MAX_INTERVALS + 1u; ++i) {
        over |= append_real(buf, size, len, i ? ", " : "", i < m->nknots ? m->knots[i] : 0.0);
    }
    over |= model_text_append(buf, size, len, "},\n   ");
    over |= append_real(buf, size, len, " ", m->y_lo);
    over |= model_text_append(buf, size, len, ",\n    {");
    for (i = 0u; i < GRID_CELLS_; ++i) {
        over |= append_real(buf, size, len, i == 0u ? "" : i % 4u == 0u ? ",\n     " : ", ",
                            i < m->nweights ? m->weights[i] : 0.0);
    }
    return over | model_text_append(buf, size, len, "}};\n");
}

/* The spline kind's initializer: the knots' values and slopes (K + 1 of
 * each; the arrays' other entries 0). */
static int header_spline(char *buf, size_t size, size_t *len, const char *name,
                         const model_text_t *m)
{
    const unsigned long k = (unsigned long)m->nvalues - 1ul;
    size_t i, a;
    int over = model_text_append(
        buf, size, len,
        "/* hyst_curve_from_spline(&curve, &%s, table, HYST_SPLINE_TABLE_LEN(%luu)) */\n"
        "static const hyst_spline_t %s = {\n    %luu,",
        name, k, name, k);
    over |= append_real(buf, size, len, " ", m->lo);
    over |= append_real(buf, size, len, ", ", m->hi);
    for (a = 0u; a < 2u; ++a) { /* the values, then the slopes */
        const double *v = a == 0u ? m->values : m->slopes;
        over |= model_text_append(buf, size, len, ",\n    {");
        for (i = 0u; i < m->nvalues; ++i) {
            over |= append_real(buf, size, len, i == 0u ? "" : i % 4u == 0u ? ",\n     " : ", ",
                                v[i]);
        }
        over |= model_text_append(buf, size, len, "}");
    }
    return over | model_text_append(buf, size, len, "};\n");
}

/* The creep term, if any: its count, time constants and weights, for
 * hyst_creep_init() with the domain's lo as the rest drive. */
static int header_creep(char *buf, size_t size, size_t *len, const char *name,
                        const model_text_t *m)
{
    size_t i;
    int over;
    if (m->ncreep == 0u) {
        return 0;
    }
    over = model_text_append(
        buf, size, len,
        "\n/* creep: add hyst_creep_step() of the model's input to its output\n"
        " * (hyst/creep.h): hyst_creep_init(&creep, %s_CREEP_TERMS,\n"
        " * %s_creep_tau, %s_creep_weight, lo) */\n#define %s_CREEP_TERMS %luu\n"
        "static const hyst_wide_t %s_creep_tau[%s_CREEP_TERMS] = {",
        name, name, name, name, (unsigned long)m->ncreep, name, name);
    for (i = 0u; i < m->ncreep; ++i) {
        over |= append_real(buf, size, len, i ? ", " : "", m->creep_tau[i]);
    }
    over |= model_text_append(buf, size, len,
                              "};\nstatic const hyst_wide_t %s_creep_weight[%s_CREEP_TERMS] = {",
                              name, name);
    for (i = 0u; i < m->ncreep; ++i) {
        over |= append_real(buf, size, len, i ? ", " : "", m->creep_weight[i]);
    }
    return over | model_text_append(buf, size, len, "};\n");
}

/* The rate term, if any: its time constant and weight, for hyst_rate_init()
 * with the domain's lo as the rest drive. */
static int header_rate(char *buf, size_t size, size_t *len, const char *name,
                       const model_text_t *m)
{
    int over;
    if (!m->has_rate) {
        return 0;
    }
    over = model_text_append(buf, size, len,
                             "\n/* rate: add hyst_rate_step() of the model's input to its output\n"
                             " * (hyst/rate.h): hyst_rate_init(&rate, %s_rate_tau,\n"
                             " * %s_rate_weight, lo) */\nstatic const hyst_wide_t %s_rate_tau =",
                             name, name, name);
    over |= append_real(buf, size, len, " ", m->rate_tau);
    over |= model_text_append(buf, size, len, ";\nstatic const hyst_wide_t %s_rate_weight =", name);
    over |= append_real(buf, size, len, " ", m->rate_weight);
    return over | model_text_append(buf, size, len, ";\n");
}

/* The include guard of NAME.h: NAME in capitals, then _H. */
static void guard_of(const char *name, char *guard, size_t size)
{
    size_t i;
    for (i = 0u; name[i] != '\0' && i + 3u < size; ++i) {
        guard[i] = name[i] >= 'a' && name[i] <= 'z' ? (char)(name[i] - 'a' + 'A') : name[i];
    }
    memcpy(guard + i, "_H", 3u);
}

/* The symmetric TCM's f0, a polynomial: its degree, domain and coefficients. */
static int header_poly(char *buf, size_t size, size_t *len, const char *name,
                       const model_text_t *m)
{
    size_t i;
    int over = model_text_append(buf, size, len, "static const hyst_poly_t %s = {\n    %uu,",
                                 name, (unsigned)(m->ncoef - 1u));
    over |= append_real(buf, size, len, " ", m->lo);
    over |= append_real(buf, size, len, ", ", m->hi);
    over |= model_text_append(buf, size, len, ",\n    {");
    for (i = 0u; i < m->ncoef; ++i) {
        over |= append_real(buf, size, len, i ? ",\n     " : "", m->coeffs[i]);
    }
    return over | model_text_append(buf, size, len, "}};\n");
}

int model_text_header_open(char *buf, size_t size, size_t *len, const char *name,
                           const model_text_t *m)
{
    char guard[256];
    int over;
    guard_of(name, guard, sizeof guard);
    over = model_text_append(buf, size, len,
                             "#ifndef %s\n#define %s\n\n#include \"hyst/curve.h\"\n%s%s\n", guard,
                             guard, m->ncreep > 0u ? "#include \"hyst/creep.h\"\n" : "",
                             m->has_rate ? "#include \"hyst/rate.h\"\n" : "");
    if (m->kind == MODEL_TEXT_EVERETT) {
        over |= header_everett(buf, size, len, name, m);
    } else if (m->kind == MODEL_TEXT_GRID) {
        over |= header_grid(buf, size, len, name, m);
    } else if (m->kind == MODEL_TEXT_SPLINE) {
        over |= header_spline(buf, size, len, name, m);
    } else {
        over |= header_poly(buf, size, len, name, m);
    }
    over |= header_creep(buf, size, len, name, m);
    return over | header_rate(buf, size, len, name, m);
}

int model_text_header_close(char *buf, size_t size, size_t *len, const char *name)
{
    char guard[256];
    guard_of(name, guard, sizeof guard);
    return model_text_append(buf, size, len, "\n#endif /* %s */\n", guard);
}

/* An ASCII letter or '_' (whatever the locale says of other bytes). */
static int identifier_start(char c)
{
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}

/* The keywords of C99 to C23: not identifiers (a header declaring one does not compile). */
static const char *const c_keywords[] = {
    "_Alignas", "_Alignof", "_Atomic", "_BitInt", "_Bool", "_Complex", "_Decimal128",
    "_Decimal32", "_Decimal64", "_Generic", "_Imaginary", "_Noreturn", "_Static_assert",
    "_Thread_local", "alignas", "alignof", "auto", "bool", "break", "case", "char", "const",
    "constexpr", "continue", "default", "do", "double", "else", "enum", "extern", "false",
    "float", "for", "goto", "if", "inline", "int", "long", "nullptr", "register", "restrict",
    "return", "short", "signed", "sizeof", "static", "static_assert", "struct", "switch",
    "thread_local", "true", "typedef", "typeof", "typeof_unqual", "union", "unsigned", "void",
    "volatile", "while"};

int model_text_identifier(const char *s)
{
    size_t i;
    if (!identifier_start(s[0])) {
        return 0;
    }
    for (i = 1u; s[i] != '\0'; ++i) {
        if (!identifier_start(s[i]) && !(s[i] >= '0' && s[i] <= '9')) {
            return 0;
        }
    }
    if (i >= 200u) {
        return 0;
    }
    for (i = 0u; i < sizeof c_keywords / sizeof c_keywords[0]; ++i) {
        if (strcmp(s, c_keywords[i]) == 0) {
            return 0;
        }
    }
    return 1;
}
