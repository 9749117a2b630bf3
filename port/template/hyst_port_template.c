/* SPDX-License-Identifier: MIT */
/**
 * @file hyst_port_template.c
 * @brief Starting point for a new board: copy it to port/<board>/ and fill
 * in every body. It builds as is, but prints nothing and never stops.
 */
#include "hyst_port.h"

void hyst_port_init(void)
{
    /* Clock the console UART and the timing GPIO, set the pin as a push-pull
     * output driven low, and enable the FPU if the core has one (before any
     * float code; startup code usually does this). */
}

void hyst_port_putc(char c)
{
    /* Busy-wait until the UART can take a byte, then write it. Translate
     * '\n' to "\r\n" if the terminal needs it. */
    (void)c;
}

void hyst_port_puts(const char *s)
{
    while (*s != '\0') {
        hyst_port_putc(*s++);
    }
}

void hyst_port_exit(int code)
{
    /* Flush output, then report @p code where the test runner can see it
     * (semihosting exit, a final "EXIT <code>" line, a debugger breakpoint)
     * and stop. There is nowhere to return to. */
    (void)code;
    for (;;) {
    }
}

void hyst_port_timing_begin(void)
{
    /* Drive the timing pin high with one store to its set register (e.g. a
     * BSRR) so the edge costs one instruction; measure the pulse with a
     * scope or logic analyser. Keep the compiler from moving work across
     * the store: __asm__ volatile("" ::: "memory") on GCC/Clang. */
}

void hyst_port_timing_end(void)
{
    /* Drive the pin low the same way. A cycle counter (DWT->CYCCNT on
     * Cortex-M) may be read here too, if the board has one. */
}

long hyst_port_file_open(const char *path, int mode_read_binary)
{
    /* Boards without a host link have no files: return -1 and build test
     * data into the image instead. With a debugger, use semihosting. */
    (void)path;
    (void)mode_read_binary;
    return -1;
}

long hyst_port_file_read(long handle, void *buf, unsigned long len)
{
    (void)handle;
    (void)buf;
    (void)len;
    return -1;
}

void hyst_port_file_close(long handle) { (void)handle; }

long hyst_port_file_length(long handle)
{
    (void)handle;
    return -1;
}
