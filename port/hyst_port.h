/* SPDX-License-Identifier: MIT */
/**
 * @file hyst_port.h
 * @brief Board contract used by hyst tests and benchmarks (not the library).
 *
 * The library itself needs none of this; tests and benchmarks do. Each port
 * (port/mps2, port/host, port/template) implements every function.
 */
#ifndef HYST_PORT_H
#define HYST_PORT_H

/* Lets -Wall see that code after hyst_port_exit() is unreachable. */
#if defined(__GNUC__)
#define HYST_PORT_NORETURN __attribute__((noreturn))
#else
#define HYST_PORT_NORETURN
#endif

#ifdef __cplusplus
extern "C" {
#endif

/** @brief Bring up whatever the console and timing pin need. Call first. */
void hyst_port_init(void);

/** @brief Write one character to the console, unbuffered. */
void hyst_port_putc(char c);

/** @brief Write a NUL-terminated string to the console, no newline added. */
void hyst_port_puts(const char *s);

/** @brief Flush stdio and end the program with @p code (0 = pass). */
HYST_PORT_NORETURN void hyst_port_exit(int code);

/**
 * @brief Mark the start of a timed region (e.g. drive a GPIO pin high).
 *
 * The marks order memory accesses only: time a non-inlined call, or store
 * the result, or the compiler may move register-only work past them.
 */
void hyst_port_timing_begin(void);

/** @brief Mark the end of a timed region (e.g. drive the pin low). */
void hyst_port_timing_end(void);

/**
 * @brief Open a host/board file for reading.
 * @param path             file name (host ports: relative to the working dir).
 * @param mode_read_binary non-zero opens as "rb", zero as "r".
 * @return a handle >= 0, or -1 on failure.
 */
long hyst_port_file_open(const char *path, int mode_read_binary);

/**
 * @brief Read up to @p len bytes into @p buf.
 * @return bytes read (0 at end of file), or -1 on error.
 */
long hyst_port_file_read(long handle, void *buf, unsigned long len);

/** @brief Close a handle from hyst_port_file_open(); -1 is ignored. */
void hyst_port_file_close(long handle);

/** @brief Length of the open file in bytes, or -1 on error. */
long hyst_port_file_length(long handle);

#ifdef __cplusplus
}
#endif

#endif /* HYST_PORT_H */
