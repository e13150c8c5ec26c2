package org.proactiverobotics.robot.link;

/**
 * The robot could not talk to the engine's side (database down, time-out, refused statement).
 * Whatever the call was to write was not written.
 */
public class LinkException extends Exception {

    private static final long serialVersionUID = 1L;

    /**
     * @param message what failed
     * @param cause   the underlying error
     */
    public LinkException(String message, Throwable cause) {
        super(message, cause);
    }
}
