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

/* The operands each family reads: "d" must name a device, "k" may be a constant too. */
static const char *const operands[PLCVEC_FAMILY_COUNT][4][2] = {
    [PLCVEC_FAMILY_FX5_TIME_COMPARE] = {{"s1", "d"}, {"s2", "d"}, {"s3", "k"}},
    [PLCVEC_FAMILY_FX5_DATE_COMPARE] = {{"s1", "d"}, {"s2", "d"}, {"s3", "k"}},
    [PLCVEC_FAMILY_FX5_TIME_ADD] = {{"s1", "d"}, {"s2", "d"}, {"d", "d"}},
    [PLCVEC_FAMILY_FC6A_HOUR_METER] = {{"D1", "d"}, {"D2", "d"}, {"S1", "k"}},
    [PLCVEC_FAMILY_CP1E_TIME_COMPARE] = {{"S1", "d"}, {"S2", "d"}, {"C", "k"}},
};

static int run(void *ctx, const plcvec_vector *v, plcvec_out *out)
{
    plcvec_reference *ref = ctx;
    memory *m = &ref->mem;
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
        if (ref->input_error) {
            const char *why = ref->input_error;
            ref->input_error = NULL;
            return plcvec_out_error(out, why);
        }
        memory_report(m, out, result);
    }
    return 0;
}

int reference_condition_holds(plcvec_condition condition, int order)
{
    switch (condition) {
    case PLCVEC_CONDITION_EQ: return order == 0;
    case PLCVEC_CONDITION_NE: return order != 0;
    case PLCVEC_CONDITION_LT: return order < 0;
    case PLCVEC_CONDITION_LE: return order <= 0;
    case PLCVEC_CONDITION_GT: return order > 0;
    case PLCVEC_CONDITION_GE: return order >= 0;
    default: return 0;
    }
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
