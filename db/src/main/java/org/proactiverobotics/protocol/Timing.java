package org.proactiverobotics.protocol;

import java.util.Locale;
import java.util.Optional;

/** How a robot's control steps relate to the engine's iterations ({@code robot_clock.timing}). */
public enum Timing {
    /** One engine iteration per control step, the robot waiting for it (the default). */
    SYNC,
    /** The robot steps on the wall clock; the engine iterates on its own period. */
    REALTIME;

    /** @return the word in robot_clock.timing and on the command line */
    public String label() {
        return name().toLowerCase(Locale.ROOT);
    }

    /**
     * @param label the word as written ({@link #label()})
     * @return the timing, or empty when the word is unknown
     */
    public static Optional<Timing> of(String label) {
        for (Timing t : values()) {
            if (t.label().equals(label)) {
                return Optional.of(t);
            }
        }
        return Optional.empty();
    }
}
