package org.proactiverobotics.app.deploy;

import java.sql.SQLException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import java.util.concurrent.locks.LockSupport;
import java.util.function.BooleanSupplier;
import javax.sql.DataSource;
import org.proactiverobotics.app.deploy.EngineClock.RobotTick;
import org.proactiverobotics.db.Backoff;
import org.proactiverobotics.db.PollPacing;
import org.proactiverobotics.engine.CorruptStateException;
import org.proactiverobotics.engine.robot.Strategy;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The engine process's loop: turns the {@link RobotServer} of every robot it may serve until
 * stopped, on a few threads, each thread owning a fixed share of the robots (robot k of the list
 * on thread k mod threads). A thread reads the clocks of all its robots in one query per pass,
 * turns each, and polls again about when the next step is due ({@link PollPacing}: a step costs
 * a few round trips, not sleeps), more slowly when no robot is stepping.
 */
public final class EngineLoop {

    /**
     * @param strategy name of the strategy written when the robot has none yet
     * @param fresh    discard the saved state at start instead of resuming it
     * @param periodMs the period of real-time iterations, ms
     * @param logEvery one INFO line every this many iterations
     * @param leaseMs  how long a robot's lease lasts without renewal, ms
     */
    public record Options(Strategy strategy, boolean fresh, long periodMs, long logEvery, long leaseMs) {
    }

    private static final Logger LOG = LoggerFactory.getLogger(EngineLoop.class);
    /** How often a thread of an engine serving several robots names those that have not started a run. */
    private static final long WAITING_EVERY_NANOS = TimeUnit.SECONDS.toNanos(30);

    private final DataSource dataSource;
    private final List<RobotServer> servers;
    private final int threads;
    private final BooleanSupplier stop;
    private final Heartbeat heartbeat;

    /**
     * @param dataSource the shared database (the robots' clocks are read from it)
     * @param servers    one per robot this engine may serve
     * @param threads    how many threads turn them (at most one per robot)
     * @param stop       true when the process should stop (checked between turns)
     * @param heartbeat  touched while the loop turns
     */
    public EngineLoop(DataSource dataSource, List<RobotServer> servers, int threads, BooleanSupplier stop,
                      Heartbeat heartbeat) {
        this.dataSource = dataSource;
        this.servers = List.copyOf(servers);
        this.threads = Math.max(1, Math.min(threads, servers.size()));
        this.stop = stop;
        this.heartbeat = heartbeat;
    }

    /**
     * Runs until stopped; every iteration is saved when it ends, every lease released at the end.
     *
     * @throws CorruptStateException when a robot's saved state cannot be read (start with --fresh to discard it)
     */
    public void run() {
        AtomicReference<RuntimeException> fatal = new AtomicReference<>();
        BooleanSupplier done = () -> stop.getAsBoolean() || fatal.get() != null;
        List<Thread> started = new ArrayList<>();
        for (int t = 1; t < threads; t++) {
            List<RobotServer> share = share(t);
            Thread thread = new Thread(() -> turnAll(share, done, null, fatal), "engine-" + t);
            thread.start();
            started.add(thread);
        }
        turnAll(share(0), done, heartbeat, fatal); // the first share on the calling thread
        for (Thread thread : started) {
            try {
                thread.join();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
        servers.forEach(RobotServer::stop);
        if (fatal.get() != null) {
            throw fatal.get();
        }
    }

    private List<RobotServer> share(int thread) {
        List<RobotServer> share = new ArrayList<>();
        for (int k = thread; k < servers.size(); k += threads) {
            share.add(servers.get(k));
        }
        return share;
    }

    private void turnAll(List<RobotServer> share, BooleanSupplier done, Heartbeat beat,
                         AtomicReference<RuntimeException> fatal) {
        int[] ids = share.stream().mapToInt(RobotServer::robotId).toArray();
        int idlePolls = 0;
        long idleSince = System.nanoTime();
        PollPacing pacing = new PollPacing(); // the robots' next steps come about as far apart as the last ones
        long nextWaitingNanos = System.nanoTime();
        Backoff backoff = new Backoff(100, 5_000, System::nanoTime);
        long failures = 0;
        while (!done.getAsBoolean()) {
            if (beat != null) {
                beat.beat();
            }
            Map<Integer, RobotTick> ticks;
            try {
                ticks = EngineClock.robots(dataSource, ids);
                if (failures > 0) {
                    LOG.info("engine: database back after {} failed attempt(s)", failures);
                    failures = 0;
                }
                backoff.succeeded();
            } catch (SQLException | RuntimeException e) {
                // the database is away for every robot of this thread: each resumes from its saved state afterwards
                share.forEach(RobotServer::databaseFailed);
                backoff.failed();
                if (++failures == 1) {
                    LOG.warn("engine: database failure ({}); retrying with back-off, then resuming from the saved state",
                            RobotServer.oneLine(e));
                }
                pause(TimeUnit.MILLISECONDS.toNanos(backoff.delayMs()), done);
                continue;
            }
            long now = System.nanoTime();
            if (servers.size() > 1 && now - nextWaitingNanos >= 0) { // one line for every robot of the share not started yet
                nextWaitingNanos = now + WAITING_EVERY_NANOS;
                String waiting = RobotIds.format(Arrays.stream(ids).filter(id -> !ticks.containsKey(id)).toArray());
                if (!waiting.isEmpty()) {
                    LOG.info("engine: waiting for the robot(s) {}: no run started yet", waiting);
                }
            }
            boolean worked = false;
            long wait = Long.MAX_VALUE;
            try {
                for (RobotServer s : share) {
                    worked |= s.turn(ticks.get(s.robotId()), now);
                    long w = s.realTimeWaitNanos();
                    if (w > 0) {
                        wait = Math.min(wait, w);
                    }
                }
            } catch (RuntimeException e) {
                fatal.compareAndSet(null, e); // a saved state that cannot be read: the command stops and says which
                return;
            }
            if (worked) {
                pacing.waited(now - idleSince);
                idlePolls = 0;
                idleSince = System.nanoTime();
                LockSupport.parkNanos(Math.min(wait, pacing.pauseNanos(0, 0))); // every robot ready was just served
            } else if (wait != Long.MAX_VALUE) { // real time: the next iteration is due at a known time
                LockSupport.parkNanos(Math.min(wait, 1_000_000));
            } else {
                LockSupport.parkNanos(pacing.pauseNanos(System.nanoTime() - idleSince, ++idlePolls));
            }
        }
    }

    private static void pause(long nanos, BooleanSupplier done) {
        long until = System.nanoTime() + nanos;
        while (System.nanoTime() - until < 0 && !done.getAsBoolean()) {
            LockSupport.parkNanos(TimeUnit.MILLISECONDS.toNanos(20));
        }
    }
}
