// SPDX-License-Identifier: MIT
// Every public header from C++: one call into every module, linked against
// the C library (extern "C" in every header) and run.
#include "hyst/hyst.h"

#include <cstdio>
#include <cstring>

namespace {

int failures = 0;

void check(bool ok, const char *what)
{
    if (!ok) {
        std::printf("FAIL %s\n", what);
        ++failures;
    }
}

}  // namespace

int main()
{
    static const hyst_poly_t f0 = {3u, 0.0, 40.0, {-6.1876e-6, 1.1949e-3, 8.6444e-2, 5.8517e-1}};
    static float xl[8], yl[8], xr[8], yr[8], il[8], jl[8], ir[8], jr[8];
    static double dxl[8], dyl[8], dxr[8], dyr[8];
    static hyst_code_word_t cx[2][8];
    static float cy[2][8];
    static unsigned char snap[HYST_SNAPSHOT_SIZE(8)];
    static const float r[3] = {0.0f, 0.5f, 1.0f}, w[3] = {1.0f, 0.5f, 0.25f};
    static float z[3], bx[4], by[4];
    hyst_tcm_t s32, s64, sc, comp;
    hyst_curve_t curve, inv, loading;
    hyst_pi_t pi;
    hyst_ident_t id;
    hyst_ident_config_t cfg;
    hyst_ident_result_t res;
    size_t len = 0;

    // tcm.h, f32 and f64
    check(hyst_f32_init(&s32, &f0, xl, yl, xr, yr, 8) == HYST_OK, "f32 init");
    check(hyst_f64_init(&s64, &f0, dxl, dyl, dxr, dyr, 8) == HYST_OK, "f64 init");
    (void)hyst_f32_step(&s32, 30.0f);
    (void)hyst_f64_step(&s64, 30.0);
    check(hyst_tp_count(&s32) == 0u && hyst_status(&s64) == HYST_OK, "tcm counts and status");
    // code.h
    check(hyst_code_init(&sc, &f0, 0u, 4000u, cx[0], cy[0], cx[1], cy[1], 8) == HYST_OK, "code init");
    check(hyst_code_step(&sc, 3000u) > 0.0f, "code step");
    // snapshot.h, for the code variant
    check(hyst_snapshot_save(&sc, snap, sizeof snap, &len) == HYST_OK, "snapshot save");
    check(hyst_snapshot_restore(&sc, snap, len) == HYST_OK, "snapshot restore");
    // curve.h, inverse.h
    check(hyst_f32_curve_from_poly(&curve, &f0) == HYST_OK, "curve");
    check(hyst_curve_inverse(&inv, &curve) == HYST_OK, "inverse curve");
    check(hyst_f32_init_inverse_exact(&comp, &inv, &f0, il, jl, ir, jr, 8) == HYST_OK, "compensator");
    check(hyst_f32_step(&comp, 3.0f) > 0.0f, "compensator step");
    // pi.h
    check(hyst_f32_pi_init(&pi, r, w, z, 3) == HYST_OK, "pi init");
    check(hyst_f32_pi_step(&pi, 0.75f) > 0.0f, "pi step");
    check(hyst_f32_pi_loading_curve(&loading, r, w, 3, 2.0f, bx, by) == HYST_OK, "pi curve");
    // ident.h
    std::memset(&cfg, 0, sizeof cfg);
    cfg.degree = 1u;
    cfg.lo = 0.0;
    cfg.hi = 1.0;
    check(hyst_ident_init(&id, &cfg) == HYST_OK, "ident init");
    for (int k = 0; k <= 20; ++k) {
        const double x = k <= 10 ? k / 10.0 : (20 - k) / 10.0;
        (void)hyst_ident_add(&id, x, 2.0 * x + 1.0);
    }
    check(hyst_ident_solve(&id, &res) == HYST_OK, "ident solve");
    // status.h
    check(std::strcmp(hyst_status_str(HYST_OK), "ok") == 0, "status string");
    std::printf("C++: %d failures\n", failures);
    return failures;
}
