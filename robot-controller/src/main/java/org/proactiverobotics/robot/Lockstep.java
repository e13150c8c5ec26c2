package org.proactiverobotics.robot;

import java.util.Locale;
import java.util.Objects;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import java.util.function.BooleanSupplier;
import org.proactiverobotics.db.Backoff;
import org.proactiverobotics.db.PollPacing;
import org.proactiverobotics.protocol.RunState;
import org.proactiverobotics.protocol.Timing;
import org.proactiverobotics.robot.link.LinkException;
import org.proactiverobotics.robot.link.RobotClock;
import org.proactiverobotics.robot.link.RobotClock.EngineTick;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The robot's half of the handshake with an engine process through the database: a
 * {@link StepGate} for {@link RobotSuperclass#run(StepGate)}.
 *
 * <p>{@link #begin()} starts a run (the robot's old readings go, step 0 is published) and waits
 * until the engine acknowledges it (having reset its own rows). Then, per control step k, the
 * robot senses, publishes "sensed step k", and in {@link Timing#SYNC} waits until the engine has
 * run the one iteration for step k before it acts: the two processes interleave exactly like
 * the one-process mission, whatever the wall clock does. In {@link Timing#REALTIME} it only
 * publishes and goes on, as a Webots controller does when the engine runs on its own period.
 *
 * <p>The database failing never ends the wait: calls back off and retry, one warning per outage.
 * A stop request ends any wait.
 */
public final class Lockstep implements StepGate {

    private static final Logger LOG = LoggerFactory.getLogger(Lockstep.class);
    private static final long FIRST_STATUS_NANOS = TimeUnit.SECONDS.toNanos(2);
    private static final long STATUS_EVERY_NANOS = TimeUnit.SECONDS.toNanos(30);

    private final RobotClock clock;
    private final int robotId;
    private final Timing timing;
    private final BooleanSupplier stopRequested;
    private final Backoff backoff = new Backoff(100, 5_000, System::nanoTime);
    /** Polls for the engine's iteration about when it is due, learnt from the last steps. */
    private final PollPacing pacing = new PollPacing();
    private long runId = -1;
    private EngineTick lastTick;
    private long lastStep;
    private long lastSimTimeMs;
    private long publishFailures;
    /** Steps served in sync timing, the looks at engine_clock they took, and those seen at the first look after a wait in the server. */
    private long servedSteps;
    private long looks;
    private long wokenInServer;

    /**
     * @param clock         the handshake tables
     * @param robotId       the robot
     * @param timing        sync or realtime
     * @param stopRequested true once the robot should stop (ends any wait)
     */
    public Lockstep(RobotClock clock, int robotId, Timing timing, BooleanSupplier stopRequested) {
        this.clock = Objects.requireNonNull(clock, "clock");
        this.robotId = robotId;
        this.timing = Objects.requireNonNull(timing, "timing");
        this.stopRequested = Objects.requireNonNull(stopRequested, "stopRequested");
    }

    /**
     * Starts a new run and waits for an engine to acknowledge it.
     *
     * @return true when acknowledged, false when a stop was requested first
     */
    public boolean begin() {
        Long id = retry("starting a run", () -> clock.beginRun(robotId, timing));
        if (id == null) {
            return false;
        }
        runId = id;
        LOG.info("robot {}: run {} started ({} timing); waiting for the engine", robotId, runId, timing.label());
        return awaitEngine(0, "to acknowledge run " + runId);
    }

    @Override
    public boolean sensed(long step, long simTimeMs) {
        lastStep = step;
        lastSimTimeMs = simTimeMs;
        if (timing == Timing.REALTIME) {
            try {
                clock.publish(robotId, runId, step, simTimeMs, RunState.RUNNING);
            } catch (LinkException e) {
                // the engine iterates on its own period: a lost progress line costs nothing
                if (publishFailures++ == 0) {
                    LOG.warn("robot {}: publishing step {} failed: {}", robotId, step, e.getMessage());
                }
            }
            return true;
        }
        if (retry("publishing step " + step, () -> {
            clock.publish(robotId, runId, step, simTimeMs, RunState.RUNNING);
            return Boolean.TRUE;
        }) == null) {
            return false;
        }
        return awaitEngine(step, "to serve step " + step + String.format(Locale.ROOT, " (%.2f s simulated)", simTimeMs / 1000.0));
    }

    /**
     * Publishes the end of the run (best effort: the engine only stops waiting for steps).
     *
     * @param state FINISHED (the mission ended) or STOPPED (a stop was requested)
     */
    public void finish(RunState state) {
        if (runId < 0) {
            return;
        }
        if (servedSteps > 0) {
            LOG.info("robot {}: handshake: {} steps served, {} of them seen at the first look after waiting in the database;"
                    + " {} looks at engine_clock in all", robotId, servedSteps, wokenInServer, looks);
        }
        try {
            clock.publish(robotId, runId, lastStep, lastSimTimeMs, state);
            lastTick = clock.engineTick(robotId).orElse(lastTick);
        } catch (LinkException e) {
            LOG.warn("robot {}: could not publish the end of run {}: {}", robotId, runId, e.getMessage());
        }
    }

    /** @return this run's id, or -1 before {@link #begin()} */
    public long runId() {
        return runId;
    }

    /** @return the engine's iterations for this run as last seen, or empty when none was seen */
    public Optional<EngineTick> lastTick() {
        return Optional.ofNullable(lastTick).filter(t -> t.runId() == runId);
    }

    /**
     * Waits until the engine serves this run up to the step: in the server when the clock can
     * ({@link RobotClock#waitsInServer}), else polling engine_clock, first about when the
     * iteration is due ({@link PollPacing}), then closely; false when stopped.
     */
    private boolean awaitEngine(long step, String what) {
        long start = System.nanoTime();
        long nextStatus = start + FIRST_STATUS_NANOS;
        boolean reported = false;
        int polls = 0;
        boolean inServer = step > 0 && clock.waitsInServer();
        if (!inServer) {
            LockSupport.parkNanos(pacing.pauseNanos(0, 0)); // the engine's iteration has only just been asked for
        }
        while (true) {
            polls++;
            long callStart = System.nanoTime();
            Optional<EngineTick> tick = retry("reading engine_clock",
                    () -> inServer ? clock.awaitServed(robotId, step) : clock.engineTick(robotId));
            if (tick == null) {
                return false;
            }
            if (tick.isPresent() && tick.get().runId() == runId && tick.get().step() >= step) {
                lastTick = tick.get();
                if (step > 0) {
                    pacing.waited(System.nanoTime() - start);
                    servedSteps++;
                    looks += polls;
                    if (inServer && polls == 1) {
                        wokenInServer++;
                    }
                }
                if (reported || step == 0) {
                    LOG.info("robot {}: the engine {} (after {} s)", robotId, step == 0 ? "acknowledged run " + runId
                            : "is back, serving step " + step, String.format(Locale.ROOT, "%.1f", (System.nanoTime() - start) / 1e9));
                }
                return true;
            }
            if (stopRequested.getAsBoolean()) {
                return false;
            }
            long now = System.nanoTime();
            if (now - nextStatus >= 0) {
                reported = true;
                nextStatus = now + STATUS_EVERY_NANOS;
                LOG.info("robot {}: waiting for the engine {}; {} ({} s so far{}); waited for as long as it takes",
                        robotId, what,
                        tick.map(t -> t.runId() == runId ? "it last served step " + t.step()
                                : "it last served run " + t.runId()).orElse("no engine has served this robot yet"),
                        String.format(Locale.ROOT, "%.0f", (now - start) / 1e9), paceSaid(now - start));
            }
            long pause = pacing.pauseNanos(now - start, polls);
            if (!inServer || now - callStart < pause) { // a wait in the server that lasted longer is the pause
                LockSupport.parkNanos(pause);
            }
        }
    }

    /**
     * The wait in the engine's own terms: how many of its recent steps would have fit in it, so
     * that a line tells an engine that is a little slow from one that has stopped serving.
     */
    private String paceSaid(long waitedNanos) {
        long pace = pacing.expectedNanos();
        if (pace <= 0) {
            return "";
        }
        return String.format(Locale.ROOT, ", %d times the %.1f ms its recent steps took", waitedNanos / pace, pace / 1e6);
    }

    /** Calls until it succeeds, backing off after failures; null when a stop was requested. */
    private <T> T retry(String what, ClockCall<T> call) {
        boolean warned = false;
        while (!stopRequested.getAsBoolean()) {
            if (!backoff.ready()) {
                LockSupport.parkNanos(10_000_000);
                continue;
            }
            try {
                T result = call.call();
                if (backoff.failing()) {
                    LOG.info("robot {}: database back ({})", robotId, what);
                }
                backoff.succeeded();
                return result;
            } catch (LinkException | RuntimeException e) {
                if (!warned && !backoff.failing()) {
                    LOG.warn("robot {}: {} failed: {}; retrying with back-off", robotId, what, e.getMessage());
                } else {
                    LOG.debug("robot {}: {} still failing: {}", robotId, what, e.getMessage());
                }
                warned = true;
                backoff.failed();
            }
        }
        return null;
    }

    /** One call to the handshake tables. */
    @FunctionalInterface
    private interface ClockCall<T> {
        T call() throws LinkException;
    }
}
