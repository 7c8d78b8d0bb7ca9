/* IDEC FC6A MICROSmart: HOUR (hour meter). From fc6a-hour-meter-HOUR.txt.
 * The fraction of a second already measured is kept in the machine's state (on the CPU it is in
 * the work area D3, D3+1, which vectors list as scratch and never compare). */
#include "fc6a_hour_meter.h"

static int m8004 = -1;     /* memory_device_named() */

/* "When the D1 value reaches the S1 value, an output ... is turned on." */
static int reached(long total, long preset)
{
    return total >= preset;
}

/* "the value returns to 0 hours 0 minutes 0 seconds" after "65,535 hours 59 minutes 59 seconds" */
const fc6a_hour_meter_rules fc6a_hour_meter_reference_rules = {65536L * 3600, reached, 1, 0};

static long seconds_of(const memory *m, address base)
{
    return (long)memory_read(m, memory_offset(base, 0)) * 3600 + (long)memory_read(m, memory_offset(base, 1)) * 60 +
           memory_read(m, memory_offset(base, 2));
}

static void write_hms(memory *m, address base, long total)
{
    long hms[3] = {total / 3600, total / 60 % 60, total % 60};
    for (int i = 0; i < 3; i++)
        memory_write(m, memory_offset(base, i), PLCVEC_WORD, (uint16_t)hms[i]);
}

/* S1, the preset, in seconds; or -1 when it is invalid (M8004 on, D2 off). */
static long check_preset(const machine *mc, memory *m, const plcvec_operand *s1, address d2)
{
    /* "When source device S1 is designated by a constant, the preset value can be 0 through
     * 65,535 in hours, then minutes and seconds are set to 0." Otherwise 3 data registers. */
    long p[3];
    if (s1->is_constant) {
        p[0] = s1->constant & 0xFFFF;
        p[1] = p[2] = 0;
    } else {
        address s = memory_device(s1->device);
        for (int i = 0; i < 3; i++)
            p[i] = memory_read(m, memory_offset(s, i));
    }
    /* "Minute and second data can be 0 through 59." Out of range: "a user program execution
     * error ... turning on special internal relay M8004 ... but the input ON duration is
     * measured", and "the comparison output is turned off". */
    if (p[1] > 59 || p[2] > 59) {
        memory_write_named(m, memory_device_named("M8004", &m8004), PLCVEC_BIT, 1);
        memory_write(m, d2, PLCVEC_BIT, 0);
        return -1;
    }
    /* The page never says M8004 turns off: HOUR-M8004-OFF=valid-preset turns it off. */
    if (mc->follows[PLCVEC_INTERP_HOUR_M8004_OFF] == PLCVEC_HOUR_M8004_OFF_VALID_PRESET)
        memory_write_named(m, memory_device_named("M8004", &m8004), PLCVEC_BIT, 0);
    return p[0] * 3600 + p[1] * 60 + p[2];
}

int fc6a_hour_meter_execute(machine *mc, const fc6a_hour_meter_rules *r, fc6a_hour_meter_state *st,
                            const plcvec_vector *v, const plcvec_step *step)
{
    memory *m = &mc->mem;
    address d1 = memory_device(plcvec_operand_named(v, "D1")->device);
    address d2 = memory_device(plcvec_operand_named(v, "D2")->device);
    const plcvec_operand *s1 = plcvec_operand_named(v, "S1");

    /* The input at the previous execution; before the first one it counts as off. */
    int turned_on = step->input == 1 && !st->input_was_on;
    st->input_was_on = step->input == 1;
    if (step->input != 1) {
        /* "While input is on, the ON duration of the input is measured." Off: HOUR-INPUT-OFF. */
        if (mc->follows[PLCVEC_INTERP_HOUR_INPUT_OFF] == PLCVEC_HOUR_INPUT_OFF_RESET) {
            write_hms(m, d1, 0);
            st->fraction_ms = 0;
        } else if (mc->follows[PLCVEC_INTERP_HOUR_INPUT_OFF] == PLCVEC_HOUR_INPUT_OFF_HOLD_DROP_FRACTION)
            st->fraction_ms = 0;        /* D1 kept; the part of a second is lost */
        /* HOUR-PRESET-CHECK=every-execution: the preset is checked with the input off too. */
        if (mc->follows[PLCVEC_INTERP_HOUR_PRESET_CHECK] == PLCVEC_HOUR_PRESET_CHECK_EVERY_EXECUTION)
            check_preset(mc, m, s1, d2);
        return PLCVEC_NONE;
    }
    /* The elapsed time since the previous execution is ON time; at the execution at which the
     * input turns on, only under HOUR-FIRST-SCAN=counts. */
    /* "Minute and second data can be 0 through 59": D1 holding more is HOUR-D1-OUT-OF-RANGE.
     * as-seconds: the count is measured on and written back in range (below); error: M8004 on,
     * nothing else read or written, the elapsed time not counted. */
    if (mc->follows[PLCVEC_INTERP_HOUR_D1_OUT_OF_RANGE] == PLCVEC_HOUR_D1_OUT_OF_RANGE_ERROR &&
        (memory_read(m, memory_offset(d1, 1)) > 59 || memory_read(m, memory_offset(d1, 2)) > 59)) {
        memory_write_named(m, memory_device_named("M8004", &m8004), PLCVEC_BIT, 1);
        return PLCVEC_NONE;
    }
    long elapsed = step->elapsed_ms > 0 ? (long)step->elapsed_ms : 0;
    if (turned_on && mc->follows[PLCVEC_INTERP_HOUR_FIRST_SCAN] == PLCVEC_HOUR_FIRST_SCAN_FROM_NEXT_SCAN)
        elapsed = 0;
    long whole = (st->fraction_ms + elapsed) / 1000;
    st->fraction_ms = r->keep_fraction ? (st->fraction_ms + elapsed) % 1000 : 0;
    if (r->fraction_offset)
        memory_write(m, memory_offset(d1, r->fraction_offset), PLCVEC_WORD, (uint16_t)st->fraction_ms);
    long total = seconds_of(m, d1) + whole;
    /* "When the measured input ON duration value exceeds 65,535 hours 59 minutes 59 seconds, the
     * value returns to 0 hours 0 minutes 0 seconds ... with the comparison output remaining on." */
    int wrapped_now = total >= r->cycle;
    total %= r->cycle;
    write_hms(m, d1, total);

    long preset = check_preset(mc, m, s1, d2);
    if (preset < 0)
        return PLCVEC_NONE;
    int on = r->reached(total, preset);
    if (preset == 0 && mc->follows[PLCVEC_INTERP_HOUR_PRESET_ZERO] == PLCVEC_HOUR_PRESET_ZERO_NEVER)
        on = 0;
    if (mc->follows[PLCVEC_INTERP_HOUR_OUTPUT_OFF] == PLCVEC_HOUR_OUTPUT_OFF_LATCHED) {
        if (on)
            memory_write(m, d2, PLCVEC_BIT, 1);
    } else {
        /* recompared: D2 = D1 >= S1, except that it stays on across a wrap */
        int d2_on = memory_read(m, d2) != 0;
        if (wrapped_now && d2_on)
            st->wrapped = 1;
        if (on)
            st->wrapped = 0;
        memory_write(m, d2, PLCVEC_BIT, (uint16_t)(on || (st->wrapped && d2_on)));
    }
    return PLCVEC_NONE;
}
