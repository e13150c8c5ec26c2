package org.proactiverobotics.app.mission;

import java.util.Map;

/**
 * What report.json holds (DESIGN section 8): ground truth from the simulator, counts from both
 * sides, and where the time went. Field names are the file's keys.
 *
 * @param world              the world's name
 * @param success            whether the mission was accomplished
 * @param outcome            how it ended
 * @param strategy           the strategy the run started with
 * @param database           the kind of database (h2, mariadb, mysql)
 * @param checkpointsReached ground truth, in order
 * @param checkpointsTotal   how many the world has
 * @param simTimeS           simulated seconds
 * @param wallTimeS          wall-clock seconds of the mission loop
 * @param realTimeFactor     simulated seconds per wall second
 * @param controlSteps       robot control steps
 * @param engineIterations   engine iterations
 * @param distanceM          ground truth, metres travelled
 * @param collisions         ground truth, contacts with walls or obstacles
 * @param minClearanceM      ground truth, the closest the robot's rim came to anything, metres
 * @param minBattery         ground truth, lowest battery, percent
 * @param finalBattery       ground truth, battery at the end, percent
 * @param recharges          ground truth, charging sessions
 * @param commandWins        commands sent, by the scenario whose suggestion won
 * @param ruleFailures       rule parts that threw
 * @param timing             mean wall time per control step, milliseconds, by phase
 */
public record MissionReport(
        String world,
        boolean success,
        Outcome outcome,
        String strategy,
        String database,
        int checkpointsReached,
        int checkpointsTotal,
        double simTimeS,
        double wallTimeS,
        double realTimeFactor,
        long controlSteps,
        long engineIterations,
        double distanceM,
        int collisions,
        double minClearanceM,
        double minBattery,
        double finalBattery,
        int recharges,
        Map<String, Long> commandWins,
        long ruleFailures,
        Timing timing) {

    /**
     * Mean wall time per control step, by phase, milliseconds.
     *
     * @param physicsMs  the dyn4j step and sensor sampling
     * @param robotIoMs  the robot side's database work (answer requests, read the command)
     * @param engineMs   one engine iteration (rules, their database work, saving state)
     */
    public record Timing(double physicsMs, double robotIoMs, double engineMs) {
    }
}
