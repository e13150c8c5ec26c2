package org.proactiverobotics.app.sweep;

import java.util.List;
import org.proactiverobotics.app.mission.MissionReport;
import org.proactiverobotics.app.mission.PoseError;
import org.proactiverobotics.app.mission.RobotReport;

/**
 * One row of results.csv: what a mission of the sweep ended with, from its report; or, for a
 * mission that threw, outcome {@value #ERROR} and the reason.
 *
 * @param mission            the mission
 * @param outcome            report.json's outcome, or {@value #ERROR}
 * @param success            whether the mission was accomplished
 * @param checkpointsReached ground truth, in order
 * @param checkpointsTotal   how many the world has
 * @param simTimeS           simulated seconds
 * @param wallTimeS          wall-clock seconds of the mission loop (of the whole attempt for an error)
 * @param distanceM          metres travelled
 * @param collisions         contacts with walls or obstacles
 * @param minBattery         lowest battery, percent
 * @param recharges          charging sessions
 * @param reason             why the mission failed, in a few words; empty when it was accomplished
 * @param poseError          report.json's pose error; null (empty cells) when the engine never had a pose, or for
 *                           an {@value #ERROR}
 * @param robots             each robot's own report in a world of several robots (robots.csv); empty for a one-robot
 *                           world and for an {@value #ERROR}
 */
public record MissionResult(SweepMission mission, String outcome, boolean success, int checkpointsReached,
                            int checkpointsTotal, double simTimeS, double wallTimeS, double distanceM, int collisions,
                            double minBattery, int recharges, String reason, PoseError poseError,
                            List<RobotReport> robots) {

    /** The outcome of a mission that threw before its end. */
    public static final String ERROR = "ERROR";

    /**
     * @param mission the mission
     * @param report  its report
     * @return its row
     */
    public static MissionResult of(SweepMission mission, MissionReport report) {
        String reason = switch (report.outcome()) {
            case MISSION_ACCOMPLISHED -> "";
            case TIME_LIMIT -> "maxSimTimeS (" + mission.world().maxSimTimeS() + " s) ran out";
            case BATTERY_DEPLETED -> "the battery ran flat";
            case CHECKPOINT_UNREACHABLE -> "no route to a checkpoint";
            case STOPPED -> "stopped";
        };
        return new MissionResult(mission, report.outcome().name(), report.success(), report.checkpointsReached(),
                report.checkpointsTotal(), report.simTimeS(), report.wallTimeS(), report.distanceM(), report.collisions(),
                report.minBattery(), report.recharges(), reason, report.poseError(),
                report.robots() == null ? List.of() : List.copyOf(report.robots()));
    }

    /**
     * @param mission   the mission
     * @param failure   what it threw
     * @param wallTimeS how long it ran, seconds
     * @return its row: outcome {@value #ERROR}, the innermost cause as the reason
     */
    public static MissionResult error(SweepMission mission, Throwable failure, double wallTimeS) {
        Throwable cause = failure;
        while (cause.getCause() != null && cause.getCause() != cause) {
            cause = cause.getCause();
        }
        String message = cause.getMessage() == null ? "" : ": " + cause.getMessage();
        int checkpoints = mission.world().robots().stream().mapToInt(r -> r.checkpoints().size()).sum();
        return new MissionResult(mission, ERROR, false, 0, checkpoints, 0, wallTimeS, 0, 0, 0, 0,
                cause.getClass().getSimpleName() + message, null, List.of());
    }
}
