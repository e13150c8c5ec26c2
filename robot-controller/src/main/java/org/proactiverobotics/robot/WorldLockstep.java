package org.proactiverobotics.robot;

import java.util.Locale;
import java.util.Objects;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import java.util.function.BooleanSupplier;
import java.util.function.IntPredicate;
import org.proactiverobotics.db.Backoff;
import org.proactiverobotics.db.PollPacing;
import org.proactiverobotics.protocol.RunState;
import org.proactiverobotics.protocol.Timing;
import org.proactiverobotics.robot.link.JdbcWorldClock;
import org.proactiverobotics.robot.link.LinkException;
import org.proactiverobotics.robot.link.RobotClock.EngineTick;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * {@link Lockstep} for every robot of one world, the {@link StepGate} of a {@link WorldLoop} in the
 * robot process that hosts them all: each robot has its own run and its own engine (one engine
 * process may serve them all, or several share them by lease). {@link #begin()} starts every
 * robot's run and waits until every one is acknowledged. Per step k, "sensed step k" of every
 * robot whose mission goes on is published at once; in {@link Timing#SYNC} the world acts only
 * once every one of their engines has served step k, so the engines iterate side by side and the
 * run is {@code run}'s, step for step. A robot whose mission ended is published FINISHED at the
 * next step: its engine stops, as {@code run} stops iterating it. In {@link Timing#REALTIME} the
 * steps are only published.
 *
 * <p>The database failing never ends a wait: calls back off and retry, one warning per outage.
 * A stop request ends any wait.
 */
public final class WorldLockstep implements StepGate {

    private static final Logger LOG = LoggerFactory.getLogger(WorldLockstep.class);
    private static final long FIRST_STATUS_NANOS = TimeUnit.SECONDS.toNanos(2);
    private static final long STATUS_EVERY_NANOS = TimeUnit.SECONDS.toNanos(30);

    private final JdbcWorldClock clock;
    private final int[] robotIds;
    private final Timing timing;
    private final BooleanSupplier stopRequested;
    private final IntPredicate done;
    private final Backoff backoff = new Backoff(100, 5_000, System::nanoTime);
    private final PollPacing pacing = new PollPacing();
    private final long[] runIds;
    private final EngineTick[] lastTicks;
    private final EngineTick[] read;
    /** Whether the robot's end was published (it takes no further step). */
    private final boolean[] ended;
    private final int[] positions;
    private long lastStep;
    private long lastSimTimeMs;
    private long publishFailures;
    private boolean begun;

    /**
     * @param clock         the world's handshake tables
     * @param robotIds      the robots' ids, in the world's order (the clock's)
     * @param timing        sync or realtime
     * @param stopRequested true once the process should stop (ends any wait)
     * @param done          whether the robot at a position has ended its mission (it takes no further step)
     */
    public WorldLockstep(JdbcWorldClock clock, int[] robotIds, Timing timing, BooleanSupplier stopRequested,
                         IntPredicate done) {
        this.clock = Objects.requireNonNull(clock, "clock");
        this.robotIds = robotIds.clone();
        this.timing = Objects.requireNonNull(timing, "timing");
        this.stopRequested = Objects.requireNonNull(stopRequested, "stopRequested");
        this.done = Objects.requireNonNull(done, "done");
        int n = robotIds.length;
        this.runIds = new long[n];
        this.lastTicks = new EngineTick[n];
        this.read = new EngineTick[n];
        this.ended = new boolean[n];
        this.positions = new int[n];
    }

    /**
     * Starts every robot's run and waits until an engine acknowledged each.
     *
     * @return true when all are acknowledged, false when a stop was requested first
     */
    public boolean begin() {
        for (int i = 0; i < robotIds.length; i++) {
            int position = i;
            Long id = retry("starting the run of robot " + robotIds[i], () -> clock.beginRun(position, timing));
            if (id == null) {
                return false;
            }
            runIds[i] = id;
            LOG.info("robot {}: run {} started ({} timing); waiting for the engine", robotIds[i], id, timing.label());
        }
        begun = true;
        int count = 0;
        for (int i = 0; i < robotIds.length; i++) {
            positions[count++] = i;
        }
        return awaitEngines(0, count, "to acknowledge their runs");
    }

    @Override
    public boolean sensed(long step, long simTimeMs) {
        lastStep = step;
        lastSimTimeMs = simTimeMs;
        int endedNow = 0;
        for (int i = 0; i < robotIds.length; i++) {
            if (!ended[i] && done.test(i)) {
                positions[endedNow++] = i;
            }
        }
        if (endedNow > 0) { // its engine stops, as run stops iterating it
            if (publish(endedNow, step - 1, simTimeMs, RunState.FINISHED, true) == null) {
                return false;
            }
            for (int k = 0; k < endedNow; k++) {
                ended[positions[k]] = true;
            }
        }
        int count = 0;
        for (int i = 0; i < robotIds.length; i++) {
            if (!ended[i]) {
                positions[count++] = i;
            }
        }
        if (timing == Timing.REALTIME) {
            publish(count, step, simTimeMs, RunState.RUNNING, false); // the engines iterate on their own period
            return true;
        }
        if (publish(count, step, simTimeMs, RunState.RUNNING, true) == null) {
            return false;
        }
        return awaitEngines(step, count, String.format(Locale.ROOT, "to serve step %d (%.2f s simulated)", step,
                simTimeMs / 1000.0));
    }

    /**
     * Publishes the end of every run not yet ended (best effort: the engines only stop waiting for steps).
     *
     * @param state FINISHED (the missions ended) or STOPPED (a stop was requested)
     */
    public void finish(RunState state) {
        if (!begun) {
            return;
        }
        int count = 0;
        for (int i = 0; i < robotIds.length; i++) {
            if (!ended[i]) {
                positions[count++] = i;
            }
        }
        try {
            clock.publish(positions, count, runIds, lastStep, lastSimTimeMs, state);
            for (int k = 0; k < count; k++) {
                ended[positions[k]] = true;
            }
            clock.ticks(read);
            for (int i = 0; i < robotIds.length; i++) {
                if (read[i] != null && read[i].runId() == runIds[i]) {
                    lastTicks[i] = read[i];
                }
            }
        } catch (LinkException e) {
            LOG.warn("robots of this world: could not publish the end of their runs: {}", e.getMessage());
        }
    }

    /**
     * @param position a robot's position in the world's order
     * @return its engine's iterations for its run as last seen, or empty when none was seen
     */
    public Optional<EngineTick> lastTick(int position) {
        EngineTick t = lastTicks[position];
        return t != null && t.runId() == runIds[position] ? Optional.of(t) : Optional.empty();
    }

    /** @return true when published; null when a stop came first (sync), or the publication failed (realtime) */
    private Boolean publish(int count, long step, long simTimeMs, RunState state, boolean retried) {
        if (!retried) {
            try {
                clock.publish(positions, count, runIds, step, simTimeMs, state);
                return Boolean.TRUE;
            } catch (LinkException e) {
                if (publishFailures++ == 0) { // in real time a lost progress line costs nothing
                    LOG.warn("robots of this world: publishing step {} failed: {}", step, e.getMessage());
                }
                return null;
            }
        }
        return retry("publishing step " + step, () -> {
            clock.publish(positions, count, runIds, step, simTimeMs, state);
            return Boolean.TRUE;
        });
    }

    /** Polls engine_clock until every robot at {@code positions[0..count)} is served up to the step; false when stopped. */
    private boolean awaitEngines(long step, int count, String what) {
        long start = System.nanoTime();
        long nextStatus = start + FIRST_STATUS_NANOS;
        boolean reported = false;
        int polls = 0;
        LockSupport.parkNanos(pacing.pauseNanos(0, 0)); // the engines' iterations have only just been asked for
        while (true) {
            polls++;
            Boolean ok = retry("reading engine_clock", () -> {
                clock.ticks(read);
                return Boolean.TRUE;
            });
            if (ok == null) {
                return false;
            }
            int waiting = -1;
            for (int k = 0; k < count; k++) {
                int p = positions[k];
                EngineTick t = read[p];
                if (t != null && t.runId() == runIds[p]) {
                    lastTicks[p] = t;
                }
                if (waiting < 0 && (t == null || t.runId() != runIds[p] || t.step() < step)) {
                    waiting = p;
                }
            }
            if (waiting < 0) {
                if (timing == Timing.SYNC) {
                    clock.handOff(positions, count); // their commands and requests, read with the ticks
                }
                if (step > 0) {
                    pacing.waited(System.nanoTime() - start);
                }
                if (reported || step == 0) {
                    LOG.info("robots of this world: the engines {} (after {} s)", step == 0
                            ? "acknowledged every run" : "are back, serving step " + step,
                            String.format(Locale.ROOT, "%.1f", (System.nanoTime() - start) / 1e9));
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
                EngineTick t = read[waiting];
                LOG.info("robot {}: waiting for the engine {}; {} ({} s so far); waited for as long as it takes",
                        robotIds[waiting], what, t == null ? "no engine has served this robot yet"
                                : t.runId() == runIds[waiting] ? "it last served step " + t.step() : "it last served run " + t.runId(),
                        String.format(Locale.ROOT, "%.0f", (now - start) / 1e9));
            }
            LockSupport.parkNanos(pacing.pauseNanos(now - start, polls));
        }
    }

    /** Calls until it succeeds, backing off after failures; null when a stop was requested. */
    private <T> T retry(String what, Call<T> call) {
        boolean warned = false;
        while (!stopRequested.getAsBoolean()) {
            if (!backoff.ready()) {
                LockSupport.parkNanos(10_000_000);
                continue;
            }
            try {
                T result = call.call();
                if (backoff.failing()) {
                    LOG.info("robots of this world: database back ({})", what);
                }
                backoff.succeeded();
                return result;
            } catch (LinkException | RuntimeException e) {
                if (!warned && !backoff.failing()) {
                    LOG.warn("robots of this world: {} failed: {}; retrying with back-off", what, e.getMessage());
                } else {
                    LOG.debug("robots of this world: {} still failing: {}", what, e.getMessage());
                }
                warned = true;
                backoff.failed();
            }
        }
        return null;
    }

    /** One call to the handshake tables. */
    @FunctionalInterface
    private interface Call<T> {
        T call() throws LinkException;
    }
}
