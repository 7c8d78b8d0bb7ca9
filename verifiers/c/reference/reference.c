/* The reference as a plcvec implementation: each vector from its own initial state, one family
 * machine per vector, the whole device image reported after every step. */
#include <string.h>

#include "reference.h"

void plcvec_reference_init(plcvec_reference *ref)
{
    memset(ref, 0, sizeof *ref);
    ref->name = "plcvec-c-reference";
    for (int i = 0; i < PLCVEC_INTERPRETATION_COUNT; i++)
        ref->declared[i] = ref->follows[i] = plcvec_interpretations[i].default_alternative;
    ref->fx5 = fx5_reference_rules;
    ref->tadd = tadd_reference_rules;
    ref->hour = hour_reference_rules;
    ref->cp1e = cp1e_reference_rules;
}

int plcvec_reference_choose(plcvec_reference *ref, const char *interpretation, const char *alternative)
{
    int i = plcvec_interpretation_named(interpretation);
    int a = plcvec_alternative_named(i, alternative);
    if (a < 0)
        return -1;
    ref->declared[i] = ref->follows[i] = (uint8_t)a;
    return 0;
}

static int run(void *ctx, const plcvec_vector *v, plcvec_out *out)
{
    plcvec_reference *ref = ctx;
    memory *m = &ref->mem;
    memory_load(m, v);
    tadd_state tadd = {0};
    hour_state hour = {0};
    for (size_t s = 0; s < v->n_steps; s++) {
        const plcvec_step *step = &v->steps[s];
        for (size_t i = 0; i < step->n_set; i++)
            memory_write_named(m, step->set[i].device, (plcvec_type)step->set[i].type, step->set[i].value);
        int result;
        switch (v->family) {
        case PLCVEC_FAMILY_FX5_TIME_COMPARE:
        case PLCVEC_FAMILY_FX5_DATE_COMPARE:
            result = fx5_execute(ref, v, step);
            break;
        case PLCVEC_FAMILY_FX5_TIME_ADD:
            result = tadd_execute(ref, &tadd, v, step);
            break;
        case PLCVEC_FAMILY_FC6A_HOUR_METER:
            result = hour_execute(ref, &hour, v, step);
            break;
        case PLCVEC_FAMILY_CP1E_TIME_COMPARE:
            result = cp1e_execute(ref, v, step);
            break;
        default:
            return plcvec_out_skip(out, "the reference does not know this family");
        }
        if (m->overflow)
            return plcvec_out_error(out, "the reference's memory is full");
        memory_report(m, out, result);
    }
    return 0;
}

plcvec_impl plcvec_reference_impl(plcvec_reference *ref)
{
    plcvec_impl impl = {0};
    size_t n = 0;
    for (int i = 0; i < PLCVEC_INTERPRETATION_COUNT; i++) {
        ref->choices[n].interpretation = (uint8_t)i;
        ref->choices[n++].alternative = ref->declared[i];
    }
    impl.name = ref->name;
    impl.ctx = ref;
    impl.choices = ref->choices;
    impl.n_choices = n;
    impl.run = run;
    return impl;
}
