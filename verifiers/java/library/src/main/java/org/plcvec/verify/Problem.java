package org.plcvec.verify;

/**
 * One field that differs: the step, the field (the contact {@code result}, a device address, or
 * {@code steps}), what the vector expects, what the implementation gave, and the device's value
 * before the step.
 */
public record Problem(int step, String field, String expected, String actual, String before, boolean mustStay) {
    /** The step of a problem about the vector as a whole (the number of steps). */
    public static final int WHOLE = -1;

    /**
     * {@code before}: the value the implementation held before the step (null: no suffix);
     * {@code mustStay}: the vector keeps the device through the step and the implementation wrote it.
     */
    public Problem {
    }

    public Problem(int step, String field, String expected, String actual, String before) {
        this(step, field, expected, actual, before, false);
    }
    static final String NOT_REPORTED = "<not reported>";
    static final String NOT_IN_VECTOR = "<not in the vector>";

    /** {@code step 0 SM709: expected false, got true (the step must leave it unchanged)}. */
    public String line() {
        StringBuilder sb = new StringBuilder();
        if (step != WHOLE) {
            sb.append("step ").append(step).append(' ');
        }
        sb.append(field).append(": expected ").append(expected).append(", got ").append(actual);
        if (before != null && mustStay && before.equals(expected)) {
            sb.append(" (the step must leave it unchanged)");
        } else if (before != null && mustStay) {
            sb.append(" (before the step: ").append(before).append("; the step must leave it unchanged)");
        } else if (before != null) {
            sb.append(" (before the step: ").append(before).append(')');
        }
        return sb.toString();
    }

    @Override
    public String toString() {
        return line();
    }
}
