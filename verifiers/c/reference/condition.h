/* The six comparisons of the contact families (FX5 LDTM/LDDT, CP1E =DT ...), as values. */
#ifndef PLCVEC_REFERENCE_CONDITION_H
#define PLCVEC_REFERENCE_CONDITION_H

#include "plcvec/plcvec.h"

/* Whether an instruction's condition (= <> < <= > >=) holds for an ordering of s1 against s2
 * (-1, 0, 1). */
int condition_holds(plcvec_condition condition, int order);

#endif
