/* The reference as a plcvec implementation: each vector from its own initial state, one family
 * machine per vector, the whole device image reported after every step. */
#include <stdio.h>
#include <string.h>

#include "reference.h"

void plcvec_reference_init(plcvec_reference *ref)
{
    memset(ref, 0, sizeof *ref);
    ref->name = "plcvec-c-reference";
    for (int i = 0; i < PLCVEC_INTERPRETATION_COUNT; i++)
        ref->declared[i] = ref->machine.follows[i] = plcvec_interpretations[i].default_alternative;
    ref->fx5 = fx5_compare_reference_rules;
    ref->tadd = fx5_time_add_reference_rules;
    ref->hour = fc6a_hour_meter_reference_rules;
    ref->cp1e = cp1e_time_compare_reference_rules;
}

int plcvec_reference_choose(plcvec_reference *ref, const char *interpretation, const char *alternative)
{
    int i = plcvec_interpretation_named(interpretation);
    int a = plcvec_alternative_named(i, alternative);
    if (a < 0)
        return -1;
    ref->declared[i] = ref->machine.follows[i] = (uint8_t)a;
    return 0;
}

/* The operands each family reads: "d" must name a device, "k" may be a constant too. */
static const char *const operands[PLCVEC_FAMILY_COUNT][4][2] = {
    [PLCVEC_FAMILY_FX5_TIME_COMPARE] = {{"s1", "d"}, {"s2", "d"}, {"s3", "k"}},
    [PLCVEC_FAMILY_FX5_DATE_COMPARE] = {{"s1", "d"}, {"s2", "d"}, {"s3", "k"}},
    [PLCVEC_FAMILY_FX5_TIME_ADD] = {{"s1", "d"}, {"s2", "d"}, {"d", "d"}},
    [PLCVEC_FAMILY_FC6A_HOUR_METER] = {{"D1", "d"}, {"D2", "d"}, {"S1", "k"}},
    [PLCVEC_FAMILY_CP1E_TIME_COMPARE] = {{"S1", "d"}, {"S2", "d"}, {"C", "k"}},
};

/* One scan of v's family on the reference's machine. */
static int execute(plcvec_reference *ref, fx5_time_add_state *tadd, fc6a_hour_meter_state *hour, const plcvec_vector *v,
                   const plcvec_step *step)
{
    machine *m = &ref->machine;
    switch (v->family) {
    case PLCVEC_FAMILY_FX5_TIME_COMPARE:
    case PLCVEC_FAMILY_FX5_DATE_COMPARE:
        return fx5_compare_execute(m, &ref->fx5, v, step);
    case PLCVEC_FAMILY_FX5_TIME_ADD:
        return fx5_time_add_execute(m, &ref->tadd, tadd, v, step);
    case PLCVEC_FAMILY_FC6A_HOUR_METER:
        return fc6a_hour_meter_execute(m, &ref->hour, hour, v, step);
    case PLCVEC_FAMILY_CP1E_TIME_COMPARE:
        return cp1e_time_compare_execute(m, &ref->cp1e, v, step);
    default:
        return -2;
    }
}

static int run(void *ctx, const plcvec_vector *v, plcvec_out *out)
{
    plcvec_reference *ref = ctx;
    memory *m = &ref->machine.mem;
    for (int i = 0; i < 4 && operands[v->family][i][0]; i++) {
        const plcvec_operand *op = plcvec_operand_named(v, operands[v->family][i][0]);
        if (!op || (op->is_constant && operands[v->family][i][1][0] == 'd')) {
            char message[96];
            snprintf(message, sizeof message, "%s needs the operand %s as a %s", plcvec_instruction_names[v->instruction],
                     operands[v->family][i][0], operands[v->family][i][1][0] == 'd' ? "device" : "device or constant");
            return plcvec_out_error(out, message);
        }
    }
    memory_load(m, v);
    fx5_time_add_state tadd = {0};
    fc6a_hour_meter_state hour = {0};
    for (size_t s = 0; s < v->n_steps; s++) {
        const plcvec_step *step = &v->steps[s];
        for (size_t i = 0; i < step->n_set; i++)
            memory_write_named(m, step->set[i].device, (plcvec_type)step->set[i].type, step->set[i].value);
        int result = execute(ref, &tadd, &hour, v, step);
        if (result == -2)
            return plcvec_out_skip(out, "the reference does not know this family");
        if (m->overflow)
            return plcvec_out_error(out, "the reference's memory is full");
        if (ref->machine.input_error) {
            const char *why = ref->machine.input_error;
            ref->machine.input_error = NULL;
            return plcvec_out_error(out, why);
        }
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
