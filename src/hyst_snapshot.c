/* Snapshot/restore of a TCM instance in a CHAR_BIT-independent octet format
 * (layout in include/hyst/snapshot.h). */
#include "hyst/snapshot.h"
#include "hyst_internal.h"

#include <stdint.h>

#if FLT_MANT_DIG != 24 || FLT_MAX_EXP != 128
#error "hyst snapshots assume IEEE-754 binary32 float"
#endif

#define MAGIC0 0x48u /* 'H' */
#define MAGIC1 0x59u /* 'Y' */
#define MAGIC2 0x53u /* 'S' */
#define MAGIC3 0x53u /* 'S' */
#define HEADER_OCTETS 32u
#define BOOK_OCTETS (4u + 3u * R) /* merge level, its bound, deadband reach and bound */
#define NO_LEVEL 0xFFFFFFFFul     /* no live merge */
#define CRC_OCTETS 4u
#define R ((size_t)HYST_SNAPSHOT_REAL_OCTETS)
#define MAX_COUNT 0x03FFFFFFul /* keeps L below 2^31 for either R */
#define EVENTS_KNOWN (HYST_EVENT_NONFINITE | HYST_EVENT_CLAMPED | HYST_EVENT_FULL)

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

/* Reals travel as their IEEE-754 bits; the union reads the representation
 * (well-defined in C99 TC3) without memcpy or CHAR_BIT assumptions. */
#if HYST_SNAPSHOT_REAL_OCTETS == 8u
typedef uint64_t real_uint_t;
#else
typedef uint32_t real_uint_t;
#endif
typedef union {
    hyst_real_t r;
    real_uint_t u;
} real_bits_t;

static void put_real(unsigned char *p, hyst_real_t v)
{
    real_bits_t b;
    unsigned k;
    b.r = v;
    for (k = 0u; k < R; ++k) {
        p[k] = (unsigned char)((b.u >> (8u * k)) & 0xFFu);
    }
}

static hyst_real_t get_real(const unsigned char *p)
{
    real_bits_t b;
    unsigned k;
    b.u = 0u;
    for (k = 0u; k < R; ++k) {
        b.u |= (real_uint_t)(p[k] & 0xFFu) << (8u * k);
    }
    return b.r;
}

static int real_is_finite(hyst_real_t v)
{
    const hyst_real_t z = v - v;
    return z == z;
}

/* Same bits, not just equal values (0.0 vs -0.0 differ here). */
static int same_real(hyst_real_t a, const unsigned char *p)
{
    unsigned char q[R];
    unsigned k;
    put_real(q, a);
    for (k = 0u; k < R; ++k) {
        if (q[k] != (p[k] & 0xFFu)) {
            return 0;
        }
    }
    return 1;
}

static unsigned long crc_real(unsigned long crc, hyst_real_t v)
{
    unsigned char q[R];
    put_real(q, v);
    return hyst_crc32(crc, q, R);
}

static unsigned long curve_id(const hyst_curve_t *c)
{
    unsigned char q[4];
    unsigned long crc;
    unsigned k;
    put_u16(q, (unsigned)c->kind & 0xFFFFu);
    put_u16(q + 2, c->degree & 0xFFFFu);
    crc = hyst_crc32(0ul, q, 4u);
    crc = crc_real(crc, c->lo);
    crc = crc_real(crc, c->hi);
    crc = crc_real(crc, c->y_lo);
    crc = crc_real(crc, c->y_hi);
    crc = crc_real(crc, c->inv_span);
    for (k = 0u; k < c->degree && k < HYST_MAX_DEGREE; ++k) {
        crc = crc_real(crc, c->a[k]);
    }
    return crc;
}

/* L in unsigned long (size_t may be 16 bits); counts <= MAX_COUNT. */
static unsigned long length_of(unsigned long n_ltp, unsigned long n_rtp)
{
    return HEADER_OCTETS + 2ul * R * (1ul + n_ltp + n_rtp) + BOOK_OCTETS + CRC_OCTETS;
}

/* A function, not an inline test: with a 16-bit size_t the comparison is
 * always true, which -Wtype-limits would flag on AVR. */
static int count_fits(unsigned long n) { return n <= MAX_COUNT; }

size_t hyst_snapshot_size(const hyst_t *S)
{
    unsigned long need;
    if (!count_fits((unsigned long)S->n_ltp) || !count_fits((unsigned long)S->n_rtp)) {
        return 0u; /* not representable; save refuses with HYST_ERR_NOSPACE */
    }
    need = length_of((unsigned long)S->n_ltp, (unsigned long)S->n_rtp);
    return need == (unsigned long)(size_t)need ? (size_t)need : 0u;
}

hyst_status_t hyst_snapshot_save(const hyst_t *S, unsigned char *buf,
                                 size_t size, size_t *len)
{
    size_t need, i, at;
    if (S == NULL || buf == NULL) {
        return HYST_ERR_NULL;
    }
    need = hyst_snapshot_size(S);
    if (need == 0u || size < need) {
        return HYST_ERR_NOSPACE;
    }
    buf[0] = MAGIC0;
    buf[1] = MAGIC1;
    buf[2] = MAGIC2;
    buf[3] = MAGIC3;
    put_u16(buf + 4, HYST_SNAPSHOT_VERSION);
    buf[6] = (unsigned char)R;
    buf[7] = 0u;
    put_u32(buf + 8, (unsigned long)need);
    put_u32(buf + 12, curve_id(&S->curve));
    put_u32(buf + 16, (unsigned long)S->n_ltp);
    put_u32(buf + 20, (unsigned long)S->n_rtp);
    put_u32(buf + 24, (unsigned long)S->events);
    put_u16(buf + 28, (unsigned)S->status & 0xFFFFu); /* two's complement */
    put_u16(buf + 30, 0u);
    put_real(buf + HEADER_OCTETS, hyst_input(S));
    put_real(buf + HEADER_OCTETS + R, S->y_prev);
    at = HEADER_OCTETS + 2u * R;
    for (i = 0u; i < S->n_ltp; ++i, at += 2u * R) {
        put_real(buf + at, S->xltp[i]);
        put_real(buf + at + R, S->yltp[i]);
    }
    for (i = 0u; i < S->n_rtp; ++i, at += 2u * R) {
        put_real(buf + at, S->xrtp[i]);
        put_real(buf + at + R, S->yrtp[i]);
    }
    put_u32(buf + at, S->forgot_level == (size_t)-1 ? NO_LEVEL
                                                     : (unsigned long)S->forgot_level);
    put_real(buf + at + 4u, S->forgot);
    put_real(buf + at + 4u + R, S->db_reach);
    put_real(buf + at + 4u + 2u * R, S->db_err);
    at += BOOK_OCTETS;
    put_u32(buf + at, hyst_crc32(0ul, buf, at));
    if (len != NULL) {
        *len = need;
    }
    return HYST_OK;
}

/* Is the saved state one the engine can reach? Turning points alternate and
 * nest strictly: LTP x ascending, RTP x descending, every LTP below every RTP,
 * all inside [lo, hi]; A0 is (lo, f0(lo)); the last input lies on the current
 * branch, between its TP and the TP below. Reads only. */
static int state_is_valid(const hyst_t *S, const unsigned char *body,
                          size_t nl, size_t nr)
{
    const hyst_real_t lo = S->curve.lo;
    const hyst_real_t hi = S->curve.hi;
    const unsigned char *ltp = body + 2u * R;
    const unsigned char *rtp = ltp + 2u * R * nl;
    const hyst_real_t x_prev = get_real(body);
    hyst_real_t top_ltp = lo;
    hyst_real_t top_rtp = hi;
    size_t i;

    if (!same_real(lo, ltp) || !same_real(S->curve.y_lo, ltp + R)) {
        return 0;
    }
    for (i = 0u; i < nl + nr; ++i) {
        const unsigned char *p = i < nl ? ltp + 2u * R * i : rtp + 2u * R * (i - nl);
        const hyst_real_t x = get_real(p);
        if (!real_is_finite(x) || !real_is_finite(get_real(p + R)) || !(x >= lo && x <= hi)) {
            return 0;
        }
        if (i > 0u && i < nl) { /* LTPs ascend strictly */
            if (!(x > top_ltp)) {
                return 0;
            }
            top_ltp = x;
        } else if (i >= nl) { /* RTPs descend strictly, above every LTP */
            if (!(x > top_ltp) || (i > nl && !(x < top_rtp))) {
                return 0;
            }
            top_rtp = x;
        }
    }
    if (!real_is_finite(x_prev) || !real_is_finite(get_real(body + R))) {
        return 0;
    }
    if (nl > nr) { /* rising from LTP nl-1, below RTP nr-1 (or hi) */
        return x_prev >= top_ltp && (nr > 0u ? x_prev < top_rtp : x_prev <= hi);
    }
    return x_prev > top_ltp && x_prev <= top_rtp; /* falling from RTP nr-1 */
}

/* The bounded-memory bookkeeping: a merge level within the stack (or none),
 * finite non-negative bounds and deadband reach. Reads only. */
static int book_is_valid(const unsigned char *p, size_t depth, hyst_tcm_book_t *book)
{
    const unsigned long level = get_u32(p);
    book->forgot_level = level == NO_LEVEL ? (size_t)-1 : (size_t)level;
    book->forgot = get_real(p + 4u);
    book->db_reach = get_real(p + 4u + R);
    book->db_err = get_real(p + 4u + 2u * R);
    return (level == NO_LEVEL || level <= (unsigned long)depth) && real_is_finite(book->forgot) &&
           book->forgot >= 0 && real_is_finite(book->db_reach) && book->db_reach >= 0 &&
           real_is_finite(book->db_err) && book->db_err >= 0;
}

hyst_status_t hyst_snapshot_restore(hyst_t *S, const unsigned char *buf,
                                    size_t len)
{
    unsigned long length, nl32, nr32, events;
    hyst_tcm_book_t book;
    size_t nl, nr, i, at;
    unsigned status16;

    if (S == NULL || buf == NULL) {
        return HYST_ERR_NULL;
    }
    if (len < HEADER_OCTETS + CRC_OCTETS || buf[0] != MAGIC0 || buf[1] != MAGIC1 ||
        buf[2] != MAGIC2 || buf[3] != MAGIC3) {
        return HYST_ERR_FORMAT;
    }
    if (get_u16(buf + 4) != HYST_SNAPSHOT_VERSION || buf[6] != R) {
        return HYST_ERR_VERSION;
    }
    length = get_u32(buf + 8);
    nl32 = get_u32(buf + 16);
    nr32 = get_u32(buf + 20);
    if (length > len || !count_fits(nl32) || !count_fits(nr32) ||
        length != length_of(nl32, nr32)) {
        return HYST_ERR_FORMAT; /* truncated, or length and counts disagree */
    }
    at = (size_t)length - CRC_OCTETS;
    if (hyst_crc32(0ul, buf, at) != get_u32(buf + at)) {
        return HYST_ERR_CRC;
    }
    if (get_u32(buf + 12) != curve_id(&S->curve)) {
        return HYST_ERR_CURVE;
    }
    nl = (size_t)nl32;
    nr = (size_t)nr32;
    if (nl > S->capacity || nr > S->capacity) {
        return HYST_ERR_CAPACITY;
    }
    events = get_u32(buf + 24);
    status16 = get_u16(buf + 28);
    if (nl < 1u || (nr != nl && nr + 1u != nl) || (events & ~(unsigned long)EVENTS_KNOWN) != 0u ||
        buf[7] != 0u || get_u16(buf + 30) != 0u ||
        !state_is_valid(S, buf + HEADER_OCTETS, nl, nr)) {
        return HYST_ERR_FORMAT;
    }
    at = HEADER_OCTETS + 2u * R * (1u + nl + nr);
    if (!book_is_valid(buf + at, nl + nr, &book)) {
        return HYST_ERR_FORMAT;
    }
    /* Everything checked: only now write the instance. */
    at = HEADER_OCTETS + 2u * R;
    for (i = 0u; i < nl; ++i, at += 2u * R) {
        S->xltp[i] = get_real(buf + at);
        S->yltp[i] = get_real(buf + at + R);
    }
    for (i = 0u; i < nr; ++i, at += 2u * R) {
        S->xrtp[i] = get_real(buf + at);
        S->yrtp[i] = get_real(buf + at + R);
    }
    S->n_ltp = nl;
    S->n_rtp = nr;
    hyst_tcm_resume(S, get_real(buf + HEADER_OCTETS), get_real(buf + HEADER_OCTETS + R), &book);
    S->events = (unsigned)events;
    /* 16-bit two's complement back to int without implementation-defined casts */
    S->status = status16 >= 0x8000u ? -(int)(0xFFFFu - status16) - 1 : (int)status16;
    return HYST_OK;
}
