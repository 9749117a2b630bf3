/* SPDX-License-Identifier: MIT */
/* The model file format hyst-model-text 1 (docs/cli.md, "Model files"): its
 * one implementation, read, written and turned into a firmware header here,
 * for the `hyst` tool, the Python extension and the MATLAB/Octave MEX
 * gateway alike, so that the three cannot read one file two ways. A host
 * module: C99 and the C library, no stdio stream, no global state; it is
 * not part of the firmware library. */
#ifndef HYST_MODEL_TEXT_H
#define HYST_MODEL_TEXT_H

#include "hyst/hyst.h"

#include <stddef.h>

/* Line 1 of every model file. */
#define MODEL_TEXT_MAGIC "hyst-model-text 1"

/* Creep terms a model file may hold (HYST_CREEP_MAX_TERMS). */
#define MODEL_TEXT_CREEP_MAX_TERMS 4

/* The longest delay a file may give (samples; its messages spell it out). */
#define MODEL_TEXT_MAX_DELAY 1000000000ul

/* A file larger than this is refused before it is parsed (a model file is
 * a few hundred bytes). */
#define MODEL_TEXT_MAX_BYTES (1ul << 20)

/* Room for any message of the reader or the checks. */
#define MODEL_TEXT_MSG_SIZE 1024u

/* The kinds a model file holds (its key `kind`). */
enum { MODEL_TEXT_POLY = 0, MODEL_TEXT_EVERETT = 1, MODEL_TEXT_GRID = 2, MODEL_TEXT_SPLINE = 3 };

typedef struct model_text {
    int kind;                               /* MODEL_TEXT_POLY, _EVERETT, _GRID or _SPLINE */
    double coeffs[HYST_MAX_DEGREE + 1];     /* poly: c_n ... c_0, highest power first */
    size_t ncoef;                           /* poly: degree + 1 */
    double lo, hi;                          /* domain, lo < hi */
    unsigned long delay; /* the output follows its input this many samples later */
    /* and a fraction of a sample more (0 <= f < 1; `delay 3.5`): the model's
     * input is the drive interpolated, (1 - f) x[k] + f x[k - 1] */
    double delay_fraction;
    /* the range of the inputs the model was identified on, within [lo, hi]
     * (key `identified LO HI`; has_identified 0: not recorded): the branches
     * continue beyond it, up to the domain */
    double id_lo, id_hi;
    int has_identified;
    unsigned degree;     /* everett: total degree of E, 1..HYST_EVERETT_MAX_DEGREE */
    double y_lo;         /* everett: the output at lo after reset */
    /* everett: e[i - 1][j], the coefficient of w^i t^j, in the file's order
     * i = 1..degree, then j = 0..degree - i */
    double terms[HYST_EVERETT_TERMS];
    size_t nterms; /* everett: degree (degree + 1) / 2 */
    /* everett_grid (hyst_everett_grid_t): its knots (the first lo, the last
     * hi) and the cells' masses, weight[i (i + 1) / 2 + j]; y_lo above */
    double knots[HYST_EVERETT_GRID_MAX_INTERVALS + 1];
    size_t nknots;
    double weights[HYST_EVERETT_GRID_CELLS(HYST_EVERETT_GRID_MAX_INTERVALS)];
    size_t nweights;
    /* spline (hyst_spline_t): f0 and its slope (output units per input
     * unit, >= 0) at the K + 1 uniform knots lo + k (hi - lo) / K */
    double values[HYST_SPLINE_MAX_INTERVALS + 1];
    size_t nvalues;
    double slopes[HYST_SPLINE_MAX_INTERVALS + 1];
    size_t nslopes; /* as read (the reader checks it equals nvalues) */
    /* creep (hyst/creep.h), either kind: lags of the model's input with
     * these time constants (samples) and weights, added to its output; 0
     * terms: none */
    double creep_tau[MODEL_TEXT_CREEP_MAX_TERMS];
    double creep_weight[MODEL_TEXT_CREEP_MAX_TERMS];
    size_t ncreep;
    size_t ncreep_weights; /* as read (the reader checks it equals ncreep) */
    /* rate (hyst/rate.h), either kind (keys rate_tau, rate_weight): the
     * model's output plus rate_weight times the low-pass, of time constant
     * rate_tau samples, of its input's change per sample; has_rate 0: none */
    double rate_tau, rate_weight;
    int has_rate;
} model_text_t;

/* Reads the whole file text[0..len) (NUL bytes included) into *m: 0, or 1
 * with the reason in msg[0..msg_size), "PATH:LINE: field K: ..." (or
 * "PATH:LINE: ..." about a whole line, "PATH: ..." about the whole file),
 * PATH being @p path as given. Lines end at "\n", "\r\n" or "\r"; a UTF-8
 * byte-order mark before line 1 is skipped. */
int model_text_parse(const char *text, size_t len, const char *path, model_text_t *m, char *msg,
                     size_t msg_size);

/* Whether *m is a model the reader would accept (counts, finite numbers,
 * slopes >= 0, lo < hi, a delay in 0..1e9 whose fraction is in [0, 1), a whole degree,
 * time constants >= 1, an identified range within [lo, hi]): 0, or 1 with the
 * reason in msg (naming the key, no line). Writers check with it. */
int model_text_check(const model_text_t *m, char *msg, size_t msg_size);

/* The file's text of *m (17 significant digits: the same doubles read back)
 * into buf: its length, or 0 if it did not fit. *m must pass
 * model_text_check(). */
size_t model_text_write(const model_text_t *m, char *buf, size_t size);

/* The firmware header of *m, declaring NAME (a C identifier): the include
 * guard, 'static const hyst_poly_t NAME = {...};' (kind poly), 'static
 * const hyst_everett_t NAME = {...};' (kind everett, every row of e written
 * out), 'static const hyst_everett_grid_t NAME = {...};' (kind
 * everett_grid: hyst_*_curve_from_everett_grid() prepares it) or 'static
 * const hyst_spline_t NAME = {...};' (kind spline:
 * hyst_*_curve_from_spline()), and with a creep term NAME_CREEP_TERMS, NAME_creep_tau and
 * NAME_creep_weight; 17-digit literals in HYST_REAL_C(). Appended to
 * buf[*len..size); 1 when it did not fit. In two parts, the guard's opening
 * and the model, then the guard's end, so that a compensator's table may go
 * between; the caller writes a comment saying where the model came from
 * before it. */
int model_text_header_open(char *buf, size_t size, size_t *len, const char *name,
                           const model_text_t *m);
int model_text_header_close(char *buf, size_t size, size_t *len, const char *name);

/* The compensator's table of a header (hyst header --compensator), put
 * between model_text_header_open() and model_text_header_close(): built by
 * the library in float and in double (the float one from the model's
 * numbers as a float build reads them), sealed, for
 * hyst_curve_inverse_table_const() (kind poly) or
 * hyst_curve_everett_inverse_table_const() (kind everett), with NAME_table,
 * NAME_seal, NAME_INTERVALS (and NAME_ROWS, kind everett); kind spline
 * NAME_INTERVALS alone and how firmware builds the table at init
 * (hyst_*_curve_spline_inverse_table(); sealed ignored); kind everett_grid
 * has none (HYST_ERR_ARG); with sealed
 * (kind poly) also the compensator's curve sealed with its table,
 * NAME_comp_sealed. rows and intervals as the library's table builders take
 * them (rows: kind everett only). Appended to buf[*len..size): 0, or 1 with
 * *status the library's refusal (or HYST_ERR_NOSPACE out of memory), or
 * with *status HYST_OK when the text did not fit. The buffer it needs at
 * most: model_text_header_table_size(). Allocates (malloc) the tables while
 * it builds them. */
int model_text_header_table(char *buf, size_t size, size_t *len, const char *name,
                            const model_text_t *m, size_t rows, size_t intervals, int sealed,
                            hyst_status_t *status);
size_t model_text_header_table_size(const model_text_t *m, size_t rows, size_t intervals);

/* v as a float build reads the header's literal of it: HYST_REAL_C(lit) is
 * lit##f, converted directly to float. */
double model_text_as_float(double v);
/* The f0 of a poly model as a build reads the header's hyst_poly_t: a
 * float build (f32) each literal as a float, a double build exactly. */
void model_text_poly_as_read(const model_text_t *m, int f32, hyst_poly_t *p);
/* sep, then v as a C literal of a build's real type (f32: 9 digits and the
 * suffix f, read back to the same float; else 17), appended; 1 when it did
 * not fit. */
int model_text_append_real(char *buf, size_t size, size_t *len, const char *sep, double v,
                           int f32);

/* 1 if s is a C identifier of fewer than 200 characters, not a keyword of
 * C99 to C23 (a header's NAME). */
int model_text_identifier(const char *s);

/* The model's delay in samples, its fraction included. */
double model_text_delay(const model_text_t *m);

/* E's terms at total degree d: degree (degree + 1) / 2. */
size_t model_text_everett_terms(unsigned degree);
/* E's terms in the file's order <-> hyst_everett_t. */
void model_text_to_everett(const model_text_t *m, hyst_everett_t *e);
void model_text_from_everett(model_text_t *m, const hyst_everett_t *e, unsigned long delay);

/* A grid model's E <-> hyst_everett_grid_t (delay 0, no creep). */
void model_text_to_grid(const model_text_t *m, hyst_everett_grid_t *g);
void model_text_from_grid(model_text_t *m, const hyst_everett_grid_t *g, unsigned long delay);

/* A spline model's f0 <-> hyst_spline_t (delay 0, no creep). */
void model_text_to_spline(const model_text_t *m, hyst_spline_t *f0);
void model_text_from_spline(model_text_t *m, const hyst_spline_t *f0, unsigned long delay);

/* Appends printf output to buf[*len..size); 1 when it did not fit. */
int model_text_append(char *buf, size_t size, size_t *len, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;

/* A number as a C floating literal (always a '.' or an exponent) of
 * `digits` significant digits (17: the double exactly). */
void model_text_c_number(char *buf, size_t len, double v, int digits);

/* Text made safe for a message: in single quotes, bytes other than
 * printable ASCII as \xNN (\\ and \' for those two), and beyond the first
 * MODEL_TEXT_QUOTE_MAX bytes "..." and the length: '7777...' (1048577
 * bytes). Writes into buf (MODEL_TEXT_QUOTE_SIZE chars) and returns it. */
#define MODEL_TEXT_QUOTE_MAX 40
#define MODEL_TEXT_QUOTE_SIZE (4 * MODEL_TEXT_QUOTE_MAX + 40)
const char *model_text_quote(char *buf, const char *s, size_t len);
/* Byte c appended to out as model_text_quote() writes it (at most 4
 * chars); the new end. */
char *model_text_escape(char *out, unsigned char c);

#endif
