/* SPDX-License-Identifier: MIT */
/**
 * @file hyst_port_host.c
 * @brief hyst_port.h for a POSIX host: stdio console, fopen() files, and
 * CLOCK_MONOTONIC as the timing "pin".
 */
#define _POSIX_C_SOURCE 199309L /* clock_gettime() under -std=c99 */

#include "hyst_port_host.h"

#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static struct timespec t_begin;
static double elapsed_s;

/* Handles index this table: a FILE * does not fit a long everywhere. */
#define HOST_MAX_FILES 8
static FILE *files[HOST_MAX_FILES];

static FILE *file_of(long handle)
{
    return (handle >= 0 && handle < HOST_MAX_FILES) ? files[handle] : NULL;
}

void hyst_port_init(void) { elapsed_s = 0.0; }

void hyst_port_putc(char c)
{
    (void)putchar((unsigned char)c);
    (void)fflush(stdout);
}

void hyst_port_puts(const char *s)
{
    (void)fputs(s, stdout);
    (void)fflush(stdout);
}

void hyst_port_exit(int code) { exit(code); }

/* Each pair of marks adds two clock reads (tens of ns) to the region: time
 * blocks of samples (hyst_process), not single ones, and report the best of
 * several runs; wall time on a shared host is never a test criterion. */
void hyst_port_timing_begin(void)
{
    (void)clock_gettime(CLOCK_MONOTONIC, &t_begin);
}

void hyst_port_timing_end(void)
{
    struct timespec t_end;
    (void)clock_gettime(CLOCK_MONOTONIC, &t_end);
    elapsed_s += (double)(t_end.tv_sec - t_begin.tv_sec) +
                 (double)(t_end.tv_nsec - t_begin.tv_nsec) * 1e-9;
}

double hyst_port_host_elapsed_s(void) { return elapsed_s; }

long hyst_port_file_open(const char *path, int mode_read_binary)
{
    for (long h = 0; h < HOST_MAX_FILES; ++h) {
        if (files[h] == NULL) {
            files[h] = fopen(path, mode_read_binary ? "rb" : "r");
            return files[h] != NULL ? h : -1;
        }
    }
    return -1;
}

long hyst_port_file_read(long handle, void *buf, unsigned long len)
{
    FILE *f = file_of(handle);
    if (f == NULL) {
        return -1;
    }
    size_t n = fread(buf, 1u, len, f);
    return ferror(f) ? -1 : (long)n;
}

void hyst_port_file_close(long handle)
{
    FILE *f = file_of(handle);
    if (f != NULL) {
        (void)fclose(f);
        files[handle] = NULL;
    }
}

long hyst_port_file_length(long handle)
{
    FILE *f = file_of(handle);
    if (f == NULL) {
        return -1;
    }
    long here = ftell(f);
    if (here < 0 || fseek(f, 0L, SEEK_END) != 0) {
        return -1;
    }
    long len = ftell(f);
    (void)fseek(f, here, SEEK_SET);
    return len;
}
