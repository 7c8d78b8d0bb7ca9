package org.plcvec.reference;

import org.plcvec.spec.Family;
import org.plcvec.spec.Instruction;
import org.plcvec.verify.Choices;
import org.plcvec.verify.Emulator;
import org.plcvec.verify.Memory;
import org.plcvec.verify.VectorRequest;

/**
 * The reference implementation: the five families, written from the manual pages
 * (../shared/manual/*.txt) and the interpretations the spec names, in plain Java. It follows the
 * alternatives it is given, and passes every vector under every combination of them.
 *
 * <p>One class per family ({@link Fx5Compare}, {@link Fx5TimeAdd}, {@link Fc6aHourMeter},
 * {@link Cp1eTimeCompare}); each is a fresh CPU per vector, so nothing carries over. The factory
 * methods are protected so that a mutant (a single-bug variant) overrides exactly one thing.
 */
public class Reference implements Emulator {
    /** The name reports show. */
    public static final String NAME = "plcvec-reference-java";
    /** The reference's own version. */
    public static final String VERSION = "1.0";

    /** The alternatives declared. */
    protected final Choices choices;
    /** The same, as the families read them. */
    protected final Settings settings;

    /** The reference following every default. */
    public Reference() {
        this(Choices.defaults());
    }

    /**
     * The reference following these alternatives.
     *
     * @param choices the alternatives to follow; undeclared ones take the default
     */
    public Reference(Choices choices) {
        this.choices = choices;
        this.settings = new Settings(choices);
    }

    @Override
    public String name() {
        return NAME;
    }

    @Override
    public String version() {
        return VERSION;
    }

    @Override
    public Choices choices() {
        return choices;
    }

    @Override
    public boolean supports(String instruction) {
        return Instruction.byMnemonic(instruction) != null;   // every instruction of the suite this names
    }

    @Override
    public Scan load(VectorRequest vector, Memory memory) {
        Family family = vector.familyName();
        if (family == null) {
            throw new IllegalArgumentException("unknown family " + vector.family());
        }
        switch (family) {
            case FX5_TIME_COMPARE:
                return fx5Compare(vector, memory, Fx5Compare.TIME);
            case FX5_DATE_COMPARE:
                return fx5Compare(vector, memory, Fx5Compare.DATE);
            case FX5_TIME_ADD:
                return fx5TimeAdd(vector, memory);
            case FC6A_HOUR_METER:
                return fc6aHourMeter(vector, memory);
            case CP1E_TIME_COMPARE:
                return cp1eTimeCompare(vector, memory);
            default:
                throw new IllegalArgumentException("no reference for family " + family);
        }
    }

    /**
     * An FX5 time or date comparison (a mutant returns its subclass).
     *
     * @param vector the vector
     * @param memory its device image
     * @param fields the family's fields
     * @return the CPU
     */
    protected Scan fx5Compare(VectorRequest vector, Memory memory, Fx5Compare.Field[] fields) {
        return new Fx5Compare(vector, memory, fields, settings);
    }

    /**
     * An FX5 TADD or TADDP (a mutant returns its subclass).
     *
     * @param vector the vector
     * @param memory its device image
     * @return the CPU
     */
    protected Scan fx5TimeAdd(VectorRequest vector, Memory memory) {
        return new Fx5TimeAdd(vector, memory, settings);
    }

    /**
     * An FC6A HOUR (a mutant returns its subclass).
     *
     * @param vector the vector
     * @param memory its device image
     * @return the CPU
     */
    protected Scan fc6aHourMeter(VectorRequest vector, Memory memory) {
        return new Fc6aHourMeter(vector, memory, settings);
    }

    /**
     * A CP1E time comparison (a mutant returns its subclass).
     *
     * @param vector the vector
     * @param memory its device image
     * @return the CPU
     */
    protected Scan cp1eTimeCompare(VectorRequest vector, Memory memory) {
        return new Cp1eTimeCompare(vector, memory, settings);
    }
}
