/* Omron SYSMAC CP1E: LD/AND/OR =DT, <>DT, <DT, <=DT, >DT, >=DT (time comparison).
 * From cp1e-time-compare-DT.txt (W483 p. 2-93). */
#include <string.h>

#include "condition.h"
#include "cp1e_time_compare.h"

/* "A351.00 to A351.07 Second (00 to 59, BCD)  A351.08 to A351.15 Minute ... A352 Hour, Day of
 * month; A353 Month, Year"; "Bits 00 to 05 of C mask the seconds, minutes, hours, day, month,
 * and year, respectively." (word offset, byte, lo, hi, C bit), the year first. */
static const cp1e_field fields[6] = {
    {2, 1, 0, 99, 5}, {2, 0, 1, 12, 4}, {1, 1, 1, 31, 3}, {1, 0, 0, 23, 2}, {0, 1, 0, 59, 1}, {0, 0, 0, 59, 0},
};

static int is_bcd(unsigned b)
{
    return (b >> 4) <= 9 && (b & 0xF) <= 9;
}

static int and_form(int rlo, int contact)
{
    return rlo && contact;
}

const cp1e_time_compare_rules cp1e_time_compare_reference_rules = {fields, is_bcd, and_form, 1, memory_in_range};

/* The flag table: rows S1 = S2, S1 > S2, S1 < S2; columns =, <>, <, <=, >, >=. */
static const char *const flag_names[6] = {"P_EQ", "P_NE", "P_LT", "P_LE", "P_GT", "P_GE"};
static const plcvec_condition flag_conditions[6] = {PLCVEC_CONDITION_EQ, PLCVEC_CONDITION_NE, PLCVEC_CONDITION_LT,
                                                    PLCVEC_CONDITION_LE, PLCVEC_CONDITION_GT, PLCVEC_CONDITION_GE};
static int flag_devices[6] = {-1, -1, -1, -1, -1, -1}, p_er = -1;

/* Error: P_ER on, the execution condition OFF. The flag table has no row for an execution without
 * a comparison result: the six flags keep their values, or (CP1E-ERROR-FLAGS=off) are written off. */
static int error(const machine *mc, memory *m)
{
    memory_write_named(m, memory_device_named("P_ER", &p_er), PLCVEC_BIT, 1);
    if (mc->follows[PLCVEC_INTERP_CP1E_ERROR_FLAGS] == PLCVEC_CP1E_ERROR_FLAGS_OFF)
        for (int s = 0; s < 6; s++)
            memory_write_named(m, memory_device_named(flag_names[s], &flag_devices[s]), PLCVEC_BIT, 0);
    return 0;
}

static int evaluate(machine *mc, const cp1e_time_compare_rules *r, const plcvec_vector *v, plcvec_condition condition)
{
    memory *m = &mc->mem;
    address s1 = memory_device(plcvec_operand_named(v, "S1")->device);
    address s2 = memory_device(plcvec_operand_named(v, "S2")->device);
    const plcvec_operand *cop = plcvec_operand_named(v, "C");
    /* "S1 to S1+2", "S2 to S2+2": three words each. One past the end of the data area (S1 or S2 in
     * one of the last two words of D) is CP1E-PAST-AREA-END, found before C or the data are read. */
    if (!r->in_range(m, s1, 3) || !r->in_range(m, s2, 3)) {
        if (mc->follows[PLCVEC_INTERP_CP1E_PAST_AREA_END] == PLCVEC_CP1E_PAST_AREA_END_PROGRAM_ERROR)
            return 0;       /* not executed: nothing written, an OFF execution condition */
        return error(mc, m);
    }
    unsigned c = (cop->is_constant ? (unsigned)cop->constant : memory_read(m, memory_device(cop->device))) & 0xFFFF;
    uint16_t a[3], b[3];
    for (int i = 0; i < 3; i++) {
        a[i] = memory_read(m, memory_offset(s1, i));
        b[i] = memory_read(m, memory_offset(s2, i));
    }
    /* Bits 06 to 15 of C: not described by the manual (CP1E-C-HIGH-BITS). */
    if ((c & 0xFFC0) && mc->follows[PLCVEC_INTERP_CP1E_C_HIGH_BITS] == PLCVEC_CP1E_C_HIGH_BITS_ERROR)
        return error(mc, m);
    /* "To mask a time value, set the corresponding bit in the control word (C) to 1." */
    int unmasked = 0;
    for (int f = 0; f < 6; f++)
        unmasked += !(c >> r->fields[f].bit & 1);
    if (!unmasked && mc->follows[PLCVEC_INTERP_CP1E_ALL_MASKED] == PLCVEC_CP1E_ALL_MASKED_ERROR)
        return error(mc, m);
    if (!unmasked && mc->follows[PLCVEC_INTERP_CP1E_ALL_MASKED] == PLCVEC_CP1E_ALL_MASKED_NOT_COMPARED) {
        /* Nothing compared, no result: OFF, the flags untouched, no error. */
        if (mc->follows[PLCVEC_INTERP_CP1E_ER_FLAG] == PLCVEC_CP1E_ER_FLAG_REFLECTS_EACH_EXECUTION)
            memory_write_named(m, memory_device_named("P_ER", &p_er), PLCVEC_BIT, 0);
        return 0;
    }
    int order = 0;
    for (int f = 0; f < 6; f++) {
        const cp1e_field *fd = &r->fields[f];
        if (c >> fd->bit & 1)
            continue;
        unsigned x = (unsigned)(a[fd->offset] >> (8 * fd->byte)) & 0xFF, y = (unsigned)(b[fd->offset] >> (8 * fd->byte)) & 0xFF;
        unsigned raw[2] = {x, y};
        for (int k = 0; k < 2; k++) {
            if (!r->is_bcd(raw[k])) {
                /* "Second (00 to 59, BCD)" ...: CP1E-NON-BCD */
                if (mc->follows[PLCVEC_INTERP_CP1E_NON_BCD] == PLCVEC_CP1E_NON_BCD_ERROR)
                    return error(mc, m);
            } else {
                int value = (int)(raw[k] >> 4) * 10 + (int)(raw[k] & 0xF);
                if ((value < fd->lo || value > fd->hi) &&
                    mc->follows[PLCVEC_INTERP_CP1E_OUT_OF_RANGE] == PLCVEC_CP1E_OUT_OF_RANGE_ERROR)
                    return error(mc, m);
            }
        }
        /* "limited to comparing 8-bit time values": for BCD the byte order is the numeric order. */
        if (order == 0 && x != y)
            order = x < y ? -1 : 1;
    }
    /* "the result of a time comparison instruction is reflected in the arithmetic flags" */
    if (r->reflect_flags)
        for (int s = 0; s < 6; s++)
            memory_write_named(m, memory_device_named(flag_names[s], &flag_devices[s]), PLCVEC_BIT, (uint16_t)condition_holds(flag_conditions[s], order));
    /* P_ER is a condition flag reflecting the instruction just executed: CP1E-ER-FLAG. */
    if (mc->follows[PLCVEC_INTERP_CP1E_ER_FLAG] == PLCVEC_CP1E_ER_FLAG_REFLECTS_EACH_EXECUTION)
        memory_write_named(m, memory_device_named("P_ER", &p_er), PLCVEC_BIT, 0);
    return condition_holds(condition, order);
}

int cp1e_time_compare_execute(machine *mc, const cp1e_time_compare_rules *r, const plcvec_vector *v,
                              const plcvec_step *step)
{
    /* The instruction as values: LD/AND/OR, and the condition (no parsing of "AND <=DT"). */
    const plcvec_instruction_info *info = &plcvec_instructions[v->instruction];
    plcvec_condition condition = info->condition;
    /* "treated just like the LD, AND, and OR instructions" */
    if (info->form == PLCVEC_FORM_LD)
        return evaluate(mc, r, v, condition);
    int rlo = step->rlo_in == 1;
    int logic = mc->follows[PLCVEC_INTERP_CP1E_AND_OR_WHEN_OFF];
    if (info->form == PLCVEC_FORM_AND) {
        if (!rlo && logic != PLCVEC_CP1E_AND_OR_WHEN_OFF_ALWAYS_EXECUTED)   /* and-skipped, short-circuit */
            return 0;
        return r->and_form(rlo, evaluate(mc, r, v, condition));
    }
    if (rlo && logic == PLCVEC_CP1E_AND_OR_WHEN_OFF_SHORT_CIRCUIT)
        return 1;
    return evaluate(mc, r, v, condition) || rlo;
}
