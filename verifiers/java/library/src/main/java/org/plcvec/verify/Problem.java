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
     * One field that differs.
     *
     * @param step the step, or {@link #WHOLE}
     * @param field {@code result}, a device, or {@code steps}
     * @param expected what the vector expects, as a report shows it
     * @param actual what the implementation gave, as a report shows it
     * @param before the value the implementation held before the step (null: no suffix)
     * @param mustStay the vector keeps the device through the step and the implementation wrote it
     */
    public Problem {
    }

    /**
     * One field that differs, which the implementation did not write where it had to stay.
     *
     * @param step the step, or {@link #WHOLE}
     * @param field {@code result}, a device, or {@code steps}
     * @param expected what the vector expects
     * @param actual what the implementation gave
     * @param before the value held before the step (null: no suffix)
     */
    public Problem(int step, String field, String expected, String actual, String before) {
        this(step, field, expected, actual, before, false);
    }
    static final String NOT_REPORTED = "<not reported>";
    static final String NOT_IN_VECTOR = "<not in the vector>";

    /**
     * The field line of TEXT.md: {@code step 0 SM709: expected false, got true (the step must leave it unchanged)}.
     *
     * @return the line
     */
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
