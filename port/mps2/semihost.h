/* SPDX-License-Identifier: MIT */
/**
 * @file semihost.h
 * @brief Arm semihosting calls (bkpt 0xAB) used by port/mps2.
 *
 * Semihosting needs QEMU (-semihosting-config enable=on) or a debugger:
 * on bare hardware without one, bkpt escalates to HardFault.
 */
#ifndef HYST_SEMIHOST_H
#define HYST_SEMIHOST_H

/** Open modes of SYS_OPEN (index into "r","rb","r+","r+b","w","wb",...). */
#define SEMIHOST_MODE_R  0u
#define SEMIHOST_MODE_RB 1u
#define SEMIHOST_MODE_W  4u
#define SEMIHOST_MODE_A  8u

/** @brief SYS_WRITEC: one character to the debug console (QEMU: stderr). */
void semihost_writec(char c);

/** @brief SYS_WRITE0: a string to the debug console (QEMU: stderr). */
void semihost_write0(const char *s);

/** @brief SYS_OPEN: returns a host handle, or -1. ":tt" is the console. */
long semihost_open(const char *path, unsigned mode);

/** @brief SYS_CLOSE: returns 0, or -1. */
long semihost_close(long handle);

/** @brief SYS_WRITE: returns the number of bytes NOT written (0 = all). */
long semihost_write(long handle, const void *buf, unsigned long len);

/** @brief SYS_READ: returns the number of bytes NOT read (len = EOF). */
long semihost_read(long handle, void *buf, unsigned long len);

/** @brief SYS_FLEN: file length in bytes, or -1. */
long semihost_flen(long handle);

/**
 * @brief Host handle for stdout (@p fd 1) or stderr (@p fd 2), opened once
 * as ":tt" for "w" or "a" (QEMU maps these to its own stdout/stderr), or -1.
 */
long semihost_stdio(int fd);

/**
 * @brief SYS_EXIT_EXTENDED with ADP_Stopped_ApplicationExit: QEMU exits
 * with @p code as its process status; codes outside 0..255 become 255.
 */
__attribute__((noreturn)) void semihost_exit(int code);

#endif /* HYST_SEMIHOST_H */
