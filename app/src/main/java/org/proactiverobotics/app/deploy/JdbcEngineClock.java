package org.proactiverobotics.app.deploy;

import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import javax.sql.DataSource;
import org.proactiverobotics.db.RobotRows;
import org.proactiverobotics.db.Writes;
import org.proactiverobotics.protocol.RunState;
import org.proactiverobotics.protocol.Timing;

/**
 * {@link EngineClock} over JDBC: {@code robot_clock}, read, and {@code engine_clock}, written, of
 * schema.sql, and the reset of the engine's rows when a new robot run starts. Runs with the
 * engine user's grants.
 */
public final class JdbcEngineClock implements EngineClock {

    private static RobotTick tick(ResultSet rs, int first) throws SQLException {
        return new RobotTick(rs.getLong(first), rs.getLong(first + 1), rs.getLong(first + 2),
                Timing.of(rs.getString(first + 3)).orElse(null), RunState.of(rs.getString(first + 4)).orElse(null));
    }

    private final DataSource dataSource;
    private final int robotId;

    /**
     * @param dataSource the shared database
     * @param robotId    the robot
     */
    public JdbcEngineClock(DataSource dataSource, int robotId) {
        this.dataSource = dataSource;
        this.robotId = robotId;
    }

    /**
     * The clocks of several robots in one query (an engine serving many robots polls them all at once).
     *
     * @param dataSource the shared database
     * @param robotIds   the robots
     * @return each robot's clock by robot id; a robot that never started a run is absent
     */
    public static Map<Integer, RobotTick> robots(DataSource dataSource, int[] robotIds) throws SQLException {
        StringBuilder sql = new StringBuilder(ROBOT_CLOCKS).append(" IN (");
        for (int k = 0; k < robotIds.length; k++) {
            sql.append(k == 0 ? "?" : ", ?");
        }
        sql.append(')');
        try (Connection c = dataSource.getConnection(); PreparedStatement ps = c.prepareStatement(sql.toString())) {
            for (int k = 0; k < robotIds.length; k++) {
                ps.setInt(k + 1, robotIds[k]);
            }
            try (ResultSet rs = ps.executeQuery()) {
                return ticks(rs);
            }
        }
    }

    /** The robots' clocks, less the robot ids' condition. */
    private static final String ROBOT_CLOCKS = "SELECT robot_id, run_id, step, sim_time_ms, timing, state FROM robot_clock WHERE robot_id";

    /** {@link #robots}' query for one robot, whose id is its one parameter (for {@link #ticks}). */
    static final String ROBOT_CLOCK = ROBOT_CLOCKS + " = ?";

    /** @return the clocks a query of {@link #ROBOT_CLOCK}'s columns returned, by robot id */
    static Map<Integer, RobotTick> ticks(ResultSet rs) throws SQLException {
        Map<Integer, RobotTick> out = new HashMap<>();
        while (rs.next()) {
            out.put(rs.getInt(1), tick(rs, 2));
        }
        return out;
    }

    @Override
    public Optional<Served> served() throws SQLException {
        try (Connection c = dataSource.getConnection(); PreparedStatement ps = c.prepareStatement(
                "SELECT run_id, step, iteration FROM engine_clock WHERE robot_id = ?")) {
            ps.setInt(1, robotId);
            try (ResultSet rs = ps.executeQuery()) {
                return rs.next() ? Optional.of(new Served(rs.getLong(1), rs.getLong(2), rs.getLong(3))) : Optional.empty();
            }
        }
    }

    @Override
    public void publish(long runId, long step, long iteration, EngineLease lease) throws SQLException {
        try (Connection c = dataSource.getConnection()) {
            try (PreparedStatement ps = c.prepareStatement("UPDATE engine_clock SET run_id = ?, step = ?, iteration = ?, "
                    + "updated_at = CURRENT_TIMESTAMP(3) WHERE robot_id = ? AND EXISTS (SELECT 1 FROM engine_lease"
                    + " WHERE robot_id = ? AND owner = ? AND epoch = ?)")) {
                ps.setLong(1, runId);
                ps.setLong(2, step);
                ps.setLong(3, iteration);
                ps.setInt(4, robotId);
                ps.setInt(5, robotId);
                ps.setString(6, lease.owner());
                ps.setLong(7, lease.epoch());
                if (ps.executeUpdate() > 0) {
                    return;
                }
            }
            // no row yet, or the lease is lost: tell which, in one transaction
            c.setAutoCommit(false);
            try {
                lease.confirm(c, iteration);
                try (PreparedStatement ps = c.prepareStatement(
                        "INSERT INTO engine_clock (robot_id, run_id, step, iteration) VALUES (?, ?, ?, ?)")) {
                    ps.setInt(1, robotId);
                    ps.setLong(2, runId);
                    ps.setLong(3, step);
                    ps.setLong(4, iteration);
                    ps.executeUpdate();
                }
                c.commit();
            } catch (SQLException | RuntimeException e) {
                c.rollback();
                throw e;
            } finally {
                c.setAutoCommit(true);
            }
        }
    }

    @Override
    public void publish(Writes writes, long runId, long step, long iteration) throws SQLException {
        writes.add("UPDATE engine_clock SET run_id = ?, step = ?, iteration = ?, updated_at = CURRENT_TIMESTAMP(3)"
                + " WHERE robot_id = ?", 4, (ps, p) -> {
                    ps.setLong(p, runId);
                    ps.setLong(p + 1, step);
                    ps.setLong(p + 2, iteration);
                    ps.setInt(p + 3, robotId);
                });
    }

    @Override
    public void resetForNewRun() throws SQLException {
        try (Connection c = dataSource.getConnection()) {
            c.setAutoCommit(false);
            try {
                RobotRows.run(c, robotId, List.of("DELETE FROM engine_comments WHERE robot_id = ?",
                        "DELETE FROM sensor_requests WHERE robot_id = ?",
                        "UPDATE checkpoints SET reached = FALSE, reached_sim_time_ms = NULL, unreachable = FALSE WHERE robot_id = ?",
                        "DELETE FROM occupancy_map WHERE robot_id = ?",
                        "DELETE FROM pose_estimate WHERE robot_id = ?"));
                c.commit();
            } catch (SQLException | RuntimeException e) {
                c.rollback();
                throw e;
            }
        }
    }
}
