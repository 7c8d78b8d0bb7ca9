/* IDEC FC6A HOUR (VOCABULARY.md's Fc6aHourMeter): its rules and its machine. */
#ifndef PLCVEC_REFERENCE_FC6A_HOUR_METER_H
#define PLCVEC_REFERENCE_FC6A_HOUR_METER_H

#include "machine.h"

typedef struct fc6a_hour_meter_rules {
    long cycle;                                     /* 65536 h, in seconds */
    int (*reached)(long total, long preset);
    int keep_fraction;                              /* the ms below a second carry to the next scan */
    int fraction_offset;                            /* where the fraction lives: 0 = its own work area */
} fc6a_hour_meter_rules;

/* What the instruction keeps from one execution to the next (all 0 at power on). */
typedef struct fc6a_hour_meter_state {
    long fraction_ms;
    int wrapped;                /* recompared: D2 stays on across a wrap */
    int input_was_on;           /* the input before the first scan counts as off */
    int executed;               /* an execution since the CPU started */
    int last_check_invalid;     /* the last check of S1 found it invalid (none yet: valid) */
} fc6a_hour_meter_state;

extern const fc6a_hour_meter_rules fc6a_hour_meter_reference_rules;

/* One scan on m; PLCVEC_NONE (not a contact). */
int fc6a_hour_meter_execute(machine *m, const fc6a_hour_meter_rules *r, fc6a_hour_meter_state *st,
                            const plcvec_vector *v, const plcvec_step *step);

#endif
