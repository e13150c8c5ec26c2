package org.proactiverobotics.engine;

import java.time.Duration;
import java.util.Objects;
import java.util.Optional;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Runs a started engine's iterations on a thread of its own, one every period (at a fixed
 * rate; an iteration longer than the period is followed at once by the next, never
 * overlapped). {@link #stop()} lets the running iteration finish, its state saved, and returns.
 * A {@link StateStoreException} (or any other exception out of an iteration) stops the runner;
 * see {@link #error()}.
 */
public final class PeriodicRunner implements AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(PeriodicRunner.class);

    private final ProactiveEngine engine;
    private final Duration period;
    private ScheduledExecutorService executor;
    private volatile Thread thread;
    private volatile Throwable error;

    /**
     * @param engine a started engine
     * @param period the time from the start of one iteration to the start of the next
     */
    public PeriodicRunner(ProactiveEngine engine, Duration period) {
        this.engine = Objects.requireNonNull(engine);
        if (period.isNegative() || period.isZero()) {
            throw new IllegalArgumentException("period must be positive: " + period);
        }
        this.period = period;
    }

    /** Starts running iterations, the first at once. @return this */
    public synchronized PeriodicRunner start() {
        if (executor != null) {
            throw new IllegalStateException("runner already started");
        }
        ScheduledThreadPoolExecutor ex = new ScheduledThreadPoolExecutor(1, r -> {
            Thread t = new Thread(r, "proactive-engine-" + engine.robotId());
            thread = t;
            return t;
        });
        ex.setExecuteExistingDelayedTasksAfterShutdownPolicy(false);
        executor = ex;
        ex.scheduleAtFixedRate(this::tick, 0, period.toNanos(), TimeUnit.NANOSECONDS);
        return this;
    }

    private void tick() {
        try {
            engine.runIteration();
        } catch (RuntimeException | Error e) {
            error = e;
            LOG.error("engine {} stopped: iteration {} failed", engine.robotId(), engine.iteration(), e);
            executor.shutdown();
        }
    }

    /**
     * Stops: no iteration starts after this call; the running one (if any) finishes and saves.
     * Returns once it has, except when called from the runner's own thread (from a rule or a
     * listener), where it returns at once and the iteration then ends normally.
     */
    public synchronized void stop() {
        if (executor == null) {
            return;
        }
        executor.shutdown();
        if (Thread.currentThread() == thread) {
            return;
        }
        boolean interrupted = false;
        while (true) {
            try {
                if (executor.awaitTermination(1, TimeUnit.DAYS)) {
                    break;
                }
            } catch (InterruptedException e) {
                interrupted = true; // keep waiting: returning mid-iteration would break the promise of stop()
            }
        }
        if (interrupted) {
            Thread.currentThread().interrupt();
        }
    }

    /** @return true between start and the end of the last iteration */
    public synchronized boolean isRunning() {
        return executor != null && !executor.isTerminated();
    }

    /** @return what stopped the runner, when an iteration threw */
    public Optional<Throwable> error() {
        return Optional.ofNullable(error);
    }

    /** Same as {@link #stop()}. */
    @Override
    public void close() {
        stop();
    }
}
