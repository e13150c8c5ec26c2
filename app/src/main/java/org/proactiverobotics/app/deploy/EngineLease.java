package org.proactiverobotics.app.deploy;

import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.SQLIntegrityConstraintViolationException;
import javax.sql.DataSource;

/**
 * One robot's row of {@code engine_lease} as one engine process holds it: which engine serves the
 * robot. An engine takes the row when nobody holds it, when it has expired (its engine died or
 * hung), or when it carries this engine's own name while this engine has just started (its
 * earlier life was killed); each taking bumps the row's epoch. Every iteration confirms the row
 * inside its own transaction ({@link #confirm(Connection, long)}), checking owner and epoch, so
 * an engine that lost the lease commits nothing more for the robot. Times are the database
 * server's clock (milliseconds), so engines on several machines agree.
 */
public final class EngineLease {

    /** The lease is not (or no longer) this engine's: the iteration must not commit. */
    public static final class LostException extends SQLException {
        private static final long serialVersionUID = 1L;

        LostException(String message) {
            super(message);
        }
    }

    private static final String EXPIRES = "TIMESTAMPADD(MICROSECOND, ?, CURRENT_TIMESTAMP(3))";

    private final DataSource dataSource;
    private final int robotId;
    private final String owner;
    private final long ttlMs;
    private long epoch = -1;
    private boolean firstTake = true;

    /**
     * @param dataSource the shared database
     * @param robotId    the robot
     * @param owner      this engine process's name (unique among the engines sharing a fleet)
     * @param ttlMs      how long the lease lasts without renewal, milliseconds
     */
    public EngineLease(DataSource dataSource, int robotId, String owner, long ttlMs) {
        this.dataSource = dataSource;
        this.robotId = robotId;
        this.owner = owner;
        this.ttlMs = ttlMs;
    }

    /** @return whether this engine holds the lease (as far as it knows: {@link #confirm} is the proof) */
    public boolean held() {
        return epoch >= 0;
    }

    /** @return this engine's name in the lease */
    public String owner() {
        return owner;
    }

    /** @return the epoch this engine took the lease with, or -1 */
    public long epoch() {
        return epoch;
    }

    /**
     * Takes the lease when it is free, expired, or this engine's own from before its start.
     *
     * @return whether this engine now holds it
     */
    public boolean tryTake() throws SQLException {
        try (Connection c = dataSource.getConnection()) {
            c.setAutoCommit(false);
            try {
                boolean taken = update(c) || insert(c);
                long newEpoch = -1;
                if (taken) {
                    try (PreparedStatement ps = c.prepareStatement(
                            "SELECT epoch FROM engine_lease WHERE robot_id = ? AND owner = ?")) {
                        ps.setInt(1, robotId);
                        ps.setString(2, owner);
                        try (ResultSet rs = ps.executeQuery()) {
                            newEpoch = rs.next() ? rs.getLong(1) : -1;
                        }
                    }
                }
                c.commit();
                epoch = newEpoch;
                firstTake = false;
                return epoch >= 0;
            } catch (SQLException | RuntimeException e) {
                c.rollback();
                throw e;
            }
        }
    }

    private boolean update(Connection c) throws SQLException {
        try (PreparedStatement ps = c.prepareStatement("UPDATE engine_lease SET owner = ?, epoch = epoch + 1, expires_at = "
                + EXPIRES + ", taken_at = CURRENT_TIMESTAMP(3) WHERE robot_id = ? AND (expires_at < CURRENT_TIMESTAMP(3)"
                + " OR (owner = ? AND ?))")) {
            ps.setString(1, owner);
            ps.setLong(2, ttlMs * 1000);
            ps.setInt(3, robotId);
            ps.setString(4, owner);
            ps.setBoolean(5, firstTake);
            return ps.executeUpdate() == 1;
        }
    }

    private boolean insert(Connection c) throws SQLException {
        try (PreparedStatement ps = c.prepareStatement(
                "INSERT INTO engine_lease (robot_id, owner, epoch, expires_at) VALUES (?, ?, 1, " + EXPIRES + ")")) {
            ps.setInt(1, robotId);
            ps.setString(2, owner);
            ps.setLong(3, ttlMs * 1000);
            return ps.executeUpdate() == 1;
        } catch (SQLIntegrityConstraintViolationException e) {
            return false; // another engine holds the row
        } catch (SQLException e) {
            if (e.getSQLState() != null && e.getSQLState().startsWith("23")) {
                return false; // a duplicate key, as drivers without the subclass say it
            }
            throw e;
        }
    }

    /**
     * Renews the lease on the iteration's connection, inside its transaction, and records the
     * iteration: the check that makes the iteration this engine's to commit.
     *
     * @param c         the iteration's connection
     * @param iteration the iteration about to commit
     * @throws LostException when another engine has taken the lease (the iteration must roll back)
     */
    public void confirm(Connection c, long iteration) throws SQLException {
        if (epoch < 0) {
            throw new LostException("robot " + robotId + ": engine " + owner + " does not hold the lease");
        }
        try (PreparedStatement ps = c.prepareStatement("UPDATE engine_lease SET expires_at = " + EXPIRES
                + ", iteration = ? WHERE robot_id = ? AND owner = ? AND epoch = ?")) {
            ps.setLong(1, ttlMs * 1000);
            ps.setLong(2, iteration);
            ps.setInt(3, robotId);
            ps.setString(4, owner);
            ps.setLong(5, epoch);
            if (ps.executeUpdate() != 1) {
                epoch = -1;
                throw new LostException("robot " + robotId + ": engine " + owner + " lost the lease to another engine");
            }
        }
    }

    /**
     * Renews the lease outside an iteration (while the robot is idle).
     *
     * @return whether this engine still holds it
     */
    public boolean renew() throws SQLException {
        if (epoch < 0) {
            return false;
        }
        try (Connection c = dataSource.getConnection(); PreparedStatement ps = c.prepareStatement(
                "UPDATE engine_lease SET expires_at = " + EXPIRES + " WHERE robot_id = ? AND owner = ? AND epoch = ?")) {
            ps.setLong(1, ttlMs * 1000);
            ps.setInt(2, robotId);
            ps.setString(3, owner);
            ps.setLong(4, epoch);
            if (ps.executeUpdate() != 1) {
                epoch = -1;
            }
        }
        return epoch >= 0;
    }

    /** Gives the lease up (a clean stop): another engine may take it at once. */
    public void release() throws SQLException {
        if (epoch < 0) {
            return;
        }
        try (Connection c = dataSource.getConnection(); PreparedStatement ps = c.prepareStatement(
                "UPDATE engine_lease SET expires_at = TIMESTAMPADD(MICROSECOND, -1000, CURRENT_TIMESTAMP(3))"
                        + " WHERE robot_id = ? AND owner = ? AND epoch = ?")) {
            ps.setInt(1, robotId);
            ps.setString(2, owner);
            ps.setLong(3, epoch);
            ps.executeUpdate();
        } finally {
            epoch = -1;
        }
    }

    /** Forgets the lease without touching the row (the database failed: it will be taken again). */
    public void forget() {
        epoch = -1;
    }
}
