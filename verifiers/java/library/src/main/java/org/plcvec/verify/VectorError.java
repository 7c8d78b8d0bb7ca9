package org.plcvec.verify;

/**
 * Thrown by an implementation that reports an error on one vector in its own words ("comparator
 * fault at s2"), as a contract-level adapter answers {@code {"error": "..."}}: the vector is an
 * error with the message {@code the implementation reported an error: <text>}, the same words
 * {@code plcvec verify} prints for that answer. Any other exception is an error too, located at
 * the implementation's own line; this one is the implementation's deliberate report, so its text
 * is shown as it is.
 */
public class VectorError extends RuntimeException {
    private static final long serialVersionUID = 1L;

    /**
     * Report an error on the vector being run.
     *
     * @param message the implementation's own words
     */
    public VectorError(String message) {
        super(message);
    }
}
