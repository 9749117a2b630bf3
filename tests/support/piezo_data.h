/* SPDX-License-Identifier: MIT */
/* Loader of the measured piezo record (tests/data/piezo_major_loop.dat, MIT,
 * from yan9a/DiscreteBacklashOperator; see tests/data/README.md): column 1 =
 * drive voltage, column 5 = displacement sensor. Reads through the port's
 * file functions, so it works on the host and under QEMU semihosting. */
#ifndef PIEZO_DATA_H
#define PIEZO_DATA_H

#include <stddef.h>

/* Fills x[i], y[i] for up to max rows; returns the rows read, or -(line)
 * of the first malformed line, or -1 if the file cannot be opened. */
long piezo_data_load(const char *path, double *x, double *y, size_t max);

#endif
