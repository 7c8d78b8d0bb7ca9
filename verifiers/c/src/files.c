/* Files the C library opens itself, looked at before they are opened: a named pipe nobody writes,
 * a device that never ends (/dev/zero) or a loop of symbolic links where the known-failures file
 * belongs would hang or fail the run in a way that names nothing (CONTRACT.md, "Loading"). */
#define _POSIX_C_SOURCE 200809L /* fdopen, O_NONBLOCK, S_ISSOCK */
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "files.h"

/* What is at `mode` when it is not a regular file, in CONTRACT.md's words; NULL for a regular file. */
static const char *kind_of(mode_t mode)
{
    if (S_ISREG(mode))
        return NULL;
    if (S_ISFIFO(mode))
        return "not a regular file (a named pipe)";
    if (S_ISCHR(mode))
        return "not a regular file (a character device)";
    if (S_ISBLK(mode))
        return "not a regular file (a block device)";
    if (S_ISSOCK(mode))
        return "not a regular file (a socket)";
    if (S_ISDIR(mode))
        return "not a regular file (a folder)";
    return "not a regular file";
}

int plcvec_file_check(const char *path, char *err, size_t errlen)
{
    struct stat st;
    if (stat(path, &st) != 0) {
        if (errno != ELOOP)
            return 0;       /* nothing there, or unreadable: opening it says which */
        snprintf(err, errlen, "%s: a loop of symbolic links", path);
        return -1;
    }
    const char *kind = kind_of(st.st_mode);
    if (kind) {
        snprintf(err, errlen, "%s: %s", path, kind);
        return -1;
    }
    return 0;
}

FILE *plcvec_file_open(const char *path, char *why, size_t whylen)
{
    struct stat st;
    if (stat(path, &st) == 0 && kind_of(st.st_mode)) {
        snprintf(why, whylen, "%s", kind_of(st.st_mode));
        return NULL;
    }
    int fd = open(path, O_RDONLY | O_NONBLOCK);
    if (fd < 0) {
        snprintf(why, whylen, "%s", errno == ELOOP ? "a loop of symbolic links" : strerror(errno));
        return NULL;
    }
    const char *kind = fstat(fd, &st) == 0 ? kind_of(st.st_mode) : "cannot be read";
    FILE *f = kind ? NULL : fdopen(fd, "rb");
    if (!f) {
        snprintf(why, whylen, "%s", kind ? kind : strerror(errno));
        close(fd);
    }
    return f;
}
