/* Known failures: what a listed vector's verdict becomes, and the message of a listed id the suite
 * does not have (TEXT.md, "Known-failure messages"). The file itself is known_file.c's. */
#ifndef PLCVEC_KNOWN_H
#define PLCVEC_KNOWN_H

#include "plcvec/plcvec.h"

/* The message of a listed id that names no vector of the suite: the vector it was merged into, or
 * that it is to be removed. */
void plcvec_known_unknown_message(const plcvec_known_failure *k, char *buf, size_t size);

#endif
