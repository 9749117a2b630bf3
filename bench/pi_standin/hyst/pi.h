/**
 * @file pi.h
 * @brief STAND-IN for the library's Prandtl-Ishlinskii model (issue 4).
 *
 * Used by the benchmarks ONLY when include/hyst/pi.h does not exist in the
 * tree (bench/CMakeLists.txt decides). Same API as the library's, so the
 * benchmark sources do not change when the real module lands; delete this
 * directory then. Not installed, not part of hyst.
 */
#ifndef HYST_PI_H
#define HYST_PI_H

#include "hyst/config.h"
#include "hyst/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/** @brief A PI model: N one-sided play operators (METHOD.md section 7). */
typedef struct hyst_pi {
    const hyst_real_t *r; /**< thresholds, ascending, r[0] = 0 */
    const hyst_real_t *w; /**< weights */
    hyst_real_t *z;       /**< operator outputs z_i(t-1), caller-owned */
    size_t n;             /**< number of operators */
} hyst_pi_t;

/**
 * @brief Sets up a PI model over caller-owned arrays; operators start at 0.
 * @return HYST_OK, HYST_ERR_NULL, HYST_ERR_CAPACITY (n == 0) or HYST_ERR_ARG
 *         (thresholds not ascending from 0).
 */
hyst_status_t hyst_pi_init(hyst_pi_t *P, const hyst_real_t *thresholds,
                           const hyst_real_t *weights, hyst_real_t *state,
                           size_t n);

/**
 * @brief One sample: z_i = max(x - r_i, min(x, z_i)), y = sum w_i z_i.
 * @return y.
 */
hyst_real_t hyst_pi_step(hyst_pi_t *P, hyst_real_t x);

/** @brief hyst_pi_step() over a block; HYST_ERR_NULL on NULL with n > 0. */
hyst_status_t hyst_pi_process(hyst_pi_t *P, const hyst_real_t *x,
                              hyst_real_t *y, size_t n);

#ifdef __cplusplus
}
#endif

#endif /* HYST_PI_H */
