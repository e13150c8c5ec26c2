package org.proactiverobotics.robot.link;

/**
 * One row of {@code engine_comments}: a command the engine sent, not yet parsed.
 *
 * @param id        the row's id; a larger id is a newer command
 * @param iteration the engine iteration that sent it
 * @param simTimeMs the simulated time (ms) of the newest reading the engine based it on
 * @param scenario  the scenario whose suggestion won
 * @param command   the command text, e.g. {@code "DRIVE 0.40 0.35"}
 */
public record CommandRecord(long id, long iteration, long simTimeMs, String scenario, String command) {
}
