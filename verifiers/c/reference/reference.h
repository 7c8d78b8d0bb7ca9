/* The C reference implementation of the five families, written from the manual excerpts and the
 * contract: plain C, one file per family (fx5_compare, fx5_time_add, fc6a_hour_meter,
 * cp1e_time_compare), each executing on a machine (machine.h) and knowing nothing of this file.
 * Each family's rules are a struct of data and functions, so that a mutant (mutants/) can replace
 * exactly one of them, as a subclass would. */
#ifndef PLCVEC_REFERENCE_H
#define PLCVEC_REFERENCE_H

#include "cp1e_time_compare.h"
#include "fc6a_hour_meter.h"
#include "fx5_compare.h"
#include "fx5_time_add.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct plcvec_reference {
    const char *name;
    uint8_t declared[PLCVEC_INTERPRETATION_COUNT];  /* what it says it follows (machine.follows: what it does) */
    plcvec_choice choices[PLCVEC_INTERPRETATION_COUNT];
    fx5_compare_rules fx5;
    fx5_time_add_rules tadd;
    fc6a_hour_meter_rules hour;
    cp1e_time_compare_rules cp1e;
    machine machine;
} plcvec_reference;

/* The reference following the default alternatives. */
void plcvec_reference_init(plcvec_reference *ref);
/* Follow (and declare) an alternative; 0, or -1 for an unknown interpretation/alternative. */
int plcvec_reference_choose(plcvec_reference *ref, const char *interpretation, const char *alternative);
/* The reference as a plcvec_impl (which points into ref). */
plcvec_impl plcvec_reference_impl(plcvec_reference *ref);

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
