package org.proactiverobotics.app.deploy;

import java.sql.SQLException;
import java.util.Locale;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import java.util.function.BooleanSupplier;
import org.proactiverobotics.app.deploy.EngineClock.RobotTick;
import org.proactiverobotics.app.deploy.EngineClock.Served;
import org.proactiverobotics.engine.CorruptStateException;
import org.proactiverobotics.engine.robot.RobotEngine;
import org.proactiverobotics.engine.robot.Strategy;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The engine process's loop: follows the robot's clock and runs the engine's iterations for it
 * until stopped.
 *
 * <ul>
 *   <li>A new robot run (a new robot process) resets the engine's rows and starts the engine
 *       fresh; the run the engine already served (the engine restarted) resumes from the saved
 *       state. An iteration saved but not yet published counts as served, so a kill between the
 *       two never runs a step twice.</li>
 *   <li>Sync timing: exactly one iteration per robot step, then "served step k".</li>
 *   <li>Real-time timing: one iteration every period, at a fixed rate, while the run goes on.</li>
 *   <li>The database failing (or an iteration failing to save) is logged once, retried with
 *       back-off, and the engine resumes from its saved state when the database is back.</li>
 * </ul>
 * The robot chooses the timing (robot_clock.timing); the engine follows it.
 */
public final class EngineLoop {

    /**
     * @param strategy name of the strategy written when the robot has none yet
     * @param fresh    discard the saved state at start instead of resuming it
     * @param periodMs the period of real-time iterations, ms
     * @param logEvery one INFO line every this many iterations
     */
    public record Options(Strategy strategy, boolean fresh, long periodMs, long logEvery) {
    }

    private static final Logger LOG = LoggerFactory.getLogger(EngineLoop.class);
    private static final long STATUS_EVERY_NANOS = TimeUnit.SECONDS.toNanos(30);

    private final RobotEngine side;
    private final EngineClock clock;
    private final int robotId;
    private final Options options;
    private final BooleanSupplier stop;
    private final Heartbeat heartbeat;
    private long runId = -1;
    private long served;
    private boolean firstContact = true;
    private boolean finishedLogged;
    private long nextStatusNanos;
    private long nextTickNanos;
    private long idlePolls;
    /** In real-time timing, how long until the next iteration is due (0: not waiting for a tick). */
    private long realTimeWaitNanos;
    private long iterationsSinceLog;
    private long iterationNanosSinceLog;
    private long failures;
    private long backoffMs;

    /**
     * @param side      the engine of this robot, built
     * @param clock     the handshake tables
     * @param robotId   the robot
     * @param options   how to run
     * @param stop      true when the process should stop (checked between iterations)
     * @param heartbeat touched while the loop turns
     */
    public EngineLoop(RobotEngine side, EngineClock clock, int robotId, Options options, BooleanSupplier stop,
                      Heartbeat heartbeat) {
        this.side = side;
        this.clock = clock;
        this.robotId = robotId;
        this.options = options;
        this.stop = stop;
        this.heartbeat = heartbeat;
    }

    /**
     * Runs until stopped; every iteration is saved when it ends.
     *
     * @throws CorruptStateException when the saved state cannot be read (start with --fresh to discard it)
     */
    public void run() {
        LOG.info("engine {}: running (strategy {} when none is set; real-time period {} ms)", robotId,
                options.strategy().name(), options.periodMs());
        while (!stop.getAsBoolean()) {
            heartbeat.beat();
            try {
                boolean worked = turn();
                if (backoffMs > 0) {
                    LOG.info("engine {}: database back after {} failed attempt(s)", robotId, failures);
                    backoffMs = 0;
                    failures = 0;
                }
                if (!worked) {
                    idle();
                } else {
                    idlePolls = 0;
                }
            } catch (CorruptStateException e) {
                throw e; // never a silent fresh start: the command says which row and stops
            } catch (SQLException | RuntimeException e) {
                failed(e);
            }
        }
        LOG.info("engine {}: stopped after iteration {} (state saved)", robotId, side.engine().iteration());
    }

    /** One look at the robot's clock and at most one iteration; @return whether an iteration ran. */
    private boolean turn() throws SQLException {
        Optional<RobotTick> seen = clock.robot();
        long now = System.nanoTime();
        if (seen.isEmpty()) {
            if (now - nextStatusNanos >= 0) {
                nextStatusNanos = now + STATUS_EVERY_NANOS;
                LOG.info("engine {}: waiting for the robot (robot {} has not started a run)", robotId, robotId);
            }
            return false;
        }
        RobotTick robot = seen.get();
        if (robot.runId() != runId) {
            adopt(robot);
        }
        if (!robot.running()) {
            if (!finishedLogged) {
                finishedLogged = true;
                LOG.info("engine {}: robot run {} {} at step {} ({} s simulated); nothing to serve until a new run",
                        robotId, runId, robot.state().toLowerCase(Locale.ROOT), robot.step(), secs(robot.simTimeMs()));
            }
            return false;
        }
        if (robot.sync()) {
            if (robot.step() <= served) {
                return false;
            }
        } else {
            if (now - nextTickNanos < 0) {
                realTimeWaitNanos = nextTickNanos - now;
                return false;
            }
            long period = TimeUnit.MILLISECONDS.toNanos(options.periodMs());
            nextTickNanos = now - nextTickNanos > 10 * period ? now + period : nextTickNanos + period; // fixed rate, no long burst after a pause
        }
        long t0 = System.nanoTime();
        side.iterate();
        long iteration = side.engine().iteration();
        served = Math.max(served, robot.step());
        clock.publish(runId, served, iteration);
        iterationNanosSinceLog += System.nanoTime() - t0;
        if (++iterationsSinceLog >= options.logEvery()) {
            LOG.info("engine {}: iteration {} for robot step {} ({} s simulated, {} timing), {} ms per iteration",
                    robotId, iteration, robot.step(), secs(robot.simTimeMs()), robot.timing(),
                    String.format(Locale.ROOT, "%.2f", iterationNanosSinceLog / 1e6 / iterationsSinceLog));
            iterationsSinceLog = 0;
            iterationNanosSinceLog = 0;
        }
        return true;
    }

    /** Takes up the robot's run: resumes it when this engine already served it, else starts it fresh. */
    private void adopt(RobotTick robot) throws SQLException {
        Optional<Served> last = clock.served();
        boolean sameRun = last.isPresent() && last.get().runId() == robot.runId();
        if (sameRun && (!firstContact || !options.fresh())) {
            boolean resumed = side.resume();
            long iteration = side.engine().iteration();
            // An iteration saved but not yet published (killed in between) served the next step.
            served = last.get().step() + Math.max(0, iteration - last.get().iteration());
            if (iteration != last.get().iteration()) {
                clock.publish(robot.runId(), served, iteration);
            }
            LOG.info("engine {}: {} robot run {} at step {} (iteration {})", robotId,
                    resumed ? "resuming" : "no saved state; starting afresh in", robot.runId(), served, iteration);
        } else if (sameRun) {
            side.startFresh();
            served = last.get().step();
            clock.publish(robot.runId(), served, side.engine().iteration());
            LOG.info("engine {}: --fresh: saved state discarded; serving robot run {} from step {}", robotId,
                    robot.runId(), served + 1);
        } else {
            clock.resetForNewRun();
            side.startFresh();
            served = 0;
            clock.publish(robot.runId(), 0, 0);
            LOG.info("engine {}: new robot run {} ({} timing): commands and requests of earlier runs cleared, "
                    + "checkpoints not reached, engine started fresh", robotId, robot.runId(), robot.timing());
        }
        writeStrategyIfNone();
        runId = robot.runId();
        firstContact = false;
        finishedLogged = false;
        nextTickNanos = System.nanoTime();
    }

    /** A strategy changed with the strategy command survives restarts: write ours only when none is set. */
    private void writeStrategyIfNone() {
        if (side.ensureStrategy(options.strategy())) {
            LOG.info("engine {}: strategy {} written", robotId, options.strategy().name());
        }
    }

    private void failed(Exception e) {
        failures++;
        backoffMs = backoffMs == 0 ? 100 : Math.min(5_000, backoffMs * 2);
        if (failures == 1) {
            LOG.warn("engine {}: database failure ({}); retrying with back-off, then resuming from the saved state",
                    robotId, oneLine(e));
        } else {
            LOG.debug("engine {}: still failing ({})", robotId, oneLine(e));
        }
        runId = -1; // resume from what was saved once the database answers again
        firstContact = false;
        long until = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(backoffMs);
        while (System.nanoTime() - until < 0 && !stop.getAsBoolean()) {
            LockSupport.parkNanos(TimeUnit.MILLISECONDS.toNanos(20));
        }
    }

    /** Back-to-back polls while the robot is busy stepping (a step costs round trips, not sleeps), longer ones when it is away. */
    private void idle() {
        if (realTimeWaitNanos > 0) { // real time: the next iteration is due at a known time, no need to poll before
            long nanos = Math.min(realTimeWaitNanos, 1_000_000);
            realTimeWaitNanos = 0;
            LockSupport.parkNanos(nanos);
            return;
        }
        long polls = ++idlePolls;
        long nanos = polls < 2_000 ? 20_000 : polls < 3_000 ? 1_000_000 : polls < 4_000 ? 10_000_000 : 50_000_000;
        LockSupport.parkNanos(nanos);
    }

    private static String secs(long ms) {
        return String.format(Locale.ROOT, "%.1f", ms / 1000.0);
    }

    private static String oneLine(Throwable e) {
        String m = e.getMessage() == null ? e.toString() : e.getMessage();
        Throwable cause = e.getCause();
        if (cause != null && cause.getMessage() != null && !m.contains(cause.getMessage())) {
            m = m + ": " + cause.getMessage();
        }
        int nl = m.indexOf('\n');
        return nl < 0 ? m : m.substring(0, nl);
    }
}
