package org.proactiverobotics.robot;

import org.proactiverobotics.protocol.RunState;
import org.proactiverobotics.protocol.Timing;
import static org.assertj.core.api.Assertions.assertThat;

import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.proactiverobotics.db.DatabaseKind;
import org.proactiverobotics.db.TestDatabase;
import org.proactiverobotics.db.TestDatabases;
import org.proactiverobotics.robot.link.JdbcRobotClock;
import org.proactiverobotics.robot.link.JdbcRobotLink;
import org.proactiverobotics.robot.link.RetentionPolicy;
import org.proactiverobotics.sim2d.Simulation;

/** The robot's side of the lockstep handshake, with a scripted engine writing engine_clock. */
class LockstepTest {

    private static ProactiveController controller(TestDatabase db) {
        RobotConfig config = RobotConfig.defaults(1).withRealTimeFactor(0).withRetention(RetentionPolicy.KEEP_ALL);
        return new ProactiveController(new Simulation(TestWorlds.arena()), new JdbcRobotLink(db.dataSource()), config);
    }

    private static long robotStep(FakeEngine engine) throws Exception {
        return engine.longValue("SELECT COALESCE(MAX(step), -1) FROM robot_clock WHERE robot_id = 1");
    }

    private static long runId(FakeEngine engine) throws Exception {
        return engine.longValue("SELECT run_id FROM robot_clock WHERE robot_id = 1");
    }

    private static void serve(FakeEngine engine, long run, long step) throws Exception {
        engine.execute("DELETE FROM engine_clock WHERE robot_id = 1");
        engine.execute("INSERT INTO engine_clock (robot_id, run_id, step, iteration) VALUES (1, " + run + ", " + step + ", " + step + ")");
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void aNewRunClearsOnlyThisRobotsReadingsAndGetsALargerId(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind)) {
            FakeEngine engine = new FakeEngine(db.dataSource(), 1);
            db.execute("INSERT INTO gps_stored_values (robot_id, sim_time_ms, x_m, y_m) VALUES (1, 0, 1, 1), (2, 0, 2, 2)");
            db.execute("INSERT INTO battery_level (robot_id, sim_time_ms, level_pct, charging) VALUES (1, 0, 50, FALSE)");
            JdbcRobotClock clock = new JdbcRobotClock(db.dataSource());
            long first = clock.beginRun(1, Timing.SYNC);
            long second = clock.beginRun(1, Timing.SYNC);
            assertThat(second).isGreaterThan(first);
            assertThat(db.count("gps_stored_values")).isEqualTo(1); // robot 2's stays
            assertThat(db.count("battery_level")).isZero();
            assertThat(engine.rows("SELECT step, timing, state FROM robot_clock WHERE robot_id = 1").get(0))
                    .containsExactly(0L, "sync", "RUNNING");
            assertThat(clock.engineTick(1)).isEmpty();
            serve(engine, second, 7);
            assertThat(clock.engineTick(1)).contains(new org.proactiverobotics.robot.link.RobotClock.EngineTick(second, 7, 7));
        }
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void inSyncTimingTheRobotActsOnlyOnStepsTheEngineServed(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind); ProactiveController robot = controller(db)) {
            FakeEngine engine = new FakeEngine(db.dataSource(), 1);
            Lockstep lockstep = new Lockstep(new JdbcRobotClock(db.dataSource()), 1, Timing.SYNC, robot::stopRequested);
            AtomicBoolean engineUp = new AtomicBoolean(true);
            AtomicLong lastServed = new AtomicLong(-1);
            // the scripted engine: acknowledges the run, then serves steps 1..5 and no more
            CompletableFuture<Void> engineThread = CompletableFuture.runAsync(() -> {
                try {
                    while (engineUp.get()) {
                        long step = robotStep(engine);
                        if (step >= 0 && step <= 5 && step > lastServed.get()) {
                            serve(engine, runId(engine), step);
                            lastServed.set(step);
                        }
                        Thread.sleep(1);
                    }
                } catch (Exception e) {
                    throw new IllegalStateException(e);
                }
            });
            assertThat(lockstep.begin()).isTrue();
            CompletableFuture<Long> loop = CompletableFuture.supplyAsync(() -> robot.run(lockstep));
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
            while (robotStep(engine) < 6 && System.nanoTime() < deadline) {
                Thread.sleep(5);
            }
            Thread.sleep(200); // the robot must still be waiting for step 6
            assertThat(robotStep(engine)).isEqualTo(6);
            assertThat(robot.stats().controlSteps()).isEqualTo(5);
            assertThat(robot.simTimeMs()).isEqualTo(5L * TestWorlds.arena().timeStepMs());
            robot.requestStop();
            assertThat(loop.get(10, TimeUnit.SECONDS)).isEqualTo(5L * TestWorlds.arena().timeStepMs());
            assertThat(robot.loopTimes().steps()).isEqualTo(5);
            engineUp.set(false);
            engineThread.get(10, TimeUnit.SECONDS);
            lockstep.finish(RunState.STOPPED);
            assertThat(engine.rows("SELECT step, state FROM robot_clock WHERE robot_id = 1").get(0)).containsExactly(6L, "STOPPED");
            assertThat(lockstep.lastTick()).hasValueSatisfying(t -> assertThat(t.step()).isEqualTo(5));
        }
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void aStopEndsTheWaitForAnEngineThatNeverComes(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind)) {
            AtomicBoolean stop = new AtomicBoolean();
            Lockstep lockstep = new Lockstep(new JdbcRobotClock(db.dataSource()), 1, Timing.SYNC, stop::get);
            CompletableFuture<Boolean> begun = CompletableFuture.supplyAsync(lockstep::begin);
            Thread.sleep(300);
            assertThat(begun).isNotDone();
            stop.set(true);
            assertThat(begun.get(5, TimeUnit.SECONDS)).isFalse();
        }
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void inRealTimeTimingTheRobotOnlyPublishesItsSteps(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind)) {
            FakeEngine engine = new FakeEngine(db.dataSource(), 1);
            JdbcRobotClock clock = new JdbcRobotClock(db.dataSource());
            Lockstep lockstep = new Lockstep(clock, 1, Timing.REALTIME, () -> false);
            CompletableFuture<Boolean> begun = CompletableFuture.supplyAsync(lockstep::begin);
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
            while (engine.count("robot_clock") == 0 && System.nanoTime() < deadline) {
                Thread.sleep(5);
            }
            serve(engine, runId(engine), 0);
            assertThat(begun.get(10, TimeUnit.SECONDS)).isTrue();
            assertThat(lockstep.sensed(1, 0)).isTrue();
            assertThat(lockstep.sensed(2, 32)).isTrue(); // the engine never served step 1: no wait
            assertThat(engine.rows("SELECT step, sim_time_ms, timing FROM robot_clock WHERE robot_id = 1").get(0))
                    .containsExactly(2L, 32L, "realtime");
        }
    }
}
