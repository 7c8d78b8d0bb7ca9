/* The C reference implementation of the five families, written from the manual excerpts and the
 * contract: plain C, one file per family. Each family's rules are a struct of data and functions,
 * so that a mutant (mutants/) can replace exactly one of them, as a subclass would. */
#ifndef PLCVEC_REFERENCE_H
#define PLCVEC_REFERENCE_H

#include "memory.h"

#ifdef __cplusplus
extern "C" {
#endif

/* FX5 LDTM/LDDT: one field of (s1)/(s2): word offset, valid range, (s3) bit that selects it. */
typedef struct fx5_field {
    int offset, lo, hi, bit;
} fx5_field;

typedef struct fx5_rules {
    const fx5_field *time_fields, *date_fields;     /* most significant first */
    /* -1/0/1: the selected fields compared, most significant first. */
    int (*order)(const fx5_field *fields, const uint16_t *s1, const uint16_t *s2, unsigned s3);
    unsigned clock_bit;                             /* (s3) bit 15: compare with the clock */
    int (*selector_valid)(unsigned s3);             /* bits 3..14 zero and some field selected */
    int (*in_range)(const memory *m, address base, int words);
    void (*sm709)(memory *m, int error);            /* after each execution */
} fx5_rules;

typedef struct tadd_rules {
    const char *const *carry_flags;                 /* SM700, SM8022 */
    int n_carry_flags;
    int hour_max;                                   /* 23 */
    int (*in_range)(const memory *m, address base, int words);
    int (*pulse)(int en, int previous_en, plcvec_instruction instruction);  /* execute this scan? */
    int flags_written;                              /* 0: the flags are never written */
} tadd_rules;

typedef struct hour_rules {
    long cycle;                                     /* 65536 h, in seconds */
    int (*reached)(long total, long preset);
    int keep_fraction;                              /* the ms below a second carry to the next scan */
    int fraction_offset;                            /* where the fraction lives: 0 = its own work area */
} hour_rules;

typedef struct cp1e_field {
    int offset, byte, lo, hi, bit;
} cp1e_field;

typedef struct cp1e_rules {
    const cp1e_field *fields;                       /* 6, year first */
    int (*is_bcd)(unsigned byte);
    int (*and_form)(int rlo, int contact);          /* AND: rlo AND contact */
    int reflect_flags;                              /* the arithmetic flags are written */
} cp1e_rules;

typedef struct plcvec_reference {
    const char *name;
    uint8_t declared[PLCVEC_INTERPRETATION_COUNT];  /* what it says it follows */
    uint8_t follows[PLCVEC_INTERPRETATION_COUNT];   /* what it does (the same, unless a mutant) */
    plcvec_choice choices[PLCVEC_INTERPRETATION_COUNT];
    fx5_rules fx5;
    tadd_rules tadd;
    hour_rules hour;
    cp1e_rules cp1e;
    memory mem;
    const char *input_error;                        /* set by a step whose inputs cannot be read */
    int fx5_failed;                                 /* the last FX5 comparison found invalid data */
} plcvec_reference;

/* The reference following the default alternatives. */
void plcvec_reference_init(plcvec_reference *ref);
/* Follow (and declare) an alternative; 0, or -1 for an unknown interpretation/alternative. */
int plcvec_reference_choose(plcvec_reference *ref, const char *interpretation, const char *alternative);
/* The reference as a plcvec_impl (which points into ref). */
plcvec_impl plcvec_reference_impl(plcvec_reference *ref);

/* Whether an instruction's condition (= <> < <= > >=) holds for an ordering of s1 against s2
 * (-1, 0, 1). */
int reference_condition_holds(plcvec_condition condition, int order);

/* The family machines: execute one step on ref->mem; return the contact result or PLCVEC_NONE. */
typedef struct tadd_state { int previous_en; } tadd_state;
typedef struct hour_state { long fraction_ms; int wrapped; int input_was_on; } hour_state;

int fx5_execute(plcvec_reference *ref, const plcvec_vector *v, const plcvec_step *step);
int tadd_execute(plcvec_reference *ref, tadd_state *st, const plcvec_vector *v, const plcvec_step *step);
int hour_execute(plcvec_reference *ref, hour_state *st, const plcvec_vector *v, const plcvec_step *step);
int cp1e_execute(plcvec_reference *ref, const plcvec_vector *v, const plcvec_step *step);

extern const fx5_rules fx5_reference_rules;
extern const tadd_rules tadd_reference_rules;
extern const hour_rules hour_reference_rules;
extern const cp1e_rules cp1e_reference_rules;

/* The mutants (mutants/): the reference with one plausible bug each. */
typedef struct plcvec_mutant {
    const char *name;
    const char *families;                           /* the families the bug is in */
    const char *bug;
    void (*apply)(plcvec_reference *ref);
} plcvec_mutant;
extern const plcvec_mutant plcvec_mutants[];
extern const size_t plcvec_mutant_count;
const plcvec_mutant *plcvec_mutant_named(const char *name);

#ifdef __cplusplus
}
#endif
#endif
