package org.proactiverobotics.app.deploy;

import java.sql.SQLException;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import java.util.function.IntFunction;
import org.proactiverobotics.app.deploy.EngineClock.RobotTick;
import org.proactiverobotics.app.deploy.EngineClock.Served;
import org.proactiverobotics.db.Backoff;
import org.proactiverobotics.engine.CorruptStateException;
import org.proactiverobotics.engine.motion.DriveProfile;
import org.proactiverobotics.engine.robot.RobotEngine;
import org.proactiverobotics.engine.robot.Strategy;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * What an engine process does for one robot, one turn at a time ({@link EngineLoop} turns many):
 * holds the robot's lease, follows its clock, runs the engine's iterations for it.
 *
 * <ul>
 *   <li>The robot is served only while this engine holds its lease ({@link EngineLease}); the
 *       lease is tried every second until taken, renewed by every iteration and while idle,
 *       and an engine that lost it stops serving the robot at once.</li>
 *   <li>A new robot run (a new robot process) resets the engine's rows and starts the engine
 *       fresh; the run the engine already served (the engine restarted, or another engine
 *       served it before) resumes from the saved state. An iteration and its "served step k"
 *       commit together, so a kill never runs a step twice.</li>
 *   <li>Sync timing: exactly one iteration per robot step; "served step k" commits with it.</li>
 *   <li>Real-time timing: one iteration every period, at a fixed rate, while the run goes on.</li>
 *   <li>A database failure (or an iteration failing to save) is logged once and retried with
 *       back-off; the engine resumes from its saved state when the database is back.</li>
 * </ul>
 * Not thread-safe: one thread turns it.
 */
public final class RobotServer {

    private static final Logger LOG = LoggerFactory.getLogger(RobotServer.class);
    private static final long STATUS_EVERY_NANOS = TimeUnit.SECONDS.toNanos(30);
    private static final long TAKE_EVERY_NANOS = TimeUnit.SECONDS.toNanos(1);
    /** In a fleet, a robot whose run ended this long ago is dropped, seconds. */
    static final long DROP_AFTER_S = 60;

    /** Builds a robot's engine for a body: its drive profile, alone in its world or not. */
    @FunctionalInterface
    public interface Engines {
        /**
         * @param robotId the robot
         * @param body    the drive profile its engine assumes, and whether other robots share its world
         * @return the engine
         */
        RobotEngine build(int robotId, RobotBody body);
    }

    /** The body a robot's engine must assume as a run is taken up (its {@code robot_body} row, or a fallback). */
    @FunctionalInterface
    public interface Bodies {
        /**
         * @param robotId the robot
         * @return its body
         * @throws SQLException when it cannot be read
         */
        RobotBody body(int robotId) throws SQLException;
    }

    private final int robotId;
    private final Engines engines;
    /** Where the body comes from at each run taken up; null: the engine's first one throughout. */
    private final Bodies bodies;
    /** The body {@link #side} was built with. */
    private RobotBody sideBody;
    private final EngineClock clock;
    private final EngineLease lease;
    private final EngineLoop.Options options;
    private final long renewEveryNanos;
    /** A standby robot is taken only once it has been running a lease's time (its own engine had the chance to take it). */
    private final boolean standby;
    private final long leaseNanos;
    /** The robot's run and whether it ran, as last seen, and since when (System.nanoTime()): a standby's wait, a drop's. */
    private long seenRunId = -1;
    private boolean seenRunning;
    private boolean seenSync;
    private long seenSinceNanos;
    /** Whether the engine serves several robots (a corrupt saved state then sets this one aside). */
    private final boolean oneOfSeveral;
    private boolean setAside;
    private RobotEngine side;
    private long runId = -1;
    private long served;
    private boolean firstContact = true;
    /** Whether this engine said it keeps the strategy already in the table. */
    private boolean strategyKeptSaid;
    private boolean finishedLogged;
    private boolean waitingLogged;
    private long nextStatusNanos;
    private long nextTickNanos;
    private long nextTakeNanos;
    private long nextRenewNanos;
    private long iterationsSinceLog;
    private long iterationNanosSinceLog;
    private long failures;
    private final Backoff backoff = new Backoff(100, 5_000, System::nanoTime);
    /** In real-time timing, how long until the next iteration is due (0: not waiting for a tick). */
    private long realTimeWaitNanos;

    /**
     * @param robotId the robot
     * @param engines builds the robot's engine the first time this engine takes its lease
     * @param clock   the robot's handshake rows
     * @param lease   the robot's lease row, as this engine holds it
     * @param options how to run
     * @param standby whether the robot is another engine's to serve first: tried only once this
     *                engine has seen the robot's run running for a lease's time, and then taken only
     *                when no other engine holds it (its engine died, or never came)
     * @param oneOfSeveral whether the engine serves several robots: then a saved state that cannot
     *                be read sets this robot aside instead of stopping the engine (one robot: it says
     *                which row and stops), and the loop, not each robot, says which have not started
     */
    public RobotServer(int robotId, IntFunction<RobotEngine> engines, EngineClock clock, EngineLease lease,
                       EngineLoop.Options options, boolean standby, boolean oneOfSeveral) {
        this(robotId, (robot, body) -> engines.apply(robot), null, DriveProfile.DEFAULT, clock, lease, options, standby,
                oneOfSeveral);
    }

    /**
     * A server whose robot's engine drives with the robot's own profile: read as each run is taken
     * up, and the engine built anew when it differs from the one it was built with (a fleet's robots
     * may differ in size and speed; docs/deployment.md).
     *
     * @param robotId      the robot
     * @param engines      builds the robot's engine for a body
     * @param bodies       the robot's body as a run is taken up, or null: {@code drive}, alone in its world, throughout
     * @param drive        the profile the engine is first built with (before any run is seen)
     * @param clock        the robot's handshake rows
     * @param lease        the robot's lease row, as this engine holds it
     * @param options      how to run
     * @param standby      as in {@link #RobotServer(int, IntFunction, EngineClock, EngineLease, EngineLoop.Options, boolean, boolean)}
     * @param oneOfSeveral as there
     */
    public RobotServer(int robotId, Engines engines, Bodies bodies, DriveProfile drive, EngineClock clock,
                       EngineLease lease, EngineLoop.Options options, boolean standby, boolean oneOfSeveral) {
        this.robotId = robotId;
        this.engines = engines;
        this.bodies = bodies;
        this.sideBody = new RobotBody(drive, false);
        this.clock = clock;
        this.lease = lease;
        this.options = options;
        this.renewEveryNanos = TimeUnit.MILLISECONDS.toNanos(Math.max(1, options.leaseMs() / 3));
        this.standby = standby;
        this.oneOfSeveral = oneOfSeveral;
        this.leaseNanos = TimeUnit.MILLISECONDS.toNanos(options.leaseMs());
    }

    /** @return the robot */
    public int robotId() {
        return robotId;
    }

    /** @return whether this engine holds the robot's lease */
    public boolean serving() {
        return lease.held();
    }

    /**
     * @return the robot step this engine waits for, the one after the last it served, while it
     *         serves a running robot in sync timing; -1 otherwise (nothing to wait for in the server)
     */
    long awaitedStep() {
        return lease.held() && runId != -1 && !setAside && seenSync && seenRunning ? served + 1 : -1;
    }

    /**
     * @param seen the robot's clock as read for this turn (null: no run started)
     * @param now  System.nanoTime() of this turn
     * @return the robot's engine when this turn will run an iteration of the run it serves
     *         already (so that it can run in a batch with other robots'), else null; null too while
     *         its iterations fail (it runs alone until one succeeds, and never rolls back others)
     */
    RobotEngine due(RobotTick seen, long now) {
        if (seen == null || side == null || setAside || runId == -1 || seen.runId() != runId || !seen.running()
                || !lease.held() || !backoff.ready() || backoff.failing()) {
            return null;
        }
        return (seen.sync() ? seen.step() > served : now - nextTickNanos >= 0) ? side : null;
    }

    /** @return the robot's engine, or null before this engine first took the robot's lease */
    RobotEngine engine() {
        return side;
    }

    /** @return how long until a real-time iteration is due, ns (0: none is waited for) */
    long realTimeWaitNanos() {
        long w = realTimeWaitNanos;
        realTimeWaitNanos = 0;
        return w;
    }

    /**
     * One look at the robot and at most one iteration for it; never throws for a database
     * failure (that is logged and retried later).
     *
     * @param seen the robot's clock as read for this turn (null: the robot never started a run)
     * @param now  System.nanoTime() of this turn
     * @return whether an iteration ran
     * @throws CorruptStateException when the saved state cannot be read (start with --fresh)
     */
    public boolean turn(RobotTick seen, long now) {
        if (!backoff.ready()) {
            return false;
        }
        try {
            boolean worked = serve(seen, now);
            if (backoff.failing()) {
                LOG.info("engine {}: database back after {} failed attempt(s)", robotId, failures);
                failures = 0;
            }
            backoff.succeeded();
            return worked;
        } catch (CorruptStateException e) {
            if (!oneOfSeveral) {
                throw e; // never a silent fresh start: the command says which row and stops
            }
            setAside = true;
            runId = -1;
            LOG.error("engine {}: the saved engine state of robot {} cannot be read ({}); robot {} is set aside, the"
                    + " others are served (start an engine for it alone with --fresh to discard that state)",
                    robotId, robotId, oneLine(e), robotId);
            return false;
        } catch (SQLException | RuntimeException e) {
            failed(e);
            return false;
        }
    }

    private boolean serve(RobotTick robot, long now) throws SQLException {
        if (robot == null) {
            if (!oneOfSeveral && now - nextStatusNanos >= 0) { // an engine of several robots says it for all at once (EngineLoop)
                nextStatusNanos = now + STATUS_EVERY_NANOS;
                LOG.info("engine {}: waiting for the robot (robot {} has not started a run)", robotId, robotId);
            }
            renewWhileIdle(now);
            return false;
        }
        seenSync = robot.sync();
        if (robot.runId() != seenRunId || robot.running() != seenRunning) {
            seenRunId = robot.runId();
            seenRunning = robot.running();
            seenSinceNanos = now;
        }
        if (setAside) {
            renewWhileIdle(now); // held, so that no other engine takes the robot and stops on the same state
            return false;
        }
        if (!lease.held()) {
            if (now - nextTakeNanos < 0 || standby && (!robot.running() || now - seenSinceNanos < leaseNanos)
                    || oneOfSeveral && !robot.running()) { // in a fleet, a robot is taken up when it runs
                return false;
            }
            nextTakeNanos = now + TAKE_EVERY_NANOS;
            if (side == null) {
                side = engines.build(robotId, sideBody); // built before the lease is taken: a failure here leaves nothing half done
            }
            if (!lease.tryTake()) {
                if (!waitingLogged) {
                    waitingLogged = true;
                    LOG.info("engine {}: robot {} is served by another engine; taking over if its lease expires",
                            robotId, robotId);
                }
                return false;
            }
            waitingLogged = false;
            LOG.info("engine {}: lease of robot {} taken (epoch {})", robotId, robotId, lease.epoch());
            runId = -1; // adopt the run anew: whatever another engine saved in between is the truth
            nextRenewNanos = now + renewEveryNanos;
        }
        if (robot.runId() != runId) {
            if (!lease.renew()) { // adopting writes outside an iteration: only while the lease is surely this engine's
                lost();
                return false;
            }
            nextRenewNanos = now + renewEveryNanos;
            adopt(robot);
        }
        if (!robot.running()) {
            if (oneOfSeveral && dropIfLongEnded(robot, now)) {
                return false;
            }
            if (!finishedLogged) {
                finishedLogged = true;
                LOG.info("engine {}: robot run {} {} at step {} ({} s simulated); nothing to serve until a new run",
                        robotId, runId, robot.stateLabel(), robot.step(), secs(robot.simTimeMs()));
            }
            renewWhileIdle(now);
            return false;
        }
        if (robot.sync()) {
            if (robot.step() <= served) {
                renewWhileIdle(now);
                return false;
            }
        } else {
            if (now - nextTickNanos < 0) {
                realTimeWaitNanos = nextTickNanos - now;
                renewWhileIdle(now);
                return false;
            }
            long period = TimeUnit.MILLISECONDS.toNanos(options.periodMs());
            nextTickNanos = now - nextTickNanos > 10 * period ? now + period : nextTickNanos + period; // fixed rate, no long burst after a pause
        }
        long t0 = System.nanoTime();
        long step = Math.max(served, robot.step());
        long run = runId;
        // the lease is confirmed, and "served step k" published, in the iteration's own transaction
        side.iterate((writes, n) -> clock.publish(writes, run, step, n));
        nextRenewNanos = t0 + renewEveryNanos;
        long iteration = side.engine().iteration();
        served = step;
        iterationNanosSinceLog += System.nanoTime() - t0;
        if (++iterationsSinceLog >= options.logEvery()) {
            LOG.info("engine {}: iteration {} for robot step {} ({} s simulated, {} timing), {} ms per iteration",
                    robotId, iteration, robot.step(), secs(robot.simTimeMs()), robot.timingLabel(),
                    String.format(Locale.ROOT, "%.2f", iterationNanosSinceLog / 1e6 / iterationsSinceLog));
            iterationsSinceLog = 0;
            iterationNanosSinceLog = 0;
        }
        return true;
    }

    /**
     * In a fleet, a robot whose run ended {@value #DROP_AFTER_S} s ago is dropped: its engine's
     * memory is freed and its lease released, and it is taken up again (by whichever engine comes
     * first) when a new run starts.
     *
     * @return whether it was dropped now
     */
    private boolean dropIfLongEnded(RobotTick robot, long now) throws SQLException {
        if (side == null || now - seenSinceNanos < TimeUnit.SECONDS.toNanos(DROP_AFTER_S)) {
            return false;
        }
        LOG.info("engine {}: robot run {} ended {} s ago; robot {} dropped (state saved, lease released;"
                + " taken up again when a new run starts)", robotId, robot.runId(), DROP_AFTER_S, robotId);
        lease.release();
        side = null;
        runId = -1;
        return true;
    }

    private void renewWhileIdle(long now) throws SQLException {
        if (lease.held() && now - nextRenewNanos >= 0) {
            nextRenewNanos = now + renewEveryNanos;
            if (!lease.renew()) {
                lost();
            }
        }
    }

    private void lost() {
        LOG.warn("engine {}: robot {} lost to another engine (its lease was taken); no longer serving it", robotId, robotId);
        runId = -1;
    }

    /** Takes up the robot's run: resumes it when it was served before, else starts it fresh. */
    private void adopt(RobotTick robot) throws SQLException {
        fitBody();
        java.util.Optional<Served> last = clock.served();
        boolean sameRun = last.isPresent() && last.get().runId() == robot.runId();
        if (sameRun && (!firstContact || !options.fresh())) {
            // with no saved state, numbering goes on: the robot ignores commands of iterations before its run's last one
            boolean resumed = side.resume(last.get().iteration());
            long iteration = side.engine().iteration();
            // Saved but not published (rows an older engine left: it published after its commit) served the next step.
            served = last.get().step() + Math.max(0, iteration - last.get().iteration());
            if (iteration != last.get().iteration()) {
                clock.publish(robot.runId(), served, iteration, lease);
            }
            LOG.info("engine {}: {} robot run {} at step {} (iteration {})", robotId,
                    resumed ? "resuming" : "no saved state; starting afresh in", robot.runId(), served, iteration);
        } else if (sameRun) {
            side.startFresh(last.get().iteration());
            served = last.get().step();
            clock.publish(robot.runId(), served, side.engine().iteration(), lease);
            LOG.info("engine {}: --fresh: saved state discarded; serving robot run {} from step {}", robotId,
                    robot.runId(), served + 1);
        } else {
            clock.resetForNewRun();
            side.startFresh();
            served = 0;
            clock.publish(robot.runId(), 0, 0, lease);
            LOG.info("engine {}: new robot run {} ({} timing): commands and requests of earlier runs cleared, "
                    + "checkpoints not reached, engine started fresh", robotId, robot.runId(), robot.timingLabel());
        }
        // among other robots, Yield right below the collision monitor, as run ranks it
        Strategy strategy = sideBody.sharedWorld() ? options.strategy().forSharedWorld() : options.strategy();
        if (side.ensureStrategy(strategy)) { // a strategy set with the strategy command survives restarts
            LOG.info("engine {}: strategy {} written", robotId, options.strategy().name());
        } else if (!strategyKeptSaid) { // once: an engine adopts the robot's old run, then its new one
            strategyKeptSaid = true;
            LOG.info("engine {}: the strategy already in the table is kept; {} is written only for a robot that has none"
                    + " (the strategy command changes it)", robotId, options.strategy().name());
        }
        runId = robot.runId();
        firstContact = false;
        finishedLogged = false;
        nextTickNanos = System.nanoTime();
    }

    /**
     * The robot's process wrote its body before it began the run: an engine built for another
     * body is built anew (before its state is resumed or started, so nothing of it is lost).
     */
    private void fitBody() throws SQLException {
        if (bodies == null) {
            return;
        }
        RobotBody body = bodies.body(robotId);
        if (!body.equals(sideBody)) {
            side = engines.build(robotId, body);
            sideBody = body;
            LOG.info("engine {}: robot {} drives at up to {} m/s with {} m between its wheels{}", robotId, robotId,
                    String.format(Locale.ROOT, "%.2f", body.drive().maxSpeedMps()),
                    String.format(Locale.ROOT, "%.3f", body.drive().axleWidthM()), body.sharedWorld() ? ", among other robots" : "");
        }
    }

    private void failed(Exception e) {
        boolean wasServing = runId != -1;
        runId = -1; // resume from what was saved once the database answers again
        firstContact = false;
        if (e instanceof EngineLease.LostException || (e.getCause() instanceof EngineLease.LostException)) {
            lease.forget();
            if (wasServing) {
                lost();
            }
            return;
        }
        failures++;
        backoff.failed();
        if (failures == 1) {
            LOG.warn("engine {}: database failure ({}); retrying with back-off, then resuming from the saved state",
                    robotId, oneLine(e));
        } else {
            LOG.debug("engine {}: still failing ({})", robotId, oneLine(e));
        }
        // the lease is kept: the next iteration's confirmation tells whether another engine took it meanwhile
    }

    /**
     * The iteration this robot ran in a batch did not commit (the batch's commit failed, or
     * another iteration of it did): as a failed iteration, it is taken up again from the saved
     * state after a back-off, alone.
     *
     * @param e why the batch did not commit
     */
    void batchRolledBack(Exception e) {
        failed(e);
    }

    /** The database failed before this robot's turn: its run is taken up again from the saved state. */
    void databaseFailed() {
        runId = -1;
        firstContact = false;
    }

    /** Gives the robot up at a clean stop: its state is saved, its lease released for another engine. */
    public void stop() {
        if (side != null && lease.held()) {
            LOG.info("engine {}: stopped after iteration {} (state saved)", robotId, side.engine().iteration());
        }
        try {
            lease.release();
        } catch (SQLException | RuntimeException e) {
            LOG.debug("engine {}: releasing the lease failed ({}); it expires by itself", robotId, oneLine(e));
        }
    }

    private static String secs(long ms) {
        return String.format(Locale.ROOT, "%.1f", ms / 1000.0);
    }

    static String oneLine(Throwable e) {
        String m = e.getMessage() == null ? e.toString() : e.getMessage();
        Throwable cause = e.getCause();
        if (cause != null && cause.getMessage() != null && !m.contains(cause.getMessage())) {
            m = m + ": " + cause.getMessage();
        }
        int nl = m.indexOf('\n');
        return nl < 0 ? m : m.substring(0, nl);
    }
}
