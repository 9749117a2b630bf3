/* SPDX-License-Identifier: MIT */
#include "piezo_data.h"

#include "hyst_port.h"

#include <stdlib.h>

/* Parses one line: 5 whitespace-separated numbers at least. */
static int parse_line(char *line, double *x, double *y)
{
    char *p = line, *end;
    int c;
    for (c = 0; c < 5; ++c) {
        const double v = strtod(p, &end);
        if (end == p) {
            return 0;
        }
        if (c == 0) {
            *x = v;
        }
        if (c == 4) {
            *y = v;
        }
        p = end;
    }
    return 1;
}

long piezo_data_load(const char *path, double *x, double *y, size_t max)
{
    static char buf[2048];
    static char line[512];
    size_t n = 0u, len = 0u;
    long line_no = 0, got;
    const long h = hyst_port_file_open(path, 0);
    if (h < 0) {
        return -1;
    }
    while ((got = hyst_port_file_read(h, buf, sizeof buf)) > 0) {
        long i;
        for (i = 0; i < got; ++i) {
            if (buf[i] != '\n' && len + 1u < sizeof line) {
                line[len++] = buf[i];
                continue;
            }
            line[len] = '\0';
            len = 0u;
            ++line_no;
            if (n >= max || !parse_line(line, &x[n], &y[n])) {
                hyst_port_file_close(h);
                return -line_no;
            }
            ++n;
        }
    }
    hyst_port_file_close(h);
    return (long)n;
}
