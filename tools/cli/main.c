/* SPDX-License-Identifier: MIT */
/* `hyst`: command-line front end of the hyst library (host only).
 * Subcommands live in cmd_<name>.c; add one by adding a row to the table. */
#include "cli.h"
#include "hyst/hyst.h"

#include <signal.h>
#include <stdio.h>
#include <string.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif

typedef struct {
    const char *name;
    int (*run)(int argc, char **argv);
    const char *summary;
} command_t;

static const command_t commands[] = {
    {"fit", cmd_fit, "identify f0 from measured input/output columns"},
    {"sim", cmd_sim, "run the hysteresis model over input samples"},
    {"inv", cmd_inv, "compensator: the input that gives each desired output"},
    {"pi", cmd_pi, "run a Prandtl-Ishlinskii model over input samples"},
    {"header", cmd_header, "firmware header (hyst_poly_t, hyst_everett_t) of a model file"},
};

static void usage(FILE *out)
{
    size_t i;
    (void)fprintf(out, "usage: hyst <command> [options] [FILE]\n\ncommands:\n");
    for (i = 0u; i < sizeof commands / sizeof commands[0]; ++i) {
        (void)fprintf(out, "  %-6s %s\n", commands[i].name, commands[i].summary);
    }
    (void)fprintf(out, "\n'hyst <command> --help' describes a command; 'hyst --version' prints\n"
                        "the version. hyst %d.%d.%d\n",
                  HYST_VERSION_MAJOR, HYST_VERSION_MINOR, HYST_VERSION_PATCH);
}

int main(int argc, char **argv)
{
    char q[CLI_QUOTE_SIZE];
    size_t i;
#ifdef SIGXFSZ
    /* beyond a file-size limit (ulimit -f) a write fails with EFBIG, reported
     * and cleaned up, instead of the process being killed mid-file */
    (void)signal(SIGXFSZ, SIG_IGN);
#endif
#ifdef __GLIBC__
    /* fit scores hundreds of candidates, each allocating and freeing buffers
     * of the record's size: kept in the heap, not returned to the system
     * and faulted in again for the next one (a tenth of fit's time) */
    (void)mallopt(M_TRIM_THRESHOLD, 1 << 30);
    (void)mallopt(M_MMAP_THRESHOLD, 1 << 25);
#endif
    if (argc < 2) {
        usage(stderr);
        return 1;
    }
    if (strcmp(argv[1], "--version") == 0 || strcmp(argv[1], "-V") == 0) {
        (void)printf("hyst %s\n", HYST_VERSION_STRING);
        return fflush(stdout) == 0 && !ferror(stdout) ? 0 : 1;
    }
    if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0 ||
        strcmp(argv[1], "help") == 0) {
        usage(stdout);
        return 0;
    }
    for (i = 0u; i < sizeof commands / sizeof commands[0]; ++i) {
        if (strcmp(argv[1], commands[i].name) == 0) {
            return commands[i].run(argc - 1, argv + 1);
        }
    }
    (void)fprintf(stderr, "hyst: unknown command %s\n", cli_quote(q, argv[1]));
    usage(stderr);
    return 1;
}
