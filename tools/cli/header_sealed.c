/* SPDX-License-Identifier: MIT */
/* hyst header --sealed: the model's prepared curve, made and checked here
 * (hyst_*_seal_poly(): every check of the polynomial curve's construction)
 * and sealed, so that firmware initialises from it with
 * hyst_init_sealed() / hyst_q31_init_sealed(): integer checks only, none of
 * the construction and no double arithmetic on the target. Each build's
 * real type reads the header's hyst_poly_t its own way (HYST_REAL_C): the
 * curves are made from the numbers that build reads. */
#include "cli.h"
#include "hyst/hyst.h"
#include "hyst/q31.h"

#include <stdio.h>
#include <string.h>

/* The sealed curves of one build's reading of the model (f32: a float
 * build's, f64: a double build's). */
typedef struct {
    unsigned long seal;
    unsigned degree;
    double num[6]; /* lo, hi, y_lo, y_hi, unit, rounding */
    double a[HYST_MAX_DEGREE];
    hyst_q31_sealed_poly_t q;
} sealed_t;

static hyst_status_t seal(const cli_model_t *m, int f32, int q31, unsigned long code_lo,
                          unsigned long code_hi, sealed_t *out)
{
    hyst_f32_sealed_poly_t s32;
    hyst_f64_sealed_poly_t s64;
    hyst_poly_t p;
    hyst_status_t st;
    unsigned k;
    cli_model_poly_as_read(m, f32, &p);
    st = f32 ? hyst_f32_seal_poly(&s32, &p) : hyst_f64_seal_poly(&s64, &p);
    if (st == HYST_OK && q31) {
        st = hyst_q31_seal_poly(&out->q, &p, (uint_least32_t)code_lo, (uint_least32_t)code_hi);
    }
    if (st != HYST_OK) {
        return st;
    }
    out->seal = f32 ? s32.seal : s64.seal;
    out->degree = p.degree;
    out->num[0] = f32 ? (double)s32.lo : s64.lo;
    out->num[1] = f32 ? (double)s32.hi : s64.hi;
    out->num[2] = f32 ? (double)s32.y_lo : s64.y_lo;
    out->num[3] = f32 ? (double)s32.y_hi : s64.y_hi;
    out->num[4] = f32 ? (double)s32.unit : s64.unit;
    out->num[5] = f32 ? (double)s32.rounding : s64.rounding;
    for (k = 0u; k < p.degree; ++k) {
        out->a[k] = f32 ? (double)s32.a[k] : s64.a[k];
    }
    return HYST_OK;
}

static int emit(char *buf, size_t size, size_t *len, const char *name, const sealed_t *s, int f32,
                int q31)
{
    unsigned k;
    int over = cli_append(buf, size, len,
                          "static const hyst_%s_sealed_poly_t %s_sealed = {\n    0x%08lXul, %uu,\n   ",
                          f32 ? "f32" : "f64", name, s->seal & 0xFFFFFFFFul, s->degree);
    for (k = 0u; k < 6u; ++k) {
        over |= model_text_append_real(buf, size, len, k == 0u ? " " : k == 4u ? ",\n    " : ", ",
                                       s->num[k], f32);
    }
    over |= cli_append(buf, size, len, ",\n    {");
    for (k = 0u; k < s->degree; ++k) {
        over |= model_text_append_real(buf, size, len, k ? ", " : "", s->a[k], f32);
    }
    over |= cli_append(buf, size, len, "}};\n");
    if (q31) {
        const hyst_q31_sealed_poly_t *q = &s->q;
        over |= cli_append(buf, size, len,
                           "static const hyst_q31_sealed_poly_t %s_q31_sealed = {\n"
                           "    0x%08lXul, %uu, %luu, %luu, %ld, %ld,\n    {",
                           name, q->seal & 0xFFFFFFFFul, q->degree, (unsigned long)q->code_lo,
                           (unsigned long)q->code_hi, (long)q->unit, (long)q->rounding);
        for (k = 0u; k < q->degree; ++k) {
            over |= cli_append(buf, size, len, "%s%ld", k ? ", " : "", (long)q->a[k]);
        }
        over |= cli_append(buf, size, len, "}};\n");
    }
    return over;
}

int cli_header_sealed(const char *cmd, const char *model, char *buf, size_t size, size_t *len,
                      const char *name, const cli_model_t *m, int q31, unsigned long code_lo,
                      unsigned long code_hi)
{
    sealed_t s32, s64;
    hyst_status_t st;
    int over;
    if (m->kind != CLI_MODEL_POLY) {
        return cli_fail(cmd, "option --sealed: model file %s is of kind everett; a sealed curve "
                             "is of kind poly", model);
    }
    st = seal(m, 1, q31, code_lo, code_hi, &s32);
    if (st == HYST_OK) {
        st = seal(m, 0, q31, code_lo, code_hi, &s64);
    }
    if (st != HYST_OK) {
        return cli_fail(cmd, "model file %s: the sealed curve: %s", model, hyst_status_str(st));
    }
    over = cli_append(
        buf, size, len,
        "\n/* The prepared curve, made and checked by 'hyst header --sealed' and sealed\n"
        " * (CRC-32 over every number): firmware initialises from it without building\n"
        " * the curve (integer checks only, no double arithmetic linked); the instance\n"
        " * is, bit for bit, hyst_init()'s from %s:\n"
        " *   HYST_INIT_SEALED(axis, &%s_sealed);",
        name, name);
    if (q31) {
        over |= cli_append(buf, size, len,
                           "\n * and the q31 model on codes %lu..%lu, hyst_q31_init()'s:\n"
                           " *   HYST_Q31_INIT_SEALED(axis, &%s_q31_sealed);",
                           code_lo, code_hi, name);
    }
    over |= cli_append(buf, size, len, " */\n%s#ifdef HYST_USE_DOUBLE\n",
                       q31 ? "#include \"hyst/q31.h\"\n" : "");
    over |= emit(buf, size, len, name, &s64, 0, q31);
    over |= cli_append(buf, size, len, "#else\n");
    over |= emit(buf, size, len, name, &s32, 1, q31);
    over |= cli_append(buf, size, len, "#endif\n");
    return over != 0 ? cli_fail(cmd, "header text too long") : 0;
}
