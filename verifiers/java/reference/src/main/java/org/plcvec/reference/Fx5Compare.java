package org.plcvec.reference;

import org.plcvec.spec.Alternatives.Fx5AndOrWhenOff;
import org.plcvec.spec.Family;
import org.plcvec.spec.Instruction;
import org.plcvec.verify.Address;
import org.plcvec.verify.Emulator;
import org.plcvec.verify.Memory;
import org.plcvec.verify.Operand;
import org.plcvec.verify.Step;
import org.plcvec.verify.VectorRequest;

/**
 * Mitsubishi MELSEC iQ-F FX5: LDTM□/ANDTM□/ORTM□ (time) and LDDT□/ANDDT□/ORDT□ (date), from the
 * manual pages fx5-time-compare-LDTM.txt and fx5-date-compare-LDDT.txt. The two pages are the
 * same text with hour/minute/second replaced by year/month/day, so one class serves both.
 */
public class Fx5Compare implements Emulator.Scan {
    /** One field of the 3-word data: its word offset, name, range and (s3) selector bit. */
    public record Field(int offset, String name, int min, int max, int bit) {
    }

    // 'Set the "hour" data ... within the range 0 to 23.' '"minute" ... (s1)+1 ... 0 to 59.'
    // '"second" ... (s1)+2 ... 0 to 59.' '(1) Set "second" as comparison target. (2) ... "minute"
    // ... (3) ... "hour"': b0 second, b1 minute, b2 hour. Most significant first.
    /** The time comparison's fields, most significant first. */
    public static final Field[] TIME = {
        new Field(0, "hour", 0, 23, 2), new Field(1, "minute", 0, 59, 1), new Field(2, "second", 0, 59, 0),
    };
    // 'Set the 4 digit "year" data ... 1980 to 2079.' '"month" ... 1 to 12.' '"date" ... 1 to 31.'
    /** The date comparison's fields, most significant first. */
    public static final Field[] DATE = {
        new Field(0, "year", 1980, 2079, 2), new Field(1, "month", 1, 12, 1), new Field(2, "day", 1, 31, 0),
    };

    static final Address SM709 = Address.of("SM709");

    /** The memory the CPU reads and writes. */
    protected final Memory mem;
    /** The fields compared: {@link #TIME} or {@link #DATE}. */
    protected final Field[] fields;
    /** The alternatives followed. */
    protected final Settings settings;
    /** LD, AND or OR. */
    protected final Instruction.Form form;
    /** What the comparison tests. */
    protected final Instruction.Condition condition;
    /** (s1), the first data. */
    protected final Operand s1;
    /** (s2), the data (s1) is compared with. */
    protected final Operand s2;
    /** (s3), the selector: which fields are compared, and bit 15 for the current time. */
    protected final Operand s3;

    /**
     * A CPU for one FX5 time or date comparison vector.
     *
     * @param vector the vector
     * @param memory its device image
     * @param fields {@link #TIME} or {@link #DATE}
     * @param settings the alternatives followed
     * @throws IllegalArgumentException for an instruction that is not a comparison of that family
     */
    public Fx5Compare(VectorRequest vector, Memory memory, Field[] fields, Settings settings) {
        Instruction m = vector.instructionName();
        if (m == null || m.form() == null
                || m.family() != (fields == TIME ? Family.FX5_TIME_COMPARE : Family.FX5_DATE_COMPARE)) {
            throw new IllegalArgumentException("not an FX5 " + (fields == TIME ? "time" : "date") + " comparison: "
                    + vector.instruction());
        }
        this.mem = memory;
        this.fields = fields;
        this.settings = settings;
        this.form = m.form();
        this.condition = m.condition();
        this.s1 = vector.operand("s1");
        this.s2 = vector.operand("s2");
        this.s3 = vector.operand("s3");
    }

    /** One scan of one LD/AND/OR contact; returns the logic state after it. */
    @Override
    public Boolean execute(Step step) {
        // "(Devices are used as a normally open contact.)" The MELSEC iQ-R Programming Manual
        // (CPU Module Instructions), processing-time tables: "an AND/OR comparison is not
        // executed while the preceding logic is off" (FX5-AND-OR-WHEN-OFF).
        Fx5AndOrWhenOff logic = settings.fx5Logic;
        erred = false;
        boolean result = Contact.result(form, step, logic != Fx5AndOrWhenOff.ALWAYS_EXECUTED,
                logic == Fx5AndOrWhenOff.SHORT_CIRCUIT, () -> evaluate(step));
        // An execution that turns SM709 on is a non-conductive contact, ORed like any other; under
        // FX5-OR-ON-ERROR=result-off it turns the OR form's result off too.
        return erred && form == Instruction.Form.OR && settings.fx5OrResultOffOnError ? false : result;
    }

    /** Whether this execution turned SM709 on. */
    protected boolean erred;

    /**
     * The comparison itself (the "contact").
     *
     * @param step the step (its clock for a current-time comparison)
     * @return the comparison's result
     */
    protected boolean evaluate(Step step) {
        int s3word = s3.word(mem);
        // "(5) When 1 is set to the 15 bit, the data in the device specified by (s1) is compared
        // with the current time ... The time data in the device specified by (s2) is regarded as
        // dummy data and ignored."
        boolean useClock = (s3word & 0x8000) != 0;

        // "(4) Set 0. If a value other than 0 is set, the operation result will be
        // non-continuity." (bits 3 to 14). "When 0 is set to the 0 to 2 bits, the time data ...
        // are not compared." Table: "Other than 0001H to 0007H, 8001H to 8007H  None".
        boolean selectorValid = (s3word & 0x7FF8) == 0 && (s3word & 0x0007) != 0;

        // "If the device areas specified by (s1) to (s1)+2 or (s2) to (s2)+2 exceed the
        // corresponding device range, SM709 turns on ... and the operation result will be
        // non-continuity as well."
        boolean s2Checked = !useClock || settings.clockS2RangeChecked;
        if (!mem.inRange(s1.device(), 3) || s2Checked && !mem.inRange(s2.device(), 3)) {
            // An invalid (s3) as well: which rule decides is FX5-INVALID-S3-DEVICE-RANGE.
            if (!selectorValid && settings.fx5InvalidS3First) {
                return false;
            }
            return error();
        }
        int[] a = read(s1.device());
        int[] b = useClock ? clock(step) : read(s2.device());
        Boolean ended = endedBeforeComparing(a, b, useClock, s3word, selectorValid);
        if (ended != null) {
            return ended;
        }
        // Date page: "Even if the data are not recognized as date data, SM709 does not turn on if
        // the data are within the setting range": 02/30 is compared as it is.
        return Contact.holds(condition, compare(a, b, s3word));
    }

    /**
     * The result of an execution that ends before the comparison: data not recognized as time (or
     * date) data ({@link #error()}), or a selector that compares nothing. Kept apart from
     * {@link #evaluate} so that evaluate stays under the size up to which the JIT inlines a hot
     * method (HotSpot's FreqInlineSize, 325 bytes of bytecode): above it, every execution pays a
     * call (InlinableTest).
     *
     * @param a the words of (s1)
     * @param b the words of (s2), or the current time
     * @param useClock whether {@code b} is the current time (whose fields are not checked)
     * @param s3word (s3)
     * @param selectorValid whether (s3) selects what to compare
     * @return the result, or null when the data are compared
     */
    private Boolean endedBeforeComparing(int[] a, int[] b, boolean useClock, int s3word, boolean selectorValid) {
        // "If the comparison target data in the device are not recognized as time data, SM709
        // turns on ... and the operation result will be non-continuity." Which words are
        // "comparison target data" is FX5-SM709-SCOPE.
        switch (settings.sm709Scope) {
            case ALL_WORDS:
                if (outOfRange(a, -1) || (!useClock && outOfRange(b, -1))) {
                    return error();
                }
                if (!selectorValid) {
                    return false;
                }
                break;
            case COMPARED_OPERANDS:
                // The operands are "comparison target data" as a whole, but only when the table
                // says they "are compared": not for a selector that compares nothing.
                if (!selectorValid) {
                    return false;
                }
                if (outOfRange(a, -1) || (!useClock && outOfRange(b, -1))) {
                    return error();
                }
                break;
            default:   // SELECTED_FIELDS: a masked word is not comparison target data
                if (!selectorValid) {
                    return false;
                }
                if (outOfRange(a, s3word) || (!useClock && outOfRange(b, s3word))) {
                    return error();
                }
        }
        return null;
    }

    /**
     * SM709 on and non-continuity. "Once SM709 turns on, the on state is held": never cleared here.
     *
     * @return the result: non-continuity
     */
    protected boolean error() {
        mem.setBit(SM709, true);
        erred = true;
        return false;
    }

    /**
     * (s1), (s2): "16-bit signed binary", three words.
     *
     * @param base the operand's first word
     * @return the three words, signed
     */
    protected int[] read(Address base) {
        return new int[] {(short) mem.word(base, 0), (short) mem.word(base, 1), (short) mem.word(base, 2)};
    }

    /**
     * The injected current time (or date), in the fields' order.
     *
     * @param step the step
     * @return the clock's fields
     */
    protected int[] clock(Step step) {
        int[] out = new int[3];
        for (Field f : fields) {
            out[f.offset()] = step.clock(f.name());
        }
        return out;
    }

    /**
     * Whether a field is outside its range.
     *
     * @param words the three words
     * @param selected the (s3) selection, or -1 for every field
     * @return true when a field checked is outside its range
     */
    protected boolean outOfRange(int[] words, int selected) {
        for (Field f : fields) {
            if (selected != -1 && ((selected >> f.bit()) & 1) == 0) {
                continue;
            }
            int v = words[f.offset()];
            if (v < f.min() || v > f.max()) {
                return true;
            }
        }
        return false;
    }

    /**
     * Field by field, most significant selected field first.
     *
     * @param a (s1)'s words
     * @param b (s2)'s words (or the clock)
     * @param selected the (s3) selection
     * @return -1, 0 or 1
     */
    protected int compare(int[] a, int[] b, int selected) {
        for (Field f : fields) {
            if (((selected >> f.bit()) & 1) == 0) {
                continue;
            }
            int x = a[f.offset()];
            int y = b[f.offset()];
            if (x != y) {
                return x < y ? -1 : 1;
            }
        }
        return 0;
    }
}
