package org.plcvec.verify;

/**
 * A problem with the input, not with the implementation under test: an unreadable vector file,
 * an unknown interpretation, a bad expectations file. The message names the file and line or the
 * vector id, so it can be shown as it is.
 */
public class VerifyException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    /**
     * A problem with the input.
     *
     * @param message what is wrong, naming the file and line or the vector id
     */
    public VerifyException(String message) {
        super(message);
    }

    /**
     * A problem with the input, caused by another.
     *
     * @param message what is wrong, naming the file and line or the vector id
     * @param cause what was thrown
     */
    public VerifyException(String message, Throwable cause) {
        super(message, cause);
    }
}
