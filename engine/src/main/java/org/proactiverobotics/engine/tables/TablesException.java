package org.proactiverobotics.engine.tables;

/** A database read or write of the robot tables failed; the rule part that asked fails with it. */
public final class TablesException extends RuntimeException {

    private static final long serialVersionUID = 1L;

    /**
     * @param message what was being done
     * @param cause   the database's error
     */
    public TablesException(String message, Throwable cause) {
        super(message + ": " + cause.getMessage(), cause);
    }
}
