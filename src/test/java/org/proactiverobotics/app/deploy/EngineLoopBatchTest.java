package org.proactiverobotics.app.deploy;

import static org.assertj.core.api.Assertions.assertThat;

import ch.qos.logback.classic.Level;
import ch.qos.logback.classic.Logger;
import ch.qos.logback.classic.spi.ILoggingEvent;
import ch.qos.logback.core.read.ListAppender;
import com.zaxxer.hikari.HikariDataSource;
import java.sql.Connection;
import java.sql.ResultSet;
import java.sql.Statement;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import org.junit.jupiter.api.Test;
import org.proactiverobotics.db.DatabaseKind;
import org.proactiverobotics.db.Databases;
import org.proactiverobotics.db.Schema;
import org.proactiverobotics.db.TestDatabase;
import org.proactiverobotics.db.TestDatabases;
import org.proactiverobotics.engine.robot.RobotEngine;
import org.proactiverobotics.engine.robot.Strategy;
import org.proactiverobotics.protocol.RunState;
import org.proactiverobotics.protocol.Timing;
import org.slf4j.LoggerFactory;

/**
 * An engine thread serving two robots on MariaDB runs their due iterations as one batch; when the
 * batch does not commit (here: the second robot's lease taken by another engine, so its iteration
 * fails its lease check after the first's ran), the first robot's iteration rolls back with it and
 * is run again from the saved state, once: no step served twice, none lost. The robots are their
 * robot_clock rows, stepped together by SQL.
 */
class EngineLoopBatchTest {

    private static final long RUN = 77;

    @Test
    void aBatchThatDoesNotCommitIsRunAgainFromTheSavedStateOnceByEachOfItsRobots() throws Exception {
        Logger log = (Logger) LoggerFactory.getLogger(EngineLoop.class);
        ListAppender<ILoggingEvent> seen = new ListAppender<>();
        seen.start();
        log.addAppender(seen);
        Level level = log.getLevel();
        log.setLevel(Level.INFO);
        try (TestDatabase db = TestDatabases.open(DatabaseKind.MARIADB);
             HikariDataSource pool = Databases.multiStatementPool(db.jdbcUrl(), db.user(), db.password())) {
            Schema.apply(pool);
            db.execute("INSERT INTO robot_clock (robot_id, run_id, step, sim_time_ms, timing, state) VALUES (9, " + RUN + ", 0, 0, '"
                    + Timing.SYNC.label() + "', '" + RunState.RUNNING.name() + "'), (10, " + RUN + ", 0, 0, '"
                    + Timing.SYNC.label() + "', '" + RunState.RUNNING.name() + "')");
            EngineLoop.Options options = new EngineLoop.Options(Strategy.named("safety-first"), false, 32, 1_000, 60_000);
            List<RobotServer> servers = List.of(server(pool, 9, options), server(pool, 10, options));
            AtomicBoolean stop = new AtomicBoolean();
            Thread loop = new Thread(() -> new EngineLoop(pool, servers, 1, stop::get, new Heartbeat(null)).run(), "engine-loop-test");
            loop.start();
            try {
                for (int k = 1; k <= 8; k++) {
                    if (k == 5) { // another engine takes robot 10 and lets its lease lapse at once
                        db.execute("UPDATE engine_lease SET owner = 'thief', epoch = epoch + 1, expires_at = CURRENT_TIMESTAMP(3)"
                                + " WHERE robot_id = 10");
                    }
                    // both robots sense step k in one statement: the engine's next pass finds both due
                    db.execute("UPDATE robot_clock SET step = " + k + ", sim_time_ms = " + 32 * k + " WHERE robot_id IN (9, 10)");
                    awaitServed(pool, k);
                }
            } finally {
                stop.set(true);
                loop.join(TimeUnit.SECONDS.toMillis(30));
            }
            assertThat(loop.isAlive()).isFalse();
            for (int robot : new int[] {9, 10}) {
                assertThat(value(pool, "SELECT iteration FROM engine_state WHERE robot_id = " + robot)).as("robot %d", robot).isEqualTo(8);
                assertThat(value(pool, "SELECT COUNT(DISTINCT iteration) FROM engine_comments WHERE robot_id = " + robot))
                        .as("robot %d: each iteration's command once", robot)
                        .isEqualTo(value(pool, "SELECT COUNT(*) FROM engine_comments WHERE robot_id = " + robot));
            }
            List<String> lines = seen.list.stream().map(ILoggingEvent::getFormattedMessage).toList();
            assertThat(lines).anyMatch(l -> l.contains("robots 9: their iterations run as one batch did not commit"));
            assertThat(lines).anyMatch(l -> l.matches("engine: robots 9-10: \\d+ of their \\d+ iterations run in [1-9]\\d* batches.*"));
        } finally {
            log.detachAppender(seen);
            log.setLevel(level);
        }
    }

    private static RobotServer server(HikariDataSource pool, int robot, EngineLoop.Options options) {
        EngineLease lease = new EngineLease(pool, robot, "engine-test", options.leaseMs());
        return new RobotServer(robot, id -> RobotEngine.builder().robotId(id).database(pool).guard(lease::confirm).build(),
                new JdbcEngineClock(pool, robot), lease, options, false, true);
    }

    private static void awaitServed(HikariDataSource pool, long step) throws Exception {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
        while (value(pool, "SELECT COALESCE(MIN(step), -1) FROM engine_clock WHERE robot_id IN (9, 10) AND run_id = " + RUN) < step
                || value(pool, "SELECT COUNT(*) FROM engine_clock WHERE robot_id IN (9, 10)") < 2) {
            assertThat(System.nanoTime() < deadline).as("both robots served step %d", step).isTrue();
            Thread.sleep(5);
        }
        assertThat(value(pool, "SELECT MAX(step) FROM engine_clock WHERE robot_id IN (9, 10)")).as("never ahead").isEqualTo(step);
    }

    private static long value(HikariDataSource pool, String sql) throws Exception {
        try (Connection c = pool.getConnection(); Statement s = c.createStatement(); ResultSet rs = s.executeQuery(sql)) {
            assertThat(rs.next()).isTrue();
            return rs.getLong(1);
        }
    }
}
