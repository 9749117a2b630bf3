#include "bench_models.h"

const hyst_real_t bench_pi10_r[BENCH_PI_N] = {
    HYST_REAL_C(0.0), HYST_REAL_C(0.1), HYST_REAL_C(0.2), HYST_REAL_C(0.3),
    HYST_REAL_C(0.4), HYST_REAL_C(0.5), HYST_REAL_C(0.6), HYST_REAL_C(0.7),
    HYST_REAL_C(0.8), HYST_REAL_C(0.9)};

const hyst_real_t bench_pi10_w[BENCH_PI_N] = {
    HYST_REAL_C(0.0789), HYST_REAL_C(0.2268), HYST_REAL_C(0.1928),
    HYST_REAL_C(0.2019), HYST_REAL_C(0.1995), HYST_REAL_C(0.2001),
    HYST_REAL_C(0.2000), HYST_REAL_C(0.2000), HYST_REAL_C(0.1999),
    HYST_REAL_C(0.2005)};

void bench_f0_codes(hyst_poly_t *f0)
{
    const double s = 40.0 / (double)(BENCH_NU - 1u); /* volts per code */
    f0->degree = 3u;
    f0->lo = HYST_REAL_C(0.0);
    f0->hi = (hyst_real_t)(BENCH_NU - 1u);
    f0->coeffs[0] = (hyst_real_t)(-6.1876e-6 * s * s * s);
    f0->coeffs[1] = (hyst_real_t)(1.1949e-3 * s * s);
    f0->coeffs[2] = (hyst_real_t)(8.6444e-2 * s);
    f0->coeffs[3] = (hyst_real_t)5.8517e-1;
}
