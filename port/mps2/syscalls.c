/* SPDX-License-Identifier: MIT */
/**
 * @file syscalls.c
 * @brief The newlib system calls printf/exit need, over semihosting.
 *
 * Only stdout/stderr exist; file I/O for test data goes through
 * hyst_port_file_*() instead of fopen().
 */
#include "semihost.h"

#include <errno.h>
#include <stddef.h>
#include <stdint.h>
#include <sys/stat.h>

/* newlib declares these only while building itself. */
int _write(int fd, const void *buf, size_t len);
int _read(int fd, void *buf, size_t len);
int _close(int fd);
int _fstat(int fd, struct stat *st);
int _isatty(int fd);
long _lseek(int fd, long offset, int whence);
int _kill(int pid, int sig);
int _getpid(void);
void *_sbrk(ptrdiff_t incr);
void _exit(int status);

/* mps2_sections.ld */
extern char __heap_start[], __heap_end[];

int _write(int fd, const void *buf, size_t len)
{
    long tt = semihost_stdio(fd);
    if (tt < 0) {
        errno = EBADF;
        return -1;
    }
    long left = semihost_write(tt, buf, len); /* bytes NOT written */
    if (left < 0) {
        errno = EIO;
        return -1;
    }
    return (int)len - (int)left;
}

int _read(int fd, void *buf, size_t len)
{
    (void)buf;
    (void)len;
    if (fd != 0) {
        errno = EBADF;
        return -1;
    }
    return 0; /* stdin is always at end of file */
}

int _close(int fd)
{
    (void)fd;
    return 0;
}

int _fstat(int fd, struct stat *st)
{
    (void)fd;
    st->st_mode = S_IFCHR; /* a terminal: newlib makes stdout line-buffered */
    return 0;
}

int _isatty(int fd) { return fd >= 0 && fd <= 2; }

long _lseek(int fd, long offset, int whence)
{
    (void)fd;
    (void)offset;
    (void)whence;
    errno = ESPIPE;
    return -1;
}

int _getpid(void) { return 1; }

/* abort() (hence a failed assert) lands here: exit like a shell would. */
int _kill(int pid, int sig)
{
    if (pid == _getpid()) {
        semihost_exit(128 + sig);
    }
    errno = EINVAL;
    return -1;
}

/* The library never allocates; newlib's stdio does, once, for its buffer. */
void *_sbrk(ptrdiff_t incr)
{
    static char *brk = __heap_start;
    if (incr > __heap_end - brk || incr < __heap_start - brk) {
        errno = ENOMEM;
        return (void *)-1;
    }
    char *old = brk;
    brk += incr;
    return old;
}

void _exit(int status) { semihost_exit(status); }
