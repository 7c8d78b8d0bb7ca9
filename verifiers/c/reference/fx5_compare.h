/* Mitsubishi FX5 LDTM/ANDTM/ORTM and LDDT/ANDDT/ORDT (VOCABULARY.md's Fx5Compare): its rules, a
 * struct a mutant can replace one member of, and its machine. */
#ifndef PLCVEC_REFERENCE_FX5_COMPARE_H
#define PLCVEC_REFERENCE_FX5_COMPARE_H

#include "machine.h"

/* One field of (s1)/(s2): word offset, valid range, (s3) bit that selects it. */
typedef struct fx5_field {
    int offset, lo, hi, bit;
} fx5_field;

typedef struct fx5_compare_rules {
    const fx5_field *time_fields, *date_fields;     /* most significant first */
    /* -1/0/1: the selected fields compared, most significant first. */
    int (*order)(const fx5_field *fields, const uint16_t *s1, const uint16_t *s2, unsigned s3);
    unsigned clock_bit;                             /* (s3) bit 15: compare with the clock */
    int (*selector_valid)(unsigned s3);             /* bits 3..14 zero and some field selected */
    int (*in_range)(const memory *m, address base, int words);
    void (*sm709)(memory *m, int error);            /* after each execution */
    int (*and_form)(int rlo, int contact);          /* AND: rlo AND contact, not executed while rlo is off */
} fx5_compare_rules;

extern const fx5_compare_rules fx5_compare_reference_rules;

/* One scan on m; the contact result. */
int fx5_compare_execute(machine *m, const fx5_compare_rules *r, const plcvec_vector *v, const plcvec_step *step);

#endif
