/* Mitsubishi MELSEC iQ-F FX5: TADD / TADDP (adding clock data). From fx5-time-add-TADD.txt. */
#include "fx5_time_add.h"

static int sd0 = -1, sd8067 = -1;     /* memory_device_named() */

#define DAY (24L * 3600)
#define ERR_DEVICE_RANGE 0x2820     /* "2820H The device range ... exceeds the corresponding device range." */
#define ERR_VALUE_RANGE 0x3405      /* "3405H Any of values specified by (s1) and (s2) is outside ..." */

static const char *const carry_flags[] = {"SM700", "SM8022"};     /* "SM700 Carry ... SM8022 Carry" */

static int pulse(int en, int previous_en, plcvec_instruction instruction)
{
    /* TADD: every scan while EN is on; TADDP: its rising edge only (the instruction's execution). */
    return plcvec_instructions[instruction].execution == PLCVEC_EXECUTION_RISING_EDGE ? en && !previous_en : en;
}

const fx5_time_add_rules fx5_time_add_reference_rules = {carry_flags, 2, 23, memory_in_range, pulse, 1,
                                                           fx5_time_add_sum_seconds};

static void error_code(memory *m, uint16_t code)
{
    /* "Error code (SD0/SD8067)" */
    memory_write_named(m, memory_device_named("SD0", &sd0), PLCVEC_WORD, code);
    memory_write_named(m, memory_device_named("SD8067", &sd8067), PLCVEC_WORD, code);
}

static void flag(memory *m, const char *name, int on, int set_only)
{
    int device = plcvec_device_named(name);
    if (device < 0 || (set_only && !on))
        return;
    memory_write_named(m, device, PLCVEC_BIT, (uint16_t)on);
}

/* Hour 0 to 23; minute, second 0 to 59: a field out of range is the 3405H condition. */
static int out_of_range(const fx5_time_add_rules *r, const int *hms)
{
    for (int i = 0; i < 3; i++)
        if (hms[i] < 0 || hms[i] > (i == 0 ? r->hour_max : 59))
            return 1;
    return 0;
}

/* An operand whose three words exist and hold a field out of range. */
static int fields_bad(const fx5_time_add_rules *r, const memory *m, address base)
{
    if (!r->in_range(m, base, 3))
        return 0;
    int hms[3];
    for (int i = 0; i < 3; i++)
        hms[i] = to_signed16(memory_read(m, memory_offset(base, i)));
    return out_of_range(r, hms);
}

/* A word of (s1) or (s2) as "16-bit signed binary", read when the order of TADD-OVERLAP reads it. */
static int source_word(const memory *m, address base, int k)
{
    return to_signed16(memory_read(m, memory_offset(base, k)));
}

static long floor_div(long a, long b)
{
    return a / b - (a % b != 0 && (a % b < 0) != (b < 0));
}

/* Seconds in an hour, a minute, a second; what each word counts up to before it carries. */
static const long weights[3] = {3600, 60, 1};
static const long radix[3] = {24, 60, 60};

/* (s1) + (s2) in seconds, the words read in the order TADD-OVERLAP says. The order shows only when
 * (d) shares words with (s1) or (s2) at another offset ((d) = (s1)+1, ...): a source word read after
 * that word of (d) was written holds what was written. */
long fx5_time_add_sum_seconds(machine *mc, address s1, address s2, address d)
{
    memory *m = &mc->mem;
    int order = mc->follows[PLCVEC_INTERP_TADD_OVERLAP];
    long total = 0, carry = 0;
    if (order == PLCVEC_TADD_OVERLAP_SOURCES_FIRST) {
        /* Both sources read, then (d) written. */
        long a[3], b[3];
        for (int k = 0; k < 3; k++)
            a[k] = source_word(m, s1, k), b[k] = source_word(m, s2, k);
        for (int k = 0; k < 3; k++)
            total += (a[k] + b[k]) * weights[k];
        return total;
    }
    if (order == PLCVEC_TADD_OVERLAP_SECOND_FIRST) {
        /* Second, minute, hour, the carry's way: each word of (d) gets its digit as soon as it is known. */
        for (int k = 2; k >= 0; k--) {
            long sum = source_word(m, s1, k) + source_word(m, s2, k);
            total += sum * weights[k];
            long carried = sum + carry;
            carry = floor_div(carried, radix[k]);
            memory_write(m, memory_offset(d, k), PLCVEC_WORD, (uint16_t)(carried - carry * radix[k]));
        }
        return total;
    }
    /* hour-first: the plain sum of each pair of words into (d), hour to second; the carries are
     * settled afterwards, from the three sums. */
    for (int k = 0; k < 3; k++) {
        long sum = source_word(m, s1, k) + source_word(m, s2, k);
        total += sum * weights[k];
        memory_write(m, memory_offset(d, k), PLCVEC_WORD, (uint16_t)sum);
    }
    return total;
}

static void add(machine *mc, const fx5_time_add_rules *r, const plcvec_vector *v)
{
    memory *m = &mc->mem;
    address s1 = memory_device(plcvec_operand_named(v, "s1")->device);
    address s2 = memory_device(plcvec_operand_named(v, "s2")->device);
    address d = memory_device(plcvec_operand_named(v, "d")->device);
    /* "These instructions occupy three points for each of three devices"; out of range: 2820H,
     * nothing read or written. */
    if (!r->in_range(m, s1, 3) || !r->in_range(m, s2, 3) || !r->in_range(m, d, 3)) {
        /* Both conditions at once (a readable s1/s2 holds a field out of range too):
         * TADD-ERROR-ORDER says which code is stored. */
        int both = fields_bad(r, m, s1) || fields_bad(r, m, s2);
        error_code(m, both && mc->follows[PLCVEC_INTERP_TADD_ERROR_ORDER] == PLCVEC_TADD_ERROR_ORDER_FIELD_RANGE_FIRST
                          ? ERR_VALUE_RANGE : ERR_DEVICE_RANGE);
        return;
    }
    if (fields_bad(r, m, s1) || fields_bad(r, m, s2)) {
        error_code(m, ERR_VALUE_RANGE);
        if (mc->follows[PLCVEC_INTERP_TADD_ON_ERROR] == PLCVEC_TADD_ON_ERROR_NOT_EXECUTED)
            return;
    }
    long total = r->sum_seconds(mc, s1, s2, d);
    /* "If the sum of two values exceeds 24:00:00, the carry flag turns on, and the result will be
     * the sum minus 24:00:00", but "If 1 second is added to 23:59:59, the result will be
     * 0:00:00. This turns on both the carry flag and the zero flag.": TADD-EXACT-24. */
    int carry = mc->follows[PLCVEC_INTERP_TADD_EXACT_24] == PLCVEC_TADD_EXACT_24_CARRY_AT_24 ? total >= DAY
                                                                                               : total > DAY;
    long result = ((total % DAY) + DAY) % DAY;
    long hms[3] = {result / 3600, result / 60 % 60, result % 60};
    for (int i = 0; i < 3; i++)
        memory_write(m, memory_offset(d, i), PLCVEC_WORD, (uint16_t)hms[i]);
    if (!r->flags_written)
        return;
    int set_only = mc->follows[PLCVEC_INTERP_TADD_FLAGS_OFF] == PLCVEC_TADD_FLAGS_OFF_SET_ONLY;
    for (int i = 0; i < r->n_carry_flags; i++)
        flag(m, r->carry_flags[i], carry, set_only);
    flag(m, "SM8020", result == 0, set_only);       /* "If the result is 0 (0:00:00), the zero flag turns on." */
}

int fx5_time_add_execute(machine *mc, const fx5_time_add_rules *r, fx5_time_add_state *st, const plcvec_vector *v,
                         const plcvec_step *step)
{
    int en = step->en == 1;
    int run = r->pulse(en, st->previous_en, v->instruction);
    st->previous_en = en;       /* TADDP: the state before the first scan is off */
    if (run)
        add(mc, r, v);
    return PLCVEC_NONE;
}
