package org.proactiverobotics.bench.sim;

import java.util.List;
import java.util.concurrent.TimeUnit;

import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;
import org.proactiverobotics.sim2d.DistanceSensor;
import org.proactiverobotics.sim2d.SensorNoise;
import org.proactiverobotics.sim2d.SimRobot;
import org.proactiverobotics.sim2d.Simulation;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * Steps per second of the sim2d world, headless: the robot wanders (drives ahead, turns away from what its
 * front sensors see) and, in {@link #stepAndReadAllSensors}, reads GPS, inertial unit, all the distance sensors
 * and the battery every step, as a controller does. {@link #stepOnly} drives blind, for the physics alone: a wide
 * circle, which on a building floor runs into walls on about half its steps and so times dyn4j's contact solving
 * as much as the floor. {@link #stepOnWanderPath} is the physics alone on the wander's own path (its wheel commands
 * recorded once, then replayed without reading a sensor), which keeps off the walls as a controller's drive does.
 * {@code world} is the bundled reference arena or a generated arena with 10, 100 or 1000 obstacles at
 * constant density, or a BigFloor building floor. The simulation restarts at each iteration so that every iteration sees the same run.
 *
 * <pre>
 * java -jar bench/target/benchmarks.jar SimStepBenchmark
 * </pre>
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.SECONDS)
@Warmup(iterations = 3, time = 2)
@Measurement(iterations = 5, time = 2)
@Fork(1)
public class SimStepBenchmark {

    /** The reference arena, a number of obstacles, or a building floor of 56 x 60 m (2 859 boxes) or 100 x 100 m (8 196). */
    @Param({"reference", "10", "100", "1000", "floor56x60", "floor100x100"})
    public String world;

    /** Sensor noise: off, or {@link SensorNoise#SMALL}. */
    @Param({"false"})
    public boolean noise;

    private WorldSpec spec;
    private Simulation sim;
    private SimRobot robot;
    private List<DistanceSensor> sensors;

    /** The default rays at 8° left and 8° right (their outer neighbours are the 20° rays). */
    private static final int LEFT_8 = WorldSpec.Robot.DEFAULT_SENSOR_ANGLES_DEG.indexOf(8.0);
    private static final int RIGHT_8 = WorldSpec.Robot.DEFAULT_SENSOR_ANGLES_DEG.indexOf(-8.0);

    /** How many of the wander's steps are recorded for {@link #stepOnWanderPath}; replays wrap round after. */
    static final int WANDER_STEPS = 3_000_000;

    /** The wander's command at each step: 0 ahead, 1 turn left, 2 turn right. */
    private byte[] wanderPath;
    private int wanderStep;

    @Setup(Level.Trial)
    public void buildWorld() {
        spec = ClutterWorlds.of(world);
        wanderPath = null;
    }

    @Setup(Level.Iteration)
    public void restart() {
        sim = new Simulation(spec, noise ? SensorNoise.SMALL : SensorNoise.NONE);
        robot = sim.robot();
        sensors = robot.distanceSensors();
        wanderStep = 0;
    }

    /** Records the wander's commands once a trial (before the first replay), from a simulation of its own. */
    private void recordWanderPath() {
        Simulation recorder = new Simulation(spec, noise ? SensorNoise.SMALL : SensorNoise.NONE);
        SimRobot r = recorder.robot();
        List<DistanceSensor> s = r.distanceSensors();
        byte[] path = new byte[WANDER_STEPS];
        for (int i = 0; i < path.length; i++) {
            path[i] = wanderCommand(s);
            drive(r, path[i]);
            recorder.step();
        }
        wanderPath = path;
    }

    /** The wander's choice from the front rays: ahead, or turn away from the nearer side. */
    private static byte wanderCommand(List<DistanceSensor> s) {
        double frontLeft = Math.min(s.get(LEFT_8).getValue(), s.get(LEFT_8 + 1).getValue());
        double frontRight = Math.min(s.get(RIGHT_8).getValue(), s.get(RIGHT_8 - 1).getValue());
        if (Math.min(frontLeft, frontRight) < 0.35) {
            return frontRight < frontLeft ? (byte) 1 : (byte) 2;
        }
        return 0;
    }

    private static void drive(SimRobot r, byte command) {
        switch (command) {
            case 1 -> r.setWheelSpeeds(-0.3, 0.3);
            case 2 -> r.setWheelSpeeds(0.3, -0.3);
            default -> r.setWheelSpeeds(0.5, 0.45);
        }
    }

    /** One step with every sensor read, as a controller's step does. */
    @Benchmark
    public double stepAndReadAllSensors() {
        double sum = 0;
        byte command = wanderCommand(sensors);
        for (DistanceSensor s : sensors) {
            sum += s.getValue();
        }
        double[] p = robot.gps().getValues();
        double[] rpy = robot.inertialUnit().getRollPitchYaw();
        sum += p[0] + p[1] + rpy[2] + robot.battery().getLevelPct();
        drive(robot, command);
        sim.step();
        return sum;
    }

    /** One step of physics and ground truth only; the robot drives a wide circle. */
    @Benchmark
    public double stepOnly() {
        robot.setWheelSpeeds(0.5, 0.45);
        sim.step();
        return sim.groundTruth().x();
    }

    /** One step of physics and ground truth only, on the wander's path (its commands replayed, no sensor read). */
    @Benchmark
    public double stepOnWanderPath() {
        if (wanderPath == null) {
            recordWanderPath();
        }
        drive(robot, wanderPath[wanderStep]);
        wanderStep = wanderStep + 1 == wanderPath.length ? 0 : wanderStep + 1;
        sim.step();
        return sim.groundTruth().x();
    }
}
