package org.proactiverobotics.e2e;

import java.sql.Connection;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import org.proactiverobotics.app.mission.MissionReport;
import org.proactiverobotics.app.mission.NoiseLevel;
import org.proactiverobotics.db.DatabaseKind;
import org.proactiverobotics.db.TestDatabase;
import org.proactiverobotics.db.TestDatabases;

/**
 * The uninterrupted one-process run of a bundled world (safety-first, embedded H2, a noise level), with the
 * checkpoints rows the engine left: what the interrupted two-process runs are compared with.
 */
record Uninterrupted(MissionReport report, List<Clocks.CheckpointRow> checkpoints) {

    private static final Map<String, Uninterrupted> RUNS = new ConcurrentHashMap<>();

    /** Runs once per test JVM and world. */
    static Uninterrupted of(String world) {
        return of(world, NoiseLevel.NONE);
    }

    /** Runs once per test JVM, world and noise level. */
    static Uninterrupted of(String world, NoiseLevel noise) {
        return RUNS.computeIfAbsent(world + "/" + noise.label(), key -> {
            try (TestDatabase db = TestDatabases.open(DatabaseKind.H2)) {
                MissionReport report = Missions.run(world, db, "safety-first", noise).report();
                List<Clocks.CheckpointRow> rows = new ArrayList<>();
                try (Connection c = db.dataSource().getConnection(); Statement s = c.createStatement();
                     ResultSet rs = s.executeQuery("SELECT seq, reached, reached_sim_time_ms FROM checkpoints "
                             + "WHERE robot_id = 1 ORDER BY seq")) {
                    while (rs.next()) {
                        boolean reached = rs.getBoolean(2);
                        long t = rs.getLong(3);
                        rows.add(new Clocks.CheckpointRow(rs.getInt(1), reached, rs.wasNull() ? null : t));
                    }
                }
                return new Uninterrupted(report, List.copyOf(rows));
            } catch (SQLException e) {
                throw new IllegalStateException(e);
            }
        });
    }
}
