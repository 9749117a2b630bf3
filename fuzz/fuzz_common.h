/* SPDX-License-Identifier: MIT */
/* Shared by the fuzz harnesses: a byte reader that yields zeros past the
 * end (so every input is valid), CHECK (abort, which libFuzzer reports as a
 * crash), the configuration reader and Horner's rounding bound. Static
 * functions: each harness is one translation unit. */
#ifndef FUZZ_COMMON_H
#define FUZZ_COMMON_H

#include "hyst/hyst.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Not every harness uses every helper. */
#if defined(__GNUC__) || defined(__clang__)
#define FUZZ_MAYBE_UNUSED __attribute__((unused))
#else
#define FUZZ_MAYBE_UNUSED
#endif

typedef struct {
    const unsigned char *p;
    size_t n, at;
} reader_t;

static unsigned rd_u8(reader_t *r) { return r->at < r->n ? r->p[r->at++] : 0u; }

FUZZ_MAYBE_UNUSED static unsigned rd_u16(reader_t *r)
{
    const unsigned lo = rd_u8(r);
    return lo | (rd_u8(r) << 8);
}

static double rd_f64(reader_t *r)
{
    unsigned char b[8];
    double v;
    unsigned k;
    for (k = 0; k < 8u; ++k) b[k] = (unsigned char)rd_u8(r);
    memcpy(&v, b, sizeof(v));
    return v;
}

/* The input of a sample op of the harnesses that fit raw outputs too
 * (fuzz_grid, fuzz_spline): 0xF4 a point of [lo, hi] from the next byte, and
 * the f64 before it as the fit's raw output (*y_fit, *raw_y set); 0xF5 hi,
 * 0xF6 lo; any other op a point op / 239 of [lo, hi]. The caller clamps at
 * hi (lo + (hi - lo) rounds past it). */
FUZZ_MAYBE_UNUSED static double fuzz_sample_input(reader_t *rd, unsigned op, double lo, double hi,
                                                  double *y_fit, int *raw_y)
{
    const double span = hi - lo;
    if (op == 0xF4u) {
        *y_fit = rd_f64(rd);
        *raw_y = 1;
        return lo + span * (double)rd_u8(rd) / 239.0;
    }
    if (op == 0xF5u) {
        return hi;
    }
    if (op == 0xF6u) {
        return lo;
    }
    return lo + span * (double)op / 239.0;
}

#define CHECK(cond)                                                               \
    do {                                                                          \
        if (!(cond)) {                                                            \
            fprintf(stderr, "fuzz: %s:%d: check failed: %s\n", __FILE__,     \
                    __LINE__, #cond);                                              \
            abort();                                                              \
        }                                                                         \
    } while (0)

/* Configuration from bytes. Structured: lo, hi and coefficients on small
 * grids, so that many curves are valid and well conditioned (differential
 * comparison is meaningful); raw: any doubles, for the init checks. */
FUZZ_MAYBE_UNUSED static void read_config(reader_t *r, int raw, hyst_poly_t *f)
{
    unsigned k;
    memset(f, 0, sizeof(*f));
    f->degree = rd_u8(r) % 12u;
    if (raw) {
        f->lo = rd_f64(r);
        f->hi = rd_f64(r);
        for (k = 0; k <= HYST_MAX_DEGREE; ++k) f->coeffs[k] = rd_f64(r);
        return;
    }
    f->lo = ((double)(signed char)rd_u8(r)) / 32.0;             /* -4 .. 4 */
    f->hi = f->lo + (double)(rd_u8(r) % 64u) / 16.0;            /* span 0 .. 4 */
    for (k = 0; k <= HYST_MAX_DEGREE; ++k) {
        f->coeffs[k] = ((double)(signed char)rd_u8(r)) / 64.0; /* -2 .. 2 */
    }
    if (f->degree >= 1u && f->degree <= HYST_MAX_DEGREE) { /* push the slope up half the time */
        f->coeffs[f->degree - 1u] += (double)(rd_u8(r) & 0x3Fu);
    }
}

/* A 24-bit number, low byte first. */
FUZZ_MAYBE_UNUSED static unsigned long rd_u24(reader_t *r)
{
    const unsigned long lo = rd_u16(r);
    return lo | ((unsigned long)rd_u8(r) << 16);
}

/* The code harnesses (fuzz_code.c, fuzz_q31.c): the code range, its map
 * onto the volts of f0's domain, and the next code of kind op & 7. */
FUZZ_MAYBE_UNUSED static unsigned long clo, chi, last_code;
FUZZ_MAYBE_UNUSED static double vlo, vhi;

FUZZ_MAYBE_UNUSED static double volts(unsigned long c)
{
    if (c <= clo) return vlo;
    if (c >= chi) return vhi;
    return vlo + (double)(c - clo) * ((vhi - vlo) / (double)(chi - clo));
}

FUZZ_MAYBE_UNUSED static unsigned long next_code(reader_t *r, unsigned op)
{
    const unsigned long span = chi - clo;
    long v;
    switch (op & 7u) {
    case 0:
    case 1: return clo + (unsigned long)rd_u16(r) % (span + 1u);
    case 2: /* a small move: noise around the last code, reversals */
        v = (long)last_code + (long)(signed char)rd_u8(r) / ((op & 8u) ? 1 : 16);
        return v < 0 ? 0ul : (unsigned long)v;
    case 3: return (op & 8u) ? chi : clo;
    case 4: /* out of range: clamped */
        if (op & 8u) return rd_u24(r) | 0x1000000ul;
        return (op & 16u) && clo > 0u ? clo - 1u - (unsigned long)rd_u8(r) % clo
                                      : chi + 1u + rd_u8(r);
    case 5: return last_code;
    default: return clo + (span * rd_u8(r)) / 255u;
    }
}

/* Rounding allowance of the differential comparison: Horner's error bound on
 * the raw coefficients (the reference evaluates those; the core a shifted,
 * scaled copy), times the depth of turning points each output hangs on. */
FUZZ_MAYBE_UNUSED static double horner_bound(const hyst_poly_t *f)
{
    const double m = fmax(fabs(f->lo), fabs(f->hi));
    double acc = 0.0;
    unsigned k;
    for (k = 0; k <= f->degree; ++k) acc = acc * m + fabs(f->coeffs[k]);
    return 8.0 * (double)(f->degree + 1u) * DBL_EPSILON * acc;
}

/* A compensator C driving its model M (both initialised) over the desired
 * outputs ys[0..n) (the model's own): each drive, into drive[k], finite, on
 * [lo, hi] up to 8 units in the last place of the larger end, and never
 * against the desired output; with tol >= 0 the model within (d + 1) tol of
 * each desired output, d the larger count of stacked turning points. Returns
 * the largest error over its allowance (0 with tol < 0 or tol 0). */
FUZZ_MAYBE_UNUSED static double fuzz_round_trip(hyst_t *C, hyst_t *M, const double *ys, size_t n,
                                                double lo, double hi, double tol, double *drive)
{
    const double end = fmax(fabs(lo), fabs(hi)), ulp = nextafter(end, INFINITY) - end;
    double worst = 0.0;
    size_t k;
    for (k = 0u; k < n; ++k) {
        const double x = hyst_step(C, ys[k]);
        const double y = hyst_step(M, x);
        const double d = (double)(hyst_tp_count(C) > hyst_tp_count(M) ? hyst_tp_count(C)
                                                                        : hyst_tp_count(M));
        drive[k] = x;
        CHECK(hyst_status(C) >= 0 && isfinite(x) && x >= lo - 8.0 * ulp && x <= hi + 8.0 * ulp);
        if (k > 0u) { /* monotone: never against the desired output */
            CHECK(ys[k] > ys[k - 1u] ? x >= drive[k - 1u] : ys[k] < ys[k - 1u] ? x <= drive[k - 1u] : 1);
        }
        if (tol >= 0) {
            const double allowed = (d + 1.0) * tol;
            CHECK(fabs(y - ys[k]) <= allowed);
            if (allowed > 0 && fabs(y - ys[k]) / allowed > worst) {
                worst = fabs(y - ys[k]) / allowed;
            }
        }
    }
    return worst;
}

/* Every kind a firmware can name (tcm.h, code.h), per variant. */
FUZZ_MAYBE_UNUSED static const hyst_kind_t fuzz_kinds[3][11] = {
    {hyst_f32_kind_poly,
    hyst_f32_kind_pwl,
    hyst_f32_kind_inverse,
    hyst_f32_kind_inverse_table,
    hyst_f32_kind_everett,
    hyst_f32_kind_everett_inverse,
    hyst_f32_kind_everett_inverse_table,
    hyst_f32_kind_everett_grid,
    hyst_f32_kind_everett_grid_inverse,
    hyst_f32_kind_spline,
    hyst_f32_kind_spline_inverse_table},
    {hyst_f64_kind_poly,
    hyst_f64_kind_pwl,
    hyst_f64_kind_inverse,
    hyst_f64_kind_inverse_table,
    hyst_f64_kind_everett,
    hyst_f64_kind_everett_inverse,
    hyst_f64_kind_everett_inverse_table,
    hyst_f64_kind_everett_grid,
    hyst_f64_kind_everett_grid_inverse,
    hyst_f64_kind_spline,
    hyst_f64_kind_spline_inverse_table},
    {hyst_code_kind_poly,
    hyst_code_kind_pwl,
    hyst_code_kind_inverse,
    hyst_code_kind_inverse_table,
    hyst_code_kind_everett,
    hyst_code_kind_everett_inverse,
    hyst_code_kind_everett_inverse_table,
    hyst_code_kind_everett_grid,
    hyst_code_kind_everett_grid_inverse,
    hyst_code_kind_spline,
    hyst_code_kind_spline_inverse_table}};
FUZZ_MAYBE_UNUSED static const unsigned fuzz_kind_variants[3] = {
    (unsigned)HYST_VARIANT_F32, (unsigned)HYST_VARIANT_F64, (unsigned)HYST_VARIANT_CODE};

/* A curve of one kind is bound, for an instance of each variant, by one
 * kind of the 33, the variant's own: hyst_*_init_kind() then runs it. */
FUZZ_MAYBE_UNUSED static void fuzz_check_kinds(const hyst_curve_t *c)
{
    size_t v, w, k;
    for (v = 0u; v < 3u; ++v) {
        unsigned bound = 0u;
        for (w = 0u; w < 3u; ++w) {
            for (k = 0u; k < 11u; ++k) {
                const void *ops = fuzz_kinds[w][k](c, fuzz_kind_variants[v]);
                CHECK(ops == NULL || w == v);
                bound += ops != NULL;
            }
        }
        CHECK(bound == 1u);
    }
}

#endif
