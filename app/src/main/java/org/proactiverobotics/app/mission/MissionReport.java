package org.proactiverobotics.app.mission;

import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import org.proactiverobotics.sim2d.GroundTruth;
import org.proactiverobotics.sim2d.Simulation;

/**
 * What report.json holds (docs/report.md): ground truth from the simulator, counts from both
 * sides, and where the time went. Field names are the file's keys.
 *
 * @param world              the world's name
 * @param success            whether the mission was accomplished
 * @param outcome            how it ended
 * @param strategy           the strategy the run started with; null, and left out of report.json, in the robot
 *                           process's report: its database user may not read the engine's strategy table
 * @param database           the kind of database (h2, mariadb, mysql)
 * @param checkpointsReached ground truth, in order
 * @param checkpointsTotal   how many the world has
 * @param simTimeS           simulated seconds
 * @param wallTimeS          wall-clock seconds of the mission loop
 * @param realTimeFactor     simulated seconds per wall second
 * @param controlSteps       robot control steps
 * @param engineIterations   engine iterations
 * @param distanceM          ground truth, metres travelled
 * @param collisions         ground truth, contacts with walls, obstacles or (in a world with several robots) other
 *                           robots; summed over the robots
 * @param robotCollisions    ground truth, the contacts between two robots among {@code collisions}, counted for each
 *                           of the two, summed over the robots; null, and left out of report.json, in a one-robot world
 * @param minClearanceM      ground truth, the closest the robot's rim came to anything, metres
 * @param minBattery         ground truth, lowest battery, percent
 * @param finalBattery       ground truth, battery at the end, percent
 * @param recharges          ground truth, charging sessions
 * @param commandWins        commands sent, by the scenario whose suggestion won
 * @param ruleFailures       rule parts that threw; null, and left out of report.json, in the robot process's
 *                           report: its database user may not read the engine's rule_failures table
 * @param poseError          how far the engine's believed pose was from the ground truth; null, and left out of
 *                           report.json, when the engine never had a pose, and in the robot process's report: that
 *                           process cannot see what the engine believed
 * @param timing             mean wall time per control step, milliseconds, by phase
 * @param robots             each robot's own report, in the world's order; null, and left out of report.json, in a
 *                           one-robot world (the whole-run fields are then that robot's)
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
        Integer robotCollisions,
        double minClearanceM,
        double minBattery,
        double finalBattery,
        int recharges,
        Map<String, Long> commandWins,
        Long ruleFailures,
        PoseError poseError,
        Timing timing,
        List<RobotReport> robots) {

    /** A one-robot report: no robotCollisions, no robots (as report.json was before fleets). */
    public MissionReport(String world, boolean success, Outcome outcome, String strategy, String database,
                         int checkpointsReached, int checkpointsTotal, double simTimeS, double wallTimeS,
                         double realTimeFactor, long controlSteps, long engineIterations, double distanceM,
                         int collisions, double minClearanceM, double minBattery, double finalBattery, int recharges,
                         Map<String, Long> commandWins, Long ruleFailures, PoseError poseError, Timing timing) {
        this(world, success, outcome, strategy, database, checkpointsReached, checkpointsTotal, simTimeS, wallTimeS,
                realTimeFactor, controlSteps, engineIterations, distanceM, collisions, null, minClearanceM, minBattery,
                finalBattery, recharges, commandWins, ruleFailures, poseError, timing, null);
    }

    /**
     * A report whose ground-truth fields are read from the simulation (rounded as in report.json).
     *
     * @param sim              the simulation, at the mission's end
     * @param outcome          how it ended
     * @param strategy         the strategy the run started with, or null when this process cannot see it
     * @param database         the kind of database ({@link #databaseKind}) or "direct"
     * @param wallTimeS        wall-clock seconds of the mission loop
     * @param controlSteps     robot control steps
     * @param engineIterations engine iterations
     * @param commandWins      commands the robot got, by scenario
     * @param ruleFailures     rule parts that threw, or null when this process cannot see them
     * @param poseError        the engine's pose error, or null when it had no pose or this process cannot see it
     * @param timing           mean wall time per control step by phase, or null
     * @return the report
     */
    public static MissionReport of(Simulation sim, Outcome outcome, String strategy, String database, double wallTimeS,
                                   long controlSteps, long engineIterations, Map<String, Long> commandWins,
                                   Long ruleFailures, PoseError poseError, Timing timing) {
        GroundTruth truth = sim.groundTruth();
        double simS = sim.simTimeMs() / 1000.0;
        return new MissionReport(sim.spec().name(), outcome == Outcome.MISSION_ACCOMPLISHED, outcome, strategy, database,
                truth.checkpointsReached(), truth.checkpointsTotal(), simS, round(wallTimeS, 3),
                round(simS / Math.max(wallTimeS, 1e-9), 1), controlSteps, engineIterations, round(truth.distanceM(), 3),
                truth.collisions(), null, round(truth.minClearanceM(), 4), round(truth.minBatteryPct(), 2),
                round(truth.batteryPct(), 2), truth.recharges(), Collections.unmodifiableMap(new TreeMap<>(commandWins)), ruleFailures, poseError,
                timing, null);
    }

    /**
     * The whole run's report of a world with several robots: success only when every robot accomplished its
     * mission, the outcome the first robot's (in the file's order) that did not, sums and minima over the robots.
     *
     * @param sim          the simulation, at the run's end
     * @param robots       each robot's report
     * @param truths       each robot's ground truth, in the same order
     * @param strategy     the strategy the run started with, or null when this process cannot see it
     * @param database     the kind of database ({@link #databaseKind}) or "direct"
     * @param wallTimeS    wall-clock seconds of the run's loop
     * @param withFailures whether the robots' rule failures are known to this process (else null)
     * @param poseError    the engines' pose error over every robot, or null
     * @param timing       mean wall time per world step by phase, or null
     * @return the report, with {@code robots}
     */
    public static MissionReport ofRobots(Simulation sim, List<RobotReport> robots, List<GroundTruth> truths,
                                         String strategy, String database, double wallTimeS, boolean withFailures,
                                         PoseError poseError, Timing timing) {
        Outcome outcome = Outcome.MISSION_ACCOMPLISHED;
        int reached = 0;
        int total = 0;
        long controlSteps = 0;
        long iterations = 0;
        double distance = 0;
        int collisions = 0;
        int robotCollisions = 0;
        double minClearance = Double.POSITIVE_INFINITY;
        double minBattery = Double.POSITIVE_INFINITY;
        double finalBattery = Double.POSITIVE_INFINITY;
        int recharges = 0;
        long failures = 0;
        Map<String, Long> wins = new TreeMap<>();
        for (int i = 0; i < robots.size(); i++) {
            RobotReport r = robots.get(i);
            GroundTruth t = truths.get(i);
            if (outcome == Outcome.MISSION_ACCOMPLISHED && !r.success()) {
                outcome = r.outcome();
            }
            reached += r.checkpointsReached();
            total += r.checkpointsTotal();
            controlSteps += r.controlSteps();
            iterations += r.engineIterations();
            distance += t.distanceM();
            collisions += t.collisions();
            robotCollisions += t.robotCollisions();
            minClearance = Math.min(minClearance, t.minClearanceM());
            minBattery = Math.min(minBattery, t.minBatteryPct());
            finalBattery = Math.min(finalBattery, t.batteryPct());
            recharges += t.recharges();
            failures += r.ruleFailures();
            r.commandWins().forEach((k, v) -> wins.merge(k, v, Long::sum));
        }
        double simS = sim.simTimeMs() / 1000.0;
        return new MissionReport(sim.spec().name(), outcome == Outcome.MISSION_ACCOMPLISHED, outcome, strategy, database,
                reached, total, simS, round(wallTimeS, 3), round(simS / Math.max(wallTimeS, 1e-9), 1), controlSteps,
                iterations, round(distance, 3), collisions, robotCollisions, round(minClearance, 4),
                round(minBattery, 2), round(finalBattery, 2), recharges, wins, withFailures ? failures : null,
                poseError, timing, List.copyOf(robots));
    }

    /** @return whether this is the report of a world with several robots (it has {@link #robots()}) */
    public boolean hasRobots() {
        return robots != null;
    }

    /** @return the database kind a JDBC URL names: "h2", "mariadb", "mysql", ... */
    public static String databaseKind(String jdbcUrl) {
        String rest = jdbcUrl.startsWith("jdbc:") ? jdbcUrl.substring(5) : jdbcUrl;
        int colon = rest.indexOf(':');
        return colon < 0 ? rest : rest.substring(0, colon);
    }

    static double round(double value, int decimals) {
        double scale = Math.pow(10, decimals);
        return Math.round(value * scale) / scale;
    }

    /**
     * Mean wall time per control step, by phase, milliseconds.
     *
     * @param physicsMs  the dyn4j step and sensor sampling
     * @param robotIoMs  the robot side's database work (answer requests, read the command)
     * @param engineMs   one engine iteration (rules, their database work, saving state)
     */
    public record Timing(double physicsMs, double robotIoMs, double engineMs) {

        /** @return the timing rounded to microseconds, as report.json shows it */
        public static Timing rounded(double physicsMs, double robotIoMs, double engineMs) {
            return new Timing(round(physicsMs, 4), round(robotIoMs, 4), round(engineMs, 4));
        }
    }
}
