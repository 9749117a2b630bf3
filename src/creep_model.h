/* SPDX-License-Identifier: MIT */
/* The creep model's per-sample functions in one real type (creep.h), as
 * always-inline bodies named *_impl: src/hyst_creep.c defines the public
 * names, one line each, so that a search for a name finds its definition
 * and a public function is the body itself, not a call to another.
 * Included once per real variant, after NUM_T (the type), NUM_F (its
 * member of hyst_num_t), NUM_NAME (the prefix) and NUM_VARIANT; no include
 * guard for that reason. */
#if !defined(NUM_T) || !defined(NUM_F) || !defined(NUM_NAME) || !defined(NUM_VARIANT)
#error "creep_model.h: define NUM_T, NUM_F, NUM_NAME and NUM_VARIANT first"
#endif

/* Finite without libm and without widening (a float-to-double conversion
 * is a call on single-precision FPUs). */
HYST_INLINE int NUM_NAME(creep_finite_)(NUM_T v)
{
    const NUM_T z = v - v;
    return z == z;
}

HYST_INLINE hyst_status_t NUM_NAME(creep_reset_impl)(hyst_creep_t *C, NUM_T x_rest)
{
    size_t k;
    if (C == NULL) {
        return HYST_ERR_NULL;
    }
    if (C->variant != (unsigned)NUM_VARIANT) {
        return HYST_ERR_LAYOUT;
    }
    if (!(x_rest >= -C->x_limit.NUM_F && x_rest <= C->x_limit.NUM_F)) { /* NaN too */
        return HYST_ERR_NONFINITE;
    }
    ++C->seq;
    for (k = 0u; k < C->n; ++k) {
        C->state[k].NUM_F = x_rest;
    }
    C->status = HYST_OK;
    C->events = 0u;
    return HYST_OK;
}

/* The same sum, in the same order, as the step's: output() is bit for bit
 * what the next step returns. */
HYST_INLINE NUM_T NUM_NAME(creep_output_impl)(const hyst_creep_t *C)
{
    NUM_T c = 0;
    size_t k;
    if (C == NULL) {
        return 0;
    }
    for (k = 0u; k < C->n; ++k) {
        c = NUM_MULADD(C->weight[k].NUM_F, C->state[k].NUM_F, c);
    }
    return c;
}

/* The refusal path calls the public output(), out of line, as the step
 * always has: the per-sample path stays as short. */
HYST_INLINE NUM_T NUM_NAME(creep_step_impl)(hyst_creep_t *C, NUM_T x)
{
    NUM_T c = 0;
    size_t k;
    if (C == NULL) {
        return 0;
    }
    ++C->seq; /* every sample changes the state (snapshot.c) */
    if (!(x >= -C->x_limit.NUM_F && x <= C->x_limit.NUM_F)) { /* NaN fails too */
        C->status = NUM_NAME(creep_finite_)(x) ? HYST_ERR_DOMAIN : HYST_ERR_NONFINITE;
        C->events |= HYST_EVENT_NONFINITE;
        return NUM_NAME(creep_output)(C);
    }
    for (k = 0u; k < C->n; ++k) {
        const NUM_T s = C->state[k].NUM_F;
        c = NUM_MULADD(C->weight[k].NUM_F, s, c);
        C->state[k].NUM_F = NUM_MULADD(C->alpha[k].NUM_F, x - s, s);
    }
    C->status = HYST_OK;
    return c;
}
