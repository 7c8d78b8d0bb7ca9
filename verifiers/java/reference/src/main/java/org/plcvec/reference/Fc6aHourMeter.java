package org.plcvec.reference;

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
    }

    @Override
    public Boolean execute(Step step) {
        boolean turnedOn = step.input() && !inputWasOn;
        inputWasOn = step.input();
        if (!step.input()) {
            inputOff();
            if (settings.hourPresetEveryExecution) {
                checkPreset();          // HOUR-PRESET-CHECK=every-execution: with the input off too
            }
            return null;
        }
        // "Minute and second data can be 0 through 59." A D1 the program set outside that is counted
        // as seconds and carried back into range (HOUR-D1-OUT-OF-RANGE=as-seconds), or is an error
        // that stops this execution (error).
        if (settings.hourD1OutOfRangeError && (mem.word(d1, 1) > 59 || mem.word(d1, 2) > 59)) {
            mem.setBit(M8004, true);
            return null;
        }
        // The elapsed time since the previous execution is ON time; at the execution the input
        // turns on, only under HOUR-FIRST-SCAN=counts.
        if (!(turnedOn && settings.hourFromNextScan)) {
            fractionMs += step.elapsedMs();
        }
        long whole = fractionMs / 1000;
        fractionMs %= 1000;
        long total = measured() + whole;
        boolean wrappedNow = total >= cycle();
        // "When the measured input ON duration value exceeds 65,535 hours 59 minutes 59 seconds, the
        // value returns to 0 hours 0 minutes 0 seconds to repeat another measuring cycle, with the
        // comparison output remaining on."
        total %= cycle();
        store(total);

        int[] p = checkPreset();
        if (p == null) {
            return null;
        }
        long preset = p[0] * 3600L + p[1] * 60L + p[2];
        boolean reached = reached(total, preset);
        if (preset == 0 && settings.hourZeroPresetNever) {
            reached = false;
        }
        // "When the D1 value reaches the S1 value, an output or internal relay assigned by
        // destination device D2 is turned on."
        if (!settings.hourRecompared) {
            if (reached) {
                mem.setBit(d2, true);
            }
        } else {
            if (wrappedNow && mem.bit(d2)) {
                wrapped = true;
            }
            if (reached) {
                wrapped = false;
            }
            mem.setBit(d2, reached || (wrapped && mem.bit(d2)));
        }
        return null;
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
            // M8004 ... but the input ON duration is measured." "... is changed to an invalid value
            // after the comparison output has turned on, the comparison output is turned off."
            mem.setBit(M8004, true);
            mem.setBit(d2, false);
            return null;
        }
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
     * in hours, then minutes and seconds are set to 0." "... when designated by a data register,
     * ... occupy 3 consecutive data registers ... to store hour, minute, and second data."
     *
     * @return hours, minutes, seconds
     */
    protected int[] preset() {
        if (s1.isConstant()) {
            return new int[] {(int) (s1.constant() & 0xFFFF), 0, 0};
        }
        Address a = s1.device();
        return new int[] {mem.word(a, 0), mem.word(a, 1), mem.word(a, 2)};
    }

    /**
     * "Hour data can be 0 through 65,535. Minute and second data can be 0 through 59."
     *
     * @param p the preset: hours, minutes, seconds
     * @return true when every field is in range
     */
    protected boolean presetValid(int[] p) {
        return p[0] >= 0 && p[0] <= 65535 && p[1] >= 0 && p[1] <= 59 && p[2] >= 0 && p[2] <= 59;
    }
}
