/* SPDX-License-Identifier: MIT */
/* hyst inv: the compensator (inverse TCM), one drive input per desired output. */
#include "cli.h"

static const char help[] =
    "usage: hyst inv (--poly cN,...,c1,c0 --range LO,HI | --model MODEL) [--xcol I]\n"
    "                [--intervals N [--rows R]] [--tp] [--digits N] [--decimal-comma]\n"
    "                [FILE]\n"
    "\n"
    "Runs the compensator of the model 'hyst sim' runs with the same --poly and\n"
    "--range: for each desired output in FILE (standard input if FILE is absent\n"
    "or '-'), the input that makes the model produce it, given the history. It is\n"
    "the same engine on the inverse curve f0^-1, starting from (f0(LO), LO), so\n"
    "'hyst sim' of the printed inputs gives back the desired outputs.\n"
    "Prints one input per line with 9 significant digits (--digits).\n"
    "\n"
    "  --poly cN,...,c0  coefficients of f0, highest power first (degree 1..9)\n"
    "  --range LO,HI     domain of f0; desired outputs outside [f0(LO), f0(HI)] are\n"
    "                    unreachable: they are clamped to it (the drive saturates at\n"
    "                    LO or HI), with a warning on stderr (count, first line)\n"
    "                    unless within 1e-9 relative (9-digit rounding of a bound);\n"
    "                    exit status stays 0 unless every target was clamped\n"
    "                    (then an error), as for 'hyst sim'\n"
    CLI_HELP_XCOL
    CLI_HELP_DECIMAL
    "  --model MODEL     f0 and its domain from a model file ('hyst fit --save');\n"
    "                    its delay is not compensated (a pure delay has no causal\n"
    "                    inverse): line k is the drive for desired output k\n"
    "  --intervals N     run the firmware's tabulated compensator instead of the\n"
    "                    exact one: kind poly f0^-1 in N cubic pieces\n"
    "                    (hyst_init_inverse_table(), HYST_INIT_INVERSE), kind\n"
    "                    spline too (hyst_curve_spline_inverse_table()), kind\n"
    "                    everett N pieces per row, a row per branch start\n"
    "                    (hyst_curve_everett_inverse_table()); kind\n"
    "                    everett_grid has none (its exact compensator is the\n"
    "                    firmware's); N in 1..1048576, or 'default': the\n"
    "                    library's, " CLI_STR(HYST_INV_TABLE) " for poly and spline\n"
    "                    (HYST_INV_TABLE), " CLI_STR(HYST_EVERETT_INV_INTERVALS)
    " for everett\n"
    "                    (HYST_EVERETT_INV_INTERVALS).\n"
    "                    Init's worst measured error (hyst_curve_inverse_error():\n"
    "                    a fraction of the drive range, then in drive units) is\n"
    "                    printed on stderr after the results\n"
    "  --rows R          kind everett, with --intervals: R + 1 rows per direction,\n"
    "                    R in 3..4096 or 'default' (" CLI_STR(HYST_EVERETT_INV_ROWS)
    ", HYST_EVERETT_INV_ROWS, also\n"
    "                    without --rows)\n"
    "  --tp              add the turning-point count as a second column: x,tp\n"
    "  --digits N        significant digits printed, 1..17 (default 9; 17 prints\n"
    "                    the double-precision results exactly)\n"
    "  --help            this text\n"
    "\n"
    CLI_HELP_EXIT;

int cmd_inv(int argc, char **argv) { return cli_tcm_command(argc, argv, "inv", help, 1); }
