package org.plcvec.reference;

import org.plcvec.spec.Alternatives.HourD1OutOfRange;
import org.plcvec.spec.Alternatives.HourD2Special;
import org.plcvec.spec.Alternatives.HourFirstScan;
import org.plcvec.spec.Alternatives.HourS1ConstantRange;
import org.plcvec.verify.Address;
import org.plcvec.verify.Emulator;
import org.plcvec.verify.Memory;
import org.plcvec.verify.Operand;
import org.plcvec.verify.Step;
import org.plcvec.verify.VectorRequest;

/**
 * IDEC FC6A MICROSmart: HOUR (hour meter), from fc6a-hour-meter-HOUR.txt. The fraction of a
 * second already measured lives in this object (on the CPU it is in the work area D3, D3+1,
 * whose contents the vectors never compare).
 */
public class Fc6aHourMeter implements Emulator.Scan {
    static final Address M8004 = Address.of("M8004");
    /** The first special internal relay, which D2 may not be (HOUR-D2-SPECIAL). */
    static final Address FIRST_SPECIAL_RELAY = Address.of("M8000");
    /** "the value returns to 0 hours 0 minutes 0 seconds" after "65,535 hours 59 minutes 59 seconds". */
    static final long CYCLE = 65536L * 3600;

    /** The memory the CPU reads and writes. */
    protected final Memory mem;
    /** The alternatives followed. */
    protected final Settings settings;
    /** D1, the measured time: hours, minutes, seconds. */
    protected final Address d1;
    /** D2, the comparison output. */
    protected final Address d2;
    /** S1, the preset: a constant (hours) or three words. */
    protected final Operand s1;
    /** The part of a second measured and not yet counted in D1. */
    protected long fractionMs;
    /** For HOUR-OUTPUT-OFF=recompared: D2 stays on across a wrap. */
    protected boolean wrapped;
    /** The input at the previous execution; before the first step it counts as off (HOUR-FIRST-SCAN). */
    protected boolean inputWasOn;
    /** An execution has run since the CPU started (HOUR-FIRST-SCAN=after-cpu-start). */
    protected boolean started;
    /** The previous check of S1 found it valid; true before the first (HOUR-M8004-REPEAT=once). */
    protected boolean lastCheckValid = true;
    /** A program the page forbids whose reading is {@code undefined}: nothing judged is done. */
    protected final boolean forbidden;
    /** HOUR-D2-SPECIAL=error and D2 a special internal relay: D2 never written, M8004 on instead. */
    protected final boolean d2Error;

    /**
     * A CPU for one HOUR vector.
     *
     * @param vector the vector
     * @param memory its device image
     * @param settings the alternatives followed
     * @throws IllegalArgumentException for an instruction that is not HOUR
     */
    public Fc6aHourMeter(VectorRequest vector, Memory memory, Settings settings) {
        if (!vector.instruction().equals("HOUR")) {
            throw new IllegalArgumentException("not HOUR: " + vector.instruction());
        }
        this.mem = memory;
        this.settings = settings;
        this.d1 = vector.operand("D1").device();
        this.d2 = vector.operand("D2").device();
        this.s1 = vector.operand("S1");
        boolean special = isSpecialRelay(d2);
        boolean outside = s1.isConstant() && !hourInRange(s1.constant());
        this.forbidden = special && settings.hourD2Special == HourD2Special.UNDEFINED
                || outside && settings.hourS1ConstantRange == HourS1ConstantRange.UNDEFINED;
        this.d2Error = special && settings.hourD2Special == HourD2Special.ERROR;
    }

    /**
     * "Special internal relays cannot be designated as destination device D2": the FC6A's special
     * internal relays are M8000 onwards (M8004, the error relay, is one).
     */
    private static boolean isSpecialRelay(Address a) {
        return a.kind().equals(FIRST_SPECIAL_RELAY.kind()) && a.number() >= FIRST_SPECIAL_RELAY.number();
    }

    /** "Hour data can be 0 through 65,535." */
    private static boolean hourInRange(long hours) {
        return hours >= 0 && hours <= 65535;
    }

    @Override
    public Boolean execute(Step step) {
        boolean turnedOn = step.input() && !inputWasOn;
        boolean first = !started;
        inputWasOn = step.input();
        started = true;
        if (forbidden) {
            return null;
        }
        if (!step.input()) {
            inputOff();
            if (settings.hourPresetEveryExecution) {
                checkPreset();          // HOUR-PRESET-CHECK=every-execution: with the input off too
            }
            return null;
        }
        measureAndCompare(step, turnedOn, first);
        if (d2Error) {
            mem.setBit(M8004, true);    // HOUR-D2-SPECIAL=error: after everything else the execution does
        }
        return null;
    }

    /**
     * An execution with the input on: D1 measured, S1 checked, D2 written.
     *
     * @param step the step
     * @param turnedOn the input was off at the previous execution
     * @param first the first execution since the CPU started
     */
    protected void measureAndCompare(Step step, boolean turnedOn, boolean first) {
        // "Minute and second data can be 0 through 59." A D1 the program set outside that is read
        // as HOUR-D1-OUT-OF-RANGE says.
        HourD1OutOfRange reading = mem.word(d1, 1) > 59 || mem.word(d1, 2) > 59
                ? settings.hourD1OutOfRange : HourD1OutOfRange.AS_SECONDS;
        if (reading == HourD1OutOfRange.UNDEFINED) {
            return;
        }
        if (reading == HourD1OutOfRange.ERROR) {
            mem.setBit(M8004, true);
            return;
        }
        // The elapsed time since the previous execution is ON time; HOUR-FIRST-SCAN says whether the
        // execution the input turns on at, or the first since the CPU started, counts it.
        boolean skip = turnedOn && settings.hourFirstScan == HourFirstScan.FROM_NEXT_SCAN
                || first && settings.hourFirstScan == HourFirstScan.AFTER_CPU_START;
        if (!skip) {
            fractionMs += step.elapsedMs();
        }
        long whole = fractionMs / 1000;
        fractionMs %= 1000;
        long[] hms;
        long wraps;
        if (reading == HourD1OutOfRange.BY_FIELD) {
            hms = new long[] {mem.word(d1, 0), mem.word(d1, 1), mem.word(d1, 2)};
            wraps = countByField(hms, whole);
            mem.setWord(d1, 0, (int) hms[0]);
            mem.setWord(d1, 1, (int) hms[1]);
            mem.setWord(d1, 2, (int) hms[2]);
        } else {
            long total = measured() + whole;
            wraps = total / cycle();
            // "When the measured input ON duration value exceeds 65,535 hours 59 minutes 59 seconds,
            // the value returns to 0 hours 0 minutes 0 seconds to repeat another measuring cycle, with
            // the comparison output remaining on."
            total %= cycle();
            hms = new long[] {total / 3600, total / 60 % 60, total % 60};
            if (whole > 0 || reading != HourD1OutOfRange.AS_SECONDS_IF_ADDED) {
                store(total);
            }
        }
        int[] p = checkPreset();
        if (p == null) {
            return;
        }
        // HOUR-WRAP-REACH=before-wrap compares the count as it was before it wrapped.
        boolean beforeWrap = wraps > 0 && settings.hourWrapBeforeWrap;
        long hours = hms[0] + (beforeWrap ? cycle() / 3600 * wraps : 0);   // 65,536 hours a wrap
        boolean reached;
        if (reading == HourD1OutOfRange.BY_FIELD) {     // word by word: the hours, then minutes, seconds
            reached = hours != p[0] ? hours > p[0] : hms[1] != p[1] ? hms[1] > p[1] : hms[2] >= p[2];
        } else {
            reached = reached(hours * 3600 + hms[1] * 60 + hms[2], p[0] * 3600L + p[1] * 60L + p[2]);
        }
        if (p[0] == 0 && p[1] == 0 && p[2] == 0 && settings.hourZeroPresetNever) {
            reached = false;
        }
        if (!d2Error) {
            setOutput(reached, wraps > 0, beforeWrap);
        }
    }

    /**
     * D1 counted on by {@code whole} seconds with each word a counter of its own
     * (HOUR-D1-OUT-OF-RANGE=by-field): a second that becomes exactly 60 becomes 0 and carries into
     * the minute, a minute likewise into the hour; a word above 59 counts on, carrying nothing,
     * until it passes 65535 to 0.
     *
     * @param hms hours, minutes, seconds; counted on in place
     * @param whole the whole seconds to add
     * @return how many times the hour passed 65535 to 0 (D1 wrapped)
     */
    protected static long countByField(long[] hms, long whole) {
        long wraps = 0;
        for (long i = 0; i < whole; i++) {
            hms[2] = (hms[2] + 1) & 0xFFFF;
            if (hms[2] != 60) {
                continue;
            }
            hms[2] = 0;
            hms[1] = (hms[1] + 1) & 0xFFFF;
            if (hms[1] != 60) {
                continue;
            }
            hms[1] = 0;
            hms[0] = (hms[0] + 1) & 0xFFFF;
            if (hms[0] == 0) {
                wraps++;
            }
        }
        return wraps;
    }

    /**
     * Write D2: "When the D1 value reaches the S1 value, an output or internal relay assigned by
     * destination device D2 is turned on" ("with the comparison output remaining on" across a wrap).
     *
     * @param reached D1 has reached S1
     * @param wrappedNow D1 wrapped at this execution
     * @param comparedFirst compared before the wrap (HOUR-WRAP-REACH=before-wrap)
     */
    protected void setOutput(boolean reached, boolean wrappedNow, boolean comparedFirst) {
        if (!settings.hourRecompared) {
            if (reached) {
                mem.setBit(d2, true);
            }
            return;
        }
        // recompared: D2 = D1 >= S1, except that it stays on across a wrap
        if (wrappedNow && !comparedFirst && mem.bit(d2)) {
            wrapped = true;
        }
        if (reached) {
            wrapped = false;
        }
        mem.setBit(d2, reached || (wrapped && mem.bit(d2)));
        if (wrappedNow && comparedFirst && mem.bit(d2)) {
            wrapped = true;         // on when D1 wrapped, after the comparison
        }
    }

    /** "While input is on, the ON duration of the input is measured." Off: HOUR-INPUT-OFF. */
    protected void inputOff() {
        switch (settings.hourInputOff) {
            case RESET:
                store(0);
                fractionMs = 0;
                break;
            case HOLD_DROP_FRACTION:
                fractionMs = 0;     // D1 kept; the part of a second is lost
                break;
            default:                // HOLD: nothing changes
        }
    }

    /**
     * Read and check S1.
     *
     * @return the preset (hours, minutes, seconds), or null when it is invalid (M8004 on, D2 off)
     */
    protected int[] checkPreset() {
        int[] p = preset();
        if (!presetValid(p)) {
            // "... a user program execution error will result, turning on special internal relay
            // M8004 ... but the input ON duration is measured." HOUR-M8004-REPEAT=once: only when the
            // check before found S1 valid.
            if (!settings.hourM8004Once || lastCheckValid) {
                mem.setBit(M8004, true);
            }
            lastCheckValid = false;
            // "... is changed to an invalid value after the comparison output has turned on, the
            // comparison output is turned off."
            if (!d2Error) {
                mem.setBit(d2, false);
            }
            return null;
        }
        lastCheckValid = true;
        if (settings.hourM8004OffWhenValid) {
            mem.setBit(M8004, false);   // the page never says M8004 turns off: HOUR-M8004-OFF=valid-preset
        }
        return p;
    }

    /**
     * The seconds after which D1 returns to 0 hours 0 minutes 0 seconds.
     *
     * @return 65,536 hours in seconds
     */
    protected long cycle() {
        return CYCLE;
    }

    /**
     * "When the measured input ON duration value in D1 reaches the preset value"
     *
     * @param total D1 in seconds
     * @param preset S1 in seconds
     * @return true when D1 has reached S1
     */
    protected boolean reached(long total, long preset) {
        return total >= preset;
    }

    /**
     * D1, D1+1, D1+2: hours, minutes, seconds.
     *
     * @return D1 in seconds
     */
    protected long measured() {
        return mem.word(d1, 0) * 3600L + mem.word(d1, 1) * 60L + mem.word(d1, 2);
    }

    /**
     * Write D1 as hours, minutes and seconds.
     *
     * @param total the seconds measured
     */
    protected void store(long total) {
        mem.setWord(d1, 0, (int) (total / 3600));
        mem.setWord(d1, 1, (int) (total / 60 % 60));
        mem.setWord(d1, 2, (int) (total % 60));
    }

    /**
     * "When source device S1 is designated by a constant, the preset value can be 0 through 65,535
     * in hours, then minutes and seconds are set to 0." (One past that is read as
     * HOUR-S1-CONSTANT-RANGE says.) "... when designated by a data register,
     * ... occupy 3 consecutive data registers ... to store hour, minute, and second data."
     *
     * @return hours, minutes, seconds
     */
    protected int[] preset() {
        if (s1.isConstant()) {
            long hours = s1.constant();
            if (!hourInRange(hours) && settings.hourS1ConstantRange == HourS1ConstantRange.LOW_16_BITS) {
                hours &= 0xFFFF;
            }
            return new int[] {(int) hours, 0, 0};
        }
        Address a = s1.device();
        return new int[] {mem.word(a, 0), mem.word(a, 1), mem.word(a, 2)};
    }

    /**
     * "Hour data can be 0 through 65,535. Minute and second data can be 0 through 59." Only a
     * constant holds an hour past that: HOUR-S1-CONSTANT-RANGE=as-is takes it.
     *
     * @param p the preset: hours, minutes, seconds
     * @return true when every field is in range
     */
    protected boolean presetValid(int[] p) {
        boolean hourOk = hourInRange(p[0]) || settings.hourS1ConstantRange == HourS1ConstantRange.AS_IS;
        return hourOk && p[1] >= 0 && p[1] <= 59 && p[2] >= 0 && p[2] <= 59;
    }
}
