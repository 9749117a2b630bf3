/* SPDX-License-Identifier: MIT */
/* The library's asymmetric table build with a tolerance no interval misses:
 * every interval keeps the cubic pieces its rows are given, none solved (what
 * a table whose solved intervals were given back their pieces holds), as
 * build_keeping_pieces() and const_keeping_pieces() (and the solved
 * compensator's curve they start from, keeping_pieces_everett_inverse()).
 * Included once by a test
 * or harness that needs such a table; it compiles src/hyst_everett_inv.c
 * into the includer under those names. */
#ifndef EVERETT_INV_KEEPING_PIECES_H
#define EVERETT_INV_KEEPING_PIECES_H

#undef HYST_INV_TABLE_TOL
#define HYST_INV_TABLE_TOL 1e6
#define hyst_curve_everett_inverse_table_ build_keeping_pieces
#define hyst_curve_everett_inverse_table_const_ const_keeping_pieces
#define hyst_everett_inverse_ keeping_pieces_everett_inverse
#include "../../src/hyst_everett_inv.c"
#undef hyst_curve_everett_inverse_table_
#undef hyst_curve_everett_inverse_table_const_
#undef hyst_everett_inverse_
#undef HYST_INV_TABLE_TOL

#endif
