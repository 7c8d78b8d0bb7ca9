/* IDEC FC6A MICROSmart: HOUR (hour meter). From fc6a-hour-meter-HOUR.txt.
 * The fraction of a second already measured is kept in the machine's state (on the CPU it is in
 * the work area D3, D3+1, which vectors list as scratch and never compare). */
#include <string.h>

#include "fc6a_hour_meter.h"

static int m8004 = -1;     /* memory_device_named() */

#define HOUR_MAX 65535L     /* "Hour data can be 0 through 65,535." */
#define FIELD_MAX 59        /* "Minute and second data can be 0 through 59." */

/* "When the D1 value reaches the S1 value, an output ... is turned on." */
static int reached(long total, long preset)
{
    return total >= preset;
}

/* "the value returns to 0 hours 0 minutes 0 seconds" after "65,535 hours 59 minutes 59 seconds" */
const fc6a_hour_meter_rules fc6a_hour_meter_reference_rules = {(HOUR_MAX + 1) * 3600, reached, 1, 0};

/* One execution: the machine, the rules, the state, and the operands' devices. */
typedef struct hour_call {
    machine *mc;
    const fc6a_hour_meter_rules *r;
    fc6a_hour_meter_state *st;
    address d1, d2;
    int write_d2;               /* 0: HOUR-D2-SPECIAL=error, D2 is never written */
    const plcvec_operand *s1;
} hour_call;

static int follows(const hour_call *c, int interpretation, int alternative)
{
    return c->mc->follows[interpretation] == alternative;
}

static void error_flag(hour_call *c, int on)
{
    memory_write_named(&c->mc->mem, memory_device_named("M8004", &m8004), PLCVEC_BIT, (uint16_t)on);
}

/* "Special internal relays cannot be designated as destination device D2": M8000 onwards. */
static int special_relay(address d2)
{
    return strcmp(d2.kind, "M") == 0 && d2.number >= 8000;
}

static long seconds_of(const long hms[3])
{
    return hms[0] * 3600 + hms[1] * 60 + hms[2];
}

static void read_hms(const memory *m, address base, long hms[3])
{
    for (int i = 0; i < 3; i++)
        hms[i] = memory_read(m, memory_offset(base, i));
}

static void write_hms(memory *m, address base, const long hms[3])
{
    for (int i = 0; i < 3; i++)
        memory_write(m, memory_offset(base, i), PLCVEC_WORD, (uint16_t)hms[i]);
}

/* S1 as hour, minute, second. "When source device S1 is designated by a constant, the preset value
 * can be 0 through 65,535 in hours, then minutes and seconds are set to 0": a constant outside is
 * HOUR-S1-CONSTANT-RANGE's (low-16-bits cuts it). Otherwise 3 data registers. */
static void preset_of(const hour_call *c, long p[3])
{
    if (c->s1->is_constant) {
        long hours = c->s1->constant;
        if ((hours < 0 || hours > HOUR_MAX) && follows(c, PLCVEC_INTERP_HOUR_S1_CONSTANT_RANGE,
                                                       PLCVEC_HOUR_S1_CONSTANT_RANGE_LOW_16_BITS))
            hours &= 0xFFFF;
        p[0] = hours, p[1] = p[2] = 0;
        return;
    }
    read_hms(&c->mc->mem, memory_device(c->s1->device), p);
}

/* Read and check S1: 1 and the preset, or 0 when it is invalid (M8004 on, D2 off). */
static int check_preset(hour_call *c, long p[3])
{
    preset_of(c, p);
    int hour_ok = (p[0] >= 0 && p[0] <= HOUR_MAX) ||
                  follows(c, PLCVEC_INTERP_HOUR_S1_CONSTANT_RANGE, PLCVEC_HOUR_S1_CONSTANT_RANGE_AS_IS);
    if (!hour_ok || p[1] > FIELD_MAX || p[2] > FIELD_MAX) {
        /* "a user program execution error ... turning on special internal relay M8004 ... but the
         * input ON duration is measured"; HOUR-M8004-REPEAT=once: only when the check before found
         * S1 valid. "... changed to an invalid value after the comparison output has turned on, the
         * comparison output is turned off." */
        if (follows(c, PLCVEC_INTERP_HOUR_M8004_REPEAT, PLCVEC_HOUR_M8004_REPEAT_EVERY_CHECK) || !c->st->last_check_invalid)
            error_flag(c, 1);
        c->st->last_check_invalid = 1;
        if (c->write_d2)
            memory_write(&c->mc->mem, c->d2, PLCVEC_BIT, 0);
        return 0;
    }
    c->st->last_check_invalid = 0;
    /* The page never says M8004 turns off: HOUR-M8004-OFF=valid-preset turns it off. */
    if (follows(c, PLCVEC_INTERP_HOUR_M8004_OFF, PLCVEC_HOUR_M8004_OFF_VALID_PRESET))
        error_flag(c, 0);
    return 1;
}

/* A program the page forbids (a special relay as D2, a constant S1 outside its range) whose reading
 * is `undefined`: nothing this execution does is judged, so it does nothing. */
static int forbidden(const hour_call *c)
{
    long hours = c->s1->is_constant ? c->s1->constant : 0;
    return (special_relay(c->d2) && follows(c, PLCVEC_INTERP_HOUR_D2_SPECIAL, PLCVEC_HOUR_D2_SPECIAL_UNDEFINED)) ||
           ((hours < 0 || hours > HOUR_MAX) &&
            follows(c, PLCVEC_INTERP_HOUR_S1_CONSTANT_RANGE, PLCVEC_HOUR_S1_CONSTANT_RANGE_UNDEFINED));
}

/* "While input is on, the ON duration of the input is measured." Off: HOUR-INPUT-OFF; and
 * HOUR-PRESET-CHECK=every-execution checks the preset with the input off too. */
static void input_off(hour_call *c)
{
    if (follows(c, PLCVEC_INTERP_HOUR_INPUT_OFF, PLCVEC_HOUR_INPUT_OFF_RESET)) {
        const long zero[3] = {0, 0, 0};
        write_hms(&c->mc->mem, c->d1, zero);
        c->st->fraction_ms = 0;
    } else if (follows(c, PLCVEC_INTERP_HOUR_INPUT_OFF, PLCVEC_HOUR_INPUT_OFF_HOLD_DROP_FRACTION))
        c->st->fraction_ms = 0;     /* D1 kept; the part of a second is lost */
    long p[3];
    if (follows(c, PLCVEC_INTERP_HOUR_PRESET_CHECK, PLCVEC_HOUR_PRESET_CHECK_EVERY_EXECUTION))
        check_preset(c, p);
}

/* One second more on a D1 whose words count each on their own (HOUR-D1-OUT-OF-RANGE=by-field): a
 * field rolls over at exactly 60; 1 when the hour went from 65535 to 0. */
static int tick(long hms[3])
{
    hms[2] = (hms[2] + 1) & 0xFFFF;
    if (hms[2] != 60)
        return 0;
    hms[2] = 0, hms[1] = (hms[1] + 1) & 0xFFFF;
    if (hms[1] != 60)
        return 0;
    hms[1] = 0, hms[0] = (hms[0] + 1) & 0xFFFF;
    return hms[0] == 0;
}

/* D1 after `whole` seconds more, as `reading` reads it; the number of wraps past 65535:59:59. */
static long add_seconds(const hour_call *c, long hms[3], long whole, int reading)
{
    long wraps = 0;
    if (reading == PLCVEC_HOUR_D1_OUT_OF_RANGE_BY_FIELD) {
        for (long k = 0; k < whole; k++)
            wraps += tick(hms);
        return wraps;
    }
    /* "When the measured input ON duration value exceeds 65,535 hours 59 minutes 59 seconds, the
     * value returns to 0 hours 0 minutes 0 seconds to repeat another measuring cycle, with the
     * comparison output remaining on." */
    long total = seconds_of(hms) + whole;
    wraps = total / c->r->cycle;
    total %= c->r->cycle;
    hms[0] = total / 3600, hms[1] = total / 60 % 60, hms[2] = total % 60;
    return wraps;
}

/* "When the D1 value reaches the S1 value, an output or internal relay assigned by destination
 * device D2 is turned on." What turns it off: HOUR-OUTPUT-OFF. */
static void set_output(hour_call *c, int on, int wrapped_now, int compared_first)
{
    memory *m = &c->mc->mem;
    if (follows(c, PLCVEC_INTERP_HOUR_OUTPUT_OFF, PLCVEC_HOUR_OUTPUT_OFF_LATCHED)) {
        if (on)
            memory_write(m, c->d2, PLCVEC_BIT, 1);
        return;
    }
    /* recompared: D2 = D1 >= S1, except that it stays on across a wrap */
    if (wrapped_now && !compared_first && memory_read(m, c->d2))
        c->st->wrapped = 1;
    if (on)
        c->st->wrapped = 0;
    memory_write(m, c->d2, PLCVEC_BIT, (uint16_t)(on || (c->st->wrapped && memory_read(m, c->d2))));
    if (wrapped_now && compared_first && memory_read(m, c->d2))
        c->st->wrapped = 1;     /* on when D1 wrapped, after the comparison */
}

/* The measured count against the preset: hour, minute, second one after the other (by-field) or as
 * seconds; HOUR-WRAP-REACH=before-wrap compares the count as it was before it wrapped. */
static int reached_preset(const hour_call *c, const long hms[3], long wraps, const long p[3], int reading)
{
    long counted[3] = {hms[0], hms[1], hms[2]};
    if (wraps && follows(c, PLCVEC_INTERP_HOUR_WRAP_REACH, PLCVEC_HOUR_WRAP_REACH_BEFORE_WRAP))
        counted[0] += (HOUR_MAX + 1) * wraps;
    int on;
    if (reading == PLCVEC_HOUR_D1_OUT_OF_RANGE_BY_FIELD)
        on = counted[0] != p[0] ? counted[0] > p[0] : counted[1] != p[1] ? counted[1] > p[1] : counted[2] >= p[2];
    else
        on = c->r->reached(seconds_of(counted), seconds_of(p));
    if (seconds_of(p) == 0 && follows(c, PLCVEC_INTERP_HOUR_PRESET_ZERO, PLCVEC_HOUR_PRESET_ZERO_NEVER))
        on = 0;
    return on;
}

static void measure_and_compare(hour_call *c, const plcvec_step *step, int turned_on, int first)
{
    memory *m = &c->mc->mem;
    /* "Minute and second data can be 0 through 59": a D1 the program set outside that is read as
     * HOUR-D1-OUT-OF-RANGE says. */
    long hms[3];
    read_hms(m, c->d1, hms);
    int reading = hms[1] > FIELD_MAX || hms[2] > FIELD_MAX ? c->mc->follows[PLCVEC_INTERP_HOUR_D1_OUT_OF_RANGE]
                                                           : PLCVEC_HOUR_D1_OUT_OF_RANGE_AS_SECONDS;
    if (reading == PLCVEC_HOUR_D1_OUT_OF_RANGE_UNDEFINED)
        return;
    if (reading == PLCVEC_HOUR_D1_OUT_OF_RANGE_ERROR) {
        error_flag(c, 1);
        return;
    }
    /* The elapsed time since the previous execution is ON time, but at the execution at which the
     * input turns on (HOUR-FIRST-SCAN=from-next-scan) or the first since the CPU started
     * (after-cpu-start). */
    int first_scan = c->mc->follows[PLCVEC_INTERP_HOUR_FIRST_SCAN];
    int skip = (turned_on && first_scan == PLCVEC_HOUR_FIRST_SCAN_FROM_NEXT_SCAN) ||
               (first && first_scan == PLCVEC_HOUR_FIRST_SCAN_AFTER_CPU_START);
    long elapsed = !skip && step->elapsed_ms > 0 ? (long)step->elapsed_ms : 0;
    long whole = (c->st->fraction_ms + elapsed) / 1000;
    c->st->fraction_ms = c->r->keep_fraction ? (c->st->fraction_ms + elapsed) % 1000 : 0;
    if (c->r->fraction_offset)
        memory_write(m, memory_offset(c->d1, c->r->fraction_offset), PLCVEC_WORD, (uint16_t)c->st->fraction_ms);
    long wraps = add_seconds(c, hms, whole, reading);
    if (whole || reading != PLCVEC_HOUR_D1_OUT_OF_RANGE_AS_SECONDS_IF_ADDED)
        write_hms(m, c->d1, hms);
    long p[3];
    if (!check_preset(c, p))
        return;
    int before_wrap = wraps && follows(c, PLCVEC_INTERP_HOUR_WRAP_REACH, PLCVEC_HOUR_WRAP_REACH_BEFORE_WRAP);
    if (c->write_d2)
        set_output(c, reached_preset(c, hms, wraps, p, reading), wraps != 0, before_wrap);
}

int fc6a_hour_meter_execute(machine *mc, const fc6a_hour_meter_rules *r, fc6a_hour_meter_state *st,
                            const plcvec_vector *v, const plcvec_step *step)
{
    hour_call c = {mc, r, st, memory_device(plcvec_operand_named(v, "D1")->device),
                   memory_device(plcvec_operand_named(v, "D2")->device), 1, plcvec_operand_named(v, "S1")};
    /* The input at the previous execution; before the first one it counts as off. */
    int on = step->input == 1, turned_on = on && !st->input_was_on, first = !st->executed;
    st->input_was_on = on, st->executed = 1;
    if (forbidden(&c))
        return PLCVEC_NONE;
    /* "Special internal relays cannot be designated as destination device D2": HOUR-D2-SPECIAL=error
     * never writes such a D2 and reports an error instead, after everything else. */
    int d2_error = special_relay(c.d2) && follows(&c, PLCVEC_INTERP_HOUR_D2_SPECIAL, PLCVEC_HOUR_D2_SPECIAL_ERROR);
    c.write_d2 = !d2_error;
    if (!on) {
        input_off(&c);
        return PLCVEC_NONE;
    }
    measure_and_compare(&c, step, turned_on, first);
    if (d2_error)
        error_flag(&c, 1);
    return PLCVEC_NONE;
}
