/* A vector's expectations under the alternatives followed (CONTRACT.md, "Declaring your
 * interpretation"): which entry applies, the state it expects before and after each step, and the
 * devices it leaves unjudged. Everything here reads the vector alone, never an answer. */
#ifndef PLCVEC_EXPECT_H
#define PLCVEC_EXPECT_H

#include "plcvec/plcvec.h"

/* The entry of `alternatives` a vector is judged by when `alternative[i]` is followed for every
 * interpretation i: NULL for the vector's own steps (its defaults), &plcvec_expect_missing when
 * the vector offers no expectation for that combination (a damaged suite). */
extern const plcvec_alternative plcvec_expect_missing;
const plcvec_alternative *plcvec_expect_entry(const plcvec_vector *v, const uint8_t *alternative);
/* The expectation of step s under `entry` (NULL: the vector's own). Inline, as those below. */
static inline const plcvec_expect *plcvec_expect_step(const plcvec_vector *v, const plcvec_alternative *entry,
                                                      size_t s)
{
    return entry ? &entry->expect[s] : &v->steps[s].expect;
}
/* The alternative `entry` follows for interpretation `interp` (the default for NULL); -1: none. */
int plcvec_expect_offered(const plcvec_alternative *entry, int interp);
/* 1 when `entry` leaves `device` unjudged (schema 1.1's unjudged map). */
int plcvec_expect_unjudged(const plcvec_alternative *entry, int device);

/* Inline: they run for every device of every vector judged. */
static inline int plcvec_expect_scratch(const plcvec_vector *v, int device)
{
    for (size_t i = 0; i < v->n_scratch; i++)
        if (v->scratch[i] == device)
            return 1;
    return 0;
}

/* A state: devices and their values, each device once. */
static inline void plcvec_state_put(plcvec_cell *state, size_t *n, const plcvec_cell *c)
{
    for (size_t i = 0; i < *n; i++)
        if (state[i].device == c->device) {
            state[i] = *c;
            return;
        }
    state[(*n)++] = *c;
}

const plcvec_cell *plcvec_state_cell(const plcvec_cell *state, size_t n, int device);
/* The most cells a state of v under `entry` can hold. */
size_t plcvec_expect_capacity(const plcvec_vector *v, const plcvec_alternative *entry);
/* The state the vector gives step k under `entry` (scratch left out): the initial devices, each
 * earlier step's `set` and changes, then step k's `set`. Returns the number of cells. */
size_t plcvec_expect_before(const plcvec_vector *v, const plcvec_alternative *entry, size_t k, plcvec_cell *state);
/* The expected value after step k under `entry` of `device` (-1: the contact result): 1 and *cell
 * when the expectation lists it, 0 otherwise. */
int plcvec_expect_value(const plcvec_vector *v, const plcvec_alternative *entry, size_t k, int device, plcvec_cell *cell);
/* Whether a vector that passed under `followed` passes under `entry` too (TEXT.md, "The
 * inference"; unjudged.md): every step's result equal, and every device judged under `entry`
 * judged under `followed` with the same value and type. -1 when out of memory. */
int plcvec_expect_same(const plcvec_vector *v, const plcvec_alternative *entry, const plcvec_alternative *followed);

#endif
