package org.proactiverobotics.robot.link;

import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.util.Objects;
import java.util.Optional;
import javax.sql.DataSource;

/**
 * {@link RobotClock} over JDBC: {@code robot_clock} and {@code engine_clock} of schema.sql. Runs
 * with the robot user's grants: it writes only {@code robot_clock} and the robot's readings.
 */
public final class JdbcRobotClock implements RobotClock {

    private static final String[] READING_TABLES = {"gps_stored_values", "iudata", "distance_sensor_data", "battery_level"};

    private final DataSource dataSource;

    /** @param dataSource the shared database (not closed by this clock) */
    public JdbcRobotClock(DataSource dataSource) {
        this.dataSource = Objects.requireNonNull(dataSource, "dataSource");
    }

    @Override
    public long beginRun(int robotId, String timing) throws LinkException {
        try (Connection c = dataSource.getConnection()) {
            c.setAutoCommit(false);
            try {
                long previous = -1;
                try (PreparedStatement ps = c.prepareStatement("SELECT run_id FROM robot_clock WHERE robot_id = ?")) {
                    ps.setInt(1, robotId);
                    try (ResultSet rs = ps.executeQuery()) {
                        if (rs.next()) {
                            previous = rs.getLong(1);
                        }
                    }
                }
                // Wall-clock millis keep run ids unique even when the robot_clock row was deleted.
                long runId = Math.max(previous + 1, System.currentTimeMillis());
                for (String table : READING_TABLES) {
                    try (PreparedStatement ps = c.prepareStatement("DELETE FROM " + table + " WHERE robot_id = ?")) {
                        ps.setInt(1, robotId);
                        ps.executeUpdate();
                    }
                }
                try (PreparedStatement ps = c.prepareStatement("UPDATE robot_clock SET run_id = ?, step = 0, sim_time_ms = 0, "
                        + "timing = ?, state = 'RUNNING', updated_at = CURRENT_TIMESTAMP(3) WHERE robot_id = ?")) {
                    ps.setLong(1, runId);
                    ps.setString(2, timing);
                    ps.setInt(3, robotId);
                    if (ps.executeUpdate() == 0) {
                        try (PreparedStatement insert = c.prepareStatement("INSERT INTO robot_clock "
                                + "(robot_id, run_id, step, sim_time_ms, timing, state) VALUES (?, ?, 0, 0, ?, 'RUNNING')")) {
                            insert.setInt(1, robotId);
                            insert.setLong(2, runId);
                            insert.setString(3, timing);
                            insert.executeUpdate();
                        }
                    }
                }
                c.commit();
                return runId;
            } catch (SQLException | RuntimeException e) {
                c.rollback();
                throw e;
            }
        } catch (SQLException e) {
            throw new LinkException("starting a run of robot " + robotId + " failed: " + e.getMessage(), e);
        }
    }

    @Override
    public void publish(int robotId, long runId, long step, long simTimeMs, String state) throws LinkException {
        try (Connection c = dataSource.getConnection(); PreparedStatement ps = c.prepareStatement("UPDATE robot_clock "
                + "SET step = ?, sim_time_ms = ?, state = ?, updated_at = CURRENT_TIMESTAMP(3) WHERE robot_id = ? AND run_id = ?")) {
            ps.setLong(1, step);
            ps.setLong(2, simTimeMs);
            ps.setString(3, state);
            ps.setInt(4, robotId);
            ps.setLong(5, runId);
            if (ps.executeUpdate() == 0) {
                throw new LinkException("robot_clock has no row for robot " + robotId + " run " + runId
                        + ": another robot process with the same robot id started a run", null);
            }
        } catch (SQLException e) {
            throw new LinkException("publishing step " + step + " of robot " + robotId + " failed: " + e.getMessage(), e);
        }
    }

    @Override
    public Optional<EngineTick> engineTick(int robotId) throws LinkException {
        try (Connection c = dataSource.getConnection();
             PreparedStatement ps = c.prepareStatement("SELECT run_id, step, iteration FROM engine_clock WHERE robot_id = ?")) {
            ps.setInt(1, robotId);
            try (ResultSet rs = ps.executeQuery()) {
                return rs.next() ? Optional.of(new EngineTick(rs.getLong(1), rs.getLong(2), rs.getLong(3))) : Optional.empty();
            }
        } catch (SQLException e) {
            throw new LinkException("reading engine_clock of robot " + robotId + " failed: " + e.getMessage(), e);
        }
    }
}
