/* SPDX-License-Identifier: MIT */
/* libFuzzer harness of the model-file format's one implementation
 * (tools/model_text/model_text.c, format hyst-model-text 1, docs/cli.md),
 * which the `hyst` tool, the Python package and the MATLAB/Octave gateway
 * all call: the input is the file's bytes. Checks, besides ASan/UBSan (no
 * crash, no over-read):
 *  - an accepted model is sound (kind poly: 2..10 finite coefficients; kind
 *    everett: degree 1..4, as many finite terms as it needs, a finite y_lo;
 *    a finite domain, lo < hi; creep terms paired, time constants >= 1) and
 *    passes the writers' check (model_text_check()); it round-trips: written
 *    by model_text_write() and read back it is the same model bit for bit,
 *    and writing that gives the same text again; its firmware header fits
 *    the tool's buffer; the library's verdict on an everett model's E is
 *    either a curve or a message with its reason;
 *  - a refusal places itself: "FILE:LINE: field K: ..." with LINE a line of
 *    the input (lines end at LF, CR LF or CR) and K at most one past that
 *    line's fields, or one of the messages about a whole line (line 1 not
 *    the format's first line) or the whole file (empty; too large; a key
 *    missing).
 * Seeds: fuzz/corpus_model_file (fuzz/make_corpus.py). */
#define _POSIX_C_SOURCE 200809L /* fmemopen */
#include "cli.h"
#include "hyst/hyst.h"
#include "model_text.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define CHECK(cond)                                                                       \
    do {                                                                                  \
        if (!(cond)) {                                                                    \
            fprintf(stderr, "fuzz: %s:%d: check failed: %s\nmessage: %s\n", __FILE__,   \
                    __LINE__, #cond, msg);                                                \
            abort();                                                                      \
        }                                                                                 \
    } while (0)

#define PATH "fuzz.hyst"

static char msg[MODEL_TEXT_MSG_SIZE]; /* the message of the last refusal */

/* Reads data[0..n) as a model file, its message (if any) into msg. */
static int parse(const unsigned char *data, size_t n, cli_model_t *m)
{
    memset(msg, 0, sizeof msg);
    return model_text_parse((const char *)data, n, PATH, m, msg, sizeof msg);
}

/* Where line 1 starts: after a UTF-8 byte-order mark, if any. */
static size_t text_start(const unsigned char *d, size_t n)
{
    return n >= 3u && d[0] == 0xEFu && d[1] == 0xBBu && d[2] == 0xBFu ? 3u : 0u;
}

/* The end of the line starting at i, and where the next one starts. */
static size_t line_end(const unsigned char *d, size_t n, size_t i, size_t *next)
{
    while (i < n && d[i] != '\n' && d[i] != '\r') {
        ++i;
    }
    *next = i + 1u < n && d[i] == '\r' && d[i + 1u] == '\n' ? i + 2u : i + 1u;
    return i;
}

/* Lines of the input (a last line without its end counts). */
static unsigned long lines_of(const unsigned char *d, size_t n)
{
    unsigned long lines = 0ul;
    size_t i = text_start(d, n), next;
    while (i < n) {
        (void)line_end(d, n, i, &next);
        ++lines;
        i = next;
    }
    return lines;
}

/* Start and length of 1-based line no. */
static const unsigned char *line_at(const unsigned char *d, size_t n, unsigned long no,
                                    size_t *len)
{
    size_t i = text_start(d, n), next = i, end = i;
    unsigned long at;
    for (at = 1ul; at <= no && i < n; ++at, i = next) {
        end = line_end(d, n, i, &next);
        if (at == no) {
            break;
        }
    }
    *len = end - i;
    return d + i;
}

/* Blank-separated fields of a line (blanks: space, tab; NUL is not one). */
static unsigned long fields_of(const unsigned char *s, size_t len)
{
    unsigned long fields = 0ul;
    int blank = 1;
    size_t i;
    for (i = 0u; i < len; ++i) {
        const int b = s[i] == ' ' || s[i] == '\t';
        fields += blank && !b;
        blank = b;
    }
    return fields;
}

static void check_refusal(const unsigned char *d, size_t n)
{
    const char *p = msg + strlen(PATH);
    const unsigned char *text;
    unsigned long no, field;
    size_t len;
    char *end;
    CHECK(strncmp(msg, PATH, strlen(PATH)) == 0);
    CHECK(strchr(msg, '\n') == NULL); /* one line */
    if (strcmp(p, ": empty model file") == 0) {
        CHECK(lines_of(d, n) == 0ul);
        return;
    }
    if (strncmp(p, ": larger than ", 14u) == 0) {
        CHECK(n > MODEL_TEXT_MAX_BYTES);
        return;
    }
    if (strncmp(p, ": the key ", 10u) == 0) {
        CHECK(strstr(p, " is missing") != NULL);
        return;
    }
    CHECK(p[0] == ':' && p[1] >= '1' && p[1] <= '9');
    no = strtoul(p + 1, &end, 10);
    CHECK(*end == ':' && no >= 1ul && no <= lines_of(d, n));
    text = line_at(d, n, no, &len);
    p = end + 1;
    if (no == 1ul && strstr(p, " is not 'hyst-model-text 1'") != NULL) {
        return;
    }
    CHECK(strncmp(p, " field ", 7u) == 0 && p[7] >= '1' && p[7] <= '9');
    field = strtoul(p + 7, &end, 10);
    CHECK(field <= fields_of(text, len) + 1ul);
}

static int same_bits(const double *a, const double *b, size_t n)
{
    return memcmp(a, b, n * sizeof *a) == 0;
}

/* The library's verdict on an everett model: a curve, or one message line
 * "model file PATH: <hyst_status_str() of a refusal>". */
static void check_everett_curve(const cli_model_t *m)
{
    FILE *err, *saved = stderr;
    hyst_curve_t curve;
    int rc;
    memset(msg, 0, sizeof msg);
    err = fmemopen(msg, sizeof msg - 1u, "w");
    CHECK(err != NULL);
    stderr = err;
    rc = cli_everett_curve("fuzz", PATH, m, &curve);
    stderr = saved;
    (void)fclose(err);
    if (rc == 0) {
        CHECK(msg[0] == '\0' && hyst_curve_check(&curve) == HYST_OK);
    } else {
        static const char lead[] = "hyst fuzz: model file " PATH ": ";
        CHECK(strncmp(msg, lead, strlen(lead)) == 0);
        CHECK(strstr(msg, "unknown status") == NULL);
    }
}

static void check_round_trip(const cli_model_t *m)
{
    static char text[4096], again[4096], header[8192];
    cli_model_t back;
    size_t len, len2, i, hlen = 0u;
    char why[MODEL_TEXT_MSG_SIZE];
    CHECK(isfinite(m->lo) && isfinite(m->hi) && m->lo < m->hi);
    CHECK(model_text_check(m, why, sizeof why) == 0);
    CHECK(m->ncreep == m->ncreep_weights && m->ncreep <= MODEL_TEXT_CREEP_MAX_TERMS);
    for (i = 0u; i < m->ncreep; ++i) {
        CHECK(m->creep_tau[i] >= 1.0 && isfinite(m->creep_tau[i]) && isfinite(m->creep_weight[i]));
    }
    if (m->kind == CLI_MODEL_EVERETT) {
        CHECK(m->ncoef == 0u && m->degree >= 1u && m->degree <= HYST_EVERETT_MAX_DEGREE);
        CHECK(m->nterms == cli_everett_terms(m->degree) && isfinite(m->y_lo));
        for (i = 0u; i < m->nterms; ++i) {
            CHECK(isfinite(m->terms[i]));
        }
    } else {
        CHECK(m->kind == CLI_MODEL_POLY && m->nterms == 0u && m->degree == 0u && m->y_lo == 0.0);
        CHECK(m->ncoef >= 2u && m->ncoef <= HYST_MAX_DEGREE + 1u);
        for (i = 0u; i < m->ncoef; ++i) {
            CHECK(isfinite(m->coeffs[i]));
        }
    }
    len = cli_model_text(m, text, sizeof text);
    CHECK(len > 0u);
    CHECK(parse((const unsigned char *)text, len, &back) == 0);
    CHECK(back.kind == m->kind && back.ncoef == m->ncoef && back.delay == m->delay);
    CHECK(m->delay_fraction >= 0.0 && m->delay_fraction < 1.0);
    CHECK(same_bits(&back.delay_fraction, &m->delay_fraction, 1u));
    CHECK(back.has_identified == m->has_identified);
    CHECK(!m->has_identified || (m->lo <= m->id_lo && m->id_lo < m->id_hi && m->id_hi <= m->hi));
    CHECK(same_bits(&back.id_lo, &m->id_lo, 1u) && same_bits(&back.id_hi, &m->id_hi, 1u));
    CHECK(back.degree == m->degree && back.nterms == m->nterms);
    CHECK(same_bits(&back.lo, &m->lo, 1u) && same_bits(&back.hi, &m->hi, 1u));
    CHECK(same_bits(&back.y_lo, &m->y_lo, 1u));
    CHECK(same_bits(back.coeffs, m->coeffs, sizeof m->coeffs / sizeof m->coeffs[0]));
    CHECK(same_bits(back.terms, m->terms, sizeof m->terms / sizeof m->terms[0]));
    CHECK(back.ncreep == m->ncreep && same_bits(back.creep_tau, m->creep_tau, m->ncreep) &&
          same_bits(back.creep_weight, m->creep_weight, m->ncreep));
    len2 = cli_model_text(&back, again, sizeof again);
    CHECK(len2 == len && memcmp(again, text, len) == 0);
    CHECK(cli_header_model(header, sizeof header, &hlen, "fuzz_model", m) == 0);
    if (m->kind == CLI_MODEL_EVERETT) {
        check_everett_curve(m);
    }
}

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size);

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size)
{
    cli_model_t m;
    if (parse(data, size, &m) == 0) {
        CHECK(msg[0] == '\0');
        check_round_trip(&m);
    } else {
        check_refusal(data, size);
    }
    return 0;
}
