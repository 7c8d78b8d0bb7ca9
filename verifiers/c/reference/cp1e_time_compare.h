/* Omron CP1E LD/AND/OR =DT ... >=DT (VOCABULARY.md's Cp1eTimeCompare): its rules and its machine. */
#ifndef PLCVEC_REFERENCE_CP1E_TIME_COMPARE_H
#define PLCVEC_REFERENCE_CP1E_TIME_COMPARE_H

#include "machine.h"

typedef struct cp1e_field {
    int offset, byte, lo, hi, bit;
} cp1e_field;

typedef struct cp1e_time_compare_rules {
    const cp1e_field *fields;                       /* 6, year first */
    int (*is_bcd)(unsigned byte);
    int (*and_form)(int rlo, int contact);          /* AND: rlo AND contact */
    int reflect_flags;                              /* the arithmetic flags are written */
    int (*in_range)(const memory *m, address base, int words);
} cp1e_time_compare_rules;

extern const cp1e_time_compare_rules cp1e_time_compare_reference_rules;

/* One scan on m; the contact result. */
int cp1e_time_compare_execute(machine *m, const cp1e_time_compare_rules *r, const plcvec_vector *v,
                              const plcvec_step *step);

#endif
