package org.plcvec.verify;

/**
 * Thrown by an implementation that cannot run one vector, saying why ("no R devices"): the
 * vector is reported as skipped, not failed. Instructions an implementation does not support at
 * all are better declared with {@link Implementation#supports(String)}.
 */
public class SkipVector extends RuntimeException {
    private static final long serialVersionUID = 1L;

    /**
     * Skip the vector being run.
     *
     * @param reason why, as the report shows it
     */
    public SkipVector(String reason) {
        super(reason);
    }
}
