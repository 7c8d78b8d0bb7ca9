package org.plcvec.reference;

import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.BooleanSupplier;

import org.plcvec.verify.Step;

/**
 * What the FX5 and CP1E comparison contacts share: the LD/AND/OR forms, the six conditions, and
 * how a form combines its comparison with the preceding logic.
 */
final class Contact {
    private Contact() {
    }

    enum Form { LD, AND, OR }

    /** The comparison a contact makes; {@code order} is the sign of the first operand against the second. */
    enum Condition {
        EQ("="), NE("<>"), LT("<"), LE("<="), GT(">"), GE(">=");

        final String symbol;

        Condition(String symbol) {
            this.symbol = symbol;
        }

        boolean holds(int order) {
            switch (this) {
                case EQ: return order == 0;
                case NE: return order != 0;
                case LT: return order < 0;
                case LE: return order <= 0;
                case GT: return order > 0;
                default: return order >= 0;
            }
        }
    }

    /** An instruction read as form, data kind and condition ({@code ANDTM<=}, {@code AND <=DT}). */
    record Mnemonic(Form form, String kind, Condition condition) {
        private static final Map<String, Mnemonic> CACHE = new ConcurrentHashMap<>();

        /**
         * FX5 {@code <form><kind><symbol>} with kind TM or DT, or CP1E {@code <form> <symbol>DT}
         * (kind "CP1E"); null when the instruction is neither.
         */
        /** By the generated instruction name: an array index, for the hot path. */
        private static final Mnemonic[] BY_NAME = new Mnemonic[org.plcvec.spec.Instruction.values().length];

        static {
            for (org.plcvec.spec.Instruction i : org.plcvec.spec.Instruction.values()) {
                BY_NAME[i.ordinal()] = read(i.mnemonic());
            }
        }

        /** The instruction of {@code vector}, read once per instruction. */
        static Mnemonic of(org.plcvec.verify.VectorRequest vector) {
            org.plcvec.spec.Instruction name = vector.instructionName();
            return name != null ? BY_NAME[name.ordinal()] : parse(vector.instruction());
        }

        static Mnemonic parse(String instruction) {
            Mnemonic m = CACHE.get(instruction);
            if (m == null) {
                m = read(instruction);
                if (m != null) {
                    CACHE.put(instruction, m);
                }
            }
            return m;
        }

        private static Mnemonic read(String instruction) {
            for (Form form : Form.values()) {
                for (Condition c : Condition.values()) {
                    for (String kind : new String[] {"TM", "DT"}) {
                        if (instruction.equals(form.name() + kind + c.symbol)) {
                            return new Mnemonic(form, kind, c);
                        }
                    }
                    if (instruction.equals(form.name() + " " + c.symbol + "DT")) {
                        return new Mnemonic(form, "CP1E", c);
                    }
                }
            }
            return null;
        }
    }

    /**
     * The logic state after the contact: LD gives the comparison, AND the preceding logic AND it, OR
     * the preceding logic OR it. {@code andSkippedWhenOff} / {@code orSkippedWhenOn}: whether the
     * form is executed at all (an unexecuted comparison writes no flag) when its outcome is already
     * decided by the preceding logic.
     */
    static boolean result(Form form, Step step, boolean andSkippedWhenOff, boolean orSkippedWhenOn, BooleanSupplier compare) {
        if (form == Form.LD) {
            return compare.getAsBoolean();
        }
        boolean rlo = step.rloIn();
        if (form == Form.AND) {
            if (!rlo && andSkippedWhenOff) {
                return false;
            }
            boolean contact = compare.getAsBoolean();    // executed: may write flags
            return rlo && contact;
        }
        if (rlo && orSkippedWhenOn) {
            return true;
        }
        boolean contact = compare.getAsBoolean();
        return rlo || contact;
    }
}
