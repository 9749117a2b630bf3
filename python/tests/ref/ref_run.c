/* SPDX-License-Identifier: MIT */
/*
 * hyst_ref: runs one block call of the C library over a raw array, for the
 * Python tests (they compare the package's results with these bit for bit).
 *
 *   hyst_ref KIND key=value...
 *   KIND  sim | inv | code | pi | bench
 *   keys  type=f64|f32  lo= hi=  coeffs=cN,...,c0  cap=  deadband=
 *         intervals= (inv: the tabulated compensator's; 0, the default: the exact one)
 *         degree= y_lo= terms=e,... (sim, inv: the asymmetric kind's E instead of f0,
 *         terms ordered i = 1..degree, then j = 0..degree - i; lo= hi= its domain)
 *         rows= (inv of E with intervals > 0: the table's rows, HYST_EVERETT_INV_ROWS
 *         by default)  err=PATH (inv: hyst_curve_inverse_error() of the curve, %.17g)
 *         values=v0,...,vK slopes=s0,...,sK (sim, inv: f0 a spline of K uniform knot
 *         intervals on lo= hi= instead of the polynomial)
 *         code_lo= code_hi=  r=r1,...  w=w1,...  in=PATH out=PATH
 *         snap=PATH (sim, inv, code: the snapshot after the block)
 *         repeat=N (bench: best of N block calls of the f64 model)
 * in holds raw samples of the input type (double, float or uint16 codes),
 * out receives the outputs as raw numbers. Prints the status of the block
 * call (bench: the best nanoseconds per sample; out holds the last run).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "hyst/hyst.h"

static int g_argc;
static char **g_argv;

static void die(const char *what, const char *detail)
{
    fprintf(stderr, "hyst_ref: %s%s\n", what, detail);
    exit(2);
}

/* Value of key=..., or dflt when absent. */
static const char *opt(const char *key, const char *dflt)
{
    const size_t k = strlen(key);
    int i;
    for (i = 2; i < g_argc; ++i) {
        if (strncmp(g_argv[i], key, k) == 0 && g_argv[i][k] == '=') {
            return g_argv[i] + k + 1;
        }
    }
    if (dflt == NULL) {
        die("missing option ", key);
    }
    return dflt;
}

static double num(const char *key, const char *dflt) { return strtod(opt(key, dflt), NULL); }

/* Comma-separated numbers of key into v (at most max); returns the count. */
static size_t list(const char *key, double *v, size_t max)
{
    const char *p = opt(key, NULL);
    size_t n = 0u;
    for (;;) {
        char *end;
        if (n == max) {
            die("too many numbers in ", key);
        }
        v[n++] = strtod(p, &end);
        if (*end != ',') {
            return n;
        }
        p = end + 1;
    }
}

static void *load(const char *path, size_t *bytes)
{
    FILE *f = fopen(path, "rb");
    char *buf;
    long len;
    if (f == NULL || fseek(f, 0, SEEK_END) != 0 || (len = ftell(f)) < 0 || fseek(f, 0, SEEK_SET) != 0) {
        die("cannot read ", path);
    }
    buf = malloc((size_t)len + 1u);
    if (buf == NULL || fread(buf, 1u, (size_t)len, f) != (size_t)len) {
        die("cannot read ", path);
    }
    fclose(f);
    *bytes = (size_t)len;
    return buf;
}

static void store(const char *path, const void *data, size_t bytes)
{
    FILE *f = fopen(path, "wb");
    if (f == NULL || fwrite(data, 1u, bytes, f) != bytes || fclose(f) != 0) {
        die("cannot write ", path);
    }
}

static hyst_poly_t poly(void)
{
    hyst_poly_t f0;
    memset(&f0, 0, sizeof f0);
    f0.degree = (unsigned)list("coeffs", f0.coeffs, HYST_MAX_DEGREE + 1u) - 1u;
    f0.lo = num("lo", NULL);
    f0.hi = num("hi", NULL);
    return f0;
}

/* No f0 (the asymmetric kind's runs). */
static hyst_poly_t no_poly(void)
{
    hyst_poly_t f0;
    memset(&f0, 0, sizeof f0);
    return f0;
}

/* The asymmetric kind's E from degree=, lo=, hi=, y_lo=, terms=. */
static hyst_everett_t everett(void)
{
    double terms[HYST_EVERETT_TERMS];
    hyst_everett_t e;
    size_t k = 0u, n;
    unsigned i, j;
    memset(&e, 0, sizeof e);
    e.degree = (unsigned)num("degree", NULL);
    e.lo = num("lo", NULL);
    e.hi = num("hi", NULL);
    e.y_lo = num("y_lo", NULL);
    n = list("terms", terms, HYST_EVERETT_TERMS);
    if (e.degree < 1u || e.degree > HYST_EVERETT_MAX_DEGREE ||
        n != (size_t)e.degree * (e.degree + 1u) / 2u) {
        die("bad degree or terms", "");
    }
    for (i = 1u; i <= e.degree; ++i) {
        for (j = 0u; i + j <= e.degree; ++j) {
            e.e[i - 1u][j] = terms[k++];
        }
    }
    return e;
}

/* A spline f0 from lo=, hi=, values=, slopes= (as many). */
static hyst_spline_t spline(void)
{
    hyst_spline_t f0;
    size_t n;
    memset(&f0, 0, sizeof f0);
    f0.lo = num("lo", NULL);
    f0.hi = num("hi", NULL);
    n = list("values", f0.value, HYST_SPLINE_MAX_INTERVALS + 1u);
    if (n < 2u || list("slopes", f0.slope, HYST_SPLINE_MAX_INTERVALS + 1u) != n) {
        die("bad values or slopes", "");
    }
    f0.intervals = (unsigned)n - 1u;
    return f0;
}

/* err=PATH: the measured error of a tabulated inverse, written as text. */
static void save_error(const hyst_curve_t *inv)
{
    const char *path = opt("err", "");
    char text[64];
    if (*path != '\0') {
        const int len = snprintf(text, sizeof text, "%.17g\n", (double)hyst_curve_inverse_error(inv));
        store(path, text, (size_t)len);
    }
}

static void save_snapshot(const hyst_tcm_t *S)
{
    const char *path = opt("snap", "");
    unsigned char *buf;
    size_t len = 0u;
    if (*path == '\0') {
        return;
    }
    buf = malloc(HYST_SNAPSHOT_SIZE(hyst_capacity(S)));
    if (buf == NULL || hyst_snapshot_save(S, buf, HYST_SNAPSHOT_SIZE(hyst_capacity(S)), &len) != HYST_OK) {
        die("snapshot failed", "");
    }
    store(path, buf, len);
    free(buf);
}

static double now_ns(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e9 + (double)t.tv_nsec;
}

/* One real variant: model or compensator (sim, inv), PI, timing. */
#define REAL_VARIANT(T, P)                                                                   \
    static int run_##P(const char *kind)                                                     \
    {                                                                                        \
        size_t bytes, n, cap = (size_t)num("cap", "2048");                                   \
        T *x = load(opt("in", NULL), &bytes), *y, *tp;                                       \
        int st;                                                                              \
        n = bytes / sizeof(T);                                                               \
        y = malloc((n + 1u) * sizeof(T));                                                    \
        tp = malloc(4u * cap * sizeof(T));                                                   \
        if (y == NULL || tp == NULL) {                                                       \
            die("out of memory", "");                                                        \
        }                                                                                    \
        if (strcmp(kind, "pi") == 0) {                                                       \
            static double r[4096], w[4096];                                                  \
            const size_t m = list("r", r, 4096u);                                            \
            hyst_pi_t pi;                                                                    \
            size_t i;                                                                        \
            if (list("w", w, 4096u) != m || m > cap) {                                       \
                die("bad r/w", "");                                                          \
            }                                                                                \
            for (i = 0; i < m; ++i) {                                                        \
                tp[i] = (T)r[i];                                                             \
                tp[cap + i] = (T)w[i];                                                       \
            }                                                                                \
            st = hyst_##P##_pi_init(&pi, tp, tp + cap, tp + 2u * cap, m);                    \
            if (st == HYST_OK) {                                                             \
                st = hyst_##P##_pi_process(&pi, x, y, n);                                    \
            }                                                                                \
        } else {                                                                             \
            hyst_tcm_t S;                                                                    \
            hyst_curve_t inv, fwd;                                                           \
            const int is_everett = *opt("terms", "") != '\0';                                \
            const int is_spline = *opt("values", "") != '\0';                                \
            const hyst_poly_t f0 = is_everett || is_spline ? no_poly() : poly();             \
            const size_t intervals = (size_t)num("intervals", "0");                          \
            const size_t rows_given = (size_t)num("rows", "0");                              \
            const size_t rows = rows_given > 0u ? rows_given : (size_t)HYST_EVERETT_INV_ROWS;\
            T *table = malloc((is_everett ? HYST_EVERETT_INV_TABLE_LEN(rows, intervals)      \
                                          : HYST_INV_TABLE_LEN(intervals)) * sizeof(T));     \
            memset(&inv, 0, sizeof inv);                                                     \
            if (table == NULL) {                                                             \
                die("out of memory", "");                                                    \
            }                                                                                \
            if (is_everett || is_spline) {                                                   \
                static T spline_table[HYST_SPLINE_TABLE_LEN(HYST_SPLINE_MAX_INTERVALS)];     \
                if (is_spline) {                                                             \
                    const hyst_spline_t sp = spline();                                       \
                    st = hyst_##P##_curve_from_spline(&fwd, &sp, spline_table,               \
                                                      HYST_SPLINE_TABLE_LEN(sp.intervals));  \
                } else {                                                                     \
                    const hyst_everett_t e = everett();                                      \
                    st = hyst_##P##_curve_from_everett(&fwd, &e);                            \
                }                                                                            \
                if (st == HYST_OK && strcmp(kind, "inv") == 0) {                             \
                    st = is_spline ? hyst_curve_spline_inverse(&inv, &fwd)                   \
                         : intervals > 0u ? hyst_##P##_curve_everett_inverse_table(          \
                                                &inv, &fwd, table, rows, intervals)          \
                                          : hyst_curve_inverse(&inv, &fwd);                  \
                }                                                                            \
                if (st == HYST_OK) {                                                         \
                    st = hyst_##P##_init_curve(&S, strcmp(kind, "inv") == 0 ? &inv : &fwd,  \
                                               tp, tp + cap, tp + 2u * cap, tp + 3u * cap,   \
                                               cap);                                         \
                }                                                                            \
            } else if (strcmp(kind, "inv") == 0 && intervals > 0u) {                         \
                st = hyst_##P##_init_inverse_table(&S, &inv, &f0, table, intervals, tp,      \
                                                   tp + cap, tp + 2u * cap, tp + 3u * cap,   \
                                                   cap);                                     \
            } else if (strcmp(kind, "inv") == 0) {                                           \
                st = hyst_##P##_init_inverse_exact(&S, &inv, &f0, tp, tp + cap,              \
                                                   tp + 2u * cap, tp + 3u * cap, cap);       \
            } else {                                                                         \
                st = hyst_##P##_init(&S, &f0, tp, tp + cap, tp + 2u * cap, tp + 3u * cap,    \
                                     cap);                                                   \
            }                                                                                \
            if (st == HYST_OK) {                                                             \
                st = hyst_##P##_set_deadband(&S, (T)num("deadband", "0"));                   \
            }                                                                                \
            if (st == HYST_OK && strcmp(kind, "bench") == 0) {                               \
                const long repeat = (long)num("repeat", "5");                                \
                double best = 0.0;                                                           \
                long k;                                                                      \
                for (k = 0; k < repeat; ++k) {                                               \
                    double t0, t;                                                            \
                    hyst_reset(&S);                                                          \
                    t0 = now_ns();                                                           \
                    st = hyst_##P##_process(&S, x, y, n);                                    \
                    t = now_ns() - t0;                                                       \
                    best = (k == 0 || t < best) ? t : best;                                  \
                }                                                                            \
                store(opt("out", NULL), y, n * sizeof(T));                                   \
                printf("%.6f\n", best / (double)n);                                          \
                return st < 0;                                                               \
            }                                                                                \
            if (st == HYST_OK) {                                                             \
                save_error(&inv);                                                            \
                st = hyst_##P##_process(&S, x, y, n);                                        \
                save_snapshot(&S);                                                           \
            }                                                                                \
        }                                                                                    \
        store(opt("out", NULL), y, n * sizeof(T));                                           \
        printf("%d\n", st);                                                                  \
        return 0;                                                                            \
    }
REAL_VARIANT(double, f64)
REAL_VARIANT(float, f32)

static int run_code(void)
{
    size_t bytes, n, cap = (size_t)num("cap", "2048");
    hyst_code_word_t *x = load(opt("in", NULL), &bytes);
    hyst_code_word_t *xl = malloc(2u * cap * sizeof *xl);
    float *yl = malloc(2u * cap * sizeof *yl), *y;
    const hyst_poly_t f0 = poly();
    hyst_tcm_t S;
    int st;
    n = bytes / sizeof *x;
    y = malloc((n + 1u) * sizeof *y);
    if (xl == NULL || yl == NULL || y == NULL) {
        die("out of memory", "");
    }
    st = hyst_code_init(&S, &f0, (uint_least32_t)num("code_lo", NULL),
                        (uint_least32_t)num("code_hi", NULL), xl, yl, xl + cap, yl + cap, cap);
    if (st == HYST_OK) {
        st = hyst_code_set_deadband(&S, (uint_least32_t)num("deadband", "0"));
    }
    if (st == HYST_OK) {
        st = hyst_code_process(&S, x, y, n);
        save_snapshot(&S);
    }
    store(opt("out", NULL), y, n * sizeof *y);
    printf("%d\n", st);
    return 0;
}

int main(int argc, char **argv)
{
    const char *kind = argc > 1 ? argv[1] : "";
    g_argc = argc;
    g_argv = argv;
    if (strcmp(kind, "code") == 0) {
        return run_code();
    }
    if (strcmp(kind, "sim") != 0 && strcmp(kind, "inv") != 0 && strcmp(kind, "pi") != 0 &&
        strcmp(kind, "bench") != 0) {
        die("usage: hyst_ref sim|inv|code|pi|bench key=value...", "");
    }
    return strcmp(opt("type", "f64"), "f32") == 0 ? run_f32(kind) : run_f64(kind);
}
