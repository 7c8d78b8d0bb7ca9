/* Files the C library opens itself (the known-failures file it reads, the one it writes): only
 * regular files, so that nothing can hang a run before it starts (CONTRACT.md, "Loading"). */
#ifndef PLCVEC_FILES_H
#define PLCVEC_FILES_H

#include <stdio.h>

/* 0 when `path` is a regular file or nothing is there; -1 with "PATH: not a regular file (a named
 * pipe)" or "PATH: a loop of symbolic links" in err otherwise. */
int plcvec_file_check(const char *path, char *err, size_t errlen);
/* `path` opened for reading without waiting on it (a file swapped for a pipe after the check is
 * refused too); NULL with why in `why` ("No such file or directory", "not a regular file (a
 * named pipe)"), without the path. */
FILE *plcvec_file_open(const char *path, char *why, size_t whylen);

#endif
