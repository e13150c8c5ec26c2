package org.proactiverobotics.robot;

import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.util.ArrayList;
import java.util.List;
import javax.sql.DataSource;

/** The engine's side of the tables, as plain SQL, for tests: writes requests and commands, reads rows. */
final class FakeEngine {

    private final DataSource dataSource;
    private final int robotId;

    FakeEngine(DataSource dataSource, int robotId) {
        this.dataSource = dataSource;
        this.robotId = robotId;
    }

    long request(String sensor) throws SQLException {
        return insert("INSERT INTO sensor_requests (robot_id, sensor, iteration) VALUES (?, ?, 1)", sensor);
    }

    long command(String text) throws SQLException {
        return insert("INSERT INTO engine_comments (robot_id, iteration, sim_time_ms, scenario, command) "
                + "VALUES (?, 1, 0, 'Test', ?)", text);
    }

    private long insert(String sql, String text) throws SQLException {
        try (Connection c = dataSource.getConnection();
             PreparedStatement ps = c.prepareStatement(sql, java.sql.Statement.RETURN_GENERATED_KEYS)) {
            ps.setInt(1, robotId);
            ps.setString(2, text);
            ps.executeUpdate();
            try (ResultSet rs = ps.getGeneratedKeys()) {
                rs.next();
                return rs.getLong(1);
            }
        }
    }

    long count(String table) throws SQLException {
        return longValue("SELECT COUNT(*) FROM " + table + " WHERE robot_id = " + robotId);
    }

    long pending() throws SQLException {
        return longValue("SELECT COUNT(*) FROM sensor_requests WHERE answered_sim_time_ms IS NULL AND robot_id = " + robotId);
    }

    long longValue(String sql) throws SQLException {
        List<Object[]> rows = rows(sql);
        return ((Number) rows.get(0)[0]).longValue();
    }

    List<Object[]> rows(String sql) throws SQLException {
        try (Connection c = dataSource.getConnection(); PreparedStatement ps = c.prepareStatement(sql);
             ResultSet rs = ps.executeQuery()) {
            int n = rs.getMetaData().getColumnCount();
            List<Object[]> out = new ArrayList<>();
            while (rs.next()) {
                Object[] row = new Object[n];
                for (int i = 0; i < n; i++) {
                    row[i] = rs.getObject(i + 1);
                }
                out.add(row);
            }
            return out;
        }
    }

    void execute(String sql) throws SQLException {
        try (Connection c = dataSource.getConnection(); PreparedStatement ps = c.prepareStatement(sql)) {
            ps.execute();
        }
    }
}
