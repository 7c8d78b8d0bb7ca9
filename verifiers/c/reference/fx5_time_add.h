/* Mitsubishi FX5 TADD/TADDP (VOCABULARY.md's Fx5TimeAdd): its rules and its machine. */
#ifndef PLCVEC_REFERENCE_FX5_TIME_ADD_H
#define PLCVEC_REFERENCE_FX5_TIME_ADD_H

#include "machine.h"

typedef struct fx5_time_add_rules {
    const char *const *carry_flags;                 /* SM700, SM8022 */
    int n_carry_flags;
    int hour_max;                                   /* 23 */
    int (*in_range)(const memory *m, address base, int words);
    int (*pulse)(int en, int previous_en, plcvec_instruction instruction);  /* execute this scan? */
    int flags_written;                              /* 0: the flags are never written */
    /* (s1) + (s2) in seconds, read (and (d) written meanwhile) as TADD-OVERLAP says */
    long (*sum_seconds)(machine *mc, address s1, address s2, address d);
} fx5_time_add_rules;

typedef struct fx5_time_add_state {
    int previous_en;
} fx5_time_add_state;

extern const fx5_time_add_rules fx5_time_add_reference_rules;

/* The reference's sum_seconds: TADD-OVERLAP followed. */
long fx5_time_add_sum_seconds(machine *mc, address s1, address s2, address d);

/* One scan on m; PLCVEC_NONE (not a contact). */
int fx5_time_add_execute(machine *m, const fx5_time_add_rules *r, fx5_time_add_state *st, const plcvec_vector *v,
                         const plcvec_step *step);

#endif
