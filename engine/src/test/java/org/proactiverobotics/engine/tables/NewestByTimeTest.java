package org.proactiverobotics.engine.tables;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.proactiverobotics.db.DatabaseKind;
import org.proactiverobotics.db.TestDatabase;
import org.proactiverobotics.db.TestDatabases;
import org.proactiverobotics.engine.persistence.IterationTransaction;

/**
 * "Newest" is by simulated time and iteration, not by id: on a Galera cluster the ids that
 * different nodes hand out interleave, so the newest reading or command may have the smaller id.
 */
class NewestByTimeTest {

    private static final int ROBOT = 4;

    /** Rows as two nodes (auto_increment_increment 3) write them: the newer ones came through the node behind. */
    private static void writeInterleaved(TestDatabase db) throws Exception {
        db.execute("INSERT INTO gps_stored_values (id, robot_id, sim_time_ms, x_m, y_m) VALUES (31, 4, 32, 1.0, 1.0)");
        db.execute("INSERT INTO gps_stored_values (id, robot_id, sim_time_ms, x_m, y_m) VALUES (29, 4, 64, 2.0, 2.0)");
        db.execute("INSERT INTO iudata (id, robot_id, sim_time_ms, roll_rad, pitch_rad, yaw_rad) VALUES (31, 4, 32, 0, 0, 0.1)");
        db.execute("INSERT INTO iudata (id, robot_id, sim_time_ms, roll_rad, pitch_rad, yaw_rad) VALUES (29, 4, 64, 0, 0, 0.2)");
        db.execute("INSERT INTO battery_level (id, robot_id, sim_time_ms, level_pct, charging) VALUES (31, 4, 32, 90, FALSE)");
        db.execute("INSERT INTO battery_level (id, robot_id, sim_time_ms, level_pct, charging) VALUES (29, 4, 64, 80, TRUE)");
        db.execute("INSERT INTO odometry (id, robot_id, sim_time_ms, left_m, right_m) VALUES (31, 4, 32, 0.01, 0.02)");
        db.execute("INSERT INTO odometry (id, robot_id, sim_time_ms, left_m, right_m) VALUES (29, 4, 64, -0.03, 0.04)");
    }

    private static List<Object> newest(JdbcRobotTables tables) {
        List<Object> seen = new ArrayList<>();
        seen.add(tables.newestGps().orElseThrow().xM());
        seen.add(tables.newestHeading().orElseThrow().yawRad());
        seen.add(tables.newestBattery().orElseThrow().levelPct());
        seen.add(tables.newestOdometry().orElseThrow());
        for (Sensor sensor : List.of(Sensor.GPS, Sensor.IU, Sensor.BATTERY, Sensor.ODOMETRY)) {
            seen.add(tables.newestSimTimeMs(sensor));
        }
        return seen;
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void theNewestReadingIsTheLatestInSimulatedTimeOutsideAndInsideAnIteration(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind)) {
            writeInterleaved(db);
            List<Object> expected = List.of(2.0, 0.2, 80.0, new WheelOdometry(64, -0.03, 0.04), 64L, 64L, 64L, 64L);
            assertThat(newest(new JdbcRobotTables(db.dataSource(), ROBOT))).isEqualTo(expected);

            IterationTransaction tx = new IterationTransaction(db.dataSource());
            JdbcRobotTables inIteration = new JdbcRobotTables(tx, ROBOT);
            tx.begin();
            assertThat(newest(inIteration)).as("through the iteration's snapshot").isEqualTo(expected);
            assertThat(inIteration.snapshotLoads()).isEqualTo(1);
            tx.rollback();
        }
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void snapshotsReadAheadGiveEachRobotItsOwnNewestOdometry(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind)) {
            int robots = IterationSnapshot.MAX_ROBOTS_PER_QUERY + 2; // two queries
            int[] ids = new int[robots];
            for (int r = 0; r < robots; r++) {
                ids[r] = 100 + r;
                if (r % 5 != 4) { // every fifth robot has no odometry yet
                    db.execute("INSERT INTO odometry (robot_id, sim_time_ms, left_m, right_m) VALUES (" + ids[r] + ", 64, "
                            + r + ", " + (-r) + "), (" + ids[r] + ", 32, 99, 99)");
                }
            }
            IterationSnapshot[] snapshots;
            try (var c = db.dataSource().getConnection()) {
                snapshots = IterationSnapshot.loadAll(c, ids);
            }
            for (int r = 0; r < robots; r++) {
                if (r % 5 == 4) {
                    assertThat(snapshots[r].odometry()).as("robot %d", ids[r]).isEmpty();
                    assertThat(snapshots[r].newestSimTimeMs(Sensor.ODOMETRY)).isEqualTo(-1);
                } else {
                    assertThat(snapshots[r].odometry()).as("robot %d", ids[r]).contains(new WheelOdometry(64, r, -r));
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void pruningTheHistoryKeepsTheLatestIterationsCommands(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind)) {
            long[] ids = {40, 43, 46, 38, 41, 44}; // iterations 1-3 on one node, 4-6 on one whose counter was behind
            for (int k = 0; k < ids.length; k++) {
                db.execute("INSERT INTO engine_comments (id, robot_id, iteration, sim_time_ms, scenario, command) VALUES ("
                        + ids[k] + ", 4, " + (k + 1) + ", " + 32 * (k + 1) + ", 'A', 'STOP')");
            }
            JdbcRobotTables tables = new JdbcRobotTables(db.dataSource(), ROBOT);
            assertThat(tables.pruneHistory(3)).isEqualTo(3);
            assertThat(db.count("engine_comments")).isEqualTo(3);
            try (var c = db.dataSource().getConnection(); var s = c.createStatement();
                 var rs = s.executeQuery("SELECT MIN(iteration), MAX(iteration) FROM engine_comments WHERE robot_id = 4")) {
                assertThat(rs.next()).isTrue();
                assertThat(rs.getLong(1)).isEqualTo(4);
                assertThat(rs.getLong(2)).isEqualTo(6);
            }
        }
    }
}
