package org.plcvec.verify;

/** The verdict on one vector. Only PASS, SKIP and XFAIL let a run pass. */
public enum Status {
    /** Every field matched. */
    PASS,
    /** Some field differs. */
    FAIL,
    /** The implementation threw, or reported something that is not a result. */
    ERROR,
    /** The implementation does not support the instruction, or skipped the vector saying why. */
    SKIP,
    /** Failed, and listed as a known failure. */
    XFAIL,
    /** Listed as a known failure but passes (or the suite has no such vector): remove the entry. */
    STALE,
    /** Never run: the run ended before it (a vector before it gave no answer in time). Never a known failure. */
    NOT_RUN;

    /**
     * Whether a vector with this status fails the run.
     *
     * @return true for fail, error, stale and not-run
     */
    public boolean failing() {
        return this == FAIL || this == ERROR || this == STALE || this == NOT_RUN;
    }

    /**
     * As the text of every plcvec runner spells it.
     *
     * @return {@code pass}, ..., {@code not-run}
     */
    public String label() {
        return name().toLowerCase(java.util.Locale.ROOT).replace('_', '-');
    }
}
