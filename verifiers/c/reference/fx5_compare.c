/* Mitsubishi MELSEC iQ-F FX5: LDTM/ANDTM/ORTM (time) and LDDT/ANDDT/ORDT (date) comparison.
 * Written from fx5-time-compare-LDTM.txt and fx5-date-compare-LDDT.txt; the two pages are the
 * same text with hour/minute/second replaced by year/month/day, so one machine serves both. */
#include <string.h>

#include "condition.h"
#include "fx5_compare.h"

static int sm709_id = -1;     /* memory_device_named() */

/* 'Set the "hour" data ... within the range 0 to 23.' ... '(1) Set "second" as comparison
 * target. (2) ... "minute" ... (3) ... "hour"': (word offset, lo, hi, (s3) bit), most
 * significant first. */
static const fx5_field time_fields[3] = {{0, 0, 23, 2}, {1, 0, 59, 1}, {2, 0, 59, 0}};
/* 'Set the 4 digit "year" data ... within the range 1980 to 2079.' month 1 to 12, "date" 1 to 31. */
static const fx5_field date_fields[3] = {{0, 1980, 2079, 2}, {1, 1, 12, 1}, {2, 1, 31, 0}};

static int order(const fx5_field *fields, const uint16_t *s1, const uint16_t *s2, unsigned s3)
{
    for (int i = 0; i < 3; i++) {
        if (!(s3 >> fields[i].bit & 1))
            continue;
        int a = to_signed16(s1[fields[i].offset]), b = to_signed16(s2[fields[i].offset]);   /* "16-bit signed binary" */
        if (a != b)
            return a < b ? -1 : 1;
    }
    return 0;
}

/* "(4) Set 0. If a value other than 0 is set, the operation result will be non-continuity."
 * (bits 3 to 14); "Other than 0001H to 0007H, 8001H to 8007H: None". */
static int selector_valid(unsigned s3)
{
    return (s3 & 0x7FF8) == 0 && (s3 & 0x0007) != 0;
}

/* "Once SM709 turns on, the on state is held until the CPU module is powered off or reset":
 * only ever turned on here. */
static void sm709(memory *m, int error)
{
    if (error)
        memory_write_named(m, memory_device_named("SM709", &sm709_id), PLCVEC_BIT, 1);
}

/* "(Devices are used as a normally open contact.)": in series with the preceding logic. */
static int and_form(int rlo, int contact)
{
    return rlo && contact;
}

const fx5_compare_rules fx5_compare_reference_rules = {time_fields, date_fields, order, 0x8000, selector_valid,
                                                       memory_in_range, sm709, and_form};

static int out_of_range(const fx5_field *fields, const uint16_t *w, int all, unsigned s3)
{
    for (int i = 0; i < 3; i++) {
        if (!all && !(s3 >> fields[i].bit & 1))
            continue;
        int x = to_signed16(w[fields[i].offset]);
        if (x < fields[i].lo || x > fields[i].hi)
            return 1;
    }
    return 0;
}

static void read_block(const memory *m, address base, uint16_t *w)
{
    for (int i = 0; i < 3; i++)
        w[i] = memory_read(m, memory_offset(base, i));
}

/* One execution of the comparison: the machine and the rules, the vector and the step, whether it
 * is the date page's, and (set by the comparison) whether it turned SM709 on. */
typedef struct fx5_call {
    machine *mc;
    const fx5_compare_rules *r;
    const plcvec_vector *v;
    const plcvec_step *step;
    int date;
    int failed;
} fx5_call;

/* The comparison itself (the "contact"). */
static int evaluate(fx5_call *call, plcvec_condition condition)
{
    const fx5_compare_rules *r = call->r;
    memory *m = &call->mc->mem;
    const uint8_t *follows = call->mc->follows;
    const plcvec_vector *v = call->v;
    int date = call->date;
    const fx5_field *fields = date ? r->date_fields : r->time_fields;
    const plcvec_operand *op1 = plcvec_operand_named(v, "s1"), *op2 = plcvec_operand_named(v, "s2"),
                         *op3 = plcvec_operand_named(v, "s3");
    address s1_dev = memory_device(op1->device), s2_dev = memory_device(op2->device);
    unsigned s3 = (op3->is_constant ? (unsigned)op3->constant : memory_read(m, memory_device(op3->device))) & 0xFFFF;
    /* "(5) When 1 is set to the 15 bit, the data in the device specified by (s1) is compared
     * with the current time ... (s2) is regarded as dummy data and ignored." */
    int use_clock = r->clock_bit && (s3 & r->clock_bit);

    /* "If the device areas specified by (s1) to (s1)+2 or (s2) to (s2)+2 exceed the
     * corresponding device range, SM709 turns on ... non-continuity." Whether (s2) is checked
     * while it is ignored: FX5-CLOCK-S2-DEVICE-RANGE. */
    int s2_checked = !use_clock ||
                     follows[PLCVEC_INTERP_FX5_CLOCK_S2_DEVICE_RANGE] == PLCVEC_FX5_CLOCK_S2_DEVICE_RANGE_CHECKED;
    int valid = r->selector_valid(s3), error;
    if (!r->in_range(m, s1_dev, 3) || (s2_checked && !r->in_range(m, s2_dev, 3))) {
        /* An (s3) that compares nothing as well: which rule decides is FX5-INVALID-S3-DEVICE-RANGE
         * (s3-first: non-continuity, SM709 untouched). */
        if (!valid && follows[PLCVEC_INTERP_FX5_INVALID_S3_DEVICE_RANGE] == PLCVEC_FX5_INVALID_S3_DEVICE_RANGE_S3_FIRST)
            return 0;
        call->failed = 1;
        r->sm709(m, 1);
        return 0;
    }
    uint16_t s1[3], s2[3];
    read_block(m, s1_dev, s1);
    if (use_clock) {
        /* The clock as an emulator reads it: only the fields its `fields` mask says are given. */
        const plcvec_clock *c = call->step->clock;
        unsigned need = date ? PLCVEC_CLOCK_YEAR | PLCVEC_CLOCK_MONTH | PLCVEC_CLOCK_DAY
                             : PLCVEC_CLOCK_HOUR | PLCVEC_CLOCK_MINUTE | PLCVEC_CLOCK_SECOND;
        if (!c || (c->fields & need) != need) {
            call->mc->input_error = date ? "the step gives no current clock with year, month and day"
                                    : "the step gives no current clock with hour, minute and second";
            return 0;
        }
        s2[0] = (uint16_t)(date ? c->year : c->hour);
        s2[1] = (uint16_t)(date ? c->month : c->minute);
        s2[2] = (uint16_t)(date ? c->day : c->second);
    } else
        read_block(m, s2_dev, s2);

    /* "If the comparison target data in the device are not recognized as time data, SM709
     * turns on ... non-continuity." Which words are comparison target data: FX5-SM709-SCOPE. */
    if (follows[PLCVEC_INTERP_FX5_SM709_SCOPE] == PLCVEC_FX5_SM709_SCOPE_ALL_WORDS) {
        error = out_of_range(fields, s1, 1, s3) || (!use_clock && out_of_range(fields, s2, 1, s3));
        if (error || !valid) {
            call->failed = error;
            r->sm709(m, error);
            return 0;
        }
    } else {
        if (!valid) {
            r->sm709(m, 0);
            return 0;
        }
        /* selected-fields: a masked word is not comparison target data; compared-operands: the
         * operands are, as a whole, but only when a comparison is made at all. */
        int all = follows[PLCVEC_INTERP_FX5_SM709_SCOPE] == PLCVEC_FX5_SM709_SCOPE_COMPARED_OPERANDS;
        error = out_of_range(fields, s1, all, s3) || (!use_clock && out_of_range(fields, s2, all, s3));
        if (error) {
            call->failed = 1;
            r->sm709(m, 1);
            return 0;
        }
    }
    /* Date page: "Even if the data are not recognized as date data, SM709 does not turn on if
     * the data are within the setting range." So 02/30 is compared as it is. */
    r->sm709(m, 0);
    return condition_holds(condition, r->order(fields, s1, s2, s3));
}

int fx5_compare_execute(machine *mc, const fx5_compare_rules *r, const plcvec_vector *v, const plcvec_step *step)
{
    /* The instruction as values: LD/AND/OR, and the condition (no parsing of "ANDTM<="). */
    const plcvec_instruction_info *info = &plcvec_instructions[v->instruction];
    fx5_call call = {mc, r, v, step, v->family == PLCVEC_FAMILY_FX5_DATE_COMPARE, 0};
    plcvec_condition condition = info->condition;
    if (info->form == PLCVEC_FORM_LD)
        return evaluate(&call, condition);
    int rlo = step->rlo_in == 1;
    int logic = mc->follows[PLCVEC_INTERP_FX5_AND_OR_WHEN_OFF];
    /* "(Devices are used as a normally open contact.)"; the MELSEC iQ-R Programming Manual (CPU
     * Module Instructions), processing-time tables: an AND/OR comparison is not executed while the
     * preceding logic is off: FX5-AND-OR-WHEN-OFF. A preceding logic that is off decides an AND
     * (and_form(0, 1) is off) unless the rules say otherwise. */
    if (info->form == PLCVEC_FORM_AND) {
        if (!rlo && logic != PLCVEC_FX5_AND_OR_WHEN_OFF_ALWAYS_EXECUTED && !r->and_form(0, 1))
            return 0;
        return r->and_form(rlo, evaluate(&call, condition));
    }
    if (rlo && logic == PLCVEC_FX5_AND_OR_WHEN_OFF_SHORT_CIRCUIT)
        return 1;
    int contact = evaluate(&call, condition);
    /* "SM709 turns on ... and the operation result will be non-continuity": a non-conductive
     * contact in parallel (contact-off), or the rung's result itself off (result-off). */
    if (call.failed && mc->follows[PLCVEC_INTERP_FX5_OR_ON_ERROR] == PLCVEC_FX5_OR_ON_ERROR_RESULT_OFF)
        return 0;
    return contact || rlo;
}
