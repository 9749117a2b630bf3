/* STAND-IN PI model for the benchmarks (see hyst/pi.h in this directory). */
#include "hyst/pi.h"

hyst_status_t hyst_pi_init(hyst_pi_t *P, const hyst_real_t *thresholds,
                           const hyst_real_t *weights, hyst_real_t *state,
                           size_t n)
{
    size_t i;
    if (P == NULL || thresholds == NULL || weights == NULL || state == NULL) {
        return HYST_ERR_NULL;
    }
    if (n == 0u) {
        return HYST_ERR_CAPACITY;
    }
    if (thresholds[0] != HYST_REAL_C(0.0)) {
        return HYST_ERR_ARG;
    }
    for (i = 1u; i < n; ++i) {
        if (!(thresholds[i] > thresholds[i - 1u])) {
            return HYST_ERR_ARG;
        }
    }
    for (i = 0u; i < n; ++i) {
        state[i] = HYST_REAL_C(0.0); /* z_i(-1) = 0 gives METHOD.md's z_i(0) */
    }
    P->r = thresholds;
    P->w = weights;
    P->z = state;
    P->n = n;
    return HYST_OK;
}

hyst_real_t hyst_pi_step(hyst_pi_t *P, hyst_real_t x)
{
    hyst_real_t y = HYST_REAL_C(0.0);
    size_t i;
    for (i = 0u; i < P->n; ++i) {
        const hyst_real_t lo = x - P->r[i];
        hyst_real_t z = P->z[i];
        z = x < z ? x : z;  /* min(x, z_i(t-1)) */
        z = lo > z ? lo : z; /* max(x - r_i, .) */
        P->z[i] = z;
        y += P->w[i] * z;
    }
    return y;
}

hyst_status_t hyst_pi_process(hyst_pi_t *P, const hyst_real_t *x,
                              hyst_real_t *y, size_t n)
{
    size_t i;
    if (n > 0u && (P == NULL || x == NULL || y == NULL)) {
        return HYST_ERR_NULL;
    }
    for (i = 0u; i < n; ++i) {
        y[i] = hyst_pi_step(P, x[i]);
    }
    return HYST_OK;
}
