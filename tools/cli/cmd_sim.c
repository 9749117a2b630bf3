/* SPDX-License-Identifier: MIT */
/* hyst sim: the TCM model over input samples, one output per line. */
#include "cli.h"

static const char help[] =
    "usage: hyst sim (--poly cN,...,c1,c0 --range LO,HI | --model MODEL) [--xcol I]\n"
    "                [--tp] [--digits N] [--decimal-comma] [FILE]\n"
    "\n"
    "Runs the hysteresis model (TCM) with major ascending curve\n"
    "f0(x) = cN x^N + ... + c1 x + c0 on [LO, HI] over the input samples of FILE\n"
    "(standard input if FILE is absent or '-'), starting from (LO, f0(LO)).\n"
    "Prints one output per line with 9 significant digits (--digits).\n"
    "\n"
    "  --poly cN,...,c0  coefficients, highest power first (degree 1..9)\n"
    "  --range LO,HI     domain of f0; inputs outside it are clamped to it, with a\n"
    "                    warning on stderr (count, first line) unless within 1e-9\n"
    "                    relative (9-digit rounding); exit status stays 0 unless\n"
    "                    every input was clamped (then an error)\n"
    CLI_HELP_XCOL
    CLI_HELP_DECIMAL
    "  --model MODEL     f0, its domain and the delay from a model file ('hyst fit\n"
    "                    --save'): line k is then the output for input k - delay\n"
    "                    (the model at rest, f0(LO), for the first delay lines)\n"
    "  --tp              add the turning-point count as a second column: y,tp\n"
    "  --digits N        significant digits printed, 1..17 (default 9; 17 prints\n"
    "                    the double-precision results exactly)\n"
    "  --help            this text\n"
    "\n"
    CLI_HELP_EXIT;

int cmd_sim(int argc, char **argv) { return cli_tcm_command(argc, argv, "sim", help, 0); }
