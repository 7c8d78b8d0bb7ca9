package org.plcvec.reference;

import org.plcvec.spec.Alternatives.Cp1eAndOrWhenOff;
import org.plcvec.spec.Family;
import org.plcvec.spec.Instruction;
import org.plcvec.verify.Address;
import org.plcvec.verify.Emulator;
import org.plcvec.verify.Memory;
import org.plcvec.verify.Operand;
import org.plcvec.verify.Step;
import org.plcvec.verify.VectorRequest;

/**
 * Omron SYSMAC CP1E: LD/AND/OR {@code =DT, <>DT, <DT, <=DT, >DT, >=DT}, from cp1e-time-compare-DT.txt
 * (W483 p. 2-93).
 *
 * <p>P_ER is a condition flag: it reflects the result of the instruction just executed, so an
 * execution that ends without error turns it off (CP1E-ER-FLAG=reflects-each-execution; the other
 * reading, that only an error writes it, is the alternative "held").
 */
public class Cp1eTimeCompare implements Emulator.Scan {
    /**
     * One byte field: word offset, byte (0: bits 00-07, 1: bits 08-15), range, and the C mask bit.
     * "A351.00 to A351.07 Second (00 to 59, BCD)  A351.08 to A351.15 Minute ... A352.00 Hour ...
     * A352.08 Day of month ... A353.00 Month ... A353.08 Year (00 to 99, BCD)"; "Bits 00 to 05 of C
     * mask the seconds, minutes, hours, day, month, and year, respectively."
     */
    public record Field(int offset, int shift, String name, int min, int max, int maskBit) {
    }

    /** Most significant first. */
    public static final Field[] FIELDS = {
        new Field(2, 8, "year", 0, 99, 5), new Field(2, 0, "month", 1, 12, 4), new Field(1, 8, "day", 1, 31, 3),
        new Field(1, 0, "hour", 0, 23, 2), new Field(0, 8, "minute", 0, 59, 1), new Field(0, 0, "second", 0, 59, 0),
    };

    static final Address P_ER = Address.of("P_ER");
    /** The arithmetic flags, one per condition. */
    static final java.util.Map<Instruction.Condition, Address> FLAGS = java.util.Map.of(
        Instruction.Condition.EQ, Address.of("P_EQ"), Instruction.Condition.NE, Address.of("P_NE"),
        Instruction.Condition.LT, Address.of("P_LT"), Instruction.Condition.LE, Address.of("P_LE"),
        Instruction.Condition.GT, Address.of("P_GT"), Instruction.Condition.GE, Address.of("P_GE"));
    /** Every condition, once: {@code values()} makes a new array at each call. */
    private static final Instruction.Condition[] CONDITIONS = Instruction.Condition.values();
    /**
     * {@link #FLAGS} by the condition's ordinal: the flags are written at every execution, where a
     * lookup in the map (hashing, probing) cost more than the comparison itself.
     */
    private static final Address[] FLAG_OF = new Address[CONDITIONS.length];

    static {
        for (Instruction.Condition k : CONDITIONS) {
            FLAG_OF[k.ordinal()] = FLAGS.get(k);
        }
    }

    /** The memory the CPU reads and writes. */
    protected final Memory mem;
    /** The alternatives followed. */
    protected final Settings settings;
    /** LD, AND or OR. */
    protected final Instruction.Form form;
    /** What the comparison tests. */
    protected final Instruction.Condition condition;
    /** S1, the first three words compared. */
    protected final Address s1;
    /** S2, the three words S1 is compared with. */
    protected final Address s2;
    /** C, the control word whose bits mask fields. */
    protected final Operand c;

    /**
     * A CPU for one CP1E time comparison vector.
     *
     * @param vector the vector
     * @param memory its device image
     * @param settings the alternatives followed
     * @throws IllegalArgumentException for an instruction that is not a CP1E time comparison
     */
    public Cp1eTimeCompare(VectorRequest vector, Memory memory, Settings settings) {
        Instruction m = vector.instructionName();
        if (m == null || m.form() == null || m.family() != Family.CP1E_TIME_COMPARE) {
            throw new IllegalArgumentException("not a CP1E time comparison: " + vector.instruction());
        }
        this.mem = memory;
        this.settings = settings;
        this.form = m.form();
        this.condition = m.condition();
        this.s1 = vector.operand("S1").device();
        this.s2 = vector.operand("S2").device();
        this.c = vector.operand("C");
    }

    /**
     * "The time comparison instructions are treated just like the LD, AND, and OR instructions to
     * control the execution of subsequent instructions."
     */
    @Override
    public Boolean execute(Step step) {
        Cp1eAndOrWhenOff logic = settings.cp1eLogic;
        return Contact.result(form, step, logic != Cp1eAndOrWhenOff.ALWAYS_EXECUTED, logic == Cp1eAndOrWhenOff.SHORT_CIRCUIT,
                this::evaluate);
    }

    /**
     * Whether the three words of S1 or S2 from {@code operand} lie in their data area.
     *
     * @param operand S1 or S2
     * @return true when all three words exist
     */
    protected boolean inArea(Address operand) {
        return mem.inRange(operand, 3);
    }

    /**
     * The comparison: C read, each unmasked field checked and compared, the flags written.
     *
     * @return the execution condition it creates
     */
    protected boolean evaluate() {
        // "S1 to S1+2", "S2 to S2+2": three words each. One past the end of the data area (S1 in
        // one of the last two words of D) is CP1E-PAST-AREA-END, found before C or the data are
        // looked at: an error, or a program error (not executed: nothing written, OFF).
        if (!inArea(s1) || !inArea(s2)) {
            return settings.cp1ePastAreaProgramError ? false : error();
        }
        int mask = c.word(mem);
        // Bits 06 to 15 of C: not described by the manual (CP1E-C-HIGH-BITS).
        if ((mask & 0xFFC0) != 0 && settings.cp1eHighBitsError) {
            return error();
        }
        // "To mask a time value, set the corresponding bit in the control word (C) to 1."
        // "compares the unmasked values (corresponding bit of C set to 0)"
        boolean any = false;
        int order = 0;
        for (Field f : fields()) {
            if (masked(mask, f)) {
                continue;
            }
            any = true;
            int a = (mem.word(s1, f.offset()) >> f.shift()) & 0xFF;
            int b = (mem.word(s2, f.offset()) >> f.shift()) & 0xFF;
            if (invalid(a, f) || invalid(b, f)) {
                return error();
            }
            a = compared(a);
            b = compared(b);
            // "The time comparison instructions are limited to comparing 8-bit time values." For
            // valid BCD the byte order is the numeric order.
            if (order == 0 && a != b) {
                order = a < b ? -1 : 1;
            }
        }
        if (!any) {
            Boolean ended = allMasked();
            if (ended != null) {
                return ended;
            }
        }
        return executed(order);
    }

    /**
     * The end of an execution without error: the flags reflect the comparison, P_ER as
     * CP1E-ER-FLAG says. Apart from {@link #evaluate} for the same reason as {@link #allMasked}.
     *
     * @param order S1 against S2: negative, 0 or positive
     * @return the execution condition it creates
     */
    private boolean executed(int order) {
        reflectFlags(order);
        if (!settings.cp1eErHeld) {
            mem.setBit(P_ER, false);      // executed without error
        }
        return Contact.holds(condition, order);
    }

    /**
     * Every field masked (CP1E-ALL-MASKED). Kept apart from {@link #evaluate} so that evaluate stays
     * under the size up to which the JIT inlines a hot method (HotSpot's FreqInlineSize, 325 bytes
     * of bytecode): above it, every execution pays a call (InlinableTest).
     *
     * @return the execution condition when the execution ends here, or null when it goes on as a
     *     comparison of equal values
     */
    private Boolean allMasked() {
        switch (settings.cp1eAllMasked) {
            case ERROR:
                return error();
            case NOT_COMPARED:
                // Nothing compared, no result: OFF, flags untouched, no error.
                if (!settings.cp1eErHeld) {
                    mem.setBit(P_ER, false);
                }
                return false;
            default:   // EQUAL: nothing differs
                return null;
        }
    }

    /**
     * Whether a field's byte is an error under the alternatives followed.
     *
     * @param raw the byte
     * @param f its field
     * @return true for a byte that is not BCD, or out of its range, where an alternative makes that an error
     */
    protected boolean invalid(int raw, Field f) {
        if (!isBcd(raw)) {
            return settings.cp1eNonBcdError;          // "Second (00 to 59, BCD)" (CP1E-NON-BCD)
        }
        int v = bcd(raw);
        return (v < f.min() || v > f.max()) && settings.cp1eOutOfRangeError;   // (CP1E-OUT-OF-RANGE)
    }

    /**
     * The value a field's byte is compared as.
     *
     * @param raw the byte
     * @return the byte itself, whose order is the numeric one for valid BCD
     */
    protected int compared(int raw) {
        return raw;
    }

    /**
     * The fields compared, most significant first.
     *
     * @return the fields
     */
    protected Field[] fields() {
        return FIELDS;
    }

    /**
     * Whether C masks a field: its bit set to 1.
     *
     * @param mask the control word
     * @param f the field
     * @return true when the field is not compared
     */
    protected boolean masked(int mask, Field f) {
        return ((mask >> f.maskBit()) & 1) != 0;
    }

    /**
     * "the result of a time comparison instruction is reflected in the arithmetic flags ({@code =, <>, <, <=, >, >=})."
     *
     * @param order S1 against S2: negative, 0 or positive
     */
    protected void reflectFlags(int order) {
        for (Instruction.Condition k : CONDITIONS) {
            mem.setBit(FLAG_OF[k.ordinal()], Contact.holds(k, order));
        }
    }

    /**
     * Error: P_ER on, execution condition OFF, the six arithmetic flags as CP1E-ERROR-FLAGS says.
     *
     * @return the execution condition: OFF
     */
    protected boolean error() {
        mem.setBit(P_ER, true);
        if (settings.cp1eErrorFlagsOff) {
            for (Address flag : FLAG_OF) {
                mem.setBit(flag, false);
            }
        }
        return false;
    }

    /**
     * Whether a byte is two BCD digits.
     *
     * @param b the byte
     * @return true when neither nibble is above 9
     */
    protected boolean isBcd(int b) {
        return (b >> 4) <= 9 && (b & 0xF) <= 9;
    }

    static int bcd(int b) {
        return (b >> 4) * 10 + (b & 0xF);
    }
}
