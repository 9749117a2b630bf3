/* SPDX-License-Identifier: MIT */
/* The header `hyst header --model` writes for a model of kind everett_grid
 * or spline, used as firmware uses it (tests/cli/grid.sh, spline.sh).
 * Built with -DMODEL_H='"NAME.h"' -DMODEL=NAME -DINTERVALS=K and
 * -DKIND_SPLINE for kind spline (else the grid), in float or in double
 * (HYST_USE_DOUBLE):
 *  - alone: the curve made by the library's constructor, exit status 1 if
 *    it refuses it;
 *  - -DWANT=y1,y2,...: also its compensator (hyst_curve_everett_grid_inverse()
 *    or hyst_curve_spline_inverse(); with -DTABLED the spline's tabulated
 *    one, hyst_curve_spline_inverse_table() on NAME_INTERVALS) from rest over
 *    those desired outputs, each drive printed with DIGITS significant
 *    digits (default 9);
 *  - -DSIM: also the model from rest over the inputs on standard input, each
 *    output printed with 17 significant digits (what 'hyst sim --model
 *    --digits 17' must print).
 * Each instance is initialised as the header says, its kind named
 * (hyst_init_kind()). */
#include "hyst/hyst.h"

#include <stdio.h>

#include MODEL_H

#ifndef DIGITS
#define DIGITS 9
#endif
#define CAPACITY 4096u

#ifdef KIND_SPLINE
#define TABLE_LEN HYST_SPLINE_TABLE_LEN(INTERVALS)
#define FORWARD(curve, table) hyst_curve_from_spline((curve), &MODEL, (table), TABLE_LEN)
#ifdef TABLED
#define PASTE_(a, b) a##b
#define PASTE(a, b) PASTE_(a, b)
#define COMP_INTERVALS PASTE(MODEL, _INTERVALS)
static hyst_real_t comp_table[HYST_INV_TABLE_LEN(COMP_INTERVALS)];
#define INVERSE(inv, fwd) hyst_curve_spline_inverse_table((inv), (fwd), comp_table, COMP_INTERVALS)
#define INVERSE_KIND hyst_kind_spline_inverse_table
#else
#define INVERSE hyst_curve_spline_inverse
#define INVERSE_KIND hyst_kind_spline
#endif
#define FORWARD_KIND hyst_kind_spline
#else
#define TABLE_LEN HYST_EVERETT_GRID_TABLE_LEN(INTERVALS)
#define FORWARD(curve, table) hyst_curve_from_everett_grid((curve), &MODEL, (table), TABLE_LEN)
#define INVERSE hyst_curve_everett_grid_inverse
#define INVERSE_KIND hyst_kind_everett_grid_inverse
#define FORWARD_KIND hyst_kind_everett_grid
#endif

/* The instance on the curve (of that kind) from rest, then each input of in[0..n) (or, n
 * 0, of standard input) stepped and its output printed: 0, or 1 if the
 * library refused something. */
static int run(const hyst_curve_t *curve, hyst_kind_t kind, const hyst_real_t *in, unsigned n,
               int digits)
{
    static hyst_real_t xl[CAPACITY], yl[CAPACITY], xr[CAPACITY], yr[CAPACITY];
    hyst_tcm_t S;
    double x;
    unsigned i;
    if (hyst_init_kind(&S, curve, kind, xl, yl, xr, yr, CAPACITY) != HYST_OK) {
        return 1;
    }
    for (i = 0u; n > 0u ? i < n : scanf("%lf", &x) == 1; ++i) {
        const hyst_real_t y = hyst_step(&S, n > 0u ? in[i] : (hyst_real_t)x);
        if (hyst_status(&S) != HYST_OK) {
            return 1;
        }
        (void)printf("%.*g\n", digits, (double)y);
    }
    return 0;
}

int main(void)
{
    static hyst_real_t table[TABLE_LEN];
    hyst_curve_t fwd;
    int failed;
    (void)run; /* a build with neither WANT nor SIM checks the constructor alone */
    failed = FORWARD(&fwd, table) != HYST_OK;
#ifdef WANT
    {
        static const hyst_real_t want[] = {WANT};
        hyst_curve_t inv;
        failed = failed || INVERSE(&inv, &fwd) != HYST_OK ||
                 run(&inv, INVERSE_KIND, want, (unsigned)(sizeof want / sizeof want[0]), DIGITS) != 0;
    }
#endif
#ifdef SIM
    failed = failed || run(&fwd, FORWARD_KIND, NULL, 0u, 17) != 0;
#endif
    return failed;
}
