package org.proactiverobotics.protocol;

import java.util.Optional;

/** Where a robot's run is ({@code robot_clock.state}). */
public enum RunState {
    /** The run goes on: the engine serves its steps. */
    RUNNING,
    /** The mission ended. */
    FINISHED,
    /** A stop was requested before the mission ended. */
    STOPPED;

    /**
     * @param word the word as written ({@link #name()})
     * @return the state, or empty when the word is unknown
     */
    public static Optional<RunState> of(String word) {
        for (RunState s : values()) {
            if (s.name().equals(word)) {
                return Optional.of(s);
            }
        }
        return Optional.empty();
    }
}
