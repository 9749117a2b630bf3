/* SPDX-License-Identifier: MIT */
/**
 * @file hyst_port_mps2.c
 * @brief hyst_port.h for the MPS2 boards under QEMU (mps2-an385, -an386,
 * -an500): semihosting console and files, FPGAIO LED0 as the timing pin.
 */
#include "hyst_port.h"
#include "semihost.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* FPGAIO LED register: bit 0 is LED0, at the same address on AN385, AN386
 * and AN500. QEMU logs writes with -trace mps2_fpgaio_write, which makes the
 * timed regions visible. */
#define FPGAIO_LED (*(volatile uint32_t *)0x40028000u)

void hyst_port_init(void) { FPGAIO_LED = 0u; }

/* Same host stream as printf (SYS_WRITEC/WRITE0 would land on stderr);
 * flushing first keeps the two in program order. */
void hyst_port_putc(char c)
{
    (void)fflush(stdout);
    (void)semihost_write(semihost_stdio(1), &c, 1u);
}

void hyst_port_puts(const char *s)
{
    (void)fflush(stdout);
    (void)semihost_write(semihost_stdio(1), s, strlen(s));
}

void hyst_port_exit(int code) { exit(code); /* flushes stdio first */ }

/* The empty asm keeps the compiler from moving memory accesses of the timed
 * work across the pin writes (volatile orders only volatile accesses). */
void hyst_port_timing_begin(void)
{
    __asm__ volatile("" ::: "memory");
    FPGAIO_LED = 1u;
    __asm__ volatile("" ::: "memory");
}

void hyst_port_timing_end(void)
{
    __asm__ volatile("" ::: "memory");
    FPGAIO_LED = 0u;
    __asm__ volatile("" ::: "memory");
}

long hyst_port_file_open(const char *path, int mode_read_binary)
{
    return semihost_open(path, mode_read_binary ? SEMIHOST_MODE_RB
                                                : SEMIHOST_MODE_R);
}

long hyst_port_file_read(long handle, void *buf, unsigned long len)
{
    long left = semihost_read(handle, buf, len);
    if (left < 0 || (unsigned long)left > len) {
        return -1;
    }
    return (long)(len - (unsigned long)left);
}

void hyst_port_file_close(long handle)
{
    if (handle >= 0) {
        (void)semihost_close(handle);
    }
}

long hyst_port_file_length(long handle) { return semihost_flen(handle); }
