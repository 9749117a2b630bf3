/* SPDX-License-Identifier: MIT */
/* Arithmetic helpers in one number type, written once: needs a number type
 * descriptor (src/num_f32.h or src/num_f64.h) included before. */
#ifndef HYST_NUM_OPS_H
#define HYST_NUM_OPS_H

#if !defined(NUM_T) || !defined(NUM_F) || !defined(NUM_NAME) || !defined(NUM_VARIANT) || \
    !defined(NUM_C) || !defined(NUM_EPS)
#error "num_ops.h: include a number type descriptor (src/num_f32.h, src/num_f64.h) first"
#endif

HYST_INLINE NUM_T NUM_NAME(abs)(NUM_T v) { return v < 0 ? -v : v; }

/* Finite without libm. */
HYST_INLINE int NUM_NAME(is_finite)(NUM_T v)
{
    const NUM_T z = v - v;
    return z == z;
}

/* G(u) = u (a[0] u^(n-1) + ... + a[n-1]): Horner's rule unrolled by a
 * switch on the degree, one multiply-add per coefficient, no loop and no
 * call (the per-sample path). n >= 1. */
HYST_INLINE NUM_T NUM_NAME(horner)(const hyst_num_t *a, unsigned n, NUM_T u)
{
    NUM_T acc;
#define HORNER_(acc_, k_) ((acc_) * u + a[k_].NUM_F)
    switch (n) { /* independent cases: no register merges */
    case 0: acc = 0; break; /* never called so; lets the jump table start at 0 (one subtraction fewer) */
    case 1: acc = a[0].NUM_F; break;
    case 2: acc = HORNER_(a[0].NUM_F, 1); break;
    case 3: acc = HORNER_(HORNER_(a[0].NUM_F, 1), 2); break;
    case 4: acc = HORNER_(HORNER_(HORNER_(a[0].NUM_F, 1), 2), 3); break;
    case 5: acc = HORNER_(HORNER_(HORNER_(HORNER_(a[0].NUM_F, 1), 2), 3), 4); break;
    case 6: acc = HORNER_(HORNER_(HORNER_(HORNER_(HORNER_(a[0].NUM_F, 1), 2), 3), 4), 5); break;
    case 7:
        acc = HORNER_(HORNER_(HORNER_(HORNER_(HORNER_(HORNER_(a[0].NUM_F, 1), 2), 3), 4), 5), 6);
        break;
    case 8:
        acc = HORNER_(
            HORNER_(HORNER_(HORNER_(HORNER_(HORNER_(HORNER_(a[0].NUM_F, 1), 2), 3), 4), 5), 6), 7);
        break;
    default: { /* 9 and above: Horner's loop */
        unsigned k;
        acc = a[0].NUM_F;
        for (k = 1u; k < n; ++k) {
            acc = HORNER_(acc, k);
        }
        break;
    }
    }
#undef HORNER_
    return acc * u;
}

#endif /* HYST_NUM_OPS_H */
