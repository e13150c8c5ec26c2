package org.proactiverobotics.robot.link;

import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
import javax.sql.DataSource;
import org.proactiverobotics.db.HandshakeLocks;
import org.proactiverobotics.db.RobotRows;
import org.proactiverobotics.db.Writes;
import org.proactiverobotics.protocol.RunState;
import org.proactiverobotics.protocol.Timing;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * {@link RobotClock} over JDBC: {@code robot_clock} and {@code engine_clock} of schema.sql. Runs
 * with the robot user's grants: it writes only {@code robot_clock} and the robot's readings.
 */
public final class JdbcRobotClock implements RobotClock {

    private static final Logger LOG = LoggerFactory.getLogger(JdbcRobotClock.class);

    private static final List<String> READING_TABLES = List.of("gps_stored_values", "iudata", "distance_sensor_data", "battery_level",
            "odometry");

    /** The engine's tick, the newest command and the pending requests, in one round trip. */
    private static final String TICK_WITH_READS = "(SELECT 1 AS k, run_id AS a, step AS b, iteration AS c, '' AS s1, '' AS s2"
            + " FROM engine_clock WHERE robot_id = ?)"
            + " UNION ALL (SELECT 2, id, iteration, sim_time_ms, scenario, command FROM engine_comments WHERE robot_id = ?"
            + " ORDER BY robot_id DESC, iteration DESC, id DESC LIMIT 1)"
            + " UNION ALL (SELECT 3, id, 0, 0, sensor, '' FROM sensor_requests WHERE robot_id = ? AND answered_sim_time_ms IS NULL)";

    /** "Sensed step k": the robot's half of the handshake. */
    private static final String PUBLISH = "UPDATE robot_clock SET step = ?, sim_time_ms = ?, state = ?, "
            + "updated_at = CURRENT_TIMESTAMP(3) WHERE robot_id = ? AND run_id = ?";

    private final DataSource dataSource;
    /** The link that takes the reads made with a sync tick, or null. */
    private final JdbcRobotLink link;
    private volatile boolean sync;
    /** The wake-ups of the sync handshake on MariaDB (one robot per clock in use), or null before a sync run. */
    private HandshakeLocks locks;
    /** The longest wait in the server for the engine's iteration: the robot looks at its stop flag this often. */
    static final long LOCK_WAIT_NANOS = 200_000_000L;

    /** @param dataSource the shared database (not closed by this clock) */
    public JdbcRobotClock(DataSource dataSource) {
        this(dataSource, null);
    }

    /**
     * @param dataSource the shared database (not closed by this clock)
     * @param link       takes the newest command and the pending requests read with each sync tick, or null
     */
    JdbcRobotClock(DataSource dataSource, JdbcRobotLink link) {
        this.dataSource = Objects.requireNonNull(dataSource, "dataSource");
        this.link = link;
    }

    @Override
    public long beginRun(int robotId, Timing timing) throws LinkException {
        sync = timing == Timing.SYNC; // in real time the engine writes while the robot steps: nothing handed off
        openLocks(sync && link != null ? robotId : -1);
        if (link != null) {
            link.dropHandOff();
            link.forgetWrites(robotId); // the run's readings start again from none
            link.deferAnswers(sync); // a step's answer commits with its publication: one round trip, one flush
        }
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
                RobotRows.delete(c, robotId, READING_TABLES);
                try (PreparedStatement ps = c.prepareStatement("UPDATE robot_clock SET run_id = ?, step = 0, sim_time_ms = 0, "
                        + "timing = ?, state = 'RUNNING', updated_at = CURRENT_TIMESTAMP(3) WHERE robot_id = ?")) {
                    ps.setLong(1, runId);
                    ps.setString(2, timing.label());
                    ps.setInt(3, robotId);
                    if (ps.executeUpdate() == 0) {
                        try (PreparedStatement insert = c.prepareStatement("INSERT INTO robot_clock "
                                + "(robot_id, run_id, step, sim_time_ms, timing, state) VALUES (?, ?, 0, 0, ?, 'RUNNING')")) {
                            insert.setInt(1, robotId);
                            insert.setLong(2, runId);
                            insert.setString(3, timing.label());
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
    public void publish(int robotId, long runId, long step, long simTimeMs, RunState state) throws LinkException {
        Writes.Binder binder = (ps, p) -> {
            ps.setLong(p, step);
            ps.setLong(p + 1, simTimeMs);
            ps.setString(p + 2, state.name());
            ps.setInt(p + 3, robotId);
            ps.setLong(p + 4, runId);
        };
        int updated = -1;
        try {
            if (link != null) {
                link.dropHandOff(); // the engine may write once it sees this step
                updated = link.commitAnswerWith(robotId, runId, step, PUBLISH, 5, binder);
            }
            if (updated < 0) {
                try (Connection c = dataSource.getConnection(); PreparedStatement ps = c.prepareStatement(PUBLISH)) {
                    binder.bind(ps, 1);
                    updated = ps.executeUpdate();
                } catch (SQLException e) {
                    throw new LinkException("publishing step " + step + " of robot " + robotId + " failed: " + e.getMessage(), e);
                }
            }
        } finally {
            if (state != RunState.RUNNING) {
                closeLocks(); // the run is over, published or not: no lock of this robot may keep the engine waiting
            }
        }
        if (updated == 0) {
            throw new LinkException("robot_clock has no row for robot " + robotId + " run " + runId
                    + ": another robot process with the same robot id started a run", null);
        }
    }

    @Override
    public Optional<EngineTick> engineTick(int robotId) throws LinkException {
        if (link != null && sync) {
            return tickWithReads(robotId);
        }
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

    @Override
    public synchronized boolean waitsInServer() {
        try {
            return locks != null && locks.usable() && !locks.paused();
        } catch (SQLException e) {
            return false; // the database is away: the polls' retries say so
        }
    }

    @Override
    public synchronized Optional<EngineTick> awaitServed(int robotId, long step) throws LinkException {
        if (!waitsInServer()) {
            return engineTick(robotId);
        }
        try { // "sensed step k" given (its answer is committed), "served step k" awaited
            Optional<EngineTick> tick = locks.exchange(HandshakeLocks.sensed(step), HandshakeLocks.served(step), LOCK_WAIT_NANOS,
                    TICK_WITH_READS, (ps, p) -> bindTick(ps, p, robotId), rs -> readTick(rs, robotId));
            locks.found(tick.isPresent() && tick.get().step() >= step); // an engine serving several robots per thread polls
            return tick;
        } catch (SQLException e) {
            throw new LinkException("waiting for the engine to serve step " + step + " of robot " + robotId + " failed: "
                    + e.getMessage(), e);
        }
    }

    /** A new run: the locks of an earlier run go; a sync run of a robot gets its own (robotId -1: none). */
    private synchronized void openLocks(int robotId) {
        closeLocks();
        if (robotId >= 0) {
            locks = new HandshakeLocks(dataSource, robotId);
        }
    }

    /** Lets go of the handshake's locks and their connection (the run is over, or the link closes). */
    synchronized void closeLocks() {
        if (locks != null) {
            if (locks.waits() > 0) {
                LOG.info("robot {}: handshake: {} waits on the engine's locks in the database, {} of them timed out", locks.robotId(),
                        locks.waits(), locks.count(HandshakeLocks.Wake.TIMED_OUT));
            }
            locks.close();
            locks = null;
        }
    }

    private Optional<EngineTick> tickWithReads(int robotId) throws LinkException {
        try (Connection c = dataSource.getConnection(); PreparedStatement ps = c.prepareStatement(TICK_WITH_READS)) {
            bindTick(ps, 1, robotId);
            try (ResultSet rs = ps.executeQuery()) {
                return readTick(rs, robotId);
            }
        } catch (SQLException e) {
            throw new LinkException("reading engine_clock of robot " + robotId + " failed: " + e.getMessage(), e);
        }
    }

    private static void bindTick(PreparedStatement ps, int first, int robotId) throws SQLException {
        ps.setInt(first, robotId);
        ps.setInt(first + 1, robotId);
        ps.setInt(first + 2, robotId);
    }

    /** Reads TICK_WITH_READS' rows: the engine's tick is returned, the command and the requests handed to the link. */
    private Optional<EngineTick> readTick(ResultSet rs, int robotId) throws SQLException {
        EngineTick tick = null;
        Optional<CommandRecord> command = Optional.empty();
        List<SensorRequest> pending = new ArrayList<>(4);
        while (rs.next()) {
            switch (rs.getInt(1)) {
                case 1 -> tick = new EngineTick(rs.getLong(2), rs.getLong(3), rs.getLong(4));
                case 2 -> command = Optional.of(new CommandRecord(rs.getLong(2), rs.getLong(3), rs.getLong(4),
                        rs.getString(5), rs.getString(6)));
                case 3 -> pending.add(new SensorRequest(rs.getLong(2), rs.getString(5)));
                default -> throw new SQLException("unknown row kind " + rs.getInt(1));
            }
        }
        pending.sort(Comparator.comparingLong(SensorRequest::id)); // as pendingRequests reads them: ORDER BY id
        link.handOff(robotId, command, pending);
        return Optional.ofNullable(tick);
    }
}
