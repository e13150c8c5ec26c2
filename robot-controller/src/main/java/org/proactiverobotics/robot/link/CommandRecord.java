package org.proactiverobotics.robot.link;

/**
 * One row of {@code engine_comments}: a command the engine sent, not yet parsed.
 *
 * @param id        the row's id (between two commands of one iteration the larger is newer; ids from
 *                  different Galera nodes interleave, so a newer iteration may have a smaller one)
 * @param iteration the engine iteration that sent it
 * @param simTimeMs the simulated time (ms) of the newest reading the engine based it on
 * @param scenario  the scenario whose suggestion won
 * @param command   the command text, e.g. {@code "DRIVE 0.40 0.35"}
 */
public record CommandRecord(long id, long iteration, long simTimeMs, String scenario, String command) {
}
