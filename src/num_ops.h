/* SPDX-License-Identifier: MIT */
/* Arithmetic helpers in one number type, written once: needs a number type
 * descriptor (src/num_f32.h, src/num_f64.h, src/num_q31.h) included before. */
#ifndef HYST_NUM_OPS_H
#define HYST_NUM_OPS_H

#if !defined(NUM_T) || !defined(NUM_F) || !defined(NUM_NAME) || !defined(NUM_VARIANT) || \
    !defined(NUM_C) || !defined(NUM_EPS)
#error "num_ops.h: include a number type descriptor (src/num_f32.h, src/num_f64.h) first"
#endif

HYST_INLINE NUM_T NUM_NAME(abs)(NUM_T v) { return v < 0 ? -v : v; }

#ifndef NUM_FIXED
/* Finite without libm. */
HYST_INLINE int NUM_NAME(is_finite)(NUM_T v)
{
    const NUM_T z = v - v;
    return z == z;
}
#endif

/* The products of Horner's rule: a multiply-add's (NUM_MUL) and G's final
 * one (NUM_MUL_G); a fixed-point type rescales them (src/num_q31.h). */
#ifndef NUM_MUL
#define NUM_MUL(a, b) ((a) * (b))
#endif
#ifndef NUM_MUL_G
#define NUM_MUL_G(a, b) ((a) * (b))
#endif
/* a b + c as the source marks it: fused by a type that says so
 * (src/num_f32.h), else a product and a sum */
#ifndef NUM_MULADD
#define NUM_MULADD(a, b, c) (NUM_MUL(a, b) + (c))
#endif

/* The cases 1..8 of Horner's rule unrolled by a switch on the degree n
 * over a curve's coefficients (curve.h, highest power first; the engine's
 * instance keeps them lowest first, src/tcm_engine.h):
 * acc = a[0] u^(n-1) + ... + a[n-1], one multiply-add per coefficient, no
 * loop and no call. The caller writes the switch, its case 0 (the jump
 * table starts there) and its default (n >= 9). */
#define NUM_HORNER_CASES_(a, u, acc)                                                         \
    case 1: acc = NUM_HORNER1_(a, u); break;                                                  \
    case 2: acc = NUM_HORNER2_(a, u); break;                                                  \
    case 3: acc = NUM_HORNER3_(a, u); break;                                                  \
    case 4: acc = NUM_HORNER4_(a, u); break;                                                  \
    NUM_HORNER_CASES_HIGH_(a, u, acc)
/* The cases 5..8 alone (a caller that writes 1..4 with labels of its own). */
#define NUM_HORNER_CASES_HIGH_(a, u, acc)                                                    \
    case 5: acc = NUM_HORNER_(a, u, NUM_HORNER4_(a, u), 4); break;                            \
    case 6: acc = NUM_HORNER_(a, u, NUM_HORNER_(a, u, NUM_HORNER4_(a, u), 4), 5); break;      \
    case 7:                                                                                   \
        acc = NUM_HORNER_(a, u, NUM_HORNER_(a, u, NUM_HORNER_(a, u, NUM_HORNER4_(a, u), 4), 5), 6); \
        break;                                                                                \
    case 8:                                                                                   \
        acc = NUM_HORNER_(a, u,                                                               \
                          NUM_HORNER_(a, u,                                                   \
                                      NUM_HORNER_(a, u,                                       \
                                                  NUM_HORNER_(a, u, NUM_HORNER4_(a, u), 4), 5), \
                                      6),                                                     \
                          7);                                                                 \
        break
/* a[k] for k < HYST_MAX_DEGREE; the cases above it cannot run (degrees
 * are at most HYST_MAX_DEGREE) and read a[0], not past the array. */
#define NUM_HORNER_(a, u, acc_, k_) \
    NUM_MULADD(acc_, u, (a)[(k_) < HYST_MAX_DEGREE ? (k_) : 0].NUM_F)
/* Degrees 1..4 (n coefficients). */
#define NUM_HORNER1_(a, u) ((a)[0].NUM_F)
#define NUM_HORNER2_(a, u) NUM_HORNER_(a, u, NUM_HORNER1_(a, u), 1)
#define NUM_HORNER3_(a, u) NUM_HORNER_(a, u, NUM_HORNER2_(a, u), 2)
#define NUM_HORNER4_(a, u) NUM_HORNER_(a, u, NUM_HORNER3_(a, u), 3)

/* Horner's loop over a[0..n), any n >= 1: the rare degrees. */
HYST_INLINE NUM_T NUM_NAME(horner_loop)(const hyst_num_t *a, unsigned n, NUM_T u)
{
    NUM_T acc = a[0].NUM_F;
    unsigned k;
    for (k = 1u; k < n; ++k) {
        acc = NUM_HORNER_(a, u, acc, k);
    }
    return acc;
}

/* G(u) = u (a[0] u^(n-1) + ... + a[n-1]), n >= 1. */
HYST_INLINE NUM_T NUM_NAME(horner)(const hyst_num_t *a, unsigned n, NUM_T u)
{
    NUM_T acc;
    switch (n) { /* independent cases: no register merges */
    case 0: acc = 0; break; /* never called so */
    NUM_HORNER_CASES_(a, u, acc);
    default: acc = NUM_NAME(horner_loop)(a, n, u); break;
    }
    return NUM_MUL_G(acc, u);
}

#ifndef NUM_FIXED /* a fixed-point type brings its own (src/num_q31.h) */
/* A cubic piece at t: c0 + t (c1 + t (c2 + t c3)), three marked multiply-adds. */
#define NUM_CUBIC_(c0, c1, c2, c3, t) \
    NUM_MULADD(t, NUM_MULADD(t, NUM_MULADD(t, c3, c2), c1), c0)

/* A tabulated inverse (curve.h, HYST_CURVE_INV_TABLE) at s >= 0: interval
 * k = floor(s), one cubic in t = s - k (exact: k <= s < 2k for k >= 1).
 * k <= N: s <= N (1 + 2 eps) by construction of the table's scale, and
 * entry N is the end of the range. An interval marked exact gives -1. */
HYST_INLINE NUM_T NUM_NAME(table_g)(const NUM_T *tab, NUM_T s)
{
    const unsigned long k = (unsigned long)s; /* 16-bit unsigned on C28x */
    const NUM_T t = s - (NUM_T)k;
    const NUM_T *c = tab + 4u * k;
    return NUM_CUBIC_(c[0], c[1], c[2], c[3], t);
}
#endif

#endif /* HYST_NUM_OPS_H */
