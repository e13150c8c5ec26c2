package org.proactiverobotics.app.deploy;

import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.util.HashMap;
import java.util.Map;
import java.util.Optional;
import javax.sql.DataSource;
import org.proactiverobotics.db.Writes;
import org.proactiverobotics.protocol.RunState;
import org.proactiverobotics.protocol.Timing;

/**
 * The engine's side of the lockstep handshake (schema.sql: {@code robot_clock}, read;
 * {@code engine_clock}, written) and the reset of the engine's rows when a new robot run starts.
 * Runs with the engine user's grants.
 */
public final class EngineClock {

    /**
     * What the robot last published.
     *
     * @param runId     its run (one robot process)
     * @param step      the control step whose sensing is done
     * @param simTimeMs the simulated time of that sensing, ms
     * @param timing    sync or realtime, or null for a word this version does not know (never served)
     * @param state     running, finished or stopped, or null for a word this version does not know (not running)
     */
    public record RobotTick(long runId, long step, long simTimeMs, Timing timing, RunState state) {
        /** @return whether the robot waits for one iteration per step */
        public boolean sync() {
            return timing == Timing.SYNC;
        }

        /** @return whether the run goes on (in a timing this version knows: else it is not served) */
        public boolean running() {
            return state == RunState.RUNNING && timing != null;
        }

        /** @return the timing as robot_clock has it, for a log line */
        public String timingLabel() {
            return timing == null ? "unknown" : timing.label();
        }

        /** @return the state in lower case, for a log line */
        public String stateLabel() {
            return state == null ? "unknown" : state.name().toLowerCase(java.util.Locale.ROOT);
        }
    }

    private static RobotTick tick(ResultSet rs, int first) throws SQLException {
        return new RobotTick(rs.getLong(first), rs.getLong(first + 1), rs.getLong(first + 2),
                Timing.of(rs.getString(first + 3)).orElse(null), RunState.of(rs.getString(first + 4)).orElse(null));
    }

    /**
     * What the engine last published.
     *
     * @param runId     the run it serves
     * @param step      the last robot step it ran an iteration for
     * @param iteration that iteration
     */
    public record Served(long runId, long step, long iteration) {
    }

    private final DataSource dataSource;
    private final int robotId;

    /**
     * @param dataSource the shared database
     * @param robotId    the robot
     */
    public EngineClock(DataSource dataSource, int robotId) {
        this.dataSource = dataSource;
        this.robotId = robotId;
    }

    /** @return the robot's clock, or empty when it never started a run */
    public Optional<RobotTick> robot() throws SQLException {
        try (Connection c = dataSource.getConnection(); PreparedStatement ps = c.prepareStatement(
                "SELECT run_id, step, sim_time_ms, timing, state FROM robot_clock WHERE robot_id = ?")) {
            ps.setInt(1, robotId);
            try (ResultSet rs = ps.executeQuery()) {
                return rs.next() ? Optional.of(tick(rs, 1)) : Optional.empty();
            }
        }
    }

    /**
     * The clocks of several robots in one query (an engine serving many robots polls them all at once).
     *
     * @param dataSource the shared database
     * @param robotIds   the robots
     * @return each robot's clock by robot id; a robot that never started a run is absent
     */
    public static Map<Integer, RobotTick> robots(DataSource dataSource, int[] robotIds) throws SQLException {
        StringBuilder sql = new StringBuilder("SELECT robot_id, run_id, step, sim_time_ms, timing, state FROM robot_clock WHERE robot_id IN (");
        for (int k = 0; k < robotIds.length; k++) {
            sql.append(k == 0 ? "?" : ", ?");
        }
        sql.append(')');
        Map<Integer, RobotTick> out = new HashMap<>();
        try (Connection c = dataSource.getConnection(); PreparedStatement ps = c.prepareStatement(sql.toString())) {
            for (int k = 0; k < robotIds.length; k++) {
                ps.setInt(k + 1, robotIds[k]);
            }
            try (ResultSet rs = ps.executeQuery()) {
                while (rs.next()) {
                    out.put(rs.getInt(1), tick(rs, 2));
                }
            }
        }
        return out;
    }

    /** @return what this engine last published, or empty */
    public Optional<Served> served() throws SQLException {
        try (Connection c = dataSource.getConnection(); PreparedStatement ps = c.prepareStatement(
                "SELECT run_id, step, iteration FROM engine_clock WHERE robot_id = ?")) {
            ps.setInt(1, robotId);
            try (ResultSet rs = ps.executeQuery()) {
                return rs.next() ? Optional.of(new Served(rs.getLong(1), rs.getLong(2), rs.getLong(3))) : Optional.empty();
            }
        }
    }

    /**
     * Publishes that the engine has served this run up to this step, only while it holds the
     * robot's lease: an engine that lost it (paused past its expiry) cannot move the robot's clock
     * back under the engine that took over.
     *
     * @throws EngineLease.LostException when the lease is another engine's
     */
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

    /**
     * Publishes that the engine has served this run up to this step, in the transaction of the
     * iteration that served it (which has confirmed the robot's lease): the robot sees the step
     * served exactly when the iteration's rows are there, and a server that flushes its log at
     * every commit flushes once for both.
     *
     * @param writes    the iteration's writes
     * @param runId     the run
     * @param step      the robot step served
     * @param iteration the iteration that served it
     */
    public void publish(Writes writes, long runId, long step, long iteration) throws SQLException {
        writes.add("UPDATE engine_clock SET run_id = ?, step = ?, iteration = ?, updated_at = CURRENT_TIMESTAMP(3)"
                + " WHERE robot_id = ?", 4, (ps, p) -> {
                    ps.setLong(p, runId);
                    ps.setLong(p + 1, step);
                    ps.setLong(p + 2, iteration);
                    ps.setInt(p + 3, robotId);
                });
    }

    /**
     * A new robot run starts from a clean slate on the engine's side, as the one-process mission
     * does: its commands and sensor requests go, its checkpoints are neither reached nor unreachable any more, its map is gone. The
     * mission rows and the strategy stay (a strategy set with the strategy command survives).
     */
    public void resetForNewRun() throws SQLException {
        try (Connection c = dataSource.getConnection()) {
            c.setAutoCommit(false);
            try {
                for (String sql : new String[] {"DELETE FROM engine_comments WHERE robot_id = ?",
                        "DELETE FROM sensor_requests WHERE robot_id = ?",
                        "UPDATE checkpoints SET reached = FALSE, reached_sim_time_ms = NULL, unreachable = FALSE WHERE robot_id = ?",
                        "DELETE FROM occupancy_map WHERE robot_id = ?"}) {
                    try (PreparedStatement ps = c.prepareStatement(sql)) {
                        ps.setInt(1, robotId);
                        ps.executeUpdate();
                    }
                }
                c.commit();
            } catch (SQLException | RuntimeException e) {
                c.rollback();
                throw e;
            }
        }
    }
}
