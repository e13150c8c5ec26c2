package org.proactiverobotics.testkit;

/**
 * The kit could not do what a test asked: its database refused a statement (it names the
 * statement and the values), or the kit was used wrongly (a step after close, say).
 */
public final class ScenarioKitException extends RuntimeException {

    private static final long serialVersionUID = 1L;

    /** @param message what failed */
    public ScenarioKitException(String message) {
        super(message);
    }

    /**
     * @param message what failed
     * @param cause   why
     */
    public ScenarioKitException(String message, Throwable cause) {
        super(message, cause);
    }
}
