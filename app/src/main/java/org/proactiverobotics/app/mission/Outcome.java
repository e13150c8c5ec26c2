package org.proactiverobotics.app.mission;

import org.proactiverobotics.sim2d.GroundTruth;
import org.proactiverobotics.sim2d.Simulation;

/** How a mission ended, as written in report.json's {@code outcome}. */
public enum Outcome {
    /** Every checkpoint reached, in order. */
    MISSION_ACCOMPLISHED,
    /** The world's maxSimTimeS ran out first. */
    TIME_LIMIT,
    /** The battery ran flat. */
    BATTERY_DEPLETED,
    /** The engine found no route to a checkpoint even with every unknown cell free, and ended the mission. */
    CHECKPOINT_UNREACHABLE,
    /** The robot process was stopped (SIGTERM / Ctrl-C) before the mission ended. */
    STOPPED;

    /**
     * How the mission stands after a step, judged on the simulator's ground truth, in the one
     * order every runner uses.
     *
     * @param sim the simulation
     * @return the outcome, or null while the mission goes on
     */
    public static Outcome of(Simulation sim) {
        return of(sim, 0);
    }

    /**
     * How one robot's mission stands after a step, in a world with several robots.
     *
     * @param sim   the simulation
     * @param index the robot's position in the world's robots
     * @return the outcome, or null while its mission goes on
     */
    public static Outcome of(Simulation sim, int index) {
        GroundTruth truth = sim.groundTruth(index);
        if (truth.checkpointsReached() == truth.checkpointsTotal()) {
            return MISSION_ACCOMPLISHED;
        }
        if (truth.batteryPct() <= 0.0) {
            return BATTERY_DEPLETED;
        }
        if (sim.timeLimitReached()) {
            return TIME_LIMIT;
        }
        return null;
    }

    /**
     * {@link #of(Simulation)}, then whether the engine marked a checkpoint unreachable (read by
     * the robot side from {@code checkpoints}).
     *
     * @param sim         the simulation
     * @param unreachable whether the robot side has read an unreachable mark
     * @return the outcome, or null while the mission goes on
     */
    public static Outcome of(Simulation sim, boolean unreachable) {
        return of(sim, 0, unreachable);
    }

    /**
     * {@link #of(Simulation, int)}, then whether that robot's engine marked a checkpoint unreachable.
     *
     * @param sim         the simulation
     * @param index       the robot's position in the world's robots
     * @param unreachable whether its robot side has read an unreachable mark
     * @return the outcome, or null while its mission goes on
     */
    public static Outcome of(Simulation sim, int index, boolean unreachable) {
        Outcome outcome = of(sim, index);
        return outcome == null && unreachable ? CHECKPOINT_UNREACHABLE : outcome;
    }
}
