package org.plcvec.verify;

/**
 * Thrown by an implementation that cannot run one vector, saying why ("no R devices"): the
 * vector is reported as skipped, not failed. Instructions an implementation does not support at
 * all are better declared with {@link Implementation#supports(String)}.
 */
public class SkipVector extends RuntimeException {
    private static final long serialVersionUID = 1L;

    public SkipVector(String reason) {
        super(reason);
    }
}
