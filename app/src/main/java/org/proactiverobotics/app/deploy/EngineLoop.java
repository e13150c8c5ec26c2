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
import org.proactiverobotics.db.HandshakeLocks;
import org.proactiverobotics.db.PollPacing;
import org.proactiverobotics.engine.CorruptStateException;
import org.proactiverobotics.engine.robot.IterationBatch;
import org.proactiverobotics.engine.robot.RobotEngine;
import org.proactiverobotics.engine.robot.Strategy;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The engine process's loop: turns the {@link RobotServer} of every robot it may serve until
 * stopped, on a few threads, each thread owning a fixed share of the robots (robot k of the list
 * on thread k mod threads). A thread reads the clocks of all its robots in one query per pass,
 * turns each, and polls again about when the next step is due ({@link PollPacing}: a step costs
 * a few round trips, not sleeps), more slowly when no robot is stepping. A thread with one robot
 * in sync timing on MariaDB waits for its next step in the server instead ({@link HandshakeLocks}),
 * and polls only when that wait ends without the step. When several robots of a thread are due
 * in a pass, their engines' tables are read in one query before their iterations and the
 * iterations commit as one transaction after ({@link IterationBatch}).
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
    /** The longest wait in the server for a robot's step: the loop looks at its stop flag and heartbeat this often. */
    static final long LOCK_WAIT_NANOS = TimeUnit.MILLISECONDS.toNanos(200);

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
        // a thread of one robot can block on its locks; one of several robots polls them all at once
        HandshakeLocks locks = share.size() == 1 ? new HandshakeLocks(dataSource, share.get(0).robotId()) : null;
        try {
            turnAllLogged(share, done, beat, fatal, locks);
        } finally {
            if (locks != null) {
                if (locks.waits() > 0) {
                    LOG.info("engine {}: handshake: {} waits on the robot's locks in the database, {} of them timed out",
                            share.get(0).robotId(), locks.waits(), locks.count(HandshakeLocks.Wake.TIMED_OUT));
                }
                locks.close();
            }
        }
    }

    /** {@link #turnUntilDone}, then one line on the batches the share ran. */
    private void turnAllLogged(List<RobotServer> share, BooleanSupplier done, Heartbeat beat,
                               AtomicReference<RuntimeException> fatal, HandshakeLocks locks) {
        BatchTally tally = new BatchTally();
        try {
            turnUntilDone(share, done, beat, fatal, locks, tally);
        } finally {
            if (tally.batches > 0) {
                LOG.info("engine: robots {}: {} of their {} iterations run in {} batches (several robots due at once: their"
                        + " tables read in one query, their iterations committed as one; the others ran alone)",
                        RobotIds.format(share.stream().mapToInt(RobotServer::robotId).toArray()), tally.iterations, tally.all,
                        tally.batches);
            }
        }
    }

    private void turnUntilDone(List<RobotServer> share, BooleanSupplier done, Heartbeat beat,
                               AtomicReference<RuntimeException> fatal, HandshakeLocks locks, BatchTally tally) {
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
            boolean inServer = false;
            try {
                long awaited = locks == null ? -1 : share.get(0).awaitedStep();
                inServer = awaited >= 0 && locks.usable() && !locks.paused();
                if (inServer) { // "served step k" given (the iteration is committed), "sensed step k + 1" awaited
                    ticks = locks.exchange(HandshakeLocks.served(awaited - 1), HandshakeLocks.sensed(awaited), LOCK_WAIT_NANOS,
                            JdbcEngineClock.ROBOT_CLOCK, (ps, p) -> ps.setInt(p, ids[0]), JdbcEngineClock::ticks);
                    RobotTick tick = ticks.get(ids[0]);
                    locks.found(tick != null && tick.step() >= awaited);
                } else {
                    if (locks != null) {
                        locks.close(); // not waiting for the robot in the server: no lock or connection kept for it
                    }
                    ticks = JdbcEngineClock.robots(dataSource, ids);
                }
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
            Batch batch = share.size() > 1 ? batch(share, ticks, now) : null;
            try {
                for (RobotServer s : share) {
                    boolean iterated = s.turn(ticks.get(s.robotId()), now);
                    worked |= iterated;
                    tally.all += iterated ? 1 : 0;
                    long w = s.realTimeWaitNanos();
                    if (w > 0) {
                        wait = Math.min(wait, w);
                    }
                    if (batch != null && s == batch.last()) {
                        batch.commit(tally); // at once: the others' turns do not hold its locks
                    }
                }
            } catch (RuntimeException e) {
                fatal.compareAndSet(null, e); // a saved state that cannot be read: the command stops and says which
                return;
            } finally {
                if (batch != null) {
                    batch.iterations.close(); // rolls back what did not commit; a snapshot not taken up is never used later
                }
            }
            if (worked) {
                pacing.waited(now - idleSince);
                idlePolls = 0;
                idleSince = System.nanoTime();
                if (!(inServer && share.get(0).awaitedStep() >= 0)) { // the next step is waited for in the server
                    LockSupport.parkNanos(Math.min(wait, pacing.pauseNanos(0, 0))); // every robot ready was just served
                }
            } else if (inServer && locks.lastWake() == HandshakeLocks.Wake.TIMED_OUT) {
                idlePolls++; // the robot still holds the lock: wait in the server again
            } else if (wait != Long.MAX_VALUE) { // real time: the next iteration is due at a known time
                LockSupport.parkNanos(Math.min(wait, 1_000_000));
            } else {
                LockSupport.parkNanos(pacing.pauseNanos(System.nanoTime() - idleSince, ++idlePolls));
            }
        }
    }

    /** How many batches a thread ran, how many iterations were in them and in all, for its last log line. */
    private static final class BatchTally {
        long batches;
        long iterations;
        long all;
        /** Whether the last batch did not commit (its failure is said once, until one commits again). */
        boolean failing;
    }

    /** The iterations of a pass that run as one batch, and the robots they are for. */
    private record Batch(IterationBatch iterations, List<RobotServer> due) {

        /** @return the last robot of the share whose iteration is in the batch */
        RobotServer last() {
            return due.get(due.size() - 1);
        }

        /**
         * Commits the pass's iterations; those that did not commit (the commit failed, or an
         * iteration of the batch did) are taken up again from their saved state, alone.
         */
        void commit(BatchTally tally) {
            try {
                iterations.commit();
                tally.batches++;
                tally.iterations += due.size();
                tally.failing = false;
            } catch (SQLException | RuntimeException e) {
                List<RobotEngine> gone = iterations.rolledBack();
                List<RobotServer> rolledBack = due.stream().filter(s -> gone.contains(s.engine())).toList();
                rolledBack.forEach(s -> s.batchRolledBack(e));
                if (!tally.failing && !rolledBack.isEmpty()) { // none rolled back: the failed iteration said so itself
                    tally.failing = true;
                    LOG.warn("engine: robots {}: their iterations run as one batch did not commit ({}); each resumes from its"
                            + " saved state", RobotIds.format(rolledBack.stream().mapToInt(RobotServer::robotId).toArray()),
                            RobotServer.oneLine(e));
                }
            }
        }
    }

    /**
     * When several robots of the share have an iteration due in this pass, reads their tables in
     * one query and makes their iterations one transaction ({@link IterationBatch}).
     *
     * @return the batch, or null: each iteration reads and commits its own
     */
    private Batch batch(List<RobotServer> share, Map<Integer, RobotTick> ticks, long now) {
        List<RobotEngine> engines = new ArrayList<>(share.size());
        List<RobotServer> due = new ArrayList<>(share.size());
        for (RobotServer s : share) {
            RobotEngine engine = s.due(ticks.get(s.robotId()), now);
            if (engine != null) {
                engines.add(engine);
                due.add(s);
            }
        }
        if (engines.size() < 2) {
            return null; // one robot reads and commits its own, as it would have
        }
        try {
            IterationBatch iterations = IterationBatch.start(dataSource, engines);
            if (!iterations.batched()) {
                iterations.close();
                return null;
            }
            return new Batch(iterations, due);
        } catch (SQLException | RuntimeException e) {
            LOG.debug("engine: reading ahead failed ({}); each iteration reads its own", RobotServer.oneLine(e));
            return null;
        }
    }

    private static void pause(long nanos, BooleanSupplier done) {
        long until = System.nanoTime() + nanos;
        while (System.nanoTime() - until < 0 && !done.getAsBoolean()) {
            LockSupport.parkNanos(TimeUnit.MILLISECONDS.toNanos(20));
        }
    }
}
