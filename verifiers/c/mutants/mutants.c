/* Mutants: the reference with one plausible bug each, so that the tests can show the vectors
 * and the runner catch it. Each replaces one rule of one family (see reference.h). None is a
 * reading: a mutant whose failures one alternative explains is an implementation that follows
 * that alternative, not a bug (tests/test_rollup.c holds every mutant to it). */
#include <string.h>

#include "reference.h"

static int sm709_id = -1;     /* memory_device_named() */

/* -- FX5 time and date comparison -- */

/* The selected fields compared from (s1)+2 up: second before hour, day before year. */
static int order_low_first(const fx5_field *fields, const uint16_t *s1, const uint16_t *s2, unsigned s3)
{
    for (int i = 2; i >= 0; i--) {
        if (!(s3 >> fields[i].bit & 1))
            continue;
        int a = to_signed16(s1[fields[i].offset]), b = to_signed16(s2[fields[i].offset]);
        if (a != b)
            return a < b ? -1 : 1;
    }
    return 0;
}
static void fx5_low_field_first(plcvec_reference *ref) { ref->fx5.order = order_low_first; }

static void fx5_clock_bit_ignored(plcvec_reference *ref) { ref->fx5.clock_bit = 0; }

/* SM709 written on every execution, off when the data are good. */
static void sm709_each_execution(memory *m, int error)
{
    memory_write_named(m, memory_device_named("SM709", &sm709_id), PLCVEC_BIT, (uint16_t)(error != 0));
}
static void fx5_sm709_not_latched(plcvec_reference *ref) { ref->fx5.sm709 = sm709_each_execution; }

static int always_in_range(const memory *m, address base, int words)
{
    (void)m, (void)base, (void)words;
    return 1;
}
static void fx5_device_range_unchecked(plcvec_reference *ref) { ref->fx5.in_range = always_in_range; }

static const fx5_field time_fields_hour_24[3] = {{0, 0, 24, 2}, {1, 0, 59, 1}, {2, 0, 59, 0}};
static void fx5_time_hour_24_accepted(plcvec_reference *ref) { ref->fx5.time_fields = time_fields_hour_24; }

/* ANDTM/ANDDT pass their own comparison on whatever the preceding logic, as LD does. (Until 0.2.0
 * this mutant executed AND while the logic was off and passed on off: that is the reading
 * FX5-AND-OR-WHEN-OFF=always-executed, which a declaration explains, so it was no bug.) */
static int and_ignores_preceding(int rlo, int contact)
{
    (void)rlo;
    return contact;
}
static void fx5_and_ignores_preceding_off(plcvec_reference *ref) { ref->fx5.and_form = and_ignores_preceding; }

/* -- FX5 TADD/TADDP -- */

static void tadd_flags_not_written(plcvec_reference *ref) { ref->tadd.flags_written = 0; }

static int every_scan(int en, int previous_en, plcvec_instruction instruction)
{
    (void)previous_en, (void)instruction;
    return en;
}
static void taddp_every_scan(plcvec_reference *ref) { ref->tadd.pulse = every_scan; }

static void tadd_hour_24_accepted(plcvec_reference *ref) { ref->tadd.hour_max = 24; }

/* (s1) copied into (d) word by word from the hour, then (s2) added to (d) in place. */
static long copy_s1_into_d_first(machine *mc, address s1, address s2, address d)
{
    for (int k = 0; k < 3; k++)
        memory_write(&mc->mem, memory_offset(d, k), PLCVEC_WORD, memory_read(&mc->mem, memory_offset(s1, k)));
    return fx5_time_add_sum_seconds(mc, d, s2, d);
}
static void tadd_s1_copied_into_d_first(plcvec_reference *ref) { ref->tadd.sum_seconds = copy_s1_into_d_first; }

/* -- FC6A HOUR -- */

static int above(long total, long preset) { return total > preset; }
static void hour_output_above_preset(plcvec_reference *ref) { ref->hour.reached = above; }

static void hour_drops_fraction(plcvec_reference *ref) { ref->hour.keep_fraction = 0; }

static void hour_fraction_in_d1_plus_3(plcvec_reference *ref) { ref->hour.fraction_offset = 3; }

/* -- CP1E time comparison -- */

static int and_as_or(int rlo, int contact) { return rlo || contact; }
static void cp1e_and_as_or(plcvec_reference *ref) { ref->cp1e.and_form = and_as_or; }

static void cp1e_flags_not_reflected(plcvec_reference *ref) { ref->cp1e.reflect_flags = 0; }

/* The words past the end of D read as 0 (memory_read of a word never written). */
static void cp1e_past_area_compared(plcvec_reference *ref) { ref->cp1e.in_range = always_in_range; }

/* The BCD check looks at the byte's value, not at each digit: up to 99H passes, so 1AH is compared.
 * (Until 0.2.0 no byte was checked: that is the reading CP1E-NON-BCD=raw-bytes, so it was no bug.) */
static int byte_up_to_99h(unsigned b) { return b <= 0x99; }
static void cp1e_bcd_read_as_binary(plcvec_reference *ref) { ref->cp1e.is_bcd = byte_up_to_99h; }

const plcvec_mutant plcvec_mutants[] = {
    {"fx5-low-field-first", "fx5-time-compare fx5-date-compare",
     "The selected fields are compared from (s1)+2 up, so a later field decides before an earlier one (contact result).",
     fx5_low_field_first},
    {"fx5-clock-bit-ignored", "fx5-time-compare fx5-date-compare",
     "Bit 15 of (s3) is ignored: (s1) is always compared with (s2), never with the current clock (contact result).",
     fx5_clock_bit_ignored},
    {"fx5-sm709-not-latched", "fx5-time-compare fx5-date-compare",
     "SM709 is written on every execution, off when the data are good, although 'the on state is held' "
     "(a device that must stay unchanged).",
     fx5_sm709_not_latched},
    {"fx5-device-range-unchecked", "fx5-time-compare fx5-date-compare",
     "(s1)..(s1)+2 and (s2)..(s2)+2 are not checked against the device range (a flag).", fx5_device_range_unchecked},
    {"fx5-time-hour-24-accepted", "fx5-time-compare",
     "The hour range check is off by one: hour 24 is compared instead of turning SM709 on (a flag).",
     fx5_time_hour_24_accepted},
    {"fx5-and-ignores-preceding-off", "fx5-time-compare fx5-date-compare",
     "ANDTM/ANDDT are executed while the preceding logic is off (as FX5-AND-OR-WHEN-OFF=always-executed says) "
     "but pass their own comparison on, as LD does (an interpretation alternative half followed: contact result).",
     fx5_and_ignores_preceding_off},
    {"tadd-flags-not-written", "fx5-time-add", "The carry flags SM700/SM8022 and the zero flag SM8020 are never written (a flag).",
     tadd_flags_not_written},
    {"taddp-every-scan", "fx5-time-add",
     "TADDP adds on every scan while EN is on, instead of once on its rising edge (a changed word).", taddp_every_scan},
    {"tadd-hour-24-accepted", "fx5-time-add",
     "Hour 24 in (s1) or (s2) is added instead of raising error 3405H (a changed word).", tadd_hour_24_accepted},
    {"tadd-s1-copied-into-d-first", "fx5-time-add",
     "(s1) is copied into (d) word by word from the hour, then (s2) is added to (d) in place, so a word of (s2), "
     "or a later word of (s1), that is also a word of (d) is overwritten before it is read (a changed word).",
     tadd_s1_copied_into_d_first},
    {"hour-output-above-preset", "fc6a-hour-meter",
     "D2 turns on only once D1 is past S1, not when 'the D1 value reaches the S1 value' (a bit).", hour_output_above_preset},
    {"hour-drops-fraction", "fc6a-hour-meter",
     "Each scan's ON time is cut to whole seconds and the remainder thrown away (a changed word).", hour_drops_fraction},
    {"hour-fraction-in-d1-plus-3", "fc6a-hour-meter",
     "The fraction of a second is kept in D1+3 instead of the work area D3 (a write outside the vector).",
     hour_fraction_in_d1_plus_3},
    {"cp1e-and-as-or", "cp1e-time-compare",
     "AND =DT ... AND >=DT combine the comparison with the preceding logic as OR does (contact result).", cp1e_and_as_or},
    {"cp1e-flags-not-reflected", "cp1e-time-compare",
     "The arithmetic flags (=, <>, <, <=, >, >=) are left alone, although the result 'is reflected in the arithmetic "
     "flags' (a flag).",
     cp1e_flags_not_reflected},
    {"cp1e-bcd-read-as-binary", "cp1e-time-compare",
     "The BCD check looks at the byte's value instead of each digit: up to 99H passes, so 1AH is compared instead "
     "of turning P_ER on, while A0H still turns it on (a flag).",
     cp1e_bcd_read_as_binary},
    {"cp1e-past-area-compared", "cp1e-time-compare",
     "S1 or S2 at the last one or two words of the data area is compared all the same, the words past the end "
     "read as 0, instead of the error or program error CP1E-PAST-AREA-END names (a flag).",
     cp1e_past_area_compared},
};
const size_t plcvec_mutant_count = sizeof plcvec_mutants / sizeof plcvec_mutants[0];

const plcvec_mutant *plcvec_mutant_named(const char *name)
{
    for (size_t i = 0; i < plcvec_mutant_count; i++)
        if (strcmp(plcvec_mutants[i].name, name) == 0)
            return &plcvec_mutants[i];
    return NULL;
}
