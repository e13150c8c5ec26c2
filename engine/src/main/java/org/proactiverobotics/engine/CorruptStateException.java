package org.proactiverobotics.engine;

/**
 * A saved state exists but cannot be read: an unknown rule type, corrupt JSON, a gap in the
 * queue. The message names the row and the problem. The engine refuses to start rather than
 * start fresh silently; starting fresh is {@link ProactiveEngine#startFresh}.
 */
public class CorruptStateException extends StateStoreException {

    /** @param message the row and the problem */
    public CorruptStateException(String message) {
        super(message);
    }

    /** @param message the row and the problem @param cause the parser's or class loader's error */
    public CorruptStateException(String message, Throwable cause) {
        super(message, cause);
    }
}
