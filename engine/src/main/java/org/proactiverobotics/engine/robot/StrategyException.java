package org.proactiverobotics.engine.robot;

/** A strategy that cannot be used: not valid JSON, a bad key or value, a scenario that is not loaded. Bad input. */
public final class StrategyException extends IllegalArgumentException {

    private static final long serialVersionUID = 1L;

    /** @param message what is wrong, naming the file and the key */
    public StrategyException(String message) {
        super(message);
    }
}
