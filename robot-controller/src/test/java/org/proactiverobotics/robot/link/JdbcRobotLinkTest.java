package org.proactiverobotics.robot.link;

import org.proactiverobotics.protocol.RunState;
import org.proactiverobotics.protocol.Timing;
import static org.assertj.core.api.Assertions.assertThat;

import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.proactiverobotics.db.DatabaseKind;
import org.proactiverobotics.db.RecordingDataSource;
import org.proactiverobotics.db.TestDatabase;
import org.proactiverobotics.db.TestDatabases;

class JdbcRobotLinkTest {

    private static final MissionSpec MISSION = new MissionSpec(
            List.of(new MissionSpec.Checkpoint(0, 3, 0.25), new MissionSpec.Checkpoint(3, -1, 0.25)),
            new MissionSpec.Station(-3, 0, 0.35), 90.0);

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void answersPendingRequestsOfItsOwnRobotAtomically(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind); RobotLink link = new JdbcRobotLink(db.dataSource())) {
            db.execute("INSERT INTO sensor_requests (robot_id, sensor, iteration) VALUES (1, 'GPS', 1)");
            db.execute("INSERT INTO sensor_requests (robot_id, sensor, iteration) VALUES (2, 'GPS', 1)");
            db.execute("INSERT INTO sensor_requests (robot_id, sensor, iteration) VALUES (1, 'DS', 1)");
            db.execute("INSERT INTO sensor_requests (robot_id, sensor, iteration, answered_sim_time_ms) VALUES (1, 'IU', 1, 0)");

            List<SensorRequest> pending = link.pendingRequests(1);
            assertThat(pending).extracting(SensorRequest::sensor).containsExactly("GPS", "DS");

            List<DistanceReading> ds = new ArrayList<>();
            for (int i = 0; i < 8; i++) {
                ds.add(new DistanceReading(i, i * 0.1, 0.5 + i, 1.0));
            }
            link.answer(1, new SensorAnswer(64, new GpsReading(1.5, -2.5), null, ds, null,
                    pending.stream().mapToLong(SensorRequest::id).toArray()));

            assertThat(link.pendingRequests(1)).isEmpty();
            assertThat(link.pendingRequests(2)).hasSize(1);
            assertThat(db.count("gps_stored_values")).isEqualTo(1);
            assertThat(db.count("distance_sensor_data")).isEqualTo(8);
            assertThat(db.count("iudata")).isZero();
            assertThat(one(db, "SELECT x_m, y_m, sim_time_ms FROM gps_stored_values WHERE robot_id = 1"))
                    .containsExactly(1.5, -2.5, 64L);
            assertThat(one(db, "SELECT COUNT(*) FROM sensor_requests WHERE robot_id = 1 AND answered_sim_time_ms = 64"))
                    .containsExactly(2L);
        }
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void aFailedAnswerWritesNothing(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind); RobotLink link = new JdbcRobotLink(db.dataSource())) {
            db.execute("INSERT INTO sensor_requests (robot_id, sensor, iteration) VALUES (1, 'GPS', 1)");
            long id = link.pendingRequests(1).get(0).id();
            db.execute("DROP TABLE battery_level"); // the battery insert fails after the GPS insert
            try {
                link.answer(1, new SensorAnswer(64, new GpsReading(1, 2), null, List.of(), new BatteryReading(50, false),
                        new long[] {id}));
                throw new AssertionError("expected a LinkException");
            } catch (LinkException expected) {
                assertThat(expected).hasMessageContaining("reading");
            }
            assertThat(db.count("gps_stored_values")).isZero();
            assertThat(link.pendingRequests(1)).hasSize(1);
        }
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void newestCommandIsTheLatestIterationsForThisRobot(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind); RobotLink link = new JdbcRobotLink(db.dataSource())) {
            assertThat(link.newestCommand(1)).isEmpty();
            db.execute("INSERT INTO engine_comments (robot_id, iteration, sim_time_ms, scenario, command) VALUES (1, 1, 32, 'A', 'STOP')");
            db.execute("INSERT INTO engine_comments (robot_id, iteration, sim_time_ms, scenario, command) VALUES (1, 2, 64, 'B', 'FORWARD 0.3')");
            db.execute("INSERT INTO engine_comments (robot_id, iteration, sim_time_ms, scenario, command) VALUES (2, 9, 96, 'C', 'DRIVE 0 0')");
            CommandRecord newest = link.newestCommand(1).orElseThrow();
            assertThat(newest.command()).isEqualTo("FORWARD 0.3");
            assertThat(newest.iteration()).isEqualTo(2);
            assertThat(newest.simTimeMs()).isEqualTo(64);
            assertThat(newest.scenario()).isEqualTo("B");
        }
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void newestCommandIsTheLatestIterationsEvenWhenItsIdIsSmaller(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind); RobotLink link = new JdbcRobotLink(db.dataSource())) {
            // Ids as two Galera nodes (auto_increment_increment 3) hand them out: iteration 8 came through the node
            // whose counter is behind.
            db.execute("INSERT INTO engine_comments (id, robot_id, iteration, sim_time_ms, scenario, command) VALUES (31, 1, 7, 224, 'A', 'STOP')");
            db.execute("INSERT INTO engine_comments (id, robot_id, iteration, sim_time_ms, scenario, command) VALUES (29, 1, 8, 256, 'B', 'FORWARD 0.3')");
            assertThat(link.newestCommand(1).orElseThrow().iteration()).isEqualTo(8);
            assertThat(link.newestCommand(1).orElseThrow().command()).isEqualTo("FORWARD 0.3");
        }
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void pruningKeepsTheNewestReadingsBySimulatedTimeNotById(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind); RobotLink link = new JdbcRobotLink(db.dataSource())) {
            long[] ids = {40, 43, 46, 38, 41, 44}; // steps 0-2 on one node, 3-5 on one whose counter was behind
            for (int step = 0; step < ids.length; step++) {
                db.execute("INSERT INTO gps_stored_values (id, robot_id, sim_time_ms, x_m, y_m) VALUES (" + ids[step] + ", 1, "
                        + step * 32 + ", " + step + ", 0)");
            }
            assertThat(link.prune(1, new RetentionPolicy(3, 1))).isEqualTo(3);
            assertThat(one(db, "SELECT COUNT(*), MIN(sim_time_ms), MAX(sim_time_ms) FROM gps_stored_values WHERE robot_id = 1"))
                    .containsExactly(3L, 3 * 32L, 5 * 32L);
            // Two readings of one time (the start battery level and an answer at 0 ms): cut between them, not both gone.
            link.writeBattery(1, 0, new BatteryReading(100, false));
            link.writeBattery(1, 0, new BatteryReading(99.9, false));
            assertThat(link.prune(1, new RetentionPolicy(1, 1))).isEqualTo(2 + 1); // gps 3 -> 1, battery 2 -> 1
            assertThat(one(db, "SELECT COUNT(*), MIN(level_pct) FROM battery_level WHERE robot_id = 1")).containsExactly(1L, 99.9);
        }
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void seedingTwiceWritesTheMissionOnce(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind); RobotLink link = new JdbcRobotLink(db.dataSource())) {
            assertThat(link.seedMission(1, MISSION)).isTrue();
            assertThat(link.seedMission(1, MISSION)).isFalse();
            assertThat(link.seedMission(2, MISSION)).isTrue();
            assertThat(db.count("checkpoints")).isEqualTo(4);
            assertThat(db.count("recharge_station")).isEqualTo(2);
            assertThat(db.count("battery_recharged")).isEqualTo(2);
            assertThat(one(db, "SELECT seq, x_m, y_m, radius_m, reached FROM checkpoints WHERE robot_id = 1 ORDER BY seq DESC LIMIT 1"))
                    .containsExactly(1, 3.0, -1.0, 0.25, false);
            assertThat(one(db, "SELECT level_pct FROM battery_recharged WHERE robot_id = 1")).containsExactly(90.0);
        }
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void pruningKeepsTheNewestReadingsOfThisRobotOnly(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind); RobotLink link = new JdbcRobotLink(db.dataSource())) {
            List<DistanceReading> ds = List.of(new DistanceReading(0, 0, 0.3, 1), new DistanceReading(1, 1, 0.4, 1));
            for (int step = 0; step < 30; step++) {
                for (int robot = 1; robot <= 2; robot++) {
                    db.execute("INSERT INTO sensor_requests (robot_id, sensor, iteration) VALUES (" + robot + ", 'GPS', " + step + ")");
                    long[] ids = link.pendingRequests(robot).stream().mapToLong(SensorRequest::id).toArray();
                    link.answer(robot, new SensorAnswer(step * 32L, new GpsReading(step, 0), new IuReading(0, 0, step), ds,
                            new BatteryReading(100 - step, false), new OdometryReading(0.01, -0.01), ids));
                }
            }
            db.execute("INSERT INTO sensor_requests (robot_id, sensor, iteration) VALUES (1, 'IU', 99)");
            List<Object> requestsBefore = one(db, "SELECT COUNT(*) FROM sensor_requests");
            int deleted = link.prune(1, new RetentionPolicy(5, 1));
            assertThat(deleted).isEqualTo(25 * 4 + 25 * 2);
            for (String table : List.of("gps_stored_values", "iudata", "battery_level", "odometry")) {
                assertThat(one(db, "SELECT COUNT(*), MIN(sim_time_ms) FROM " + table + " WHERE robot_id = 1"))
                        .as(table).containsExactly(5L, 25 * 32L);
                assertThat(one(db, "SELECT COUNT(*) FROM " + table + " WHERE robot_id = 2")).containsExactly(30L);
            }
            assertThat(one(db, "SELECT COUNT(*), MIN(sim_time_ms) FROM distance_sensor_data WHERE robot_id = 1"))
                    .containsExactly(10L, 25 * 32L);
            // sensor_requests is the engine's table: the robot leaves its pruning to the engine
            assertThat(one(db, "SELECT COUNT(*) FROM sensor_requests")).isEqualTo(requestsBefore);
            assertThat(link.pendingRequests(1)).hasSize(1);
            assertThat(link.prune(1, new RetentionPolicy(5, 1))).isZero();
        }
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void aLinkThatDidNotWriteTheReadingsPrunesTheSameRows(DatabaseKind kind) throws Exception {
        List<String> writerSent = new java.util.concurrent.CopyOnWriteArrayList<>();
        List<String> restartedSent = new java.util.concurrent.CopyOnWriteArrayList<>();
        try (TestDatabase db = TestDatabases.open(kind); RobotLink writer = new JdbcRobotLink(RecordingDataSource.of(db.dataSource(), writerSent));
             RobotLink restarted = new JdbcRobotLink(RecordingDataSource.of(db.dataSource(), restartedSent))) {
            List<DistanceReading> ds = List.of(new DistanceReading(0, 0, 0.3, 1), new DistanceReading(1, 1, 0.4, 1));
            for (int step = 0; step < 30; step++) {
                for (int robot = 1; robot <= 2; robot++) {
                    writer.answer(robot, new SensorAnswer(step * 32L, null, null, ds, null, new long[0]));
                }
            }
            // robot 1's cut-off comes from what the writer remembers, robot 2's from the table
            assertThat(writer.prune(1, new RetentionPolicy(5, 1))).isEqualTo(25 * 2);
            assertThat(restarted.prune(2, new RetentionPolicy(5, 1))).isEqualTo(25 * 2);
            assertThat(writerSent).as("the writer knows its cut-off").noneMatch(sql -> sql.contains("SELECT DISTINCT"));
            assertThat(restartedSent).as("a restarted link asks").anyMatch(sql -> sql.contains("SELECT DISTINCT"));
            for (int robot = 1; robot <= 2; robot++) {
                assertThat(one(db, "SELECT COUNT(*), MIN(sim_time_ms) FROM distance_sensor_data WHERE robot_id = " + robot))
                        .containsExactly(10L, 25 * 32L);
            }
            // a retention larger than the writer remembers asks the table, then remembers enough
            writer.answer(1, new SensorAnswer(30 * 32L, null, null, ds, null, new long[0]));
            assertThat(writer.prune(1, new RetentionPolicy(3000, 1))).isZero();
            assertThat(writer.prune(1, new RetentionPolicy(2, 1))).isEqualTo(4 * 2);
            assertThat(one(db, "SELECT COUNT(*), MIN(sim_time_ms) FROM distance_sensor_data WHERE robot_id = 1"))
                    .containsExactly(4L, 29 * 32L);
        }
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void aNewRunPrunesByItsOwnReadingsOnly(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind); JdbcRobotLink link = new JdbcRobotLink(db.dataSource())) {
            List<DistanceReading> ds = List.of(new DistanceReading(0, 0, 0.3, 1));
            link.clock().beginRun(1, Timing.SYNC);
            for (int step = 0; step < 30; step++) {
                link.answer(1, new SensorAnswer(step * 32L, null, null, ds, null, new long[0]));
            }
            link.clock().beginRun(1, Timing.SYNC); // a second run: its clock starts again from 0
            for (int step = 0; step < 8; step++) {
                link.answer(1, new SensorAnswer(step * 32L, null, null, ds, null, new long[0]));
            }
            link.prune(1, new RetentionPolicy(5, 1));
            assertThat(one(db, "SELECT COUNT(*), MIN(sim_time_ms), MAX(sim_time_ms) FROM distance_sensor_data WHERE robot_id = 1"))
                    .containsExactly(5L, 3 * 32L, 7 * 32L);
        }
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void onMariaDbAnAnswerIsOneRoundTripOnH2AStatementEach(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind);
             com.zaxxer.hikari.HikariDataSource robotPool = RobotPool.open(db.jdbcUrl(), db.user(), db.password())) {
            List<String> sent = new java.util.concurrent.CopyOnWriteArrayList<>();
            try (RobotLink link = new JdbcRobotLink(RecordingDataSource.of(robotPool, sent))) {
                db.execute("INSERT INTO sensor_requests (robot_id, sensor, iteration) VALUES (1, 'GPS', 1), (1, 'DS', 1)");
                long[] ids = link.pendingRequests(1).stream().mapToLong(SensorRequest::id).toArray();
                List<DistanceReading> ds = List.of(new DistanceReading(0, -0.5, 0.75, 2), new DistanceReading(1, 0.5, 2, 2));
                link.answer(1, new SensorAnswer(64, null, null, List.of(), null, new long[0])); // finds out what the server takes
                sent.clear();
                link.answer(1, new SensorAnswer(96, new GpsReading(0.5, 1.5), new IuReading(0, 0, 0.25), ds,
                        new BatteryReading(88.5, true), ids));
                if (kind == DatabaseKind.MARIADB) {
                    assertThat(sent).as("readings, marks and commit together").hasSize(1);
                    assertThat(sent.get(0)).startsWith("START TRANSACTION").endsWith("COMMIT");
                } else {
                    assertThat(sent.size()).isGreaterThanOrEqualTo(6);
                }
            }
            assertThat(one(db, "SELECT x_m, y_m FROM gps_stored_values WHERE sim_time_ms = 96")).containsExactly(0.5, 1.5);
            assertThat(one(db, "SELECT yaw_rad FROM iudata WHERE sim_time_ms = 96")).containsExactly(0.25);
            assertThat(one(db, "SELECT COUNT(*), MIN(distance_m), MAX(distance_m) FROM distance_sensor_data WHERE sim_time_ms = 96"))
                    .containsExactly(2L, 0.75, 2.0);
            assertThat(one(db, "SELECT level_pct, charging FROM battery_level WHERE sim_time_ms = 96")).containsExactly(88.5, true);
            assertThat(one(db, "SELECT COUNT(*) FROM sensor_requests WHERE answered_sim_time_ms = 96")).containsExactly(2L);
        }
    }

    @ParameterizedTest
    @EnumSource(value = DatabaseKind.class, names = "MARIADB")
    void aPoolThatRefusesMultiStatementsIsAnsweredStatementByStatement(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind);
             com.zaxxer.hikari.HikariDataSource plain = RobotPool.open(
                     db.jdbcUrl() + (db.jdbcUrl().contains("?") ? "&" : "?") + "allowMultiQueries=false", db.user(), db.password());
             RobotLink link = new JdbcRobotLink(plain)) {
            for (int step = 1; step <= 2; step++) {
                db.execute("INSERT INTO sensor_requests (robot_id, sensor, iteration) VALUES (1, 'GPS', " + step + ")");
                long[] ids = link.pendingRequests(1).stream().mapToLong(SensorRequest::id).toArray();
                link.answer(1, new SensorAnswer(step * 32L, new GpsReading(step, 0), null, List.of(), null, ids));
            }
            assertThat(one(db, "SELECT COUNT(*), MAX(x_m) FROM gps_stored_values")).containsExactly(2L, 2.0);
            assertThat(link.pendingRequests(1)).isEmpty();
        }
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void inSyncTimingAStepsAnswerCommitsWithItsPublicationInOneRoundTrip(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind);
             com.zaxxer.hikari.HikariDataSource robotPool = RobotPool.open(db.jdbcUrl(), db.user(), db.password())) {
            List<String> sent = new java.util.concurrent.CopyOnWriteArrayList<>();
            try (JdbcRobotLink link = new JdbcRobotLink(RecordingDataSource.of(robotPool, sent))) {
                RobotClock clock = link.clock();
                long run = clock.beginRun(1, Timing.SYNC);
                link.answer(1, new SensorAnswer(0, new GpsReading(0, 0), null, List.of(), null, new long[0])); // finds out what the server takes
                clock.publish(1, run, 1, 0, RunState.RUNNING);
                db.execute("INSERT INTO sensor_requests (robot_id, sensor, iteration) VALUES (1, 'GPS', 1)");
                long[] ids = link.pendingRequests(1).stream().mapToLong(SensorRequest::id).toArray();
                sent.clear();
                link.answer(1, new SensorAnswer(32, new GpsReading(2.5, 0), null, List.of(), null, ids));
                if (kind == DatabaseKind.MARIADB) {
                    assertThat(sent).as("nothing sent before the step is published").isEmpty();
                    assertThat(one(db, "SELECT COUNT(*) FROM gps_stored_values WHERE sim_time_ms = 32")).containsExactly(0L);
                }
                clock.publish(1, run, 2, 32, RunState.RUNNING);
                if (kind == DatabaseKind.MARIADB) {
                    assertThat(sent).as("readings, marks, the step and the commit together").hasSize(1);
                    assertThat(sent.get(0)).startsWith("START TRANSACTION").contains("UPDATE robot_clock").endsWith("COMMIT");
                }
                assertThat(one(db, "SELECT x_m FROM gps_stored_values WHERE sim_time_ms = 32")).containsExactly(2.5);
                assertThat(one(db, "SELECT COUNT(*) FROM sensor_requests WHERE answered_sim_time_ms = 32")).containsExactly(1L);
                assertThat(one(db, "SELECT step, sim_time_ms FROM robot_clock WHERE robot_id = 1")).containsExactly(2L, 32L);

                link.answer(1, new SensorAnswer(64, new GpsReading(3, 0), null, List.of(), null, new long[0]));
                db.execute("UPDATE robot_clock SET run_id = run_id + 1 WHERE robot_id = 1"); // another process took the robot id
                org.assertj.core.api.Assertions.assertThatThrownBy(() -> clock.publish(1, run, 3, 64, RunState.RUNNING))
                        .isInstanceOf(LinkException.class).hasMessageContaining("another robot process with the same robot id");
            }
        }
    }

    @ParameterizedTest
    @EnumSource(value = DatabaseKind.class, names = "MARIADB")
    void aFailedPublicationKeepsItsAnswerForTheRetry(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind);
             com.zaxxer.hikari.HikariDataSource robotPool = RobotPool.open(db.jdbcUrl(), db.user(), db.password());
             JdbcRobotLink link = new JdbcRobotLink(robotPool)) {
            RobotClock clock = link.clock();
            long run = stepOneAndAnAnswerKeptForStepTwo(link);
            db.execute("RENAME TABLE iudata TO iudata_away"); // the round trip fails at the inertial reading
            try {
                org.assertj.core.api.Assertions.assertThatThrownBy(() -> clock.publish(1, run, 2, 32, RunState.RUNNING))
                        .isInstanceOf(LinkException.class);
                assertThat(one(db, "SELECT COUNT(*) FROM gps_stored_values WHERE sim_time_ms = 32")).as("rolled back").containsExactly(0L);
                assertThat(one(db, "SELECT step FROM robot_clock WHERE robot_id = 1")).containsExactly(1L);
            } finally {
                db.execute("RENAME TABLE iudata_away TO iudata");
            }
            clock.publish(1, run, 2, 32, RunState.RUNNING); // the retry: the kept answer goes with it
            assertThat(one(db, "SELECT COUNT(*) FROM gps_stored_values WHERE sim_time_ms = 32")).containsExactly(1L);
            assertThat(one(db, "SELECT yaw_rad FROM iudata WHERE sim_time_ms = 32")).containsExactly(0.5);
            assertThat(one(db, "SELECT step FROM robot_clock WHERE robot_id = 1")).containsExactly(2L);
        }
    }

    @ParameterizedTest
    @EnumSource(value = DatabaseKind.class, names = "MARIADB")
    void aPublicationThatCommittedThoughItsAnswerWasLostIsNotSentTwice(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind);
             com.zaxxer.hikari.HikariDataSource robotPool = RobotPool.open(db.jdbcUrl(), db.user(), db.password());
             JdbcRobotLink link = new JdbcRobotLink(robotPool)) {
            RobotClock clock = link.clock();
            long run = stepOneAndAnAnswerKeptForStepTwo(link);
            db.execute("RENAME TABLE iudata TO iudata_away");
            try {
                org.assertj.core.api.Assertions.assertThatThrownBy(() -> clock.publish(1, run, 2, 32, RunState.RUNNING))
                        .isInstanceOf(LinkException.class);
            } finally {
                db.execute("RENAME TABLE iudata_away TO iudata");
            }
            // what the server holds when a commit went through but its answer was lost on the way back
            db.execute("INSERT INTO gps_stored_values (robot_id, sim_time_ms, x_m, y_m) VALUES (1, 32, 1, 0)");
            db.execute("INSERT INTO iudata (robot_id, sim_time_ms, roll_rad, pitch_rad, yaw_rad) VALUES (1, 32, 0, 0, 0.5)");
            db.execute("UPDATE robot_clock SET step = 2, sim_time_ms = 32 WHERE robot_id = 1");

            clock.publish(1, run, 2, 32, RunState.RUNNING); // the retry finds the step published: the answer is not sent again
            assertThat(one(db, "SELECT COUNT(*) FROM gps_stored_values WHERE sim_time_ms = 32")).containsExactly(1L);
            assertThat(one(db, "SELECT COUNT(*) FROM iudata WHERE sim_time_ms = 32")).containsExactly(1L);
            link.answer(1, new SensorAnswer(64, new GpsReading(2, 0), null, List.of(), null, new long[0]));
            clock.publish(1, run, 3, 64, RunState.RUNNING); // and the next step goes on as usual
            assertThat(one(db, "SELECT COUNT(*), MAX(x_m) FROM gps_stored_values")).containsExactly(3L, 2.0);
        }
    }

    /** Begins a sync run, publishes step 1, and keeps step 2's answer (a GPS and an inertial reading) for its publication. */
    private static long stepOneAndAnAnswerKeptForStepTwo(JdbcRobotLink link) throws LinkException {
        RobotClock clock = link.clock();
        long run = clock.beginRun(1, Timing.SYNC);
        link.answer(1, new SensorAnswer(0, new GpsReading(0, 0), null, List.of(), null, new long[0]));
        clock.publish(1, run, 1, 0, RunState.RUNNING);
        link.answer(1, new SensorAnswer(32, new GpsReading(1, 0), new IuReading(0, 0, 0.5), List.of(), null, new long[0]));
        return run;
    }

    /** The first row of a query, numbers normalised (Long for integers, Double, Boolean). */
    static List<Object> one(TestDatabase db, String sql) throws SQLException {
        try (Connection c = db.dataSource().getConnection(); PreparedStatement ps = c.prepareStatement(sql);
             ResultSet rs = ps.executeQuery()) {
            assertThat(rs.next()).as(sql).isTrue();
            List<Object> row = new ArrayList<>();
            for (int i = 1; i <= rs.getMetaData().getColumnCount(); i++) {
                Object o = rs.getObject(i);
                if (o instanceof Long || o instanceof java.math.BigInteger || o instanceof java.math.BigDecimal) {
                    o = ((Number) o).longValue();
                } else if (o instanceof Float f) {
                    o = f.doubleValue();
                }
                row.add(o);
            }
            return row;
        }
    }
}
