package org.plcvec.mutants;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

import org.plcvec.reference.Cp1eTimeCompare;
import org.plcvec.reference.Fc6aHourMeter;
import org.plcvec.reference.Fx5Compare;
import org.plcvec.reference.Fx5TimeAdd;
import org.plcvec.reference.Reference;
import org.plcvec.reference.Settings;
import org.plcvec.spec.Alternatives;
import org.plcvec.spec.Family;
import org.plcvec.spec.Instruction;
import org.plcvec.verify.Address;
import org.plcvec.verify.Choices;
import org.plcvec.verify.Emulator.Scan;
import org.plcvec.verify.Memory;
import org.plcvec.verify.Step;
import org.plcvec.verify.VectorRequest;

/**
 * Every mutant: each is the reference with one method of one family's class overridden. Together
 * they cover the five families and every comparison aspect: the contact result, a changed word,
 * a flag, a device that must stay unchanged, a write outside the vector, and an interpretation
 * alternative followed other than the one declared.
 */
public final class Mutants {
    private Mutants() {
    }

    private static final List<Mutant> ALL = new ArrayList<>();

    private static void add(String name, List<Family> families, String bug, java.util.function.Function<Choices, Reference> build) {
        ALL.add(new Mutant(name, families, bug, build));
    }

    private static final List<Family> FX5_COMPARE = List.of(Family.FX5_TIME_COMPARE, Family.FX5_DATE_COMPARE);

    static {
        // -- FX5 time and date comparison ---------------------------------------------------------
        add("fx5-low-field-first", FX5_COMPARE,
                "The selected fields are compared from (s1)+2 up (second before minute before hour), so a later field "
                        + "decides before an earlier one.",
                c -> fx5(c, (v, m, fields, settings) -> new Fx5Compare(v, m, fields, settings) {
                    @Override
                    protected int compare(int[] a, int[] b, int selected) {
                        for (int i = fields.length - 1; i >= 0; i--) {
                            Fx5Compare.Field f = fields[i];
                            if (((selected >> f.bit()) & 1) != 0 && a[f.offset()] != b[f.offset()]) {
                                return a[f.offset()] < b[f.offset()] ? -1 : 1;
                            }
                        }
                        return 0;
                    }
                }));
        add("fx5-sm709-not-latched", FX5_COMPARE,
                "SM709 is written on every execution, off when the data are good, although 'Once SM709 turns on, the "
                        + "on state is held until the CPU module is powered off or reset'.",
                c -> fx5(c, (v, m, fields, settings) -> new Fx5Compare(v, m, fields, settings) {
                    @Override
                    protected boolean evaluate(Step step) {
                        mem.setBit(Address.of("SM709"), false);
                        return super.evaluate(step);
                    }
                }));
        add("fx5-clock-bit-ignored", FX5_COMPARE,
                "Bit 15 of (s3) does not bring in the current time: (s1) is compared with (s2) all the same.",
                c -> fx5(c, (v, m, fields, settings) -> new Fx5Compare(v, m, fields, settings) {
                    @Override
                    protected int[] clock(Step step) {
                        return read(s2.device());
                    }
                }));
        add("fx5-date-calendar-check", List.of(Family.FX5_DATE_COMPARE),
                "A date that does not exist but is within the setting range (2006/02/30) turns SM709 on, although "
                        + "'Even if the data are not recognized as date data, SM709 does not turn on if the data are "
                        + "within the setting range'.",
                c -> fx5(c, (v, m, fields, settings) -> new Fx5Compare(v, m, fields, settings) {
                    @Override
                    protected boolean outOfRange(int[] words, int selected) {
                        if (fields == Fx5Compare.DATE && words[1] >= 1 && words[1] <= 12 && words[0] >= 1
                                && words[2] > java.time.YearMonth.of(words[0], words[1]).lengthOfMonth()) {
                            return true;
                        }
                        return super.outOfRange(words, selected);
                    }
                }));
        add("fx5-and-executed-when-off", List.of(Family.FX5_TIME_COMPARE),
                "Declares FX5-AND-OR-WHEN-OFF=and-skipped (the default) but executes AND while the preceding logic is "
                        + "off, and skips OR while it is on: AND as always-executed, OR as short-circuit, which no "
                        + "alternative does together.",
                c -> fx5(c, (v, m, fields, settings) -> new Fx5Compare(v, m, fields, settings) {
                    @Override
                    public Boolean execute(Step step) {
                        erred = false;
                        if (form == Instruction.Form.OR && step.rloIn()) {
                            return true;              // skipped: the preceding logic decides
                        }
                        boolean contact = evaluate(step);   // AND executed whatever the preceding logic
                        return form == Instruction.Form.LD ? contact
                                : form == Instruction.Form.AND ? step.rloIn() && contact : step.rloIn() || contact;
                    }
                }));

        // -- FX5 TADD / TADDP ---------------------------------------------------------------------
        add("tadd-no-wrap-at-24", List.of(Family.FX5_TIME_ADD),
                "'If the sum of two values exceeds 24:00:00' read literally: a sum of exactly 24:00:00 is stored as "
                        + "24:00:00 with neither flag, not as 0:00:00 with carry and zero.",
                c -> tadd(c, (v, m, settings) -> new Fx5TimeAdd(v, m, settings) {
                    @Override
                    protected int wrap(int total) {
                        return total == 24 * 3600 ? total : super.wrap(total);
                    }

                    @Override
                    protected boolean carries(int total) {
                        return total > 24 * 3600;
                    }
                }));
        add("tadd-sm8022-not-written", List.of(Family.FX5_TIME_ADD),
                "Only SM700 is written as the carry flag; SM8022, the table's second 'Carry' relay, is left alone.",
                c -> tadd(c, (v, m, settings) -> new Fx5TimeAdd(v, m, settings) {
                    @Override
                    protected void setFlags(boolean carry, boolean zero) {
                        boolean before = mem.bit(Address.of("SM8022"));
                        super.setFlags(carry, zero);
                        mem.setBit(Address.of("SM8022"), before);
                    }
                }));
        add("taddp-every-scan", List.of(Family.FX5_TIME_ADD),
                "TADDP adds on every scan while EN is on, like TADD, instead of once on its rising edge.",
                c -> tadd(c, (v, m, settings) -> new Fx5TimeAdd(v, m, settings) {
                    @Override
                    public Boolean execute(Step step) {
                        previousEn = false;
                        return super.execute(step);
                    }
                }));
        add("tadd-writes-past-d", List.of(Family.FX5_TIME_ADD),
                "The destination is cleared as four words, (d) to (d)+3, although 'These instructions occupy three "
                        + "points': (d)+3 is written outside the vector.",
                c -> tadd(c, (v, m, settings) -> new Fx5TimeAdd(v, m, settings) {
                    @Override
                    protected void add() {
                        super.add();
                        mem.setWord(d, 3, 0);
                    }
                }));
        add("tadd-s1-copied-into-d-first", List.of(Family.FX5_TIME_ADD),
                "(s1) is copied into (d) first and (s2) then added to (d) in place, so a (d) that shares words "
                        + "with (s2) at another offset adds a changed (s2), under every reading of TADD-OVERLAP.",
                c -> tadd(c, (v, m, settings) -> new Fx5TimeAdd(v, m, settings) {
                    @Override
                    protected int sum() {
                        int[] first = read(s1);
                        for (int k = 0; k < 3; k++) {
                            mem.setWord(d, k, first[k] & 0xFFFF);
                        }
                        return sum(d);
                    }
                }));

        // -- FC6A HOUR ----------------------------------------------------------------------------
        add("hour-drops-fraction", List.of(Family.FC6A_HOUR_METER),
                "Each scan's ON time is cut to whole seconds and the remainder thrown away, so many short scans never "
                        + "add up to the 'measured input ON duration'.",
                c -> hour(c, (v, m, settings) -> new Fc6aHourMeter(v, m, settings) {
                    @Override
                    public Boolean execute(Step step) {
                        fractionMs = 0;
                        return super.execute(step);
                    }
                }));
        add("hour-wrap-clears-d2", List.of(Family.FC6A_HOUR_METER),
                "When D1 returns to 0 hours 0 minutes 0 seconds D2 is turned off with it, instead of 'with the "
                        + "comparison output remaining on'.",
                c -> hour(c, (v, m, settings) -> new Fc6aHourMeter(v, m, settings) {
                    @Override
                    public Boolean execute(Step step) {
                        long before = measured();
                        Boolean r = super.execute(step);
                        if (measured() < before && step.input()) {
                            mem.setBit(d2, false);
                        }
                        return r;
                    }
                }));
        add("hour-input-off-resets", List.of(Family.FC6A_HOUR_METER),
                "Declares HOUR-INPUT-OFF=hold (the default) but clears D1 while the input is off, as reset does, yet "
                        + "keeps the fraction of a second already counted, which reset drops: no alternative does both.",
                c -> hour(c, (v, m, settings) -> new Fc6aHourMeter(v, m, settings) {
                    @Override
                    protected void inputOff() {
                        store(0);
                    }
                }));

        // -- CP1E time comparison -----------------------------------------------------------------
        add("cp1e-mask-inverted", List.of(Family.CP1E_TIME_COMPARE),
                "A C bit set to 1 selects its field for comparison, the opposite of 'To mask a time value, set the "
                        + "corresponding bit in the control word (C) to 1'.",
                c -> cp1e(c, (v, m, settings) -> new Cp1eTimeCompare(v, m, settings) {
                    @Override
                    protected boolean masked(int mask, Field f) {
                        return !super.masked(mask, f);
                    }
                }));
        add("cp1e-flags-not-reflected", List.of(Family.CP1E_TIME_COMPARE),
                "The arithmetic flags (=, <>, <, <=, >, >=) are left alone, although 'the result of a time comparison "
                        + "instruction is reflected in the arithmetic flags'.",
                c -> cp1e(c, (v, m, settings) -> new Cp1eTimeCompare(v, m, settings) {
                    @Override
                    protected void reflectFlags(int order) {
                        // the bug: nothing
                    }
                }));
        add("cp1e-bcd-read-as-binary", List.of(Family.CP1E_TIME_COMPARE),
                "The time bytes are read as BCD digits without checking them (tens x 10 + units), so a byte such as "
                        + "1AH is compared as 20 instead of turning P_ER on (nor as the byte 1AH, as raw-bytes compares it).",
                c -> cp1e(c, (v, m, settings) -> new Cp1eTimeCompare(v, m, settings) {
                    @Override
                    protected boolean isBcd(int b) {
                        return true;
                    }

                    @Override
                    protected int compared(int raw) {
                        return (raw >> 4) * 10 + (raw & 0x0F);
                    }
                }));
        add("cp1e-past-area-compared", List.of(Family.CP1E_TIME_COMPARE),
                "S1 or S2 at the last one or two words of the data area is compared all the same, the words past the "
                        + "end read as 0, instead of the error or program error CP1E-PAST-AREA-END names.",
                c -> cp1e(c, (v, m, settings) -> new Cp1eTimeCompare(v, m, settings) {
                    @Override
                    protected boolean inArea(Address operand) {
                        return true;
                    }
                }));
    }

    /** Builds one family's class for a vector: a mutant returns its subclass. */
    @FunctionalInterface
    interface Fx5Factory {
        Scan make(VectorRequest v, Memory m, Fx5Compare.Field[] fields, Settings settings);
    }

    @FunctionalInterface
    interface Factory {
        Scan make(VectorRequest v, Memory m, Settings settings);
    }

    private static Reference fx5(Choices c, Fx5Factory f) {
        return new Reference(c) {
            @Override
            protected Scan fx5Compare(VectorRequest v, Memory m, Fx5Compare.Field[] fields) {
                return f.make(v, m, fields, settings);
            }
        };
    }

    private static Reference tadd(Choices c, Factory f) {
        return new Reference(c) {
            @Override
            protected Scan fx5TimeAdd(VectorRequest v, Memory m) {
                return f.make(v, m, settings);
            }
        };
    }

    private static Reference hour(Choices c, Factory f) {
        return new Reference(c) {
            @Override
            protected Scan fc6aHourMeter(VectorRequest v, Memory m) {
                return f.make(v, m, settings);
            }
        };
    }

    private static Reference cp1e(Choices c, Factory f) {
        return new Reference(c) {
            @Override
            protected Scan cp1eTimeCompare(VectorRequest v, Memory m) {
                return f.make(v, m, settings);
            }
        };
    }

    /** Every mutant, in a fixed order. */
    public static List<Mutant> all() {
        return Collections.unmodifiableList(ALL);
    }

    /** The mutant named {@code name}, or null. */
    public static Mutant byName(String name) {
        return ALL.stream().filter(m -> m.name().equals(name)).findFirst().orElse(null);
    }
}
