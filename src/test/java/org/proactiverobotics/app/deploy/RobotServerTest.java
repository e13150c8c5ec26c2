package org.proactiverobotics.app.deploy;

import org.proactiverobotics.protocol.RunState;
import org.proactiverobotics.protocol.Timing;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.sql.Connection;
import java.sql.Statement;
import javax.sql.DataSource;
import org.junit.jupiter.api.Test;
import org.proactiverobotics.db.DatabaseKind;
import org.proactiverobotics.db.Schema;
import org.proactiverobotics.db.TestDatabase;
import org.proactiverobotics.db.TestDatabases;
import org.proactiverobotics.engine.CorruptStateException;
import org.proactiverobotics.engine.robot.RobotEngine;
import org.proactiverobotics.engine.robot.Strategy;

/** One robot's turn in an engine process: what a saved state that cannot be read does, with one robot and with several. */
class RobotServerTest {

    private static final long RUN = 42;

    private static RobotServer server(DataSource ds, int robot, boolean setAsideOnCorrupt) {
        return server(ds, robot, setAsideOnCorrupt, false);
    }

    private static RobotServer server(DataSource ds, int robot, boolean setAsideOnCorrupt, boolean fresh) {
        EngineLease lease = new EngineLease(ds, robot, "engine-test", 5_000);
        EngineLoop.Options options = new EngineLoop.Options(Strategy.named("safety-first"), fresh, 32, 500, 5_000);
        return new RobotServer(robot, id -> RobotEngine.builder().robotId(id).database(ds).guard(lease::confirm).build(),
                new JdbcEngineClock(ds, robot), lease, options, false, setAsideOnCorrupt);
    }

    @Test
    void aStateThatCannotBeReadStopsAOneRobotEngineButOnlySetsThatRobotAsideInAFleet() throws Exception {
        try (TestDatabase db = TestDatabases.open(DatabaseKind.H2)) {
            DataSource ds = db.dataSource();
            Schema.apply(ds);
            try (Connection c = ds.getConnection(); Statement s = c.createStatement()) {
                for (int robot : new int[] {1, 2}) {
                    // the run this engine served before, and a saved state that is not JSON
                    s.executeUpdate("INSERT INTO engine_clock (robot_id, run_id, step, iteration) VALUES (" + robot + ", " + RUN + ", 10, 10)");
                    s.executeUpdate("INSERT INTO engine_state (robot_id, iteration, memory_json) VALUES (" + robot + ", 10, 'not json')");
                }
            }
            EngineClock.RobotTick running = new EngineClock.RobotTick(RUN, 11, 352, Timing.SYNC, RunState.RUNNING);

            RobotServer alone = server(ds, 1, false);
            assertThatThrownBy(() -> alone.turn(running, System.nanoTime())).isInstanceOf(CorruptStateException.class)
                    .hasMessageContaining("robot_id=1");

            RobotServer inFleet = server(ds, 2, true);
            assertThat(inFleet.turn(running, System.nanoTime())).isFalse();
            assertThat(inFleet.turn(running, System.nanoTime())).as("set aside, not retried into the same failure").isFalse();
            assertThat(inFleet.serving()).as("its lease is kept: no other engine takes it and stops on the same row").isTrue();
        }
    }

    @Test
    void inAFleetARobotIsTakenUpWhenItRunsAndDroppedAMinuteAfterItsRunEnded() throws Exception {
        try (TestDatabase db = TestDatabases.open(DatabaseKind.H2)) {
            DataSource ds = db.dataSource();
            Schema.apply(ds);
            RobotServer server = server(ds, 3, true);
            long t = System.nanoTime();
            assertThat(server.turn(new EngineClock.RobotTick(7, 5, 160, Timing.SYNC, RunState.FINISHED), t)).isFalse();
            assertThat(server.serving()).as("an ended run is nobody's to take up").isFalse();

            assertThat(server.turn(new EngineClock.RobotTick(8, 1, 32, Timing.SYNC, RunState.RUNNING), t)).as("one iteration").isTrue();
            assertThat(server.serving()).isTrue();
            EngineClock.RobotTick ended = new EngineClock.RobotTick(8, 1, 32, Timing.SYNC, RunState.FINISHED);
            assertThat(server.turn(ended, t + 1)).isFalse();
            assertThat(server.turn(ended, t + java.util.concurrent.TimeUnit.SECONDS.toNanos(30))).isFalse();
            assertThat(server.serving()).as("kept for a while after its run").isTrue();
            assertThat(server.turn(ended, t + java.util.concurrent.TimeUnit.SECONDS.toNanos(RobotServer.DROP_AFTER_S + 1))).isFalse();
            assertThat(server.serving()).as("dropped, its lease released").isFalse();
            try (Connection c = ds.getConnection(); Statement s = c.createStatement();
                 java.sql.ResultSet rs = s.executeQuery("SELECT expires_at < CURRENT_TIMESTAMP(3), iteration FROM engine_lease WHERE robot_id = 3")) {
                assertThat(rs.next()).isTrue();
                assertThat(rs.getBoolean(1)).isTrue();
                assertThat(rs.getLong(2)).isEqualTo(1);
            }
        }
    }

    /**
     * An engine that starts fresh in the middle of a run (--fresh, or no saved state) numbers its
     * iterations on from the run's last one: the robot ignores a command of an earlier iteration
     * than one it ran, so going back to 1 would leave it stopped.
     */
    @Test
    void aFreshStartInTheMiddleOfARunNumbersItsIterationsOnFromTheRunsLastOne() throws Exception {
        try (TestDatabase db = TestDatabases.open(DatabaseKind.H2)) {
            DataSource ds = db.dataSource();
            Schema.apply(ds);
            try (Connection c = ds.getConnection(); Statement s = c.createStatement()) {
                for (int robot : new int[] {4, 5}) {
                    s.executeUpdate("INSERT INTO engine_clock (robot_id, run_id, step, iteration) VALUES (" + robot + ", " + RUN + ", 10, 10)");
                    s.executeUpdate("INSERT INTO engine_comments (robot_id, iteration, sim_time_ms, scenario, command) VALUES ("
                            + robot + ", 10, 320, 'ReachDestination', 'FORWARD 0.3')");
                }
                // robot 4: a saved state to discard (--fresh); robot 5: none saved
                s.executeUpdate("INSERT INTO engine_state (robot_id, iteration, memory_json) VALUES (4, 10, 'not json')");
            }
            EngineClock.RobotTick running = new EngineClock.RobotTick(RUN, 11, 352, Timing.SYNC, RunState.RUNNING);
            assertThat(server(ds, 4, false, true).turn(running, System.nanoTime())).isTrue();
            assertThat(server(ds, 5, false, false).turn(running, System.nanoTime())).isTrue();
            try (Connection c = ds.getConnection(); Statement s = c.createStatement();
                 java.sql.ResultSet rs = s.executeQuery("SELECT e.robot_id, e.iteration, k.iteration FROM engine_state e"
                         + " JOIN engine_clock k ON k.robot_id = e.robot_id ORDER BY e.robot_id")) {
                for (int robot : new int[] {4, 5}) {
                    assertThat(rs.next()).isTrue();
                    assertThat(rs.getInt(1)).isEqualTo(robot);
                    assertThat(rs.getLong(2)).as("robot %d's saved iteration", robot).isEqualTo(11);
                    assertThat(rs.getLong(3)).as("robot %d's published iteration", robot).isEqualTo(11);
                }
            }
        }
    }
}
