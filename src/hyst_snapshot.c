/* SPDX-License-Identifier: MIT */
/* Snapshot/restore of a TCM instance of any variant, and of a creep term's
 * lags, in a CHAR_BIT-independent octet format (layouts in
 * include/hyst/snapshot.h). */
#include "hyst/snapshot.h"
#include "hyst_util.h"

#include <float.h>
#include <stdint.h>
#include <string.h>

#if FLT_MANT_DIG != 24 || FLT_MAX_EXP != 128
#error "hyst snapshots assume IEEE-754 binary32 float"
#endif
#if HYST_ENABLE_F64 && (DBL_MANT_DIG != 53 || DBL_MAX_EXP != 1024)
#error "hyst snapshots assume IEEE-754 binary64 double"
#endif

#define MAGIC0 0x48u /* 'H' */
#define MAGIC1 0x59u /* 'Y' */
#define MAGIC2 0x53u /* 'S' */
#define MAGIC3 0x53u /* 'S' */
#define MAGIC3_CREEP 0x43u /* 'C': a creep term's snapshot */
#define MAGIC3_RATE 0x52u  /* 'R': a rate term's snapshot */
#define HEADER_OCTETS 32u
#define NO_LEVEL 0xFFFFFFFFul /* no live merge */
#define CRC_OCTETS 4u
#define MAX_COUNT 0x03FFFFFFul /* keeps L below 2^31 */
#define EVENTS_KNOWN (HYST_EVENT_NONFINITE | HYST_EVENT_CLAMPED | HYST_EVENT_FULL)

/* How the numbers of a variant travel: R octets per output, X per stored
 * input; the types of its inputs and outputs (NUM_Q31: a fixed-point
 * number, 4 octets of two's complement). */
typedef enum { NUM_CODE, NUM_F32, NUM_F64, NUM_Q31 } num_type_t;
typedef struct {
    unsigned r, x;
    num_type_t xt, yt;
} format_t;

static int format_of(unsigned variant, format_t *f)
{
    switch (variant) {
    case HYST_VARIANT_F32: f->r = 4u; f->x = 4u; f->xt = NUM_F32; f->yt = NUM_F32; return 1;
#if HYST_ENABLE_F64
    case HYST_VARIANT_F64: f->r = 8u; f->x = 8u; f->xt = NUM_F64; f->yt = NUM_F64; return 1;
#endif
    case HYST_VARIANT_CODE: f->r = 4u; f->x = 4u; f->xt = NUM_CODE; f->yt = NUM_F32; return 1;
    case HYST_VARIANT_Q31: f->r = 4u; f->x = 4u; f->xt = NUM_CODE; f->yt = NUM_Q31; return 1;
    case HYST_VARIANT_Q31_INV: f->r = 4u; f->x = 4u; f->xt = NUM_Q31; f->yt = NUM_Q31; return 1;
    default: return 0;
    }
}

unsigned long hyst_crc32(unsigned long crc, const unsigned char *buf, size_t n)
{
    size_t i;
    crc = ~crc & 0xFFFFFFFFul;
    for (i = 0u; i < n; ++i) {
        unsigned bit;
        crc ^= (unsigned long)(buf[i] & 0xFFu);
        for (bit = 0u; bit < 8u; ++bit) { /* bitwise: no 1 KB table in flash */
            crc = (crc >> 1) ^ (0xEDB88320ul & (0ul - (crc & 1ul)));
        }
    }
    return ~crc & 0xFFFFFFFFul;
}

static void put_u16(unsigned char *p, unsigned v)
{
    p[0] = (unsigned char)(v & 0xFFu);
    p[1] = (unsigned char)((v >> 8) & 0xFFu);
}

static void put_u32(unsigned char *p, unsigned long v)
{
    put_u16(p, (unsigned)(v & 0xFFFFul));
    put_u16(p + 2, (unsigned)((v >> 16) & 0xFFFFul));
}

static unsigned get_u16(const unsigned char *p)
{
    return (unsigned)(p[0] & 0xFFu) | ((unsigned)(p[1] & 0xFFu) << 8);
}

static unsigned long get_u32(const unsigned char *p)
{
    return (unsigned long)get_u16(p) | ((unsigned long)get_u16(p + 2) << 16);
}

/* A status as 16-bit two's complement, and back to int without
 * implementation-defined casts. */
static void put_status(unsigned char *p, int status) { put_u16(p, (unsigned)status & 0xFFFFu); }

static int get_status(const unsigned char *p)
{
    const unsigned v = get_u16(p);
    return v >= 0x8000u ? -(int)(0xFFFFu - v) - 1 : (int)v;
}

/* Reals travel as their IEEE-754 bits; the unions read the representation
 * (well-defined in C99 TC3) without memcpy or CHAR_BIT assumptions. */
typedef union {
    float r;
    uint32_t u;
} bits32_t;
#if HYST_ENABLE_F64
typedef union {
    double r;
    uint64_t u;
} bits64_t;
#endif

static void put_num(unsigned char *p, const hyst_num_t *v, num_type_t t)
{
#if HYST_ENABLE_F64
    if (t == NUM_F64) {
        bits64_t b;
        unsigned k;
        b.r = v->f64;
        for (k = 0u; k < 8u; ++k) {
            p[k] = (unsigned char)((b.u >> (8u * k)) & 0xFFu);
        }
        return;
    }
#endif
    if (t == NUM_F32) {
        bits32_t b;
        b.r = v->f32;
        put_u32(p, (unsigned long)b.u);
        return;
    }
    if (t == NUM_Q31) { /* two's complement without implementation-defined casts */
        put_u32(p, v->q31 < 0 ? 0xFFFFFFFFul - (unsigned long)(-(v->q31 + 1)) : (unsigned long)v->q31);
        return;
    }
    put_u32(p, (unsigned long)v->code);
}

/* The number at p; 0 if it cannot be one of type t (a code too wide). */
static int get_num(const unsigned char *p, hyst_num_t *v, num_type_t t)
{
#if HYST_ENABLE_F64
    if (t == NUM_F64) {
        bits64_t b;
        unsigned k;
        b.u = 0u;
        for (k = 0u; k < 8u; ++k) {
            b.u |= (uint64_t)(p[k] & 0xFFu) << (8u * k);
        }
        v->f64 = b.r;
        return 1;
    }
#endif
    if (t == NUM_F32) {
        bits32_t b;
        b.u = (uint32_t)get_u32(p);
        v->f32 = b.r;
        return 1;
    }
    if (t == NUM_Q31) {
        const unsigned long u = get_u32(p);
        v->q31 = u >= 0x80000000ul ? -(hyst_q31_t)(0xFFFFFFFFul - u) - 1 : (hyst_q31_t)u;
        return 1;
    }
    if (get_u32(p) > (unsigned long)HYST_CODE_MAX) {
        v->code = 0u; /* defined, though refused */
        return 0;
    }
    v->code = (hyst_code_word_t)get_u32(p);
    return 1;
}

/* A number as hyst_wide_t, for the checks of magnitudes; exact but for a
 * q31 number of more than 24 bits with HYST_NO_DOUBLE (orders: below()). */
static hyst_wide_t wide_of(const hyst_num_t *v, num_type_t t)
{
#if HYST_ENABLE_F64
    if (t == NUM_F64) {
        return (hyst_wide_t)v->f64;
    }
#endif
    return t == NUM_F32   ? (hyst_wide_t)v->f32
           : t == NUM_Q31 ? (hyst_wide_t)v->q31
                          : (hyst_wide_t)v->code;
}

/* a < b, exactly in the type (not as hyst_wide_t: distinct q31 numbers can
 * round to one float); NaN is below nothing and nothing is below it. */
static int below(const hyst_num_t *a, const hyst_num_t *b, num_type_t t)
{
#if HYST_ENABLE_F64
    if (t == NUM_F64) {
        return a->f64 < b->f64;
    }
#endif
    return t == NUM_F32 ? a->f32 < b->f32 : t == NUM_Q31 ? a->q31 < b->q31 : a->code < b->code;
}

/* Entry i of a caller array, as a number. */
static hyst_num_t elem(hyst_ptr_t a, size_t i, num_type_t t)
{
    hyst_num_t v;
#if HYST_ENABLE_F64
    if (t == NUM_F64) {
        v.f64 = a.f64[i];
        return v;
    }
#endif
    if (t == NUM_F32) {
        v.f32 = a.f32[i];
    } else if (t == NUM_Q31) {
        v.q31 = a.q31[i];
    } else {
        v.code = a.code[i];
    }
    return v;
}

static void set_elem(hyst_ptr_t a, size_t i, const hyst_num_t *v, num_type_t t)
{
#if HYST_ENABLE_F64
    if (t == NUM_F64) {
        a.f64[i] = v->f64;
        return;
    }
#endif
    if (t == NUM_F32) {
        a.f32[i] = v->f32;
    } else if (t == NUM_Q31) {
        a.q31[i] = v->q31;
    } else {
        a.code[i] = v->code;
    }
}

static unsigned long crc_num(unsigned long crc, const hyst_num_t *v, num_type_t t)
{
    unsigned char q[8];
    put_num(q, v, t);
    return hyst_crc32(crc, q, t == NUM_F64 ? 8u : 4u);
}

static unsigned long crc_word(unsigned long crc, unsigned long w)
{
    unsigned char q[4];
    put_u32(q, w);
    return hyst_crc32(crc, q, 4u);
}

unsigned long hyst_crc_real_(unsigned long crc, hyst_wide_t v, unsigned variant)
{
    hyst_num_t n;
    (void)hyst_num_set(&n, variant, v);
    return crc_num(crc, &n, variant == (unsigned)HYST_VARIANT_F64 ? NUM_F64 : NUM_F32);
}

unsigned long hyst_crc_word_(unsigned long crc, unsigned long w) { return crc_word(crc, w); }

/* The type a variant stores its numbers in. */
HYST_INLINE num_type_t num_type_of(unsigned variant)
{
    return variant == (unsigned)HYST_VARIANT_F64    ? NUM_F64
           : variant == (unsigned)HYST_VARIANT_Q31  ? NUM_Q31
           : variant == (unsigned)HYST_VARIANT_CODE ? NUM_CODE
                                                    : NUM_F32;
}

unsigned long hyst_crc_num_(unsigned long crc, const hyst_num_t *v, unsigned variant)
{
    return crc_num(crc, v, num_type_of(variant));
}

/* Entry i of a curve's table as the table stores it: t is the instance's
 * output type, the table's (no float widened to double). */
static hyst_num_t table_num(hyst_cptr_t table, size_t i, num_type_t t)
{
    hyst_num_t v;
    if (t == NUM_Q31) {
        v.q31 = table.q31[i];
#if HYST_ENABLE_F64
    } else if (t == NUM_F64) {
        v.f64 = table.f64[i];
#endif
    } else {
        v.f32 = table.f32[i];
    }
    return v;
}

/* The first n entries of a curve's table. */
HYST_INLINE unsigned long crc_table(unsigned long crc, hyst_cptr_t table, size_t n, num_type_t t)
{
    size_t i;
    for (i = 0u; i < n; ++i) {
        const hyst_num_t v = table_num(table, i, t);
        crc = crc_num(crc, &v, t);
    }
    return crc;
}

unsigned long hyst_crc_table_(unsigned long crc, hyst_cptr_t table, size_t n, unsigned variant)
{
    return crc_table(crc, table, n, num_type_of(variant));
}

/* The identity of a curve whose G is a table of cubic pieces (a tabulated
 * inverse, a spline or its compensators): the forward polynomial's G (an
 * inverse table's exact intervals), the span, the pieces; for a spline's
 * tabulated compensator then its spline's (the exact intervals'), the same
 * way. */
static unsigned long pieces_id(unsigned long crc, const hyst_curve_t *c, const format_t *f)
{
    const int spline = c->kind == (unsigned)HYST_CURVE_SPLINE ||
                       c->kind == (unsigned)HYST_CURVE_SPLINE_INV;
    unsigned tables = c->kind == (unsigned)HYST_CURVE_SPLINE_INV_TABLE ? 2u : 1u;
    size_t n = spline ? c->u.spline.intervals : c->u.inv_table.intervals;
    hyst_cptr_t table = spline ? c->u.spline.table : c->u.inv_table.table;
    const hyst_num_t *span = spline ? &c->u.spline.span : &c->u.inv_table.span;
    if (c->kind == (unsigned)HYST_CURVE_INV_TABLE) {
        unsigned k;
        crc = crc_word(crc, c->u.inv_table.fwd.degree);
        for (k = 0u; k < c->u.inv_table.fwd.degree && k < HYST_MAX_DEGREE; ++k) {
            crc = crc_num(crc, &c->u.inv_table.fwd.a[k], f->yt);
        }
    }
    for (; tables > 0u; --tables) {
        crc = crc_num(crc, span, f->yt);
        crc = crc_word(crc, (unsigned long)n);
        crc = crc_table(crc, table, HYST_INV_TABLE_LEN(n), f->yt);
        span = &c->u.inv_table.fwd_spline.span;
        n = c->u.inv_table.fwd_spline.intervals;
        table = c->u.inv_table.fwd_spline.table;
    }
    if (f->yt == NUM_Q31) { /* the drive's format: its fraction bits and first code */
        crc = crc_word(crc, (unsigned long)c->u.inv_table.drive_bits);
        crc = crc_word(crc, (unsigned long)c->u.inv_table.drive_code_lo);
    }
    return crc;
}

/* Curve identity: everything that shapes the branches of this instance,
 * each kind's numbers here (not at attach): only a firmware that saves or
 * restores snapshots computes it. */
static unsigned long curve_id(const hyst_tcm_t *S, const format_t *f)
{
    const hyst_curve_t *c = S->curve;
    unsigned long crc;
    unsigned k;
    crc = crc_word(0ul, S->variant);
    crc = crc_word(crc, c != NULL ? c->kind : (unsigned long)HYST_CURVE_POLY);
    crc = crc_word(crc, S->degree);
    crc = crc_num(crc, &S->lo, f->xt);
    crc = crc_num(crc, &S->hi, f->xt);
    crc = crc_num(crc, &S->y_lo, f->yt);
    crc = crc_num(crc, &S->y_hi, f->yt);
    crc = crc_num(crc, &S->unit, f->yt);
    if (c != NULL && (c->kind == (unsigned)HYST_CURVE_EVERETT ||
                      c->kind == (unsigned)HYST_CURVE_EVERETT_INV ||
                      c->kind == (unsigned)HYST_CURVE_EVERETT_INV_TABLE)) {
        /* the branch's coefficients are not the curve's: its tables (and a
         * blended branch's table size) */
        for (k = 0u; k < (unsigned)HYST_EVERETT_TERMS; ++k) {
            crc = crc_num(crc, &c->u.everett.rise[k], f->yt);
            crc = crc_num(crc, &c->u.everett.fall[k], f->yt);
        }
        if (c->kind == (unsigned)HYST_CURVE_EVERETT_INV_TABLE) {
            crc = crc_word(crc, (unsigned long)c->u.everett.rows);
            crc = crc_word(crc, (unsigned long)c->u.everett.intervals);
        }
        crc = crc_num(crc, &c->u.everett.span, f->yt);
        return crc_num(crc, &c->u.everett.tol, f->yt);
    }
    if (c != NULL && (c->kind == (unsigned)HYST_CURVE_EVERETT_GRID ||
                      c->kind == (unsigned)HYST_CURVE_EVERETT_GRID_INV)) {
        /* no coefficients: the caller's table, the knots to the cells' numbers */
        crc = crc_word(crc, (unsigned long)c->u.everett_grid.intervals);
        return crc_table(crc, c->u.everett_grid.table,
                         HYST_EVERETT_GRID_TABLE_LEN((size_t)c->u.everett_grid.intervals), f->yt);
    }
    for (k = 0u; k < S->degree && k < HYST_MAX_DEGREE; ++k) {
        /* a polynomial's coefficients highest power first, as the curve
         * holds them (the instance keeps them lowest first); other kinds'
         * numbers as stored */
        const unsigned at = S->degree <= HYST_MAX_DEGREE ? S->degree - 1u - k : k;
        crc = crc_num(crc, &S->coef[at], f->yt);
    }
    if (c == NULL) {
        return crc;
    }
    if (c->kind == (unsigned)HYST_CURVE_POLY_INV) {
        crc = crc_word(crc, c->u.poly_inv.fwd.degree);
        for (k = 0u; k < c->u.poly_inv.fwd.degree && k < HYST_MAX_DEGREE; ++k) {
            crc = crc_num(crc, &c->u.poly_inv.fwd.a[k], f->yt);
        }
        crc = crc_num(crc, &c->u.poly_inv.span, f->yt);
        crc = crc_num(crc, &c->u.poly_inv.knot_scale, f->yt);
        for (k = 0u; k <= HYST_INV_KNOTS; ++k) {
            crc = crc_num(crc, &c->u.poly_inv.knot_u[k], f->yt);
        }
    } else if (c->kind == (unsigned)HYST_CURVE_INV_TABLE || c->kind == (unsigned)HYST_CURVE_SPLINE ||
               c->kind == (unsigned)HYST_CURVE_SPLINE_INV ||
               c->kind == (unsigned)HYST_CURVE_SPLINE_INV_TABLE) {
        crc = pieces_id(crc, c, f);
    } else if (c->kind == (unsigned)HYST_CURVE_PWL || c->kind == (unsigned)HYST_CURVE_PWL_INV) {
        size_t i;
        crc = crc_word(crc, (unsigned long)c->u.pwl.n);
        for (i = 0u; i < c->u.pwl.n; ++i) { /* interior points shape the curve too */
            const hyst_num_t px = table_num(c->u.pwl.x, i, f->yt);
            const hyst_num_t py = table_num(c->u.pwl.y, i, f->yt);
            crc = crc_num(crc, &px, f->yt);
            crc = crc_num(crc, &py, f->yt);
        }
    }
    return crc;
}

/* L in unsigned long (size_t may be 16 bits); counts <= MAX_COUNT. */
static unsigned long length_of(const format_t *f, unsigned long n_ltp, unsigned long n_rtp)
{
    return HEADER_OCTETS + (unsigned long)(f->x + f->r) * (1ul + n_ltp + n_rtp) + 4ul +
           2ul * f->r + f->x + CRC_OCTETS;
}

/* A function, not an inline test: with a 16-bit size_t the comparison is
 * always true, which -Wtype-limits would flag on AVR. */
static int count_fits(unsigned long n) { return n <= MAX_COUNT; }

/* Octets of a snapshot with these counts, 0 if not representable. */
static size_t size_for(const format_t *f, size_t nl, size_t nr)
{
    unsigned long need;
    if (!count_fits((unsigned long)nl) || !count_fits((unsigned long)nr)) {
        return 0u;
    }
    need = length_of(f, (unsigned long)nl, (unsigned long)nr);
    return need == (unsigned long)(size_t)need ? (size_t)need : 0u;
}

size_t hyst_snapshot_size(const hyst_tcm_t *S)
{
    format_t f;
    if (S == NULL || S->layout != HYST_LAYOUT || !format_of(S->variant, &f)) {
        return 0u;
    }
    return size_for(&f, S->n_ltp, S->n_rtp);
}

/* Bit-identical numbers. */
static int same_num(const hyst_num_t *a, const hyst_num_t *b, num_type_t t)
{
    unsigned char p[8] = {0}, q[8] = {0};
    unsigned k, n = t == NUM_F64 ? 8u : 4u;
    put_num(p, a, t);
    put_num(q, b, t);
    for (k = 0u; k < n; ++k) {
        if (p[k] != q[k]) {
            return 0;
        }
    }
    return 1;
}

/* The part of a snapshot that only slow samples change (tcm.h: they
 * change seq): everything but the last sample, read with counts nl, nr
 * into buf, with the curve's identity id. Returns the offset of the CRC. */
static size_t put_body(const hyst_tcm_t *S, const format_t *f, unsigned char *buf,
                       size_t need, size_t nl, size_t nr, unsigned long id)
{
    size_t i, at;
    hyst_num_t v;
    buf[0] = MAGIC0;
    buf[1] = MAGIC1;
    buf[2] = MAGIC2;
    buf[3] = MAGIC3;
    put_u16(buf + 4, HYST_SNAPSHOT_VERSION);
    buf[6] = (unsigned char)f->r;
    buf[7] = (unsigned char)S->variant;
    put_u32(buf + 8, (unsigned long)need);
    put_u32(buf + 12, id);
    put_u32(buf + 16, (unsigned long)nl);
    put_u32(buf + 20, (unsigned long)nr);
    put_u32(buf + 24, (unsigned long)S->events);
    put_status(buf + 28, S->status);
    put_u16(buf + 30, 0u);
    at = HEADER_OCTETS + f->x + f->r;
    for (i = 0u; i < nl + nr; ++i, at += f->x + f->r) {
        const int left = i < nl;
        const size_t k = left ? i : i - nl;
        v = elem(left ? S->xltp : S->xrtp, k, f->xt);
        put_num(buf + at, &v, f->xt);
        v = elem(left ? S->yltp : S->yrtp, k, f->yt);
        put_num(buf + at + f->x, &v, f->yt);
    }
    put_u32(buf + at, S->forgot_level == (size_t)-1 ? NO_LEVEL : (unsigned long)S->forgot_level);
    put_num(buf + at + 4u, &S->forgot, f->yt);
    put_num(buf + at + 4u + f->r, &S->db_reach, f->xt);
    put_num(buf + at + 4u + f->r + f->x, &S->db_err, f->yt);
    return at + 4u + f->r + f->r + f->x;
}

/* Consistency with a stepping context that may preempt this one (tcm.h,
 * "Concurrency"): the body is copied between two reads of seq; the last
 * sample, which fast-path samples change without seq, is read after it as
 * one pair (the engine's view: x moves strictly along a branch). Equal seq
 * around both proves that the octets describe one state. Bounded attempts,
 * then HYST_ERR_BUSY with the magic cleared: never a torn snapshot. */
hyst_status_t hyst_snapshot_save(const hyst_tcm_t *S, unsigned char *buf, size_t size,
                                 size_t *len)
{
    const volatile hyst_tcm_t *V = S;
    format_t f;
    unsigned long id;
    unsigned attempt;
    if (S == NULL || buf == NULL) {
        return HYST_ERR_NULL;
    }
    if (S->layout != HYST_LAYOUT || !format_of(S->variant, &f)) {
        return HYST_ERR_ARG;
    }
    /* before the attempts: the identity is the curve's, which no sample
     * changes, and a grid's or a table's is long to hash */
    id = curve_id(S, &f);
    for (attempt = 0u; attempt < HYST_READ_ATTEMPTS; ++attempt) {
        const unsigned long seq = V->seq;
        size_t nl, nr, need, at;
        hyst_num_t x, y, x_again;
        HYST_BARRIER();
        /* The counts are read once: the size and the copy agree, whatever
         * the step does meanwhile. */
        nl = V->n_ltp;
        nr = V->n_rtp;
        need = size_for(&f, nl, nr);
        if (need == 0u || size < need) {
            HYST_BARRIER();
            /* A volatile re-read: the stepping context may have changed it (cppcheck
             * takes it for the value read above). */
            /* cppcheck-suppress knownConditionTrueFalse */
            if (V->seq != seq) {
                continue; /* counts of two states: read them again */
            }
            if (attempt > 0u) {
                buf[0] = 0u; /* an earlier attempt's body: not a snapshot */
            }
            return HYST_ERR_NOSPACE;
        }
        at = put_body(S, &f, buf, need, nl, nr, id);
        HYST_BARRIER();
        x = V->window[V->moving_end];
        y = V->y_prev;
        HYST_BARRIER();
        x_again = V->window[V->moving_end];
        /* volatile re-reads, as above */
        /* cppcheck-suppress knownConditionTrueFalse */
        if (V->seq != seq || !same_num(&x, &x_again, f.xt)) {
            continue;
        }
        put_num(buf + HEADER_OCTETS, &x, f.xt);
        put_num(buf + HEADER_OCTETS + f.x, &y, f.yt);
        put_u32(buf + at, hyst_crc32(0ul, buf, at));
        if (len != NULL) {
            *len = need;
        }
        return HYST_OK;
    }
    buf[0] = 0u;
    return HYST_ERR_BUSY;
}

/* Reads entry `at` of the body as (x, y) into wide values; 0 if a number is
 * not of its type, not finite, or outside the instance's input domain or
 * its output band [y_lo - h, y_hi + h] (h = y_hi - y_lo: the model's
 * outputs lie in [y_lo, y_hi] up to rounding; a forged value does not). */
static int read_point(const hyst_tcm_t *S, const format_t *f, const unsigned char *p,
                      hyst_num_t *x, hyst_num_t *y)
{
    const hyst_wide_t ylo = wide_of(&S->y_lo, f->yt), yhi = wide_of(&S->y_hi, f->yt);
    hyst_wide_t wx, wy;
    if (!get_num(p, x, f->xt) || !get_num(p + f->x, y, f->yt)) {
        return 0;
    }
    wx = wide_of(x, f->xt);
    wy = wide_of(y, f->yt);
    return hyst_wide_is_finite(wx) && hyst_wide_is_finite(wy) && !below(x, &S->lo, f->xt) &&
           !below(&S->hi, x, f->xt) && wy >= ylo - (yhi - ylo) && wy <= yhi + (yhi - ylo);
}

/* Is the saved state one the engine can reach? Turning points alternate and
 * nest strictly: LTP x ascending, RTP x descending, every LTP below every RTP,
 * all inside [lo, hi]; A0 is (lo, f0(lo)); the last input lies on the current
 * branch, between its TP and the TP below. Reads only. */
static int state_is_valid(const hyst_tcm_t *S, const format_t *f, const unsigned char *body,
                          size_t nl, size_t nr)
{
    const unsigned char *tp = body + f->x + f->r;
    hyst_num_t x, y, top_ltp = S->lo, top_rtp = S->hi;
    size_t i;
    if (!read_point(S, f, tp, &x, &y) || !same_num(&x, &S->lo, f->xt) ||
        !same_num(&y, &S->y_lo, f->yt)) {
        return 0;
    }
    for (i = 1u; i < nl + nr; ++i) {
        if (!read_point(S, f, tp + (f->x + f->r) * i, &x, &y)) {
            return 0;
        }
        if (i < nl) { /* LTPs ascend strictly */
            if (!below(&top_ltp, &x, f->xt)) {
                return 0;
            }
            top_ltp = x;
        } else { /* RTPs descend strictly, above every LTP */
            if (!below(&top_ltp, &x, f->xt) || (i > nl && !below(&x, &top_rtp, f->xt))) {
                return 0;
            }
            top_rtp = x;
        }
    }
    if (!read_point(S, f, body, &x, &y)) {
        return 0;
    }
    if (nl > nr) { /* rising from LTP nl-1, below RTP nr-1 (or hi) */
        return !below(&x, &top_ltp, f->xt) && (nr > 0u ? below(&x, &top_rtp, f->xt) : 1);
    }
    return below(&top_ltp, &x, f->xt) && !below(&top_rtp, &x, f->xt); /* falling from RTP nr-1 */
}

/* The bounded-memory bookkeeping: a merge level within the stack (or none),
 * finite non-negative bounds no larger than the stack can owe (one loop
 * height per stored pair, one for the deadband) and a deadband reach inside
 * the domain. Reads only. */
static int book_is_valid(const hyst_tcm_t *S, const format_t *f, const unsigned char *p,
                         size_t depth, hyst_tcm_book_t *book)
{
    const unsigned long level = get_u32(p);
    const hyst_wide_t height =
        wide_of(&S->y_hi, f->yt) - wide_of(&S->y_lo, f->yt);
    const hyst_wide_t width = wide_of(&S->hi, f->xt) - wide_of(&S->lo, f->xt);
    hyst_wide_t forgot, db_reach, db_err;
    int ok = 1;
    book->forgot_level = level == NO_LEVEL ? (size_t)-1 : (size_t)level;
    ok &= get_num(p + 4u, &book->forgot, f->yt);
    ok &= get_num(p + 4u + f->r, &book->db_reach, f->xt);
    ok &= get_num(p + 4u + f->r + f->x, &book->db_err, f->yt);
    forgot = wide_of(&book->forgot, f->yt);
    db_reach = wide_of(&book->db_reach, f->xt);
    db_err = wide_of(&book->db_err, f->yt);
    /* a bound with no merge alive: the output still held after the input
     * left the merged loops (tcm_engine.h, TCM_SETTLING) */
    return ok && (level == NO_LEVEL || level <= (unsigned long)depth) &&
           hyst_wide_is_finite(forgot) && forgot >= 0 &&
           forgot <= height * (hyst_wide_t)(depth + 1u) && hyst_wide_is_finite(db_reach) &&
           db_reach >= 0 && db_reach <= width && hyst_wide_is_finite(db_err) && db_err >= 0 &&
           db_err <= height;
}

/* A status a sample can leave. */
static int status_is_known(int status)
{
    return status == HYST_OK || status == HYST_WARN_CLAMPED || status == HYST_WARN_FULL ||
           status == HYST_ERR_NONFINITE;
}

hyst_status_t hyst_snapshot_restore(hyst_tcm_t *S, const unsigned char *buf, size_t len)
{
    unsigned long length, nl32, nr32, events;
    hyst_tcm_book_t book;
    format_t f;
    size_t nl, nr, i, at;
    int status;
    hyst_num_t x, y;

    if (S == NULL || buf == NULL) {
        return HYST_ERR_NULL;
    }
    if (S->layout != HYST_LAYOUT || !format_of(S->variant, &f)) {
        return HYST_ERR_ARG;
    }
    if (len < HEADER_OCTETS + CRC_OCTETS || buf[0] != MAGIC0 || buf[1] != MAGIC1 ||
        buf[2] != MAGIC2 || buf[3] != MAGIC3) {
        return HYST_ERR_FORMAT;
    }
    if (get_u16(buf + 4) != HYST_SNAPSHOT_VERSION || buf[6] != f.r || buf[7] != S->variant) {
        return HYST_ERR_VERSION;
    }
    length = get_u32(buf + 8);
    nl32 = get_u32(buf + 16);
    nr32 = get_u32(buf + 20);
    if (length > len || !count_fits(nl32) || !count_fits(nr32) ||
        length != length_of(&f, nl32, nr32)) {
        return HYST_ERR_FORMAT; /* truncated, or length and counts disagree */
    }
    at = (size_t)length - CRC_OCTETS;
    if (hyst_crc32(0ul, buf, at) != get_u32(buf + at)) {
        return HYST_ERR_CRC;
    }
    if (get_u32(buf + 12) != curve_id(S, &f)) {
        return HYST_ERR_CURVE;
    }
    nl = (size_t)nl32;
    nr = (size_t)nr32;
    if (nl > S->capacity || nr > S->capacity) {
        return HYST_ERR_CAPACITY;
    }
    events = get_u32(buf + 24);
    status = get_status(buf + 28);
    if (nl < 1u || (nr != nl && nr + 1u != nl) || (events & ~(unsigned long)EVENTS_KNOWN) != 0u ||
        !status_is_known(status) || get_u16(buf + 30) != 0u ||
        !state_is_valid(S, &f, buf + HEADER_OCTETS, nl, nr)) {
        return HYST_ERR_FORMAT;
    }
    at = HEADER_OCTETS + (f.x + f.r) * (1u + nl + nr);
    if (!book_is_valid(S, &f, buf + at, nl + nr, &book)) {
        return HYST_ERR_FORMAT;
    }
    /* Everything checked: only now write the instance. */
    at = HEADER_OCTETS + f.x + f.r;
    for (i = 0u; i < nl + nr; ++i, at += f.x + f.r) {
        const int left = i < nl;
        const size_t k = left ? i : i - nl;
        (void)get_num(buf + at, &x, f.xt);
        (void)get_num(buf + at + f.x, &y, f.yt);
        set_elem(left ? S->xltp : S->xrtp, k, &x, f.xt);
        set_elem(left ? S->yltp : S->yrtp, k, &y, f.yt);
    }
    S->n_ltp = nl;
    S->n_rtp = nr;
    (void)get_num(buf + HEADER_OCTETS, &x, f.xt);
    (void)get_num(buf + HEADER_OCTETS + f.x, &y, f.yt);
    switch (S->variant) {
    case HYST_VARIANT_F32: hyst_f32_resume_(S, &x, &y, status, &book); break;
#if HYST_ENABLE_F64
    case HYST_VARIANT_F64: hyst_f64_resume_(S, &x, &y, status, &book); break;
#endif
    case HYST_VARIANT_Q31: hyst_q31_resume_(S, &x, &y, status, &book); break;
    case HYST_VARIANT_Q31_INV: hyst_q31_inv_resume_(S, &x, &y, status, &book); break;
    default: hyst_code_resume_(S, &x, &y, status, &book); break;
    }
    S->events = (unsigned)events;
    return HYST_OK;
}

/* ---- Snapshots of a term (creep, rate): one head, one tail ---- */

/* Octets 0..15 of a term's snapshot: magic ending in magic3, version, the
 * octets per real, the variant, the length and the term's id. */
static void put_term_head(unsigned char *buf, unsigned magic3, unsigned version, unsigned r,
                          unsigned variant, size_t need, unsigned long id)
{
    buf[0] = MAGIC0;
    buf[1] = MAGIC1;
    buf[2] = MAGIC2;
    buf[3] = (unsigned char)magic3;
    put_u16(buf + 4, version);
    buf[6] = (unsigned char)r;
    buf[7] = (unsigned char)variant;
    put_u32(buf + 8, (unsigned long)need);
    put_u32(buf + 12, id);
}

/* The CRC of a term's snapshot of `need` octets, and its length. */
static void put_term_crc(unsigned char *buf, size_t need, size_t *len)
{
    put_u32(buf + need - CRC_OCTETS, hyst_crc32(0ul, buf, need - CRC_OCTETS));
    if (len != NULL) {
        *len = need;
    }
}

/* ---- Creep snapshots (snapshot.h, "Creep snapshots") ---- */

#define CREEP_HEADER_OCTETS 28u

/* The octets per real and the number type of an initialised creep
 * instance's variant; 0 if it is none. */
static unsigned creep_format(const hyst_creep_t *C, num_type_t *t)
{
    if (C->n < 1u || C->n > HYST_CREEP_MAX_TERMS) {
        return 0u;
    }
    switch (C->variant) {
    case HYST_VARIANT_F32: *t = NUM_F32; return 4u;
#if HYST_ENABLE_F64
    case HYST_VARIANT_F64: *t = NUM_F64; return 8u;
#endif
    default: return 0u;
    }
}

/* What a snapshot restores into only the same creep term: the variant, the
 * lags' count, rates and weights. */
static unsigned long creep_id(const hyst_creep_t *C, num_type_t t)
{
    unsigned long crc = crc_word(0ul, (unsigned long)C->variant);
    size_t k;
    crc = crc_word(crc, (unsigned long)C->n);
    for (k = 0u; k < C->n; ++k) {
        crc = crc_num(crc, &C->alpha[k], t);
        crc = crc_num(crc, &C->weight[k], t);
    }
    return crc;
}

/* L of a creep snapshot: n states of r octets. */
static size_t creep_length(unsigned r, size_t n) { return CREEP_HEADER_OCTETS + r * n + CRC_OCTETS; }

size_t hyst_creep_snapshot_size(const hyst_creep_t *C)
{
    num_type_t t;
    const unsigned r = C != NULL ? creep_format(C, &t) : 0u;
    return r != 0u ? creep_length(r, C->n) : 0u;
}

hyst_status_t hyst_creep_snapshot_save(const hyst_creep_t *C, unsigned char *buf, size_t size,
                                       size_t *len)
{
    const volatile hyst_creep_t *V = C;
    num_type_t t;
    unsigned r, attempt;
    size_t need, k;
    if (C == NULL || buf == NULL) {
        return HYST_ERR_NULL;
    }
    r = creep_format(C, &t);
    if (r == 0u) {
        return HYST_ERR_ARG;
    }
    need = creep_length(r, C->n); /* n, variant: set by init only */
    if (size < need) {
        return HYST_ERR_NOSPACE;
    }
    for (attempt = 0u; attempt < HYST_READ_ATTEMPTS; ++attempt) {
        const unsigned long seq = V->seq;
        HYST_BARRIER();
        put_term_head(buf, MAGIC3_CREEP, HYST_CREEP_SNAPSHOT_VERSION, r, C->variant, need,
                      creep_id(C, t));
        put_u32(buf + 16, (unsigned long)C->n);
        put_u32(buf + 20, (unsigned long)C->events);
        put_status(buf + 24, C->status);
        put_u16(buf + 26, 0u);
        for (k = 0u; k < C->n; ++k) {
            put_num(buf + CREEP_HEADER_OCTETS + r * k, &C->state[k], t);
        }
        HYST_BARRIER();
        /* a volatile re-read: a step may have run meanwhile */
        /* cppcheck-suppress knownConditionTrueFalse */
        if (V->seq != seq) {
            continue;
        }
        put_term_crc(buf, need, len);
        return HYST_OK;
    }
    buf[0] = 0u;
    return HYST_ERR_BUSY;
}

hyst_status_t hyst_creep_snapshot_restore(hyst_creep_t *C, const unsigned char *buf, size_t len)
{
    hyst_num_t state[HYST_CREEP_MAX_TERMS];
    num_type_t t;
    unsigned long length, events;
    unsigned r;
    int status;
    size_t k, n;
    if (C == NULL || buf == NULL) {
        return HYST_ERR_NULL;
    }
    r = creep_format(C, &t);
    if (r == 0u) {
        return HYST_ERR_ARG;
    }
    memset(state, 0, sizeof state); /* a float leaves the rest of its union as init does: 0 */
    if (len < CREEP_HEADER_OCTETS + CRC_OCTETS || buf[0] != MAGIC0 || buf[1] != MAGIC1 ||
        buf[2] != MAGIC2 || buf[3] != MAGIC3_CREEP) {
        return HYST_ERR_FORMAT;
    }
    if (get_u16(buf + 4) != HYST_CREEP_SNAPSHOT_VERSION || buf[6] != r || buf[7] != C->variant) {
        return HYST_ERR_VERSION;
    }
    length = get_u32(buf + 8);
    n = (size_t)get_u32(buf + 16);
    if (get_u32(buf + 16) < 1ul || get_u32(buf + 16) > (unsigned long)HYST_CREEP_MAX_TERMS ||
        length != creep_length(r, n) || length > len) {
        return HYST_ERR_FORMAT; /* truncated, or length and count disagree */
    }
    if (hyst_crc32(0ul, buf, (size_t)length - CRC_OCTETS) !=
        get_u32(buf + (size_t)length - CRC_OCTETS)) {
        return HYST_ERR_CRC;
    }
    if (get_u32(buf + 12) != creep_id(C, t)) {
        return HYST_ERR_CURVE;
    }
    events = get_u32(buf + 20);
    status = get_status(buf + 24);
    if (n != C->n || (events & ~(unsigned long)HYST_EVENT_NONFINITE) != 0u ||
        (status != HYST_OK && status != HYST_ERR_NONFINITE && status != HYST_ERR_DOMAIN) ||
        get_u16(buf + 26) != 0u) { /* a step's statuses: a drive beyond x_limit is DOMAIN */
        return HYST_ERR_FORMAT;
    }
    for (k = 0u; k < n; ++k) {
        (void)get_num(buf + CREEP_HEADER_OCTETS + r * k, &state[k], t);
        if (!hyst_wide_is_finite(wide_of(&state[k], t))) {
            return HYST_ERR_FORMAT;
        }
    }
    /* Everything checked: only now write the instance. */
    ++C->seq;
    for (k = 0u; k < n; ++k) {
        C->state[k] = state[k];
    }
    C->status = status;
    C->events = (unsigned)events;
    return HYST_OK;
}

/* ---- Rate snapshots (snapshot.h, "Rate snapshots") ---- */

#define RATE_HEADER_OCTETS 24u

/* The octets per real and the number type of an initialised rate
 * instance's variant; 0 if it is none. */
static unsigned rate_format(const hyst_rate_t *R, num_type_t *t)
{
    switch (R->variant) {
    case HYST_VARIANT_F32: *t = NUM_F32; return 4u;
#if HYST_ENABLE_F64
    case HYST_VARIANT_F64: *t = NUM_F64; return 8u;
#endif
    default: return 0u;
    }
}

/* What a snapshot restores into only the same rate term: the variant, a
 * and w. */
static unsigned long rate_id(const hyst_rate_t *R, num_type_t t)
{
    const unsigned long crc = crc_word(0ul, (unsigned long)R->variant);
    return crc_num(crc_num(crc, &R->alpha, t), &R->weight, t);
}

/* L of a rate snapshot: p and v, r octets each. */
static size_t rate_length(unsigned r) { return RATE_HEADER_OCTETS + 2u * r + CRC_OCTETS; }

size_t hyst_rate_snapshot_size(const hyst_rate_t *R)
{
    num_type_t t;
    const unsigned r = R != NULL ? rate_format(R, &t) : 0u;
    return r != 0u ? rate_length(r) : 0u;
}

hyst_status_t hyst_rate_snapshot_save(const hyst_rate_t *R, unsigned char *buf, size_t size,
                                      size_t *len)
{
    const volatile hyst_rate_t *V = R;
    num_type_t t;
    unsigned r, attempt;
    size_t need;
    if (R == NULL || buf == NULL) {
        return HYST_ERR_NULL;
    }
    r = rate_format(R, &t);
    if (r == 0u) {
        return HYST_ERR_ARG;
    }
    need = rate_length(r); /* variant: set by init only */
    if (size < need) {
        return HYST_ERR_NOSPACE;
    }
    for (attempt = 0u; attempt < HYST_READ_ATTEMPTS; ++attempt) {
        const unsigned long seq = V->seq;
        HYST_BARRIER();
        put_term_head(buf, MAGIC3_RATE, HYST_RATE_SNAPSHOT_VERSION, r, R->variant, need,
                      rate_id(R, t));
        put_u32(buf + 16, (unsigned long)R->events);
        put_status(buf + 20, R->status);
        put_u16(buf + 22, 0u);
        put_num(buf + RATE_HEADER_OCTETS, &R->last, t);
        put_num(buf + RATE_HEADER_OCTETS + r, &R->state, t);
        HYST_BARRIER();
        /* a volatile re-read: a step may have run meanwhile */
        /* cppcheck-suppress knownConditionTrueFalse */
        if (V->seq != seq) {
            continue;
        }
        put_term_crc(buf, need, len);
        return HYST_OK;
    }
    buf[0] = 0u;
    return HYST_ERR_BUSY;
}

hyst_status_t hyst_rate_snapshot_restore(hyst_rate_t *R, const unsigned char *buf, size_t len)
{
    hyst_num_t last, state;
    hyst_wide_t limit, p, v;
    num_type_t t;
    unsigned long events;
    unsigned r;
    int status;
    size_t need;
    if (R == NULL || buf == NULL) {
        return HYST_ERR_NULL;
    }
    r = rate_format(R, &t);
    if (r == 0u) {
        return HYST_ERR_ARG;
    }
    memset(&last, 0, sizeof last); /* a float leaves the rest of its union as init does: 0 */
    memset(&state, 0, sizeof state);
    if (len < RATE_HEADER_OCTETS + CRC_OCTETS || buf[0] != MAGIC0 || buf[1] != MAGIC1 ||
        buf[2] != MAGIC2 || buf[3] != MAGIC3_RATE) {
        return HYST_ERR_FORMAT;
    }
    if (get_u16(buf + 4) != HYST_RATE_SNAPSHOT_VERSION || buf[6] != r || buf[7] != R->variant) {
        return HYST_ERR_VERSION;
    }
    need = rate_length(r);
    if (get_u32(buf + 8) != (unsigned long)need || need > len) {
        return HYST_ERR_FORMAT; /* truncated, or another length */
    }
    if (hyst_crc32(0ul, buf, need - CRC_OCTETS) != get_u32(buf + need - CRC_OCTETS)) {
        return HYST_ERR_CRC;
    }
    if (get_u32(buf + 12) != rate_id(R, t)) {
        return HYST_ERR_CURVE;
    }
    events = get_u32(buf + 16);
    status = get_status(buf + 20);
    (void)get_num(buf + RATE_HEADER_OCTETS, &last, t);
    (void)get_num(buf + RATE_HEADER_OCTETS + r, &state, t);
    limit = wide_of(&R->x_limit, t);
    p = wide_of(&last, t);
    v = wide_of(&state, t);
    /* p a drive the term took, v a low-pass of changes of such drives (NaN fails too) */
    if ((events & ~(unsigned long)HYST_EVENT_NONFINITE) != 0u ||
        (status != HYST_OK && status != HYST_ERR_NONFINITE && status != HYST_ERR_DOMAIN) ||
        get_u16(buf + 22) != 0u || !(p >= -limit && p <= limit) ||
        !(v >= -2 * limit && v <= 2 * limit)) {
        return HYST_ERR_FORMAT;
    }
    /* Everything checked: only now write the instance. */
    ++R->seq;
    R->last = last;
    R->state = state;
    R->status = status;
    R->events = (unsigned)events;
    return HYST_OK;
}
