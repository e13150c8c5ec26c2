package org.proactiverobotics.engine;

/** Saving or loading the engine state failed. */
public class StateStoreException extends RuntimeException {

    /** @param message what failed */
    public StateStoreException(String message) {
        super(message);
    }

    /** @param message what failed @param cause why */
    public StateStoreException(String message, Throwable cause) {
        super(message, cause);
    }
}
