/* Interpretation choices: the alternatives declared, resolved into the one followed for each
 * interpretation, and the interpretations a verdict was judged by (TEXT.md, "judged by"). */
#ifndef PLCVEC_CHOICES_H
#define PLCVEC_CHOICES_H

#include "plcvec/plcvec.h"

/* alternative[i] for every interpretation i: the declared one, else the default. -1 with a message
 * in err when a declaration names an interpretation or alternative the suite does not have, or
 * gives one interpretation two alternatives. */
int plcvec_choices_resolve(const plcvec_impl *impl, uint8_t *alternative, char *err, size_t errlen);
/* The interpretations (bit i) that decide the field `device` (-1: the result) at step `step` of v
 * judged by `followed` (the entry of `alternative`): those for which v offers an expectation
 * differing from the followed combination in that interpretation alone that leaves the field
 * unjudged or expects another value or type of it. */
uint64_t plcvec_choices_deciders(const plcvec_vector *v, const uint8_t *alternative, const plcvec_alternative *followed,
                                 int step, int device);
/* The interpretations of `which` with their followed alternative, sorted by id, into out. */
size_t plcvec_choices_judged_by(uint64_t which, const uint8_t *alternative, plcvec_choice *out);

#endif
