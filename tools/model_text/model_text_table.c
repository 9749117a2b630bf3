/* SPDX-License-Identifier: MIT */
/* The compensator's table of a firmware header (hyst header --compensator),
 * the one implementation the `hyst` tool, the Python extension and the
 * MATLAB/Octave MEX gateway share: built here by the library in float and
 * in double (a firmware build's real type picks one, HYST_USE_DOUBLE) and
 * sealed (hyst_curve_table_seal()), so firmware takes it from flash with
 * hyst_curve_inverse_table_const() or hyst_curve_everett_inverse_table_const()
 * instead of building it at boot; a spline's, which firmware builds, is
 * measured here and its size written. */
#include "model_text.h"

#include <stdlib.h>
#include <string.h>

double model_text_as_float(double v)
{
    char lit[40];
    model_text_c_number(lit, sizeof lit, v, 17);
    return (double)strtof(lit, NULL);
}

void model_text_poly_as_read(const model_text_t *m, int f32, hyst_poly_t *p)
{
    size_t i;
    memset(p, 0, sizeof *p);
    p->degree = (unsigned)(m->ncoef - 1u);
    p->lo = f32 ? model_text_as_float(m->lo) : m->lo;
    p->hi = f32 ? model_text_as_float(m->hi) : m->hi;
    for (i = 0u; i < m->ncoef; ++i) {
        p->coeffs[i] = f32 ? model_text_as_float(m->coeffs[i]) : m->coeffs[i];
    }
}

int model_text_append_real(char *buf, size_t size, size_t *len, const char *sep, double v,
                           int f32)
{
    char lit[48];
    model_text_c_number(lit, sizeof lit - 1u, v, f32 ? 9 : 17);
    return model_text_append(buf, size, len, "%s%s%s", sep, lit, f32 ? "f" : "");
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
static hyst_status_t build(const model_text_t *m, int f32, size_t rows, size_t intervals,
                           built_t *out)
{
    const int everett = m->kind == MODEL_TEXT_EVERETT;
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
        model_text_to_everett(m, &e);
        if (f32) {
            e.lo = model_text_as_float(e.lo);
            e.hi = model_text_as_float(e.hi);
            e.y_lo = model_text_as_float(e.y_lo);
            for (a = 0u; a < HYST_EVERETT_MAX_DEGREE; ++a) {
                for (b = 0u; b < HYST_EVERETT_MAX_DEGREE; ++b) {
                    e.e[a][b] = model_text_as_float(e.e[a][b]);
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
    } else if (m->kind == MODEL_TEXT_SPLINE) {
        float fwd32[HYST_SPLINE_TABLE_LEN(HYST_SPLINE_MAX_INTERVALS)];
        double fwd64[HYST_SPLINE_TABLE_LEN(HYST_SPLINE_MAX_INTERVALS)];
        hyst_spline_t f0;
        model_text_to_spline(m, &f0);
        if (f32) {
            f0.lo = model_text_as_float(f0.lo);
            f0.hi = model_text_as_float(f0.hi);
            for (i = 0u; i <= f0.intervals; ++i) {
                f0.value[i] = model_text_as_float(f0.value[i]);
                f0.slope[i] = model_text_as_float(f0.slope[i]);
            }
            st = hyst_f32_curve_from_spline(&fwd, &f0, fwd32, HYST_SPLINE_TABLE_LEN(f0.intervals));
            if (st == HYST_OK) {
                st = hyst_f32_curve_spline_inverse_table(&inv, &fwd, t32, intervals);
            }
        } else {
            st = hyst_f64_curve_from_spline(&fwd, &f0, fwd64, HYST_SPLINE_TABLE_LEN(f0.intervals));
            if (st == HYST_OK) {
                st = hyst_f64_curve_spline_inverse_table(&inv, &fwd, out->num, intervals);
            }
        }
        /* no seal for the kind: firmware builds its table; the error as init measured it */
        out->seal.max_err = st == HYST_OK ? hyst_curve_inverse_error(&inv) : 0;
    } else {
        hyst_poly_t p;
        model_text_poly_as_read(m, f32, &p);
        st = f32 ? hyst_f32_curve_from_poly(&fwd, &p) : hyst_f64_curve_from_poly(&fwd, &p);
        if (st == HYST_OK) {
            st = f32 ? hyst_f32_curve_inverse_table(&inv, &fwd, t32, intervals)
                     : hyst_f64_curve_inverse_table(&inv, &fwd, out->num, intervals);
        }
    }
    if (st == HYST_OK && m->kind != MODEL_TEXT_SPLINE) {
        st = hyst_curve_table_seal(&inv, &out->seal);
    }
    if (st == HYST_OK && m->kind == MODEL_TEXT_POLY) { /* before the float table is freed */
        st = f32 ? hyst_f32_seal_inverse_table(&out->s32, &inv)
                 : hyst_f64_seal_inverse_table(&out->s64, &inv);
    }
    for (i = 0u; f32 && i < n; ++i) {
        out->num[i] = (double)t32[i];
    }
    free(t32);
    out->exact = st != HYST_OK ? 0u : everett ? inv.u.everett.exact : inv.u.inv_table.exact;
    return st;
}

/* One variant's table and seal, an interval (four numbers) per line. */
static int emit(char *buf, size_t size, size_t *len, const char *name, const built_t *b, int f32,
                const char *len_macro)
{
    size_t i;
    int over = model_text_append(buf, size, len, "static const %s %s_table[%s] = {",
                                 f32 ? "float" : "double", name, len_macro);
    for (i = 0u; i < b->n; ++i) {
        over |= model_text_append_real(buf, size, len, i % 4u == 0u ? "\n    " : " ", b->num[i],
                                       f32);
        if (i + 1u < b->n) {
            over |= model_text_append(buf, size, len, ",");
        }
    }
    over |= model_text_append(buf, size, len,
                              "};\nstatic const hyst_table_seal_t %s_seal = {0x%08lXul, ", name,
                              b->seal.crc & 0xFFFFFFFFul);
    over |= model_text_append_real(buf, size, len, "", (double)b->seal.max_err, 0);
    return over | model_text_append(buf, size, len, "};\n");
}

/* The compensator's curve sealed with its table, 'NAME_comp_sealed', of
 * one real type (the other NULL). */
static int emit_sealed_inverse(char *buf, size_t size, size_t *len, const char *name,
                               const hyst_f32_sealed_inverse_t *s32,
                               const hyst_f64_sealed_inverse_t *s64)
{
    const int f32 = s32 != NULL;
    const unsigned n = f32 ? s32->degree : s64->degree;
    const double num[7] = {f32 ? (double)s32->lo : s64->lo,     f32 ? (double)s32->hi : s64->hi,
                           f32 ? (double)s32->y_lo : s64->y_lo, f32 ? (double)s32->y_hi : s64->y_hi,
                           f32 ? (double)s32->unit : s64->unit, f32 ? (double)s32->span : s64->span,
                           f32 ? (double)s32->u_per_d : s64->u_per_d};
    unsigned k;
    int over = model_text_append(
        buf, size, len,
        "static const hyst_%s_sealed_inverse_t %s_comp_sealed = {\n    0x%08lXul, %uu,\n   ",
        f32 ? "f32" : "f64", name, (f32 ? s32->seal : s64->seal) & 0xFFFFFFFFul, n);
    for (k = 0u; k < 7u; ++k) {
        over |= model_text_append_real(buf, size, len,
                                       k == 0u ? " " : k == 4u ? ",\n    " : ", ", num[k], f32);
    }
    over |= model_text_append(buf, size, len, ",\n    {");
    for (k = 0u; k < n; ++k) {
        over |= model_text_append_real(buf, size, len, k ? ", " : "",
                                       f32 ? (double)s32->a[k] : s64->a[k], f32);
    }
    over |= model_text_append(buf, size, len, "},\n    %luul, %luul,",
                              f32 ? s32->intervals : s64->intervals,
                              f32 ? s32->exact : s64->exact);
    over |= model_text_append_real(buf, size, len, " ",
                                   (double)(f32 ? s32->max_err : s64->max_err), 1);
    return over | model_text_append(buf, size, len, "};\n");
}

/* The spline's compensator, built and measured here in float and in double:
 * no table from flash for the kind (no seal), so the header says how
 * firmware builds it at init and sizes it, NAME_INTERVALS. */
static int spline_table_text(char *buf, size_t size, size_t *len, const char *name,
                             const model_text_t *m, size_t intervals, const built_t *b32,
                             const built_t *b64)
{
    const unsigned long k = (unsigned long)m->nvalues - 1ul;
    return model_text_append(
        buf, size, len,
        "\n/* The compensator's table: f0^-1 in %lu intervals, which firmware builds at\n"
        " * init (hyst_curve_spline_inverse_table(); the kind takes no table from\n"
        " * flash). Built here in float and in double: %lu of them solved per sample\n"
        " * instead; worst error measured %.3g (float) / %.3g (double) of the drive\n"
        " * range:\n"
        " *   static hyst_real_t fwd_table[HYST_SPLINE_TABLE_LEN(%luu)];\n"
        " *   static hyst_real_t comp_table[HYST_INV_TABLE_LEN(%s_INTERVALS)];\n"
        " *   hyst_curve_from_spline(&fwd, &%s, fwd_table, HYST_SPLINE_TABLE_LEN(%luu));\n"
        " *   hyst_curve_spline_inverse_table(&comp, &fwd, comp_table, %s_INTERVALS);\n"
        " *   hyst_init_curve(&S, &comp, ...);  // both tables outlive S */\n"
        "#define %s_INTERVALS %luu\n",
        (unsigned long)intervals, (unsigned long)b32->exact, (double)b32->seal.max_err,
        (double)b64->seal.max_err, k, name, name, k, name, name, (unsigned long)intervals);
}

size_t model_text_header_table_size(const model_text_t *m, size_t rows, size_t intervals)
{
    const size_t n = m->kind == MODEL_TEXT_EVERETT ? HYST_EVERETT_INV_TABLE_LEN(rows, intervals)
                     : m->kind == MODEL_TEXT_SPLINE ? 0u /* built by firmware: not written */
                                                    : HYST_INV_TABLE_LEN(intervals);
    return 4096u + 2u * n * 28u; /* comment and seals; each number with its separator */
}

int model_text_header_table(char *buf, size_t size, size_t *len, const char *name,
                            const model_text_t *m, size_t rows, size_t intervals, int sealed,
                            hyst_status_t *status)
{
    const int everett = m->kind == MODEL_TEXT_EVERETT;
    built_t b32, b64;
    char len_macro[256];
    size_t macro_len = 0u;
    int over;
    if (m->kind == MODEL_TEXT_GRID) { /* the grid's compensator has none */
        *status = HYST_ERR_ARG;
        return 1;
    }
    memset(&b32, 0, sizeof b32);
    memset(&b64, 0, sizeof b64);
    *status = build(m, 1, rows, intervals, &b32);
    if (*status == HYST_OK) {
        *status = build(m, 0, rows, intervals, &b64);
    }
    if (*status != HYST_OK) {
        free(b32.num);
        free(b64.num);
        return 1;
    }
    if (m->kind == MODEL_TEXT_SPLINE) {
        over = spline_table_text(buf, size, len, name, m, intervals, &b32, &b64);
        free(b32.num);
        free(b64.num);
        return over != 0;
    }
    sealed = sealed && !everett;
    len_macro[0] = '\0';
    over = everett ? model_text_append(len_macro, sizeof len_macro, &macro_len,
                                       "HYST_EVERETT_INV_TABLE_LEN(%s_ROWS, %s_INTERVALS)", name,
                                       name)
                   : model_text_append(len_macro, sizeof len_macro, &macro_len,
                                       "HYST_INV_TABLE_LEN(%s_INTERVALS)", name);
    over |= model_text_append(
        buf, size, len,
        "\n/* The compensator's table, built by 'hyst header --compensator' in float and in\n"
        " * double and sealed: %s%lu intervals%s, %lu of them solved per sample instead;\n"
        " * worst error measured by the build %.3g (float) / %.3g (double) of the drive\n"
        " * range. Firmware takes it from flash instead of building it at init (checks:\n"
        " * the seal, then that it is this model's table):\n",
        everett ? "" : "f0^-1 in ", (unsigned long)intervals, everett ? " per row" : "",
        (unsigned long)(b32.exact), (double)b32.seal.max_err, (double)b64.seal.max_err);
    if (everett) {
        over |= model_text_append(
            buf, size, len,
            " *   hyst_curve_from_everett(&fwd, &%s);\n"
            " *   hyst_curve_everett_inverse_table_const(&comp, &fwd, %s_table, %s_ROWS,\n"
            " *                                          %s_INTERVALS, &%s_seal);\n"
            " *   hyst_init_curve(&S, &comp, ...);  // comp outlives S */\n"
            "#define %s_ROWS %luu\n",
            name, name, name, name, name, name, (unsigned long)rows);
    } else {
        over |= model_text_append(
            buf, size, len,
            " *   hyst_curve_from_poly(&fwd, &%s);\n"
            " *   hyst_curve_inverse_table_const(&comp, &fwd, %s_table, %s_INTERVALS,\n"
            " *                                  &%s_seal);\n"
            " *   hyst_init_curve(&S, &comp, ...);  // comp outlives S",
            name, name, name, name);
        if (sealed) {
            over |= model_text_append(
                buf, size, len,
                "\n * or, the compensator's curve sealed with the table (--sealed): no\n"
                " * table measured, no curve built, integer checks only:\n"
                " *   HYST_INIT_INVERSE_SEALED(S, &comp, &%s_comp_sealed, %s_table);",
                name, name);
        }
        over |= model_text_append(buf, size, len, " */\n%s",
                                  sealed ? "#include \"hyst/inverse.h\"\n" : "");
    }
    over |= model_text_append(buf, size, len, "#define %s_INTERVALS %luu\n#ifdef HYST_USE_DOUBLE\n",
                              name, (unsigned long)intervals);
    over |= emit(buf, size, len, name, &b64, 0, len_macro);
    if (sealed) {
        over |= emit_sealed_inverse(buf, size, len, name, NULL, &b64.s64);
    }
    over |= model_text_append(buf, size, len, "#else\n");
    over |= emit(buf, size, len, name, &b32, 1, len_macro);
    if (sealed) {
        over |= emit_sealed_inverse(buf, size, len, name, &b32.s32, NULL);
    }
    over |= model_text_append(buf, size, len, "#endif\n");
    free(b32.num);
    free(b64.num);
    return over != 0;
}
