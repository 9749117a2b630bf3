/* SPDX-License-Identifier: MIT */
/* The symmetric polynomial kind (HYST_CURVE_POLY, the paper's TCM with
 * f0's G), a curve kind of the engine (src/tcm_engine.h, TCM_NAME(kind_t)):
 * G is one polynomial for every branch, its coefficients copied into the
 * instance at init; the fast path and the engine's slow sample evaluate
 * them (Horner's rule, src/num_ops.h). Included after the engine by every
 * variant (src/kinds.h; the q31 model, src/hyst_q31.c, alone). */
#ifndef HYST_KIND_POLY_H
#define HYST_KIND_POLY_H

/* f0's G of degree 1..HYST_MAX_DEGREE: S->degree and S->coef. */
static void TCM_NAME(poly_attach)(hyst_tcm_t *S, const hyst_curve_t *curve)
{
    unsigned k;
    S->degree = curve->u.poly.degree;
    for (k = 0u; k < S->degree && k < HYST_MAX_DEGREE; ++k) {
        YV(S->coef[k]) = YV(curve->u.poly.a[k]);
    }
}

#ifndef NUM_FIXED
/* The deadband's error bound of a skipped loop [b, a] of width d = a - b
 * (full: d as g's argument difference, u in g's units). Inside the window
 * the full model differs from the branch moved back along by the measure
 * of relays in a rectangle (x - b) x (a - x) of density g''(a' - b'), whose
 * diagonal a' - b' = v is at most min(v, u - v) long: the error is at most
 * the integral of |g''(v)| min(v, u - v) over [0, u], bounded term by term
 * (g = sum a_k u^k: |a_2| u^2 / 2 + the sum of |a_k| u^k, k >= 3, with
 * min(v, u - v) <= u - v). Where g'' is proven one-signed on [0, u] (its
 * constant term wins), the tighter height of the loop at its middle,
 * |g(d) - 2 g(d/2)| (docs/memory.md). */
static TCM_NOINLINE TCM_Y TCM_NAME(poly_loop_error)(const hyst_tcm_t *S, TCM_X b, TCM_X a)
{
    const TCM_Y full = TCM_D((TCM_X)(a - b), (TCM_X)0);
    const unsigned n = S->degree;
    const TCM_Y u = full * YV(S->unit);
    TCM_Y rest = 0, sum = 0, pw = u; /* pw = u^(k-2) from k = 3 */
    unsigned k;
    for (k = 3u; k <= n; ++k) { /* coef[n - k] multiplies u^k */
        const TCM_Y t = NUM_NAME(abs)(YV(S->coef[n - k])) * pw;
        rest += (TCM_Y)(k * (k - 1u)) * t;
        sum += t;
        pw *= u;
    }
    if (n >= 2u) {
        const TCM_Y a2 = NUM_NAME(abs)(YV(S->coef[n - 2u]));
        if (rest < 2 * a2) {
            return NUM_NAME(abs)(TCM_NAME(g)(S, full) - 2 * TCM_G_HALF(S, full));
        }
        sum += a2 * NUM_C(0.5);
    }
    return sum * u * u * NUM_C(1.01); /* rounded up by 1 % */
}
#endif

/* Fixed-point outputs: the deadband's bound of the engine (loop_error NULL). */
#ifdef NUM_FIXED
#define TCM_POLY_LOOP_ERROR NULL
#else
#define TCM_POLY_LOOP_ERROR TCM_NAME(poly_loop_error)
#endif

static const TCM_NAME(kind_t) TCM_NAME(kind_poly) = {
    .loop_error = TCM_POLY_LOOP_ERROR,
    .attach = TCM_NAME(poly_attach)};

#undef TCM_POLY_LOOP_ERROR

#endif /* HYST_KIND_POLY_H */
