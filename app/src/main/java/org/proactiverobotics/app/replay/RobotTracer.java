package org.proactiverobotics.app.replay;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;
import org.proactiverobotics.robot.link.CommandRecord;
import org.proactiverobotics.sim2d.DistanceSensor;
import org.proactiverobotics.sim2d.GroundTruth;
import org.proactiverobotics.sim2d.SimRobot;
import org.proactiverobotics.sim2d.Simulation;

/**
 * The robot process's side of the replay: what the robot knows at each control step — its
 * ground truth, the readings its sensors gave, the command it executed (scenario and command as
 * engine_comments had them) — and the step's events. The engine's suggestions, PriorityArray and
 * rule failures are not visible from here. Robot thread only.
 */
public final class RobotTracer {

    private final Simulation sim;
    /** The robot's position among the world's robots. */
    private final int index;
    private final ReplayData data;
    private final List<TraceEvent> pending = new ArrayList<>();
    private Consumer<TraceStep> alsoTo = step -> { };
    private String scenario = "none";
    private String command = "STOP";
    private long simTimeMs;
    private double x;
    private double y;
    private double heading;
    private double battery;
    private boolean charging;
    private double gpsX;
    private double gpsY;
    private double yaw;
    private double[] scan;
    private int checkpoints;
    private int recharges;
    private int collisions;

    /**
     * @param sim  the robot's world (its first robot is traced)
     * @param data where the steps go
     */
    public RobotTracer(Simulation sim, ReplayData data) {
        this(sim, 0, data);
    }

    /**
     * @param sim   the robots' world
     * @param index the traced robot's position among the world's robots
     * @param data  where the steps go
     */
    public RobotTracer(Simulation sim, int index, ReplayData data) {
        this.sim = sim;
        this.index = index;
        this.data = data;
        GroundTruth t = sim.groundTruth(index);
        checkpoints = t.checkpointsReached();
        recharges = t.recharges();
        collisions = t.collisions();
        charging = sim.robot(index).battery().isCharging();
    }

    /** @param sink also receives every step (run.mcap's recorder) */
    public void alsoTo(Consumer<TraceStep> sink) {
        this.alsoTo = sink;
    }

    /** @param record a command the robot executes from now on */
    public void command(CommandRecord record) {
        scenario = record.scenario();
        command = record.command();
    }

    /** After the robot sensed, before it acts and the world steps: the pose and readings of this step. */
    public void sensed() {
        GroundTruth t = sim.groundTruth(index);
        SimRobot robot = sim.robot(index);
        simTimeMs = sim.simTimeMs();
        x = t.x();
        y = t.y();
        heading = t.headingRad();
        battery = t.batteryPct();
        double[] gps = robot.gps().getValues();
        gpsX = gps[0];
        gpsY = gps[1];
        yaw = robot.inertialUnit().getRollPitchYaw()[2];
        List<DistanceSensor> sensors = robot.distanceSensors();
        scan = new double[sensors.size()];
        for (int i = 0; i < scan.length; i++) {
            scan[i] = sensors.get(i).getValue();
        }
    }

    /**
     * After the world stepped: records the step.
     *
     * @param iteration the engine iteration that served this step (as engine_clock said), or the step
     */
    public void stepped(long iteration) {
        GroundTruth t = sim.groundTruth(index);
        boolean chargingBefore = charging;
        while (checkpoints < t.checkpointsReached()) {
            pending.add(TraceEvent.checkpoint(checkpoints++));
        }
        if (t.recharges() > recharges) {
            recharges = t.recharges();
            pending.add(TraceEvent.of(TraceEvent.RECHARGE_STARTED));
        }
        charging = sim.robot(index).battery().isCharging();
        if (chargingBefore && !charging) {
            pending.add(TraceEvent.of(TraceEvent.RECHARGE_FINISHED));
        }
        if (t.collisions() > collisions) {
            collisions = t.collisions();
            pending.add(TraceEvent.of(TraceEvent.COLLISION));
        }
        TraceStep step = new TraceStep(iteration, simTimeMs, null, scenario, command, null, x, y, heading, gpsX, gpsY, yaw,
                scan, battery, battery, chargingBefore, sim.robot(index).leftSpeedMps(), sim.robot(index).rightSpeedMps(),
                List.copyOf(pending));
        data.add(step);
        alsoTo.accept(step);
        pending.clear();
    }
}
