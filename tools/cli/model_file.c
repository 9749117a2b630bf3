/* SPDX-License-Identifier: MIT */
/* Model files, format hyst-model-text 1 (docs/cli.md, "Model files"): the
 * tool's side of the one reader (tools/model_text/model_text.c, which the
 * Python package and the MATLAB/Octave functions call too). */
#include "cli.h"
#include "hyst/hyst.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

int cli_model_parse(const char *cmd, const char *path, FILE *in, cli_model_t *m)
{
    char msg[MODEL_TEXT_MSG_SIZE];
    /* one byte more than the format allows, for the reader to refuse it */
    const size_t cap = MODEL_TEXT_MAX_BYTES + 1u;
    char *text = (char *)malloc(cap);
    size_t len;
    int rc;
    if (text == NULL) {
        return cli_fail(cmd, "%s: out of memory to read the model file", path);
    }
    len = fread(text, 1u, cap, in);
    if (ferror(in)) {
        free(text);
        return cli_fail(cmd, "%s: read error", path);
    }
    rc = model_text_parse(text, len, path, m, msg, sizeof msg);
    free(text);
    return rc != 0 ? cli_fail(cmd, "%s", msg) : 0;
}

int cli_model_read(const char *cmd, const char *path, cli_model_t *m)
{
    int rc;
    struct stat st;
    FILE *in = fopen(path, "rb");
    if (in == NULL) {
        return cli_fail(cmd, "%s: cannot open the model file: %s", path, strerror(errno));
    }
    /* fopen() opens a directory for reading; the first read fails (EISDIR) */
    if (fstat(fileno(in), &st) == 0 && S_ISDIR(st.st_mode)) {
        (void)fclose(in);
        return cli_fail(cmd, "%s: is a directory, not a model file", path);
    }
    rc = cli_model_parse(cmd, path, in, m);
    (void)fclose(in);
    return rc;
}

/* A model's curve as the library made it: 0, or 1 after a message with its reason. */
static int curve_made(const char *cmd, const char *path, hyst_status_t st)
{
    return st == HYST_OK ? 0 : cli_fail(cmd, "model file %s: %s", path, hyst_status_str(st));
}

int cli_everett_curve(const char *cmd, const char *path, const cli_model_t *m, hyst_curve_t *c)
{
    hyst_everett_t e;
    cli_model_to_everett(m, &e);
    return curve_made(cmd, path, hyst_f64_curve_from_everett(c, &e));
}

int cli_grid_curve(const char *cmd, const char *path, const cli_model_t *m, hyst_curve_t *c,
                   double *table)
{
    hyst_everett_grid_t g;
    model_text_to_grid(m, &g);
    return curve_made(cmd, path, hyst_f64_curve_from_everett_grid(c, &g, table, CLI_GRID_TABLE_LEN));
}

int cli_spline_curve(const char *cmd, const char *path, const cli_model_t *m, hyst_curve_t *c,
                     double *table)
{
    hyst_spline_t f0;
    model_text_to_spline(m, &f0);
    return curve_made(cmd, path, hyst_f64_curve_from_spline(c, &f0, table, CLI_SPLINE_TABLE_LEN));
}

int cli_header_model(char *buf, size_t size, size_t *len, const char *name, const cli_model_t *m)
{
    return model_text_header_open(buf, size, len, name, m) |
           model_text_header_close(buf, size, len, name);
}
