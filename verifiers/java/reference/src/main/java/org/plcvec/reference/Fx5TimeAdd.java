package org.plcvec.reference;

import org.plcvec.verify.Address;
import org.plcvec.verify.Emulator;
import org.plcvec.verify.Memory;
import org.plcvec.verify.Step;
import org.plcvec.verify.VectorRequest;

/** Mitsubishi MELSEC iQ-F FX5: TADD / TADDP (adding clock data), from fx5-time-add-TADD.txt. */
public class Fx5TimeAdd implements Emulator.Scan {
    static final int DAY = 24 * 3600;
    // "SM700 Carry ... SM8020 Zero ... SM8022 Carry"
    static final Address SM700 = Address.of("SM700");
    static final Address SM8022 = Address.of("SM8022");
    static final Address ZERO = Address.of("SM8020");
    // "Error code (SD0/SD8067)"
    static final Address SD0 = Address.of("SD0");
    static final Address SD8067 = Address.of("SD8067");
    /** "2820H The device range specified by (s1), (s2), and (d) exceeds the corresponding device range." */
    static final int ERR_DEVICE_RANGE = 0x2820;
    /** "3405H Any of values specified by (s1) and (s2) is outside the following range." */
    static final int ERR_VALUE_RANGE = 0x3405;
    /** "(s1) hour (0 to 23) ... minute (0 to 59) ... second (0 to 59)". */
    static final int[] MAX = {23, 59, 59};
    /** Seconds in one hour, minute, second; and what each word counts up to before it carries. */
    static final int[] WEIGHT = {3600, 60, 1};
    static final int[] RADIX = {24, 60, 60};

    /** The memory the CPU reads and writes. */
    protected final Memory mem;
    /** The alternatives followed. */
    protected final Settings settings;
    /** TADDP: executed on the rising edge of EN only. */
    protected final boolean pulse;
    /** (s1), the first time added. */
    protected final Address s1;
    /** (s2), the second time added. */
    protected final Address s2;
    /** (d), where the sum is stored. */
    protected final Address d;
    /** TADDP: the state of EN before the first step is off. */
    protected boolean previousEn;

    /**
     * A CPU for one TADD or TADDP vector.
     *
     * @param vector the vector
     * @param memory its device image
     * @param settings the alternatives followed
     * @throws IllegalArgumentException for an instruction that is not TADD or TADDP
     */
    public Fx5TimeAdd(VectorRequest vector, Memory memory, Settings settings) {
        String instruction = vector.instruction();
        if (!instruction.equals("TADD") && !instruction.equals("TADDP")) {
            throw new IllegalArgumentException("not TADD/TADDP: " + instruction);
        }
        this.mem = memory;
        this.settings = settings;
        this.pulse = instruction.equals("TADDP");
        this.s1 = vector.operand("s1").device();
        this.s2 = vector.operand("s2").device();
        this.d = vector.operand("d").device();
    }

    @Override
    public Boolean execute(Step step) {
        boolean en = step.en();
        // TADD: every scan while EN is on; TADDP: on the rising edge of EN only.
        boolean run = pulse ? en && !previousEn : en;
        previousEn = en;
        if (run) {
            add();
        }
        return null;
    }

    /** One execution of the addition. */
    protected void add() {
        // "These instructions occupy three points for each of three devices"; out of range:
        // error 2820H, nothing read or written.
        if (!mem.inRange(s1, 3) || !mem.inRange(s2, 3) || !mem.inRange(d, 3)) {
            // Both conditions in one execution: TADD-ERROR-ORDER says which code. Only an operand
            // whose three words exist can be read and checked; nothing else is written.
            boolean fieldBad = (mem.inRange(s1, 3) && !valid(read(s1))) || (mem.inRange(s2, 3) && !valid(read(s2)));
            error(fieldBad && settings.taddFieldRangeFirst ? ERR_VALUE_RANGE : ERR_DEVICE_RANGE);
            return;
        }
        int[] a = read(s1);
        int[] b = read(s2);
        if (!valid(a) || !valid(b)) {
            error(ERR_VALUE_RANGE);
            if (!settings.taddComputedOnError) {
                return;      // TADD-ON-ERROR=not-executed: (d) and the flags keep their values
            }
        }
        int total = sum();
        boolean carry = carries(total);
        int result = wrap(total);
        mem.setWord(d, 0, result / 3600);
        mem.setWord(d, 1, result / 60 % 60);
        mem.setWord(d, 2, result % 60);
        // "If the result is 0 (0:00:00), the zero flag turns on."
        setFlags(carry, result == 0);
    }

    /**
     * (s1) + (s2) in seconds, the words read in the order TADD-OVERLAP says. The order shows only
     * when (d) shares words with (s1) or (s2) at another offset ((d) = (s1)+1, ...): a source word
     * read after a word of (d) was written holds what was written.
     *
     * @return the sum of the times in seconds, of the words as read
     */
    protected int sum() {
        return sum(s1);
    }

    /**
     * {@code first} + (s2) in seconds, read as {@link #sum()} reads (s1) + (s2).
     *
     * @param first the three words added to (s2): (s1), or where an implementation has copied it
     * @return the sum of the times in seconds, of the words as read
     */
    protected int sum(Address first) {
        int total = 0;
        switch (settings.taddOverlap) {
            case SECOND_FIRST:
                // Second, minute, hour, the carry's way: each word of (d) gets its digit as soon as it
                // is known.
                int carry = 0;
                for (int k = 2; k >= 0; k--) {
                    int ab = signed(first, k) + signed(s2, k);
                    total += ab * WEIGHT[k];
                    mem.setWord(d, k, Math.floorMod(ab + carry, RADIX[k]) & 0xFFFF);
                    carry = Math.floorDiv(ab + carry, RADIX[k]);
                }
                return total;
            case HOUR_FIRST:
                // Hour, minute, second, each pair's plain sum into (d); the carries are settled
                // afterwards, from the three sums.
                for (int k = 0; k < 3; k++) {
                    int ab = signed(first, k) + signed(s2, k);
                    total += ab * WEIGHT[k];
                    mem.setWord(d, k, ab & 0xFFFF);
                }
                return total;
            default:
                // SOURCES_FIRST: all six words read before (d) is written (into no array: this is
                // every execution's path under the defaults).
                for (int k = 0; k < 3; k++) {
                    total += (signed(first, k) + signed(s2, k)) * WEIGHT[k];
                }
                return total;
        }
    }

    /** Word {@code k} of an operand, "16-bit signed binary". */
    private int signed(Address base, int k) {
        return (short) mem.word(base, k);
    }

    /**
     * "If the sum of two values exceeds 24:00:00, the carry flag turns on, and the result will be
     * the sum minus 24:00:00." But "If 1 second is added to 23:59:59, the result will be 0:00:00.
     * This turns on both the carry flag and the zero flag." (TADD-EXACT-24)
     *
     * @param total the sum in seconds
     * @return true when it carries
     */
    protected boolean carries(int total) {
        return settings.taddCarryAbove24 ? total > DAY : total >= DAY;
    }

    /**
     * The sum as stored: "the result will be the sum minus 24:00:00".
     *
     * @param total the sum in seconds
     * @return the seconds stored
     */
    protected int wrap(int total) {
        return Math.floorMod(total, DAY);
    }

    /**
     * Whether every field is within its range (hour 0 to 23, minute and second 0 to 59).
     *
     * @param hms hours, minutes, seconds
     * @return true when valid
     */
    protected boolean valid(int[] hms) {
        for (int i = 0; i < 3; i++) {
            if (hms[i] < 0 || hms[i] > MAX[i]) {
                return false;
            }
        }
        return true;
    }

    /**
     * Three words, "16-bit signed binary".
     *
     * @param base the operand's first word
     * @return hours, minutes, seconds, signed
     */
    protected int[] read(Address base) {
        return new int[] {(short) mem.word(base, 0), (short) mem.word(base, 1), (short) mem.word(base, 2)};
    }

    /**
     * An operation error: its code in SD0 and SD8067.
     *
     * @param code the error code (2820H, 3405H)
     */
    protected void error(int code) {
        mem.setWord(SD0, code);
        mem.setWord(SD8067, code);
    }

    /**
     * Write the carry flags (SM700, SM8022) and the zero flag (SM8020) as TADD-FLAGS-OFF says.
     *
     * @param carry whether the sum carried
     * @param zero whether the result is 0:00:00
     */
    protected void setFlags(boolean carry, boolean zero) {
        if (settings.taddFlagsSetOnly) {
            // TADD-FLAGS-OFF=set-only: an execution only ever turns a flag on.
            if (carry) {
                mem.setBit(SM700, true);
                mem.setBit(SM8022, true);
            }
            if (zero) {
                mem.setBit(ZERO, true);
            }
            return;
        }
        mem.setBit(SM700, carry);
        mem.setBit(SM8022, carry);
        mem.setBit(ZERO, zero);
    }
}
