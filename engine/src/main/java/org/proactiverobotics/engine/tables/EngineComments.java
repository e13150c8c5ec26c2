package org.proactiverobotics.engine.tables;

/** The commands the engine sends the robot ({@code engine_comments}). */
public interface EngineComments {

    /**
     * Sends a command.
     *
     * @param iteration the engine iteration that decided it
     * @param simTimeMs simulated time of the newest reading it was based on, milliseconds
     * @param scenario  the scenario whose suggestion won
     * @param command   the command text, e.g. {@code "DRIVE 0.4000 0.3500"}
     */
    void send(long iteration, long simTimeMs, String scenario, String command);
}
