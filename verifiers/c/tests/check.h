/* The tests' one assertion: a failed check names its file, line and condition, and is counted. */
#ifndef PLCVEC_TESTS_CHECK_H
#define PLCVEC_TESTS_CHECK_H

#include <stdio.h>

static int failures;

#define CHECK(cond)                                                                     \
    do {                                                                                \
        if (!(cond)) {                                                                  \
            fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond);    \
            failures++;                                                                 \
        }                                                                               \
    } while (0)

/* `text` holds `want`, or the check fails showing both. */
#define CHECK_HAS(text, want)                                                                           \
    do {                                                                                                \
        if (!strstr((text), (want))) {                                                                  \
            fprintf(stderr, "%s:%d: no '%s' in:\n%s\n", __FILE__, __LINE__, (want), (text));            \
            failures++;                                                                                 \
        }                                                                                               \
    } while (0)

#endif
