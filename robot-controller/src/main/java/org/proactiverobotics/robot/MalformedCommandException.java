package org.proactiverobotics.robot;

/** A command text that is not in the grammar of {@link Command}; the message says why. */
public class MalformedCommandException extends Exception {

    private static final long serialVersionUID = 1L;

    /** @param message what is wrong, quoting the text */
    public MalformedCommandException(String message) {
        super(message);
    }
}
