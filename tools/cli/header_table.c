/* SPDX-License-Identifier: MIT */
/* hyst header --compensator: the model's compensator table, built here in
 * float and in double (a firmware build's real type picks one,
 * HYST_USE_DOUBLE) and sealed (hyst_curve_table_seal()), so firmware takes
 * it from flash with hyst_curve_inverse_table_const() or
 * hyst_curve_everett_inverse_table_const() instead of building it at boot. */
#include "cli.h"
#include "hyst/hyst.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

double cli_as_float_literal(double v)
{
    char lit[40];
    cli_c_literal(lit, sizeof lit, v);
    return (double)strtof(lit, NULL);
}

void cli_model_poly_as_read(const cli_model_t *m, int f32, hyst_poly_t *p)
{
    size_t i;
    memset(p, 0, sizeof *p);
    p->degree = (unsigned)(m->ncoef - 1u);
    p->lo = f32 ? cli_as_float_literal(m->lo) : m->lo;
    p->hi = f32 ? cli_as_float_literal(m->hi) : m->hi;
    for (i = 0u; i < m->ncoef; ++i) {
        p->coeffs[i] = f32 ? cli_as_float_literal(m->coeffs[i]) : m->coeffs[i];
    }
}

/* A table of one variant (f32 or f64): its numbers as doubles, its seal
 * (with the build's measured error). */
typedef struct {
    double *num;
    size_t n;
    hyst_table_seal_t seal;
    size_t exact;
    hyst_f32_sealed_inverse_t s32; /* kind poly: the compensator's curve sealed with its table */
    hyst_f64_sealed_inverse_t s64;
} built_t;

/* The model's curve in the variant, from the numbers the header gives a
 * build of that real type; then its table and seal. */
static hyst_status_t build(const cli_model_t *m, int f32, size_t rows, size_t intervals,
                           built_t *out)
{
    const int everett = m->kind == CLI_MODEL_EVERETT;
    const size_t n = everett ? HYST_EVERETT_INV_TABLE_LEN(rows, intervals)
                             : HYST_INV_TABLE_LEN(intervals);
    float *t32 = f32 ? (float *)malloc(n * sizeof(float)) : NULL;
    hyst_curve_t fwd, inv;
    hyst_status_t st;
    size_t i;
    out->n = n;
    out->num = (double *)malloc(n * sizeof(double));
    if (out->num == NULL || (f32 && t32 == NULL)) {
        free(t32);
        return HYST_ERR_NOSPACE;
    }
    if (everett) {
        hyst_everett_t e;
        unsigned a, b;
        cli_model_to_everett(m, &e);
        if (f32) {
            e.lo = cli_as_float_literal(e.lo);
            e.hi = cli_as_float_literal(e.hi);
            e.y_lo = cli_as_float_literal(e.y_lo);
            for (a = 0u; a < HYST_EVERETT_MAX_DEGREE; ++a) {
                for (b = 0u; b < HYST_EVERETT_MAX_DEGREE; ++b) {
                    e.e[a][b] = cli_as_float_literal(e.e[a][b]);
                }
            }
            st = hyst_f32_curve_from_everett(&fwd, &e);
            if (st == HYST_OK) {
                st = hyst_f32_curve_everett_inverse_table(&inv, &fwd, t32, rows, intervals);
            }
        } else {
            st = hyst_f64_curve_from_everett(&fwd, &e);
            if (st == HYST_OK) {
                st = hyst_f64_curve_everett_inverse_table(&inv, &fwd, out->num, rows, intervals);
            }
        }
    } else {
        hyst_poly_t p;
        cli_model_poly_as_read(m, f32, &p);
        st = f32 ? hyst_f32_curve_from_poly(&fwd, &p) : hyst_f64_curve_from_poly(&fwd, &p);
        if (st == HYST_OK) {
            st = f32 ? hyst_f32_curve_inverse_table(&inv, &fwd, t32, intervals)
                     : hyst_f64_curve_inverse_table(&inv, &fwd, out->num, intervals);
        }
    }
    if (st == HYST_OK) {
        st = hyst_curve_table_seal(&inv, &out->seal);
    }
    if (st == HYST_OK && !everett) { /* before the float table is freed */
        st = f32 ? hyst_f32_seal_inverse_table(&out->s32, &inv)
                 : hyst_f64_seal_inverse_table(&out->s64, &inv);
    }
    for (i = 0u; f32 && i < n; ++i) {
        out->num[i] = (double)t32[i];
    }
    free(t32);
    out->exact = everett ? inv.u.everett.exact : inv.u.inv_table.exact;
    return st;
}

/* A number of the table as a C literal of its type (float: 9 digits and
 * the suffix f, which the compiler reads back to the same float; double:
 * 17). */
static void literal(char *lit, size_t size, double v, int f32)
{
    cli_c_number(lit, size - 1u, v, f32 ? 9 : 17);
    if (f32) {
        (void)strcat(lit, "f");
    }
}

/* One variant's table and seal, an interval (four numbers) per line. */
static int emit(char *buf, size_t size, size_t *len, const char *name, const built_t *b, int f32,
                const char *len_macro)
{
    char lit[48];
    size_t i;
    int over = cli_append(buf, size, len, "static const %s %s_table[%s] = {", f32 ? "float" : "double",
                          name, len_macro);
    for (i = 0u; i < b->n; ++i) {
        literal(lit, sizeof lit, b->num[i], f32);
        over |= cli_append(buf, size, len, "%s%s%s", i % 4u == 0u ? "\n    " : " ", lit,
                           i + 1u < b->n ? "," : "");
    }
    cli_c_literal(lit, sizeof lit, (double)b->seal.max_err);
    return over | cli_append(buf, size, len,
                             "};\nstatic const hyst_table_seal_t %s_seal = {0x%08lXul, %s};\n",
                             name, b->seal.crc & 0xFFFFFFFFul, lit);
}

size_t cli_header_table_size(const cli_model_t *m, size_t rows, size_t intervals)
{
    const size_t n = m->kind == CLI_MODEL_EVERETT ? HYST_EVERETT_INV_TABLE_LEN(rows, intervals)
                                                  : HYST_INV_TABLE_LEN(intervals);
    return 4096u + 2u * n * 28u; /* comment and seals; each number with its separator */
}

int cli_header_table(const char *cmd, const char *model, char *buf, size_t size, size_t *len,
                     const char *name, const cli_model_t *m, size_t rows, size_t intervals,
                     int sealed)
{
    const int everett = m->kind == CLI_MODEL_EVERETT;
    built_t b32, b64;
    char len_macro[96];
    hyst_status_t st;
    int over;
    memset(&b32, 0, sizeof b32);
    memset(&b64, 0, sizeof b64);
    st = build(m, 1, rows, intervals, &b32);
    if (st == HYST_OK) {
        st = build(m, 0, rows, intervals, &b64);
    }
    if (st != HYST_OK) {
        free(b32.num);
        free(b64.num);
        return cli_fail(cmd, "model file %s: the compensator's table: %s", model,
                        hyst_status_str(st));
    }
    if (everett) {
        (void)snprintf(len_macro, sizeof len_macro,
                       "HYST_EVERETT_INV_TABLE_LEN(%s_ROWS, %s_INTERVALS)", name, name);
    } else {
        (void)snprintf(len_macro, sizeof len_macro, "HYST_INV_TABLE_LEN(%s_INTERVALS)", name);
    }
    over = cli_append(
        buf, size, len,
        "\n/* The compensator's table, built by 'hyst header --compensator' in float and in\n"
        " * double and sealed: %s%lu intervals%s, %lu of them solved per sample instead;\n"
        " * worst error measured by the build %.3g (float) / %.3g (double) of the drive\n"
        " * range. Firmware takes it from flash instead of building it at init (checks:\n"
        " * the seal, then that it is this model's table):\n",
        everett ? "" : "f0^-1 in ", (unsigned long)intervals,
        everett ? " per row" : "", (unsigned long)(b32.exact), (double)b32.seal.max_err,
        (double)b64.seal.max_err);
    if (everett) {
        over |= cli_append(
            buf, size, len,
            " *   hyst_curve_from_everett(&fwd, &%s);\n"
            " *   hyst_curve_everett_inverse_table_const(&comp, &fwd, %s_table, %s_ROWS,\n"
            " *                                          %s_INTERVALS, &%s_seal);\n"
            " *   hyst_init_curve(&S, &comp, ...);  // comp outlives S */\n"
            "#define %s_ROWS %luu\n",
            name, name, name, name, name, name, (unsigned long)rows);
    } else {
        over |= cli_append(buf, size, len,
                           " *   hyst_curve_from_poly(&fwd, &%s);\n"
                           " *   hyst_curve_inverse_table_const(&comp, &fwd, %s_table, %s_INTERVALS,\n"
                           " *                                  &%s_seal);\n"
                           " *   hyst_init_curve(&S, &comp, ...);  // comp outlives S",
                           name, name, name, name);
        if (sealed) {
            over |= cli_append(buf, size, len,
                               "\n * or, the compensator's curve sealed with the table (--sealed): no\n"
                               " * table measured, no curve built, integer checks only:\n"
                               " *   HYST_INIT_INVERSE_SEALED(S, &comp, &%s_comp_sealed, %s_table);",
                               name, name);
        }
        over |= cli_append(buf, size, len, " */\n%s",
                           sealed ? "#include \"hyst/inverse.h\"\n" : "");
    }
    over |= cli_append(buf, size, len, "#define %s_INTERVALS %luu\n#ifdef HYST_USE_DOUBLE\n", name,
                       (unsigned long)intervals);
    over |= emit(buf, size, len, name, &b64, 0, len_macro);
    if (sealed && !everett) {
        over |= cli_header_sealed_inverse(buf, size, len, name, NULL, &b64.s64);
    }
    over |= cli_append(buf, size, len, "#else\n");
    over |= emit(buf, size, len, name, &b32, 1, len_macro);
    if (sealed && !everett) {
        over |= cli_header_sealed_inverse(buf, size, len, name, &b32.s32, NULL);
    }
    over |= cli_append(buf, size, len, "#endif\n");
    free(b32.num);
    free(b64.num);
    return over != 0 ? cli_fail(cmd, "header text too long") : 0;
}
