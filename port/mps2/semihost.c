/* SPDX-License-Identifier: MIT */
/**
 * @file semihost.c
 * @brief Arm semihosting (v2) over bkpt 0xAB for Thumb M-profile cores.
 */
#include "semihost.h"

#include <stdint.h>
#include <string.h>

enum {
    SYS_OPEN = 0x01,
    SYS_CLOSE = 0x02,
    SYS_WRITEC = 0x03,
    SYS_WRITE0 = 0x04,
    SYS_WRITE = 0x05,
    SYS_READ = 0x06,
    SYS_FLEN = 0x0C,
    SYS_EXIT = 0x18,
    SYS_EXIT_EXTENDED = 0x20
};

#define ADP_STOPPED_APPLICATION_EXIT 0x20026u
#define ADP_STOPPED_RUNTIME_ERROR 0x20023u

/* r0 = operation, r1 = argument (usually a pointer to a word block);
 * the result comes back in r0. "memory": the host reads/writes our RAM. */
static uint32_t sh_call(uint32_t op, const void *arg)
{
    register uint32_t r0 __asm__("r0") = op;
    register const void *r1 __asm__("r1") = arg;
    __asm__ volatile("bkpt 0xAB" : "+r"(r0) : "r"(r1) : "memory");
    return r0;
}

static uint32_t word(const void *p) { return (uint32_t)(uintptr_t)p; }

/* Handles and counts are 32-bit words; results are signed (-1 = error). */
static long sh_result(uint32_t r) { return (long)(int32_t)r; }

void semihost_writec(char c) { (void)sh_call(SYS_WRITEC, &c); }

void semihost_write0(const char *s) { (void)sh_call(SYS_WRITE0, s); }

long semihost_open(const char *path, unsigned mode)
{
    const uint32_t args[3] = {word(path), mode, (uint32_t)strlen(path)};
    return sh_result(sh_call(SYS_OPEN, args));
}

long semihost_close(long handle)
{
    const uint32_t args[1] = {(uint32_t)handle};
    return sh_result(sh_call(SYS_CLOSE, args));
}

long semihost_write(long handle, const void *buf, unsigned long len)
{
    const uint32_t args[3] = {(uint32_t)handle, word(buf), (uint32_t)len};
    return sh_result(sh_call(SYS_WRITE, args));
}

long semihost_read(long handle, void *buf, unsigned long len)
{
    const uint32_t args[3] = {(uint32_t)handle, word(buf), (uint32_t)len};
    return sh_result(sh_call(SYS_READ, args));
}

long semihost_flen(long handle)
{
    const uint32_t args[1] = {(uint32_t)handle};
    return sh_result(sh_call(SYS_FLEN, args));
}

long semihost_stdio(int fd)
{
    /* ARM-compat semihosting pre-opens nothing: handle 1 is not stdout. */
    static long tt[2] = {-1, -1};
    if (fd != 1 && fd != 2) {
        return -1;
    }
    if (tt[fd - 1] < 0) {
        tt[fd - 1] = semihost_open(":tt", fd == 1 ? SEMIHOST_MODE_W
                                                  : SEMIHOST_MODE_A);
    }
    return tt[fd - 1];
}

void semihost_exit(int code)
{
    /* QEMU passes the code to exit(), which keeps the low 8 bits: 256 would
     * read as success, so anything outside 0..255 becomes 255. */
    const uint32_t status = (code < 0 || code > 255) ? 255u : (uint32_t)code;
    const uint32_t args[2] = {ADP_STOPPED_APPLICATION_EXIT, status};
    (void)sh_call(SYS_EXIT_EXTENDED, args);
    /* Only reached if the host lacks SYS_EXIT_EXTENDED: plain SYS_EXIT can
     * still tell success from failure. */
    (void)sh_call(SYS_EXIT, (const void *)(uintptr_t)(code == 0
                  ? ADP_STOPPED_APPLICATION_EXIT : ADP_STOPPED_RUNTIME_ERROR));
    for (;;) {
    }
}
