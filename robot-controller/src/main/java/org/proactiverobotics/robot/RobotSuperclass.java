package org.proactiverobotics.robot;

import java.util.Objects;
import java.util.concurrent.locks.LockSupport;
import org.proactiverobotics.db.Backoff;
import org.proactiverobotics.robot.link.LinkException;
import org.proactiverobotics.robot.link.RobotLink;
import org.proactiverobotics.sim2d.SimRobot;
import org.proactiverobotics.sim2d.Simulation;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * What every robot controller shares (the paper's {@code RobotSuperclass}): the devices of the
 * simulated robot, the control-step loop, and guarded access to the engine's side through a
 * {@link RobotLink} (the database, with its pool when this controller owns one).
 *
 * <p>A control step is split in two so that an app can interleave it with the engine in
 * lockstep: {@link #sense()} (answer the engine's requests) and {@link #act()} (execute the
 * newest command); {@link #controlStep()} does both; {@link #run()} is the Webots-style loop of a
 * standalone robot process, stepping the simulation itself.
 *
 * <p>Database failures never escape a step: each call goes through {@link #call}, which backs off
 * after a failure (skipping database work until the delay elapses), logs one warning per outage
 * and one line when it ends, and counts every failed or skipped call and every lost reading.
 */
public abstract class RobotSuperclass implements AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(RobotSuperclass.class);

    /** The simulation the robot lives in (Webots' role). */
    protected final Simulation simulation;
    /** The robot's position in the world's robots (0 for the robot of a one-robot world). */
    protected final int robotIndex;
    /** The robot's devices and wheels. */
    protected final SimRobot robot;
    /** The channel to the engine. */
    protected final RobotLink link;
    /** The configuration. */
    protected final RobotConfig config;
    /** The counters; see {@link #stats()}. */
    final StatsCounter stats = new StatsCounter();

    private final Backoff backoff;
    private final AutoCloseable owned;
    private volatile boolean stopRequested;
    private long loopSteps;
    private long senseNanos;
    private long waitNanos;
    private long actNanos;
    private long physicsNanos;
    private long outageStartNanos;
    private long failedAtOutageStart;
    private long skippedAtOutageStart;
    private long lostAtOutageStart;

    /**
     * @param simulation the simulation whose robot this controls
     * @param link       the channel to the engine (closed by {@link #close()})
     * @param config     the configuration
     * @param owned      a resource this controller owns and closes last (its pool), or null
     */
    protected RobotSuperclass(Simulation simulation, RobotLink link, RobotConfig config, AutoCloseable owned) {
        this(simulation, 0, link, config, owned);
    }

    /**
     * @param simulation the simulation one of whose robots this controls
     * @param robotIndex that robot's position in the world's robots (0-based; see {@link Simulation#robot(int)})
     * @param link       the channel to the engine (closed by {@link #close()})
     * @param config     the configuration
     * @param owned      a resource this controller owns and closes last (its pool), or null
     */
    protected RobotSuperclass(Simulation simulation, int robotIndex, RobotLink link, RobotConfig config,
                              AutoCloseable owned) {
        this.simulation = Objects.requireNonNull(simulation, "simulation");
        if (robotIndex < 0 || robotIndex >= simulation.robotCount()) {
            throw new IllegalArgumentException("robot index " + robotIndex + " is not one of the world's "
                    + simulation.robotCount() + " robot(s)");
        }
        this.robotIndex = robotIndex;
        this.robot = simulation.robot(robotIndex);
        this.link = Objects.requireNonNull(link, "link");
        this.config = Objects.requireNonNull(config, "config");
        this.owned = owned;
        this.backoff = new Backoff(config.backoffInitialMs(), config.backoffMaxMs(), System::nanoTime);
    }

    /** Answers the engine's pending requests (first half of a control step). Never throws for the database. */
    public abstract void sense();

    /** Reads the newest command and sets the wheels (second half of a control step). Never throws for the database. */
    public abstract void act();

    /** One control step: {@link #sense()} then {@link #act()}; the simulation is not stepped. */
    public final void controlStep() {
        sense();
        act();
        stats.controlSteps++;
    }

    /**
     * The Webots-style loop of a standalone robot process: control step, simulation step, paced
     * by {@link RobotConfig#realTimeFactor()}, until {@link #missionOver()} or {@link #requestStop()}.
     *
     * @return the simulated time at the end, ms
     */
    public long run() {
        return run(StepGate.NONE);
    }

    /**
     * {@link #run()} with a gate between sensing and acting: in lockstep with an engine process
     * ({@link Lockstep}) the robot acts on step k only once the engine has served step k, so the
     * two processes interleave exactly as the one-process mission does.
     *
     * @param gate told of each sensed and each simulated step; may hold the robot back
     * @return the simulated time at the end, ms
     */
    public long run(StepGate gate) {
        LOG.info("robot {}: running (time step {} ms, {})", config.robotId(), simulation.timeStepMs(),
                config.realTimeFactor() > 0 ? "real-time factor " + config.realTimeFactor() : "unpaced: as fast as it goes");
        long startNanos = System.nanoTime();
        long startSimMs = simulation.simTimeMs();
        long step = 0;
        while (!stopRequested && !missionOver()) {
            long t0 = System.nanoTime();
            sense();
            long t1 = System.nanoTime();
            if (!gate.sensed(step + 1, simulation.simTimeMs())) {
                break;
            }
            step++;
            long t2 = System.nanoTime();
            act();
            stats.controlSteps++;
            long t3 = System.nanoTime();
            simulation.step();
            long t4 = System.nanoTime();
            senseNanos += t1 - t0;
            waitNanos += t2 - t1;
            actNanos += t3 - t2;
            physicsNanos += t4 - t3;
            loopSteps++;
            gate.stepped(step, simulation.simTimeMs());
            pace(startNanos, simulation.simTimeMs() - startSimMs);
        }
        robot.setWheelSpeeds(0.0, 0.0);
        LOG.info("robot {}: stopped at {} ms simulated; {}", config.robotId(), simulation.simTimeMs(), stats());
        return simulation.simTimeMs();
    }

    /** @return where the time of {@link #run(StepGate)} went so far */
    public LoopTimes loopTimes() {
        double n = Math.max(1, loopSteps);
        return new LoopTimes(loopSteps, senseNanos / 1e6 / n, waitNanos / 1e6 / n, actNanos / 1e6 / n,
                physicsNanos / 1e6 / n);
    }

    /** @return whether {@link #requestStop()} was called */
    public boolean stopRequested() {
        return stopRequested;
    }

    /** Asks {@link #run()} to return after the current step; safe from any thread. */
    public void requestStop() {
        stopRequested = true;
    }

    /**
     * When {@link #run()} ends on its own. This default, as the one-process mission: every
     * checkpoint of this robot reached (ground truth), its battery flat, or the world's time limit passed.
     *
     * @return whether the mission is over
     */
    public boolean missionOver() {
        var truth = simulation.groundTruth(robotIndex);
        return truth.allCheckpointsReached() || truth.batteryPct() <= 0.0 || simulation.timeLimitReached();
    }

    /** @return the robot's position in the world's robots (0-based) */
    public int robotIndex() {
        return robotIndex;
    }

    /** @return the simulated time now, ms */
    public long simTimeMs() {
        return simulation.simTimeMs();
    }

    /** @return the configuration */
    public RobotConfig config() {
        return config;
    }

    /** @return a snapshot of the counters */
    public RobotStats stats() {
        return stats.snapshot();
    }

    /** @return whether the last database call failed and the controller is backing off */
    public boolean databaseFailing() {
        return backoff.failing();
    }

    /**
     * A call to the engine's side, guarded: skipped while backing off; a failure (a
     * {@link LinkException} or any runtime error of a driver) is counted, logged once per outage,
     * and never thrown.
     *
     * @param what               what the call does, for the log
     * @param readingsIfLost     how many readings are lost when it fails or is skipped
     * @param body               the call
     * @param <T>                its result
     * @return the call's result, or null when it failed or was skipped
     */
    protected final <T> T call(String what, int readingsIfLost, LinkCall<T> body) {
        if (!backoff.ready()) {
            stats.skippedCalls++;
            stats.readingsNotWritten += readingsIfLost;
            return null;
        }
        try {
            T result = body.call(link);
            if (backoff.failing()) {
                LOG.info("robot {}: database back after {} ms; during the outage {} call(s) failed, {} were skipped, "
                                + "{} reading(s) were not written (their requests stay pending)", config.robotId(),
                        (System.nanoTime() - outageStartNanos) / 1_000_000L, stats.failedCalls - failedAtOutageStart,
                        stats.skippedCalls - skippedAtOutageStart, stats.readingsNotWritten - lostAtOutageStart);
            }
            backoff.succeeded();
            return result;
        } catch (LinkException | RuntimeException e) {
            if (!backoff.failing()) {
                stats.outages++;
                outageStartNanos = System.nanoTime();
                failedAtOutageStart = stats.failedCalls;
                skippedAtOutageStart = stats.skippedCalls;
                lostAtOutageStart = stats.readingsNotWritten;
                LOG.warn("robot {}: database call failed ({}): {}; the robot stops until a new command comes and "
                        + "retries with back-off", config.robotId(), what, e.toString());
            } else {
                LOG.debug("robot {}: database still failing ({}): {}", config.robotId(), what, e.toString());
            }
            stats.failedCalls++;
            stats.readingsNotWritten += readingsIfLost;
            backoff.failed();
            return null;
        }
    }

    /** Closes the link, then the owned pool if any. */
    @Override
    public void close() {
        try {
            link.close();
        } finally {
            if (owned != null) {
                try {
                    owned.close();
                } catch (Exception e) {
                    LOG.warn("robot {}: closing the pool failed: {}", config.robotId(), e.toString());
                }
            }
        }
    }

    private void pace(long startNanos, long simElapsedMs) {
        double factor = config.realTimeFactor();
        if (factor <= 0) {
            return;
        }
        long dueNanos = startNanos + (long) (simElapsedMs * 1_000_000L / factor);
        long wait = dueNanos - System.nanoTime();
        if (wait > 0) {
            LockSupport.parkNanos(wait);
        }
    }

    /**
     * One call through the link.
     *
     * @param <T> its result
     */
    @FunctionalInterface
    protected interface LinkCall<T> {
        /**
         * @param link the link
         * @return the result (non-null; use {@link Boolean#TRUE} for none)
         * @throws LinkException when the engine's side failed
         */
        T call(RobotLink link) throws LinkException;
    }
}
