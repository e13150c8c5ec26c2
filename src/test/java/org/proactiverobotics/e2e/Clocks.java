package org.proactiverobotics.e2e;

import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.LongPredicate;

/**
 * What the reliability tests watch of a two-process mission, as the administrator over one
 * connection of their own (straight to the database, never through a test proxy): the two
 * clocks of the lockstep handshake and the checkpoints the engine marks.
 */
final class Clocks implements AutoCloseable {

    /** A checkpoints row. */
    record CheckpointRow(int seq, boolean reached, Long reachedSimTimeMs) {
    }

    private final Connection connection;
    private final int robotId;

    Clocks(String adminUrl, int robotId) throws SQLException {
        this.connection = DriverManager.getConnection(adminUrl);
        this.robotId = robotId;
    }

    /** @return the last robot step the engine served (engine_clock.step), or -1 when it has no row */
    long engineStep() throws SQLException {
        return value("SELECT step FROM engine_clock WHERE robot_id = ?");
    }

    /** @return the engine's last published iteration, or -1 */
    long engineIteration() throws SQLException {
        return value("SELECT iteration FROM engine_clock WHERE robot_id = ?");
    }

    /** @return the robot's last sensed step (robot_clock.step), or -1 */
    long robotStep() throws SQLException {
        return value("SELECT step FROM robot_clock WHERE robot_id = ?");
    }

    /** @return the robot's simulated time (robot_clock.sim_time_ms), or -1 */
    long robotSimTimeMs() throws SQLException {
        return value("SELECT sim_time_ms FROM robot_clock WHERE robot_id = ?");
    }

    /** @return the robot's run id, or -1 */
    long robotRun() throws SQLException {
        return value("SELECT run_id FROM robot_clock WHERE robot_id = ?");
    }

    /** @return the saved engine state's iteration, or -1 */
    long savedIteration() throws SQLException {
        return value("SELECT iteration FROM engine_state WHERE robot_id = ?");
    }

    /** @return how many checkpoints the engine has marked reached */
    long reached() throws SQLException {
        return value("SELECT COUNT(*) FROM checkpoints WHERE robot_id = ? AND reached");
    }

    /** @return the robot's checkpoints rows in seq order */
    List<CheckpointRow> checkpoints() throws SQLException {
        List<CheckpointRow> rows = new ArrayList<>();
        try (PreparedStatement ps = connection.prepareStatement(
                "SELECT seq, reached, reached_sim_time_ms FROM checkpoints WHERE robot_id = ? ORDER BY seq")) {
            ps.setInt(1, robotId);
            try (ResultSet rs = ps.executeQuery()) {
                while (rs.next()) {
                    boolean reached = rs.getBoolean(2);
                    long t = rs.getLong(3);
                    rows.add(new CheckpointRow(rs.getInt(1), reached, rs.wasNull() ? null : t));
                }
            }
        }
        return rows;
    }

    /** @return the first column of the first row for this robot (one ? for robot_id), or -1 without a row */
    long value(String sql) throws SQLException {
        try (PreparedStatement ps = connection.prepareStatement(sql)) {
            ps.setInt(1, robotId);
            try (ResultSet rs = ps.executeQuery()) {
                return rs.next() ? rs.getLong(1) : -1;
            }
        }
    }

    /**
     * Polls until a value satisfies the predicate; fails after the time-out or when the process
     * it waits on ended first.
     */
    long await(String what, ThrowingLong value, LongPredicate until, Process alive, long timeoutS) throws Exception {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(timeoutS);
        long v = value.get();
        while (!until.test(v)) {
            if (System.nanoTime() - deadline > 0) {
                throw new AssertionError(what + ": not reached within " + timeoutS + " s (last value " + v + ")");
            }
            if (alive != null && !alive.isAlive()) {
                throw new AssertionError(what + ": the process ended first (exit " + alive.exitValue() + ", last value " + v + ")");
            }
            Thread.sleep(2);
            v = value.get();
        }
        return v;
    }

    /** A query. */
    @FunctionalInterface
    interface ThrowingLong {
        long get() throws Exception;
    }

    @Override
    public void close() throws SQLException {
        connection.close();
    }
}
