/* Comparing an answer with an expectation (CONTRACT.md, "Comparing"), field by field. */
#ifndef PLCVEC_COMPARE_H
#define PLCVEC_COMPARE_H

#include "plcvec/plcvec.h"

typedef struct plcvec_problems {
    plcvec_problem *items;
    size_t n, cap;
} plcvec_problems;

/* The states a comparison works in, kept from vector to vector. */
typedef struct plcvec_states {
    plcvec_cell *state, *before;
    size_t cap;
} plcvec_states;

/* The differences between the answer in `out` and v's expectation `entry` (NULL: its own),
 * appended to `problems`: the result and every device judged after every step, a listed device
 * reported twice, a write outside the vector (but to a declared `cpu_writes` device). -1 when out
 * of memory. */
int plcvec_compare(const plcvec_vector *v, const plcvec_alternative *entry, const plcvec_out *out,
                   const char *const *cpu_writes, plcvec_states *states, plcvec_problems *problems);
/* TEXT.md's order of problems: by step, the result first, then the devices by name. */
int plcvec_problem_order(const void *a, const void *b);

#endif
