/* SPDX-License-Identifier: MIT */
/* The rate term's per-sample functions in one real type (rate.h), as
 * always-inline bodies named *_impl: src/hyst_rate.c defines the public
 * names, one line each. Included once per real variant, after NUM_T (the
 * type), NUM_F (its member of hyst_num_t), NUM_NAME (the prefix),
 * NUM_VARIANT and NUM_MULADD; no include guard for that reason. */
#if !defined(NUM_T) || !defined(NUM_F) || !defined(NUM_NAME) || !defined(NUM_VARIANT)
#error "rate_model.h: define NUM_T, NUM_F, NUM_NAME and NUM_VARIANT first"
#endif

/* Finite without libm and without widening. */
HYST_INLINE int NUM_NAME(rate_finite_)(NUM_T v)
{
    const NUM_T z = v - v;
    return z == z;
}

HYST_INLINE hyst_status_t NUM_NAME(rate_reset_impl)(hyst_rate_t *R, NUM_T x_rest)
{
    if (R == NULL) {
        return HYST_ERR_NULL;
    }
    if (R->variant != (unsigned)NUM_VARIANT) {
        return HYST_ERR_LAYOUT;
    }
    if (!(x_rest >= -R->x_limit.NUM_F && x_rest <= R->x_limit.NUM_F)) { /* NaN too */
        return HYST_ERR_NONFINITE;
    }
    ++R->seq;
    R->last.NUM_F = x_rest;
    R->state.NUM_F = 0;
    R->status = HYST_OK;
    R->events = 0u;
    return HYST_OK;
}

HYST_INLINE NUM_T NUM_NAME(rate_output_impl)(const hyst_rate_t *R)
{
    return R != NULL ? R->weight.NUM_F * R->state.NUM_F : 0;
}

HYST_INLINE NUM_T NUM_NAME(rate_step_impl)(hyst_rate_t *R, NUM_T x)
{
    NUM_T r, v;
    if (R == NULL) {
        return 0;
    }
    ++R->seq; /* every sample changes the state (snapshot.c) */
    v = R->state.NUM_F;
    r = R->weight.NUM_F * v; /* as output() computes it: bit for bit the same */
    if (!(x >= -R->x_limit.NUM_F && x <= R->x_limit.NUM_F)) { /* NaN fails too */
        R->status = NUM_NAME(rate_finite_)(x) ? HYST_ERR_DOMAIN : HYST_ERR_NONFINITE;
        R->events |= HYST_EVENT_NONFINITE;
        return r;
    }
    R->state.NUM_F = NUM_MULADD(R->alpha.NUM_F, (x - R->last.NUM_F) - v, v);
    R->last.NUM_F = x;
    R->status = HYST_OK;
    return r;
}
