package org.plcvec.reference;

import java.util.function.BooleanSupplier;

import org.plcvec.spec.Instruction.Condition;
import org.plcvec.spec.Instruction.Form;
import org.plcvec.verify.Step;

/**
 * What the FX5 and CP1E comparison contacts share: what each of the six conditions holds for, and
 * how a form combines its comparison with the preceding logic. The form and the condition of an
 * instruction are read from the generated names ({@link org.plcvec.spec.Instruction#form()},
 * {@link org.plcvec.spec.Instruction#condition()}), not parsed from its spelling.
 */
final class Contact {
    private Contact() {
    }

    /**
     * {@code HOLDS[condition.ordinal()]} has bit {@code order + 1} set (order -1, 0, +1: the first
     * operand below, equal to, above the second) for each order under which the condition holds,
     * worked out once from {@link #rule}: {@link #holds} is then a load and a shift, with no branch
     * on the condition, which changes from one vector to the next and was mispredicted as often.
     */
    private static final int[] HOLDS = new int[Condition.values().length];

    static {
        for (Condition condition : Condition.values()) {
            for (int order = -1; order <= 1; order++) {
                if (rule(condition, order)) {
                    HOLDS[condition.ordinal()] |= 1 << (order + 1);
                }
            }
        }
    }

    /** Whether {@code condition} holds when the first operand compares to the second as {@code order} (its sign). */
    static boolean holds(Condition condition, int order) {
        return (HOLDS[condition.ordinal()] >> (Integer.signum(order) + 1) & 1) != 0;
    }

    /** The comparison each condition names, as the manual's table states it. */
    private static boolean rule(Condition condition, int order) {
        switch (condition) {
            case EQ: return order == 0;
            case NE: return order != 0;
            case LT: return order < 0;
            case LE: return order <= 0;
            case GT: return order > 0;
            default: return order >= 0;
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
