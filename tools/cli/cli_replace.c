/* SPDX-License-Identifier: MIT */
/* A file replaced whole or not at all (cli.h, "files replaced whole"): the
 * text goes to a temporary file beside the target (TARGET.XXXXXX), synced
 * and closed, each step checked; only the caller's commit renames it over
 * the target (atomic on POSIX file systems) and syncs the directory. Any
 * failure before removes the temporary file and leaves the target as it was. */
#ifndef _XOPEN_SOURCE
#define _XOPEN_SOURCE 700 /* realpath() (POSIX, in glibc's headers under XSI) */
#endif
#include "cli.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

int cli_header_path(const char *cmd, const char *option, const char *dir, const char *name,
                    char *path)
{
    struct stat st;
    char q[CLI_QUOTE_SIZE];
    if (dir == NULL) {
        (void)sprintf(path, "%s.h", name); /* NAME: a C identifier, < 200 chars */
        return 0;
    }
    if (strlen(dir) + strlen(name) + 4u > CLI_PATH_MAX) {
        return cli_fail(cmd, "option %s: %s: too long a path", option, cli_quote(q, dir));
    }
    if (stat(dir, &st) != 0) {
        const int err = errno;
        return cli_fail(cmd, "option %s: %s: %s", option, cli_quote(q, dir), strerror(err));
    }
    if (!S_ISDIR(st.st_mode)) {
        return cli_fail(cmd, "option %s: %s: not a directory", option, cli_quote(q, dir));
    }
    (void)sprintf(path, "%s%s%s.h", dir, dir[strlen(dir) - 1u] == '/' ? "" : "/", name);
    return 0;
}

int cli_replace_check(cli_replace_t *r, const char *cmd, const char *what, const char *path)
{
    struct stat st;
    const char *slash;
    char *target = NULL;
    size_t n = strlen(path);
    r->cmd = cmd;
    r->what = what;
    r->tmp[0] = '\0';
    if (n > 0u && lstat(path, &st) == 0 && S_ISLNK(st.st_mode)) {
        /* written through: the file the link names is replaced, the link kept */
        if ((target = realpath(path, NULL)) == NULL) {
            const int err = errno;
            return cli_fail(cmd, "%s: a symbolic link to nothing (%s): cannot write the %s",
                            cli_file_name(path), strerror(err), what);
        }
        path = target;
        n = strlen(path);
    }
    if (n == 0u || n + 8u > sizeof r->path) {
        free(target);
        return cli_fail(cmd, "%s path empty or longer than %u bytes", what,
                        (unsigned)(sizeof r->path - 8u));
    }
    memcpy(r->path, path, n + 1u);
    free(target);
    path = r->path;
    /* the directory to sync after the rename: the path's, or "." */
    slash = strrchr(path, '/');
    if (slash == NULL) {
        (void)strcpy(r->dir, ".");
    } else if (slash == path) {
        (void)strcpy(r->dir, "/");
    } else {
        memcpy(r->dir, path, (size_t)(slash - path));
        r->dir[slash - path] = '\0';
    }
    if (stat(r->path, &st) == 0 && S_ISDIR(st.st_mode)) {
        return cli_fail(cmd, "%s: is a directory: cannot write the %s", r->path, what);
    }
    if (stat(r->path, &st) == 0 && !S_ISREG(st.st_mode)) {
        /* a rename would put a file in its place (as root, /dev/null's) */
        return cli_fail(cmd, "%s: not a regular file (a device, pipe or socket): cannot write "
                             "the %s",
                        r->path, what);
    }
    return 0;
}

/* Whether paths a and b name one file: one inode when both exist, else the
 * same name in the same directory. */
static int same_file(const char *a, const char *b)
{
    struct stat sa, sb;
    const char *na = strrchr(a, '/'), *nb = strrchr(b, '/');
    char da[CLI_PATH_MAX], db[CLI_PATH_MAX];
    if (stat(a, &sa) == 0 && stat(b, &sb) == 0) {
        return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
    }
    na = na != NULL ? na + 1 : a;
    nb = nb != NULL ? nb + 1 : b;
    if (strcmp(na, nb) != 0 || (size_t)(na - a) >= sizeof da || (size_t)(nb - b) >= sizeof db) {
        return 0;
    }
    (void)sprintf(da, "%.*s", na == a ? 1 : (int)(na - a), na == a ? "." : a);
    (void)sprintf(db, "%.*s", nb == b ? 1 : (int)(nb - b), nb == b ? "." : b);
    return stat(da, &sa) == 0 && stat(db, &sb) == 0 && sa.st_dev == sb.st_dev &&
           sa.st_ino == sb.st_ino;
}

int cli_outputs_distinct(const char *cmd, const char *input, const char *header, const char *save)
{
    const int from_file = input != NULL && strcmp(input, "-") != 0;
    if (save != NULL && from_file && same_file(save, input)) {
        return cli_fail(cmd, "option --save: %s is the record being read: the model file would "
                             "replace it",
                        cli_file_name(save));
    }
    if (header != NULL && from_file && same_file(header, input)) {
        return cli_fail(cmd, "option --header: %s is the record being read: the header would "
                             "replace it",
                        cli_file_name(header));
    }
    if (header != NULL && save != NULL && same_file(header, save)) {
        return cli_fail(cmd, "options --header and --save both name %s: the header and the model "
                             "file would replace each other",
                        cli_file_name(save));
    }
    return 0;
}

void cli_replace_discard(cli_replace_t *r)
{
    if (r->tmp[0] != '\0') {
        (void)remove(r->tmp);
        r->tmp[0] = '\0';
    }
}

int cli_replace_write(cli_replace_t *r, const char *text, size_t len)
{
    struct stat st;
    mode_t mode, mask;
    FILE *f;
    int fd, err;
    /* the mode the target has, or a new file's (0666 less the umask; mkstemp gives 0600) */
    mask = umask(0);
    (void)umask(mask);
    mode = stat(r->path, &st) == 0 ? (mode_t)(st.st_mode & 07777) : (mode_t)(0666 & ~mask);
    (void)sprintf(r->tmp, "%s.XXXXXX", r->path);
    if ((fd = mkstemp(r->tmp)) < 0) {
        err = errno;
        r->tmp[0] = '\0';
        return cli_fail(r->cmd, "%s: cannot write the %s: %s (creating a temporary file "
                                "beside it)",
                        r->path, r->what, strerror(err));
    }
    if (fchmod(fd, mode) != 0 || (f = fdopen(fd, "w")) == NULL) {
        err = errno;
        (void)close(fd);
        cli_replace_discard(r);
        return cli_fail(r->cmd, "%s: cannot write the %s: %s", r->path, r->what, strerror(err));
    }
    errno = 0;
    if (fwrite(text, 1u, len, f) != len || fflush(f) != 0 || fsync(fileno(f)) != 0) {
        err = errno;
        (void)fclose(f);
        cli_replace_discard(r);
        return cli_fail(r->cmd, "%s: cannot write the %s: %s", r->path, r->what, strerror(err));
    }
    if (fclose(f) != 0) {
        err = errno;
        cli_replace_discard(r);
        return cli_fail(r->cmd, "%s: cannot write the %s: %s", r->path, r->what, strerror(err));
    }
    return 0;
}

int cli_replace_commit(cli_replace_t *r)
{
    int fd;
    if (rename(r->tmp, r->path) != 0) {
        const int err = errno;
        cli_replace_discard(r);
        return cli_fail(r->cmd, "%s: cannot replace the %s: %s (the results above are "
                                "valid, the %s was not written)",
                        r->path, r->what, strerror(err), r->what);
    }
    r->tmp[0] = '\0';
    /* the rename itself to disk: best effort */
    if ((fd = open(r->dir, O_RDONLY)) >= 0) {
        (void)fsync(fd);
        (void)close(fd);
    }
    (void)fprintf(stderr, "hyst %s: wrote %s\n", r->cmd, r->path);
    return 0;
}
