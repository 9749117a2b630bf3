/* SPDX-License-Identifier: MIT */
/* Library-internal helpers and entry points shared between modules; not
 * installed. Every helper that more than one module needs lives here once. */
#ifndef HYST_UTIL_H
#define HYST_UTIL_H

#include <float.h>

#include "hyst/curve.h"
#include "hyst/tcm.h"

/* No product fused unless the source marks it (NUM_MULADD, src/num_f32.h):
 * the C99 pragma for compilers that honour it; GCC takes -ffp-contract=off
 * (CMakeLists.txt), and its -Wall warns of the pragma. docs/porting.md,
 * "Floating point". */
#if !defined(__GNUC__) || defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#endif

/* An f32 multiply-add the source marks (Horner's rule, the tables' cubic
 * pieces, the PI and creep sums): rounded once where HYST_F32_FMA (config.h:
 * the target's fused instruction, else the C library's fmaf), twice
 * elsewhere. Doubles are never fused: their results are the same on every
 * IEEE-754 target. */
#if HYST_F32_FMA && (defined(__GNUC__) || defined(__clang__))
#define HYST_F32_MULADD(a, b, c) __builtin_fmaf((a), (b), (c))
#elif HYST_F32_FMA
#include <math.h>
#define HYST_F32_MULADD(a, b, c) fmaf((a), (b), (c))
#else
#define HYST_F32_MULADD(a, b, c) ((a) * (b) + (c))
#endif

/* Rounding unit of hyst_wide_t. */
#ifdef HYST_NO_DOUBLE
#define HYST_WIDE_EPS ((hyst_wide_t)FLT_EPSILON)
#define HYST_WIDE_MIN ((hyst_wide_t)FLT_MIN)
#define HYST_WIDE_MAX ((hyst_wide_t)FLT_MAX)
#else
#define HYST_WIDE_EPS ((hyst_wide_t)DBL_EPSILON)
#define HYST_WIDE_MIN ((hyst_wide_t)DBL_MIN)
#define HYST_WIDE_MAX ((hyst_wide_t)DBL_MAX)
#endif

/* Square root in hyst_wide_t, for set-up and identification (the files
 * that use it include <math.h>); sqrtf where double must not be linked. */
#ifdef HYST_NO_DOUBLE
#define HYST_WIDE_SQRT(v) sqrtf(v)
#else
#define HYST_WIDE_SQRT(v) sqrt(v)
#endif

/* Finite test without libm: NaN fails v == v, +-Inf gives Inf - Inf = NaN. */
HYST_INLINE int hyst_wide_is_finite(hyst_wide_t v)
{
    const hyst_wide_t z = v - v;
    return z == z;
}

/* The same test of a float, in float: no conversion to hyst_wide_t. */
HYST_INLINE int hyst_float_is_finite(float v)
{
    const float z = v - v;
    return z == z;
}

HYST_INLINE hyst_wide_t hyst_wide_abs(hyst_wide_t v) { return v < 0 ? -v : v; }

/* A real number of a curve or instance of real variant `variant`, as
 * hyst_wide_t (exact: float and double both widen to double). */
HYST_INLINE hyst_wide_t hyst_num_get(const hyst_num_t *v, unsigned variant)
{
#if HYST_ENABLE_F64
    if (variant == (unsigned)HYST_VARIANT_F64) {
        return (hyst_wide_t)v->f64;
    }
#else
    (void)variant;
#endif
    return (hyst_wide_t)v->f32;
}

/* Entry i of a caller's read-only real array of variant `variant`, as
 * hyst_wide_t (exact). */
HYST_INLINE hyst_wide_t hyst_cptr_get(hyst_cptr_t a, size_t i, unsigned variant)
{
#if HYST_ENABLE_F64
    if (variant == (unsigned)HYST_VARIANT_F64) {
        return (hyst_wide_t)a.f64[i];
    }
#else
    (void)variant;
#endif
    return (hyst_wide_t)a.f32[i];
}

/* A caller's array of real variant `variant`, read-only. */
HYST_INLINE hyst_cptr_t hyst_cptr_of(hyst_ptr_t a, unsigned variant)
{
    hyst_cptr_t c;
    c.f32 = a.f32;
#if HYST_ENABLE_F64
    if (variant == (unsigned)HYST_VARIANT_F64) {
        c.f64 = a.f64;
    }
#else
    (void)variant;
#endif
    return c;
}

/* The rounding unit of the real variant `variant`'s type, and its
 * smallest positive number (subnormal: the absolute rounding near 0). */
HYST_INLINE hyst_wide_t hyst_real_eps(unsigned variant)
{
    return variant == (unsigned)HYST_VARIANT_F32 ? (hyst_wide_t)FLT_EPSILON : HYST_WIDE_EPS;
}
HYST_INLINE hyst_wide_t hyst_real_tiny(unsigned variant)
{
    return variant == (unsigned)HYST_VARIANT_F32 ? (hyst_wide_t)FLT_MIN * (hyst_wide_t)FLT_EPSILON
                                                 : HYST_WIDE_MIN * HYST_WIDE_EPS;
}

/* Stores w rounded to the variant's real type; returns 0 if the result is
 * not finite (overflow). */
HYST_INLINE int hyst_num_set(hyst_num_t *v, unsigned variant, hyst_wide_t w)
{
#if HYST_ENABLE_F64
    if (variant == (unsigned)HYST_VARIANT_F64) {
        v->f64 = (double)w;
        return hyst_wide_is_finite((hyst_wide_t)v->f64);
    }
#else
    (void)variant;
#endif
    v->f32 = (float)w;
    return hyst_float_is_finite(v->f32);
}

/* Concurrency (tcm.h): the compiler must not move memory accesses across
 * these points of the readers and of the request functions. One core: no
 * hardware fence is needed, the stepping context runs whole between two
 * instructions of the other one. Compilers without GNU inline assembly get
 * an out-of-line call, which they cannot move accesses across. */
#if defined(__GNUC__) || defined(__clang__)
#define HYST_BARRIER() __asm__ __volatile__("" ::: "memory")
#else
void hyst_barrier_(void);
#define HYST_BARRIER() hyst_barrier_()
#endif

/* Attempts of a reader before it gives up (snapshot: HYST_ERR_BUSY; an
 * accessor returns its last read). */
#define HYST_READ_ATTEMPTS 4u

/* S->degree and S->horner: what the fast path evaluates (src/tcm_engine.h,
 * emit()), set by the instance's kind at init (its attach()): 1..
 * HYST_MAX_DEGREE, a polynomial (S->coef); 0, a table of cubic pieces
 * (S->table) or, without one, nothing (every sample slow); or one of the
 * values below. They lie above every degree and above the engine's unrolled
 * Horner cases (1..8, src/num_ops.h, which a build with HYST_MAX_DEGREE < 8
 * still compiles); they are those of the layout before the kinds had
 * tables of their own, so that a snapshot's curve identity, which covers
 * S->degree, stays the same. */
#define HYST_HORNER_TOP_ (HYST_MAX_DEGREE > 8 ? (unsigned)HYST_MAX_DEGREE : 8u)

/* S->horner - S->degree of a kind whose branches take a bank of Horner's
 * cases of their own (tcm_engine.h, TCM_HORNER_BANK_): two banks of
 * HYST_EVERETT_MAX_DEGREE cases. */
#define HYST_HORNER_BANK1_ HYST_HORNER_TOP_
#define HYST_HORNER_BANK2_ (HYST_HORNER_BANK1_ + (unsigned)HYST_EVERETT_MAX_DEGREE)

/* S->horner while a request is pending. */
#define HYST_HORNER_REQUEST_ (HYST_HORNER_BANK2_ + (unsigned)HYST_EVERETT_MAX_DEGREE + 1u)

/* The kind evaluates every sample itself (its fast() and emit()). */
#define HYST_HORNER_OWN_ (HYST_HORNER_REQUEST_ + 1u)

/* A cubic piece of the branch (S->coef) cached for one interval
 * (S->cached_k, S->v_scale); the kind's fast() and emit() for the others. */
#define HYST_HORNER_PIECE_ (HYST_HORNER_OWN_ + 1u)

/* Posts a request from another context: increments *counter, then routes
 * the next per-sample evaluation to the engine's serve(). */
hyst_status_t hyst_post_request_(hyst_tcm_t *S, unsigned *counter);

/* The deadband of the integer-code variants (code, q31): the checks shared
 * by the immediate call and the request (an instance of `variant`, a width
 * within the code range), and the request. */
hyst_status_t hyst_codes_deadband_check_(const hyst_tcm_t *S, unsigned variant,
                                         uint_least32_t codes);
hyst_status_t hyst_codes_request_deadband_(hyst_tcm_t *S, unsigned variant, uint_least32_t codes);

/* 1 if [a, a + na) and [b, b + nb) (byte ranges) overlap. */
int hyst_ranges_overlap(const void *a, size_t na, const void *b, size_t nb);

/* Nonzero if a block call's output of n entries of ysize bytes at y would
 * overwrite inputs (n entries of xsize at x) not yet read. y == x is safe
 * when ysize <= xsize: y[i] is written after x[i] is read, before x[i + 1]. */
int hyst_block_overlap(const void *x, size_t xsize, const void *y, size_t ysize, size_t n);

/* Pointer, capacity, layout and overlap checks of every instance init:
 * four arrays of `capacity` entries of xsize and ysize bytes. */
hyst_status_t hyst_check_memory(const hyst_tcm_t *S, const void *xltp, const void *yltp,
                                const void *xrtp, const void *yrtp, size_t capacity,
                                size_t xsize, size_t ysize, unsigned long layout);

/* hyst_check_memory(), then the curve: prepared by this library, of the
 * variant `curve_variant` (HYST_ERR_LAYOUT otherwise). */
hyst_status_t hyst_check_init(const hyst_tcm_t *S, const hyst_curve_t *curve,
                              unsigned curve_variant, const void *xltp, const void *yltp,
                              const void *xrtp, const void *yrtp, size_t capacity, size_t xsize,
                              size_t ysize, unsigned long layout);

/* Prepares a polynomial curve of a real variant (the work of the
 * hyst_f32/f64_curve_from_poly constructors, written once). */
hyst_status_t hyst_curve_poly_(hyst_curve_t *curve, const hyst_poly_t *f0, unsigned variant,
                               unsigned long layout);

/* The checks hyst_curve_poly_() makes for the f64 variant on a target with
 * a double type, made in hyst_wide_t whether or not the f64 variant exists:
 * what the q31 model and compensator, whose numbers are their own, check f0
 * with (src/hyst_curve.c). f0's normalised coefficients into g (lowest
 * power first, hyst_unit_poly_()). */
hyst_status_t hyst_poly_check_(const hyst_poly_t *f0, hyst_wide_t *g, unsigned long layout);

/* The asymmetric curve of a branch function E in the variant's type
 * (src/hyst_everett.c; curve.h, hyst_*_curve_from_everett()). */
hyst_status_t hyst_curve_everett_(hyst_curve_t *curve, const hyst_everett_t *e, unsigned variant,
                                  unsigned long layout);

/* The structural check of a grid curve (HYST_CURVE_EVERETT_GRID, and its
 * compensator's, _INV), which
 * hyst_curve_check() refuses (the functions that take any prepared curve
 * have nothing for it yet) and the inits accept (hyst_check_init()):
 * HYST_OK or HYST_ERR_ARG. */
hyst_status_t hyst_everett_grid_check_(const hyst_curve_t *curve);

/* The same for a spline curve (HYST_CURVE_SPLINE, _INV, _INV_TABLE;
 * src/hyst_spline.c). */
hyst_status_t hyst_spline_check_(const hyst_curve_t *curve);

/* 1 if E increases in a and decreases in b on its whole triangle (the
 * check hyst_curve_everett_() makes, proved by Bernstein-Bezier
 * coefficients, subdivided where undecided). */
int hyst_everett_monotone_(const hyst_everett_t *e);

/* E(hi, lo), the major loop's height (w = 1, t = 0): the curve refuses an E
 * whose height is not above 0, and the fit reports one. */
hyst_wide_t hyst_everett_range_(const hyst_everett_t *e);

/* 2^-30: a tabulated asymmetric branch's least output step, as a fraction
 * of the desired outputs' range per interval (kind_everett_inv_table.h, blend_attach());
 * its table's builder checks that step and its index scale fit the type. */
#define HYST_BLEND_LEAST_STEP 9.313225746154785e-10

/* Most Bernstein-Bezier coefficients hyst_everett_bernstein_() gives. */
#define HYST_EVERETT_BERNSTEIN_MAX (HYST_EVERETT_MAX_DEGREE * (HYST_EVERETT_MAX_DEGREE + 1))

/* The Bernstein-Bezier coefficients on the whole triangle of span dE/da
 * and of -span dE/db, interleaved, into c: degree (degree + 1) numbers,
 * linear in E's coefficients. All >= 0 is sufficient for E monotone: the
 * check then accepts E without subdividing. Returns their number. */
size_t hyst_everett_bernstein_(const hyst_everett_t *e, hyst_wide_t *c);

/* Lawson-Hanson non-negative least squares in normal-equation form:
 * w >= 0 minimising w'H w - 2 w'c, H (n x n, symmetric, positive
 * semi-definite) read through gram(ctx, i, j). Columns of H that depend on
 * the passive ones are left at 0; at most `most` are passive at a time. */
typedef struct {
    size_t n;
    hyst_wide_t (*gram)(const void *ctx, size_t i, size_t j);
    const void *ctx;
    const hyst_wide_t *c;  /* right-hand side, n */
    hyst_wide_t *w;        /* n: the solution */
    hyst_wide_t *s;        /* n: the passive set's unconstrained solution */
    hyst_wide_t *g;        /* n: the gradient c - H w */
    hyst_wide_t *set;      /* n: flags */
    hyst_wide_t *b;        /* n: the passive set's right-hand side */
    hyst_wide_t *l;        /* most x most: Cholesky factor of H on the passive set */
    size_t most;           /* 1..n */
} hyst_nnls_t;

/* Offset of row i of an m-column packed upper-triangular factor (row i holds
 * columns i..m-1), as the fits of f0 and of E keep theirs. */
HYST_INLINE size_t hyst_packed_row_(size_t i, size_t m) { return i * m - i * (i - 1u) / 2u; }

/* Runs the problem f to its w (src/hyst_ident.c); returns 1 if it ends at the
 * optimum (no zero weight whose gradient exceeds tol), 0 if it ran out of
 * iterations (w is then feasible, not optimal). */
int hyst_nnls_(const hyst_nnls_t *f, hyst_wide_t tol);

/* The turning-point stack of an identification of E (src/hyst_ident.c): the
 * caller's tp_x (TP inputs) and tp_r (each TP's regressors, cols numbers),
 * A0 = (lo, regressors 1, 0, ...) at the bottom; r_prev holds the last
 * input's regressors. hyst_tp_start_ lays A0 and sets r_prev to its row. */
void hyst_tp_start_(hyst_wide_t *tp_x, hyst_wide_t *tp_r, size_t cols, hyst_wide_t *r_prev,
                    hyst_wide_t lo);
/* Madelung's rules for the input moving from x_prev to x (x != x_prev) on the
 * stack of height *n_tp: pushes x_prev where the input turns, wipes out the
 * TPs x passes and copies the current TP's regressors to r_prev. x's
 * regressors are then r_prev plus sign times E(a, b)'s: returns that sign
 * (1 rising from an LTP, -1 falling from a UTP); 0, nothing changed, if
 * x_prev would not fit in the capacity. */
int hyst_tp_step_(hyst_wide_t *tp_x, hyst_wide_t *tp_r, size_t *n_tp, size_t capacity,
                  size_t cols, hyst_wide_t *r_prev, hyst_wide_t x_prev, hyst_wide_t x,
                  hyst_wide_t *a, hyst_wide_t *b);

/* The fits along the record's branches with y_lo free and weights >= 0
 * (ident.h, hyst_branch_fit_t: the grid's masses, the spline's weights),
 * on that stack. A kind's regressors of E(a, b), scaled by `sign`, added to
 * r from its column 1 on. */
typedef void (*hyst_branch_terms_t)(const void *ctx, hyst_wide_t a, hyst_wide_t b,
                                    hyst_wide_t sign, hyst_wide_t *r);
struct hyst_branch_fit;
/* Lays out the caller's workspace (work_len checked against
 * HYST_BRANCH_FIT_WORK(cols, 2) by the caller) for the domain [lo, hi],
 * the record at lo. */
void hyst_branch_fit_start_(struct hyst_branch_fit *f, size_t cols, hyst_wide_t lo, hyst_wide_t hi,
                            hyst_wide_t *work, size_t work_len);
/* One sample, the statuses of hyst_everett_grid_fit_add() (f not NULL). */
hyst_status_t hyst_branch_fit_add_(struct hyst_branch_fit *f, hyst_wide_t x, hyst_wide_t y,
                                   hyst_branch_terms_t terms, const void *ctx);
/* The weights (cols - 1 of them, in the solver's workspace: *w) by NNLS
 * with y_lo eliminated, y_lo and the residual RMS: HYST_ERR_SINGULAR
 * (fewer than two samples), HYST_ERR_COEFF (a weight, y_lo or the
 * residual not finite), HYST_ERR_NOT_MONOTONE (every weight 0) or HYST_OK
 * (f not NULL). */
hyst_status_t hyst_branch_fit_solve_(const struct hyst_branch_fit *f, const hyst_wide_t **w,
                                     hyst_wide_t *y_lo, hyst_wide_t *rms);
/* 1 if the samples determine every weight (hyst_everett_grid_fit_determined()). */
int hyst_branch_fit_determined_(const struct hyst_branch_fit *f);

/* f0 (coefficients c, highest power first, degree n) on [lo, hi] as a
 * polynomial in u = (x - lo) / (hi - lo): g[k] multiplies u^k. */
void hyst_unit_poly_(hyst_wide_t *g, const hyst_wide_t *c, unsigned n, hyst_wide_t lo,
                     hyst_wide_t hi);
/* Bound on the error of those g, as an error of f0 on [lo, hi] (src/hyst_curve.c). */
hyst_wide_t hyst_unit_poly_error_(const hyst_wide_t *c, unsigned n, hyst_wide_t lo,
                                  hyst_wide_t hi);

/* What bounded memory keeps besides the TPs, as the instance holds it
 * (snapshots): the stack level of the shallowest live merge ((size_t)-1:
 * none), its error bound, and the deadband window (widest skipped reversal
 * and its bound). Numbers, not hyst_wide_t: a q31 output does not fit a
 * float's mantissa (HYST_NO_DOUBLE). */
typedef struct {
    size_t forgot_level;
    hyst_num_t forgot;
    hyst_num_t db_reach;
    hyst_num_t db_err;
} hyst_tcm_book_t;

/* Per-variant entry points the modules written once dispatch to (generated
 * by src/tcm_engine.h): reset, and resume after a snapshot restore
 * (re-derives the per-sample cache from the arrays and counts, with x, y as
 * the last valid sample, its status and the saved bookkeeping, each read
 * through the variant's member). */
void hyst_f32_reset_(hyst_tcm_t *S);
void hyst_f32_resume_(hyst_tcm_t *S, const hyst_num_t *x, const hyst_num_t *y, int status,
                      const hyst_tcm_book_t *book);
void hyst_code_reset_(hyst_tcm_t *S);
void hyst_code_resume_(hyst_tcm_t *S, const hyst_num_t *x, const hyst_num_t *y, int status,
                       const hyst_tcm_book_t *book);
void hyst_q31_reset_(hyst_tcm_t *S);
void hyst_q31_resume_(hyst_tcm_t *S, const hyst_num_t *x, const hyst_num_t *y, int status,
                      const hyst_tcm_book_t *book);
void hyst_q31_inv_reset_(hyst_tcm_t *S);
void hyst_q31_inv_resume_(hyst_tcm_t *S, const hyst_num_t *x, const hyst_num_t *y, int status,
                          const hyst_tcm_book_t *book);
#if HYST_ENABLE_F64
void hyst_f64_reset_(hyst_tcm_t *S);
void hyst_f64_resume_(hyst_tcm_t *S, const hyst_num_t *x, const hyst_num_t *y, int status,
                      const hyst_tcm_book_t *book);
#endif

/* fwd with its axes swapped: its domain the output range and its output
 * range the domain (where each kind's inverse starts). */
HYST_INLINE void hyst_curve_swap_axes_(hyst_curve_t *out, const hyst_curve_t *fwd)
{
    *out = *fwd;
    out->lo = fwd->y_lo;
    out->hi = fwd->y_hi;
    out->y_lo = fwd->lo;
    out->y_hi = fwd->hi;
}

/* The asymmetric kind's solved compensator of a checked forward curve, or
 * the forward curve of a compensator (src/hyst_everett_inv.c; the work of
 * hyst_curve_inverse() for that kind). */
hyst_status_t hyst_everett_inverse_(hyst_curve_t *inv, const hyst_curve_t *fwd);

/* The tabulated inverse of a polynomial curve of a real variant (the work
 * of the hyst_f32/f64_curve_inverse_table constructors, written once). */
hyst_status_t hyst_curve_inverse_table_(hyst_curve_t *inv, const hyst_curve_t *fwd,
                                        hyst_ptr_t table, size_t intervals, unsigned variant);
/* The same for the asymmetric kind (hyst_*_curve_everett_inverse_table). */
hyst_status_t hyst_curve_everett_inverse_table_(hyst_curve_t *inv, const hyst_curve_t *fwd,
                                                hyst_ptr_t table, size_t rows, size_t intervals,
                                                unsigned variant);
/* hyst_crc32 continued over a real number as the variant stores it (its
 * bit pattern, little-endian, as snapshots serialise it), or over a 32-bit
 * word (src/hyst_snapshot.c). */
unsigned long hyst_crc_real_(unsigned long crc, hyst_wide_t v, unsigned variant);
unsigned long hyst_crc_word_(unsigned long crc, unsigned long w);
/* The same over a number as stored (no conversion: integer work only); its
 * type is the variant's (HYST_VARIANT_CODE: an input code). */
unsigned long hyst_crc_num_(unsigned long crc, const hyst_num_t *v, unsigned variant);
/* The same over the first n numbers of a table, as the variant stores them. */
unsigned long hyst_crc_table_(unsigned long crc, hyst_cptr_t table, size_t n, unsigned variant);
/* The seal of a prepared polynomial curve (hyst_*_sealed_poly_t, curve.h):
 * the format, kind, variant, degree, the domain (codes for q31), the
 * outputs at its ends, unit, rounding and G's coefficients, as stored
 * (src/hyst_table_seal.c). */
unsigned long hyst_poly_seal_crc_(const hyst_curve_t *curve);
/* The seal of a tabulated compensator's prepared curve (inverse.h): its
 * numbers (the forward polynomial's included), intervals, exact count, the
 * error as a float, and every number of its table, as stored. */
unsigned long hyst_inverse_seal_crc_(const hyst_curve_t *inv, const hyst_num_t *max_err);
/* (hyst_wide_t)v without floating-point work where hyst_wide_t is an IEEE
 * double kept in software: a cast would link the soft double library. */
hyst_wide_t hyst_wide_of_float_(float v);
/* A tabulated inverse's measured error as tables keep it: rounded up to a
 * float, so a seal (hyst_table_seal_t) states it the same on every target;
 * and the seal's check of a table given ready-made (src/hyst_table_seal.c):
 * HYST_OK or HYST_ERR_CRC. */
hyst_wide_t hyst_table_err_(hyst_wide_t err);
/* An inverse curve's last rounding of the drive (src/hyst_curve_inv.c). */
hyst_wide_t hyst_drive_rounding_(const hyst_curve_t *inv);
hyst_status_t hyst_table_seal_check_(unsigned kind, unsigned variant, hyst_cptr_t table,
                                     size_t rows, size_t intervals, const hyst_table_seal_t *seal);
/* A row of a table given ready-made (its intervals' four numbers from
 * entry base, then the end): every number finite, each interval's start a
 * drive step between the one before and the end, or the mark of an
 * interval solved instead (-1 0 0 0). 1 if so. */
int hyst_table_shape_ok_(hyst_cptr_t table, size_t base, size_t intervals, unsigned variant);
/* The constructors of tables given ready-made (hyst_*_curve_inverse_table_const,
 * hyst_*_curve_everett_inverse_table_const), written once. */
/* A built symmetric table (HYST_CURVE_INV_TABLE, checked) measured as its
 * const init measures it: its scales the build's, its knots on the model,
 * every piece within HYST_INV_TABLE_TOL and the error it claims; else
 * HYST_ERR_CURVE. The seal's check: firmware checks only the seal. */
hyst_status_t hyst_inverse_table_measure_(const hyst_curve_t *inv);
hyst_status_t hyst_curve_inverse_table_const_(hyst_curve_t *inv, const hyst_curve_t *fwd,
                                              hyst_cptr_t table, size_t intervals,
                                              const hyst_table_seal_t *seal, unsigned variant);
hyst_status_t hyst_curve_everett_inverse_table_const_(hyst_curve_t *inv, const hyst_curve_t *fwd,
                                                      hyst_cptr_t table, size_t rows,
                                                      size_t intervals,
                                                      const hyst_table_seal_t *seal,
                                                      unsigned variant);
/* Stores entry i of an inverse table in the variant's type (+0 for 0: the
 * sign marks solved intervals); returns it rounded. */
hyst_wide_t hyst_table_put_(hyst_ptr_t table, size_t i, unsigned variant, hyst_wide_t w);

/* The q31 compensator's cubic on an interval's coefficients b (q31.h,
 * "Compensator"; drive units) at t, the offset from the interval's middle
 * in Q32: t / 2^32 in [-1/2, 1/2). b0 + t (b1 + t (b2 + t b3)), each step
 * the high word of a signed 64-bit product (one SMULL) and an add. Shared
 * by the per-sample path and the set-up, which measures the stored pieces
 * with it. */
#define HYST_Q31_HI_(a, t) ((hyst_q31_t)(((int_least64_t)(a) * (t)) >> 32))
HYST_INLINE hyst_q31_t hyst_q31_cubic_(const hyst_q31_t *b, hyst_q31_t t)
{
    return b[0] + HYST_Q31_HI_(b[1] + HYST_Q31_HI_(b[2] + HYST_Q31_HI_(b[3], t), t), t);
}

/* The offset from the middle (hyst_q31_cubic_()) of a position w in Q32
 * from the interval's start: w - 2^31 as a signed word. */
#define HYST_Q31_MID_(w) ((hyst_q31_t)((uint_least32_t)(w) ^ 0x80000000ul))

/* The q31 model's fixed-point G (src/hyst_q31.c): the coefficients of
 * G(v / c), v in Q30, from f0's normalised coefficients g (lowest power
 * first, degree n, range = G(1) > 0) into q->u.poly and its rounding bound
 * into q->rounding; 0 if a Horner partial sum could overflow. */
int hyst_q31_curve_(hyst_curve_t *q, const hyst_wide_t *g, unsigned n, hyst_wide_t range,
                    hyst_wide_t c);

/* The kinds of g evaluated out of line (src/curve_eval.h), per real type:
 * g at its argument, already scaled by the curve's unit (1 for the kinds
 * but the inverse table, whose argument is s = e N / (f0(hi) - f0(lo))). */
float hyst_f32_curve_g_other_(const hyst_curve_t *curve, float d);
#if HYST_ENABLE_F64
double hyst_f64_curve_g_other_(const hyst_curve_t *curve, double d);
#endif
/* G of a tabulated inverse at s (table intervals): its cubic, or in an
 * interval marked exact the bisection on f0's G (src/curve_eval.h;
 * src/kind_inv_table.h's g). */
float hyst_f32_inv_table_g_(const hyst_curve_t *curve, float s);
#if HYST_ENABLE_F64
double hyst_f64_inv_table_g_(const hyst_curve_t *curve, double s);
#endif
/* G of a spline at s (knot intervals from lo), or of its inverse at the
 * output step (src/curve_eval.h; src/kind_spline.h's g). */
float hyst_f32_spline_g_(const hyst_curve_t *curve, float s);
#if HYST_ENABLE_F64
double hyst_f64_spline_g_(const hyst_curve_t *curve, double s);
#endif
/* G of a spline's tabulated compensator at s (table intervals), its exact
 * intervals solved (src/curve_eval.h; src/kind_spline.h's g). */
float hyst_f32_spline_table_g_(const hyst_curve_t *curve, float s);
#if HYST_ENABLE_F64
double hyst_f64_spline_table_g_(const hyst_curve_t *curve, double s);
#endif

#endif /* HYST_UTIL_H */
