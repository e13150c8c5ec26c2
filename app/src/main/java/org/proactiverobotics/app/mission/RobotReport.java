package org.proactiverobotics.app.mission;

import java.util.Collections;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import org.proactiverobotics.app.Plural;
import org.proactiverobotics.app.replay.ReplayData;
import org.proactiverobotics.app.replay.ReplayRobot;
import org.proactiverobotics.sim2d.GroundTruth;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * One robot's part of report.json's {@code robots} in a world with several robots (docs/report.md): how its own
 * mission went, from the simulator's ground truth and its own engine. Field names are the file's keys.
 *
 * @param id                 the robot's id in the world file (its rows' {@code robot_id})
 * @param success            whether its mission was accomplished
 * @param outcome            how its mission ended
 * @param reason             the outcome in a few words (which checkpoint, when)
 * @param endSimTimeS        simulated seconds when its mission ended (it stood still after), or the run's end
 * @param checkpointsReached ground truth, in its order
 * @param checkpointsTotal   how many checkpoints its mission has
 * @param distanceM          ground truth, metres travelled
 * @param collisions         ground truth, contacts with walls, obstacles or other robots
 * @param robotCollisions    ground truth, the contacts with another robot among {@code collisions}
 * @param minClearanceM      ground truth, the closest its rim came to a wall or an obstacle, metres
 * @param minBattery         ground truth, lowest battery, percent
 * @param finalBattery       ground truth, battery at the end, percent
 * @param recharges          ground truth, charging sessions
 * @param controlSteps       its controller's control steps
 * @param engineIterations   its engine's iterations
 * @param commandWins        commands it executed, by the scenario whose suggestion won
 * @param ruleFailures       its engine's rule parts that threw
 * @param poseError          how far its engine's believed pose was from the ground truth; null when it never had one
 */
public record RobotReport(
        int id,
        boolean success,
        Outcome outcome,
        String reason,
        double endSimTimeS,
        int checkpointsReached,
        int checkpointsTotal,
        double distanceM,
        int collisions,
        int robotCollisions,
        double minClearanceM,
        double minBattery,
        double finalBattery,
        int recharges,
        long controlSteps,
        long engineIterations,
        Map<String, Long> commandWins,
        long ruleFailures,
        PoseError poseError) {

    /**
     * @param entry the robot's entry of the world's robots
     * @param steps its steps
     * @return the robot as replay.html draws it, with a line on how its mission went
     */
    public ReplayRobot replayRobot(WorldSpec.RobotEntry entry, ReplayData steps) {
        String line = String.format(Locale.ROOT, "robot %d: %s, checkpoints %d/%d, %s", id, reason(),
                checkpointsReached, checkpointsTotal, Plural.of(collisions, "collision"));
        return new ReplayRobot(id, outcome.name(), line, entry, steps);
    }

    /**
     * A robot's report, its ground-truth fields read now (rounded as in report.json).
     *
     * @param id               the robot's id
     * @param truth            its ground truth at the run's end
     * @param outcome          how its mission ended
     * @param endSimTimeMs     when, simulated ms
     * @param controlSteps     its control steps
     * @param engineIterations its engine's iterations
     * @param commandWins      commands it executed, by scenario
     * @param ruleFailures     its rule parts that threw
     * @param poseError        its pose error, or null
     * @return the report
     */
    public static RobotReport of(int id, GroundTruth truth, Outcome outcome, long endSimTimeMs, long controlSteps,
                                 long engineIterations, Map<String, Long> commandWins, long ruleFailures,
                                 PoseError poseError) {
        double endS = endSimTimeMs / 1000.0;
        return new RobotReport(id, outcome == Outcome.MISSION_ACCOMPLISHED, outcome, reason(outcome, truth, endS), endS,
                truth.checkpointsReached(), truth.checkpointsTotal(), MissionReport.round(truth.distanceM(), 3),
                truth.collisions(), truth.robotCollisions(), MissionReport.round(truth.minClearanceM(), 4),
                MissionReport.round(truth.minBatteryPct(), 2), MissionReport.round(truth.batteryPct(), 2),
                truth.recharges(), controlSteps, engineIterations,
                Collections.unmodifiableMap(new TreeMap<>(commandWins)), ruleFailures, poseError);
    }

    private static String reason(Outcome outcome, GroundTruth truth, double endS) {
        return switch (outcome) {
            case MISSION_ACCOMPLISHED -> String.format(Locale.ROOT, "every checkpoint reached at %.1f s", endS);
            case BATTERY_DEPLETED -> String.format(Locale.ROOT, "battery flat at %.1f s, before checkpoint %d",
                    endS, truth.checkpointsReached() + 1);
            case CHECKPOINT_UNREACHABLE -> String.format(Locale.ROOT, "checkpoint %d found unreachable at %.1f s",
                    truth.checkpointsReached() + 1, endS);
            case TIME_LIMIT -> String.format(Locale.ROOT, "time limit at %.1f s with %d/%d checkpoints", endS,
                    truth.checkpointsReached(), truth.checkpointsTotal());
            case STOPPED -> String.format(Locale.ROOT, "stopped at %.1f s", endS);
        };
    }
}
