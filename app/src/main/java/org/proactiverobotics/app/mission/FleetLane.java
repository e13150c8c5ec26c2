package org.proactiverobotics.app.mission;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import org.proactiverobotics.app.Plural;
import org.proactiverobotics.app.replay.ReplayData;
import org.proactiverobotics.app.replay.ReplayRobot;
import org.proactiverobotics.app.replay.SeenReadings;
import org.proactiverobotics.engine.CommandArray;
import org.proactiverobotics.engine.IterationSummary;
import org.proactiverobotics.engine.Suggestion;
import org.proactiverobotics.engine.robot.RobotEngine;
import org.proactiverobotics.robot.ProactiveController;
import org.proactiverobotics.sim2d.GroundTruth;
import org.proactiverobotics.sim2d.Simulation;
import org.proactiverobotics.sim2d.SvgRenderer;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * One robot of a {@link FleetMission}: its engine, its controller, and what its part of the trace and the report
 * gathers (belief, pose error, command wins, path). Its engine's iteration may run on a worker thread; everything
 * else on the mission's thread. Once its mission is over it takes no further step and its robot stands still,
 * except one that accomplished it while others still go on ({@link FleetSteps}): it keeps stepping, its report
 * keeping the time it reached its last checkpoint.
 */
final class FleetLane {

    final int index;
    final int robotId;
    final BeliefTracer belief = new BeliefTracer();
    final PoseErrorMeter poseError = new PoseErrorMeter();
    final Map<String, Long> commandWins = new TreeMap<>();
    final List<SvgRenderer.TrajectoryPoint> path = new ArrayList<>();
    final List<SvgRenderer.Marker> markers = new ArrayList<>();
    /** Its steps for replay.html, made once its engine's CommandArray slots are known. */
    ReplayData replay;
    RobotEngine engine;
    ProactiveController controller;
    StepTracer tracer;
    SeenReadings seen;
    /** The last iteration's summary (written by the thread that ran it, read after the step's join). */
    IterationSummary summary;
    long ruleFailures;
    long controlSteps;
    private int recharges;
    private Outcome outcome;
    private long endSimTimeMs;

    /**
     * @param index   the robot's position in the world's robots
     * @param robotId its id (its rows' {@code robot_id})
     * @param sim     the simulation
     */
    FleetLane(int index, int robotId, Simulation sim) {
        this.index = index;
        this.robotId = robotId;
        this.recharges = sim.groundTruth(index).recharges();
        GroundTruth t = sim.groundTruth(index);
        path.add(new SvgRenderer.TrajectoryPoint(t.x(), t.y(), category()));
    }

    /** @return this robot's colour category in trajectory.svg */
    String category() {
        return "robot " + robotId;
    }

    /** The decision rule's observer: to this robot's tracer. */
    void decided(long iteration, CommandArray suggestions, Suggestion winner) {
        tracer.decided(iteration, suggestions, winner);
    }

    /** Runs this robot's engine's iteration (on any thread). */
    void iterate() {
        summary = engine.iterate();
    }

    /** After the world stepped: the trace line, the path, a recharge marker, and whether its mission just ended. */
    void afterStep(Simulation sim) {
        controlSteps++;
        ruleFailures += summary.rulesFailed();
        tracer.afterPhysics(engine.engine().memory(), engine.engine().lastIterationFailures());
        GroundTruth t = sim.groundTruth(index);
        path.add(new SvgRenderer.TrajectoryPoint(t.x(), t.y(), category()));
        if (t.recharges() > recharges) {
            recharges = t.recharges();
            markers.add(new SvgRenderer.Marker(t.x(), t.y(), "robot " + robotId + " recharge " + recharges));
        }
        if (outcome != null) {
            return; // accomplished, stepping on out of the others' way: its outcome and end time stay
        }
        outcome = Outcome.of(sim, index, controller.checkpointUnreachable());
        if (outcome != null) {
            endSimTimeMs = sim.simTimeMs();
            if (outcome != Outcome.MISSION_ACCOMPLISHED) {
                sim.robot(index).setWheelSpeeds(0.0, 0.0); // over: it stays where it is, a body the others see
            }
        }
    }

    /** @return whether this robot's mission is over */
    boolean done() {
        return outcome != null;
    }

    /** @return how its mission ended, or null while it goes on */
    Outcome outcome() {
        return outcome;
    }

    /**
     * @param entry  its entry of the world's robots
     * @param report the whole run's report (its robots' parts included)
     * @return this robot as replay.html shows it
     */
    ReplayRobot replayRobot(WorldSpec.RobotEntry entry, MissionReport report) {
        RobotReport mine = report.robots().stream().filter(r -> r.id() == robotId).findFirst().orElseThrow();
        return mine.replayRobot(entry, replay);
    }

    /** @return its part of report.json (call once the run is over) */
    RobotReport report(Simulation sim) {
        Outcome end = outcome != null ? outcome : Outcome.STOPPED;
        long endMs = outcome != null ? endSimTimeMs : sim.simTimeMs();
        return RobotReport.of(robotId, sim.groundTruth(index), end, endMs, controlSteps, engine.engine().iteration(),
                commandWins, ruleFailures, poseError.result());
    }
}
