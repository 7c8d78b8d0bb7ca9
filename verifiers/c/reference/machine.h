/* What every family's machine executes on: the device memory, the alternative it follows for each
 * interpretation, and why a step's inputs could not be read. Knows no family and no mutant. */
#ifndef PLCVEC_REFERENCE_MACHINE_H
#define PLCVEC_REFERENCE_MACHINE_H

#include "memory.h"

typedef struct machine {
    memory mem;
    uint8_t follows[PLCVEC_INTERPRETATION_COUNT];   /* what it does: the declared alternative, unless a mutant */
    const char *input_error;                        /* set by a step whose inputs cannot be read */
} machine;

#endif
