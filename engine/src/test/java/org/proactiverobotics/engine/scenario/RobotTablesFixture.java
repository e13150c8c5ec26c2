package org.proactiverobotics.engine.scenario;

import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import org.proactiverobotics.db.DatabaseKind;
import org.proactiverobotics.db.TestDatabase;
import org.proactiverobotics.db.TestDatabases;
import org.proactiverobotics.engine.CommandArray;
import org.proactiverobotics.engine.ProactiveEngine;
import org.proactiverobotics.engine.ScenarioRegistry;
import org.proactiverobotics.engine.StateStore;
import org.proactiverobotics.engine.Suggestion;
import org.proactiverobotics.engine.motion.DriveProfile;
import org.proactiverobotics.engine.scenario.decision.DecisionObserver;
import org.proactiverobotics.engine.tables.EngineComments;
import org.proactiverobotics.engine.tables.JdbcRobotTables;
import org.proactiverobotics.engine.tables.MissionTables;
import org.proactiverobotics.engine.tables.SensorReadings;
import org.proactiverobotics.engine.tables.SensorRequests;
import org.proactiverobotics.engine.tables.StrategyTable;

/**
 * One scenario (or a few) run alone by a real engine over a fresh H2 database with the real
 * schema, and the robot's half played by hand: write readings, answer requests, read commands.
 */
final class RobotTablesFixture implements AutoCloseable {

    static final int ROBOT = 1;

    final TestDatabase db;
    final JdbcRobotTables tables;
    final ProactiveEngine engine;
    /** What the engine's rules read and write through: the tables, with a fault to inject. */
    final FaultyTables faulty;
    /** Every decision: the suggestions it saw (scenario to command) and the winner. */
    final List<Decision> decisions = new ArrayList<>();

    /** One decision of ReadRobotCommands. */
    record Decision(long iteration, Map<String, String> suggestions, String winner, String command) {
    }

    /** One engine_comments row. */
    record Sent(long id, long iteration, String scenario, String command) {
    }

    RobotTablesFixture(String... scenarios) throws SQLException {
        this.db = TestDatabases.open(DatabaseKind.H2);
        this.tables = new JdbcRobotTables(db.dataSource(), ROBOT);
        this.faulty = new FaultyTables(tables);
        this.engine = ProactiveEngine.builder()
                .robotId(ROBOT)
                .store(StateStore.none())
                .service(SensorReadings.class, faulty)
                .service(SensorRequests.class, faulty)
                .service(MissionTables.class, faulty)
                .service(StrategyTable.class, faulty)
                .service(EngineComments.class, faulty)
                .service(DriveProfile.class, DriveProfile.DEFAULT)
                .service(DecisionObserver.class, this::decided)
                .slot("ReachDestination", 0)
                .slot("BatteryMonitor", 1)
                .slot("ObstacleAvoidance", 2)
                .build();
        engine.startFresh(ScenarioRegistry.load().startUp(List.of(scenarios)));
    }

    private void decided(long iteration, CommandArray suggestions, Suggestion winner) {
        Map<String, String> seen = new TreeMap<>();
        for (int slot = 0; slot < suggestions.size(); slot++) {
            Suggestion s = suggestions.get(slot);
            if (s != null) {
                seen.put(s.scenario(), s.command());
            }
        }
        decisions.add(new Decision(iteration, seen, winner.scenario(), winner.command()));
    }

    /** Runs iterations; the scenarios' own rules first run in iteration 3 (StartUp, then meta-rules). */
    void iterate(int n) {
        for (int i = 0; i < n; i++) {
            engine.runIteration();
        }
    }

    void gps(long simTimeMs, double x, double y) throws SQLException {
        update("INSERT INTO gps_stored_values (robot_id, sim_time_ms, x_m, y_m) VALUES (?, ?, ?, ?)", ROBOT, simTimeMs, x, y);
    }

    void heading(long simTimeMs, double yawRad) throws SQLException {
        update("INSERT INTO iudata (robot_id, sim_time_ms, roll_rad, pitch_rad, yaw_rad) VALUES (?, ?, 0, 0, ?)",
                ROBOT, simTimeMs, yawRad);
    }

    void battery(long simTimeMs, double levelPct, boolean charging) throws SQLException {
        update("INSERT INTO battery_level (robot_id, sim_time_ms, level_pct, charging) VALUES (?, ?, ?, ?)",
                ROBOT, simTimeMs, levelPct, charging);
    }

    /** Eight sensors at the robot's default angles, reading these distances (index 0 rightmost). */
    void scan(long simTimeMs, double... distances) throws SQLException {
        double[] degrees = {-90, -45, -20, -8, 8, 20, 45, 90};
        for (int i = 0; i < degrees.length; i++) {
            update("INSERT INTO distance_sensor_data (robot_id, sim_time_ms, sensor_index, angle_rad, distance_m, range_m)"
                    + " VALUES (?, ?, ?, ?, ?, 1.0)", ROBOT, simTimeMs, i, Math.toRadians(degrees[i]), distances[i]);
        }
    }

    void checkpoint(int seq, double x, double y) throws SQLException {
        update("INSERT INTO checkpoints (robot_id, seq, x_m, y_m, radius_m) VALUES (?, ?, ?, ?, 0.25)", ROBOT, seq, x, y);
    }

    void station(double x, double y, double rechargeToPct) throws SQLException {
        update("INSERT INTO recharge_station (robot_id, x_m, y_m, radius_m) VALUES (?, ?, ?, 0.35)", ROBOT, x, y);
        update("INSERT INTO battery_recharged (robot_id, level_pct) VALUES (?, ?)", ROBOT, rechargeToPct);
    }

    /** The robot's answer: every pending request marked answered at this time. */
    void answerAll(long simTimeMs) throws SQLException {
        update("UPDATE sensor_requests SET answered_sim_time_ms = ? WHERE robot_id = ? AND answered_sim_time_ms IS NULL",
                simTimeMs, ROBOT);
    }

    List<String> pendingSensors() throws SQLException {
        return strings("SELECT sensor FROM sensor_requests WHERE robot_id = 1 AND answered_sim_time_ms IS NULL ORDER BY id");
    }

    List<String> commands() throws SQLException {
        return strings("SELECT command FROM engine_comments WHERE robot_id = 1 ORDER BY id");
    }

    List<Sent> sent() throws SQLException {
        List<Sent> out = new ArrayList<>();
        try (Connection c = db.dataSource().getConnection(); PreparedStatement ps = c.prepareStatement(
                "SELECT id, iteration, scenario, command FROM engine_comments WHERE robot_id = 1 ORDER BY id");
             ResultSet rs = ps.executeQuery()) {
            while (rs.next()) {
                out.add(new Sent(rs.getLong(1), rs.getLong(2), rs.getString(3), rs.getString(4)));
            }
        }
        return out;
    }

    List<String> reachedCheckpoints() throws SQLException {
        return strings("SELECT seq FROM checkpoints WHERE robot_id = 1 AND reached = TRUE ORDER BY seq");
    }

    private List<String> strings(String sql) throws SQLException {
        List<String> out = new ArrayList<>();
        try (Connection c = db.dataSource().getConnection(); PreparedStatement ps = c.prepareStatement(sql);
             ResultSet rs = ps.executeQuery()) {
            while (rs.next()) {
                out.add(rs.getString(1));
            }
        }
        return out;
    }

    private void update(String sql, Object... params) throws SQLException {
        try (Connection c = db.dataSource().getConnection(); PreparedStatement ps = c.prepareStatement(sql)) {
            for (int i = 0; i < params.length; i++) {
                ps.setObject(i + 1, params[i]);
            }
            ps.executeUpdate();
        }
    }

    @Override
    public void close() {
        db.close();
    }
}
