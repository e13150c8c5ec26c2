package org.proactiverobotics.robot.link;

import com.zaxxer.hikari.HikariDataSource;
import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;
import javax.sql.DataSource;
import org.proactiverobotics.db.MultiRow;
import org.proactiverobotics.db.RoundTrip;
import org.proactiverobotics.db.RobotRows;
import org.proactiverobotics.db.Writes;

/**
 * {@link RobotLink} over JDBC and the tables of {@code schema.sql}; the same SQL runs on H2
 * (MODE=MySQL) and MySQL 8 / MariaDB. Each call borrows one connection from the pool it was
 * given (keep that pool's connection time-out short on the robot: see {@link RobotPool}) and
 * gives it back; an answer is one transaction, its distance rows one batch.
 */
public final class JdbcRobotLink implements RobotLink {

    // "Newest" is by simulated time (readings) or iteration (commands), never by id: ids from
    // different Galera nodes interleave. The reads name every column of their index, as in
    // ORDER BY robot_id DESC, iteration DESC, id DESC: H2 reads the index backwards only then;
    // with ORDER BY id DESC alone it scanned every row of the robot (1 row instead of 10 000).
    private static final String PENDING =
            "SELECT id, sensor FROM sensor_requests WHERE robot_id = ? AND answered_sim_time_ms IS NULL ORDER BY id";
    private static final String INSERT_GPS =
            "INSERT INTO gps_stored_values (robot_id, sim_time_ms, x_m, y_m) VALUES (?, ?, ?, ?)";
    private static final String INSERT_IU =
            "INSERT INTO iudata (robot_id, sim_time_ms, roll_rad, pitch_rad, yaw_rad) VALUES (?, ?, ?, ?, ?)";
    /** A scan's rows in one statement (a batch was a statement per row on H2, 21 a step). */
    private static final MultiRow INSERT_DS = MultiRow.insert("distance_sensor_data",
            "robot_id", "sim_time_ms", "sensor_index", "angle_rad", "distance_m", "range_m");
    private static final String INSERT_BATTERY =
            "INSERT INTO battery_level (robot_id, sim_time_ms, level_pct, charging) VALUES (?, ?, ?, ?)";
    private static final String INSERT_ODOMETRY =
            "INSERT INTO odometry (robot_id, sim_time_ms, left_m, right_m) VALUES (?, ?, ?, ?)";
    /** Marks the requests answered in one statement; {@link #markAnswered(int)} adds the ids' placeholders. */
    private static final String MARK_ANSWERED = "UPDATE sensor_requests SET answered_sim_time_ms = ? "
            + "WHERE robot_id = ? AND answered_sim_time_ms IS NULL AND id IN (";
    private static final String[] MARK_ANSWERED_BY_COUNT = new String[17];
    private static final String NEWEST_COMMAND = "SELECT id, iteration, sim_time_ms, scenario, command "
            + "FROM engine_comments WHERE robot_id = ? ORDER BY robot_id DESC, iteration DESC, id DESC LIMIT 1";

    private final DataSource dataSource;
    private final int queryTimeoutS;
    /**
     * Per robot, the times of the distance readings this link committed, newest last: prune's cut-off
     * without asking the database, whose DISTINCT over every kept row was 3 % of an H2 mission (JFR).
     */
    private final Map<Integer, ReadingTimes> distanceTimes = new ConcurrentHashMap<>();
    /** Whether the server takes an answer as one multi-statement round trip; null until the first answer. */
    private volatile Boolean multiStatements;
    /** What a sync clock read with the engine's tick, for the next read of it (each taken once); null: nothing. */
    private volatile HandedOff handedOff;
    /** Whether answers are kept to commit with the step's publication (a sync clock over multi-statements). */
    private volatile boolean deferAnswers;
    /** The answer kept for the step's publication, or null. */
    private volatile Deferred deferred;
    /** The robot's clock, made on the first {@link #clock()} (its handshake locks are let go of by {@link #close()}). */
    private JdbcRobotClock clock;

    /** An answer not yet committed, for one robot, and whether a commit of it failed (its outcome unknown). */
    private record Deferred(int robotId, SensorAnswer answer, boolean failedBefore) {
    }

    /** The newest command and the pending requests as read with an engine tick, for one robot. */
    private record HandedOff(int robotId, Optional<CommandRecord> command, List<SensorRequest> pending,
                             boolean commandTaken, boolean pendingTaken) {
    }

    /**
     * @param dataSource    the database (not closed by this link)
     * @param queryTimeoutS the longest any one statement may run, seconds, or 0 for no limit.
     *                      Costly on H2 (each statement then changes a session setting: about 5x
     *                      the time of a step); {@link RobotPool} bounds a hung MariaDB / MySQL
     *                      server with a socket time-out instead
     */
    public JdbcRobotLink(DataSource dataSource, int queryTimeoutS) {
        this.dataSource = Objects.requireNonNull(dataSource, "dataSource");
        if (queryTimeoutS < 0) {
            throw new IllegalArgumentException("queryTimeoutS must be >= 0: " + queryTimeoutS);
        }
        this.queryTimeoutS = queryTimeoutS;
    }

    /** @param dataSource the database (not closed by this link); no statement time-out */
    public JdbcRobotLink(DataSource dataSource) {
        this(dataSource, 0);
    }

    /**
     * A clock over the same database that, in sync timing, reads the newest command and the
     * pending requests in the same query as the engine's tick, and hands them to this link: the
     * robot's next {@link #newestCommand} and {@link #pendingRequests} are then no round trips
     * (nothing writes them between the engine's iteration and the robot's next step).
     *
     * @return the robot's clock, sharing reads with this link
     */
    public synchronized JdbcRobotClock clock() {
        if (clock == null) {
            clock = new JdbcRobotClock(dataSource, this);
        }
        return clock;
    }

    /** Keeps what was read with the engine's tick for the next reads (see {@link #clock()}). */
    void handOff(int robotId, Optional<CommandRecord> command, List<SensorRequest> pending) {
        handedOff = new HandedOff(robotId, command, List.copyOf(pending), false, false);
    }

    /** Forgets the times of the readings written for a robot (its run begins again: its readings were deleted). */
    void forgetWrites(int robotId) {
        distanceTimes.remove(robotId);
    }

    /** Forgets what was handed off (the robot published a step: the engine may write again). */
    void dropHandOff() {
        handedOff = null;
    }

    @Override
    public List<SensorRequest> pendingRequests(int robotId) throws LinkException {
        HandedOff h = handedOff;
        if (h != null && h.robotId() == robotId && !h.pendingTaken()) {
            handedOff = new HandedOff(robotId, h.command(), h.pending(), h.commandTaken(), true);
            return new ArrayList<>(h.pending());
        }
        return withConnection("reading sensor_requests", c -> {
            try (PreparedStatement ps = prepare(c, PENDING)) {
                ps.setInt(1, robotId);
                try (ResultSet rs = ps.executeQuery()) {
                    List<SensorRequest> out = new ArrayList<>(4);
                    while (rs.next()) {
                        out.add(new SensorRequest(rs.getLong(1), rs.getString(2)));
                    }
                    return out;
                }
            }
        });
    }

    /**
     * Whether answers wait for the step's publication, to commit with it (the sync clock asks for
     * it: the engine reads the answer only once the step is published).
     */
    synchronized void deferAnswers(boolean defer) {
        deferAnswers = defer;
        deferred = null; // a run begins: an answer kept from an earlier run is not this run's
    }

    /**
     * For a world's publication of several robots' steps in one transaction ({@link JdbcWorldClock}):
     * adds the answer kept for the robot's step to the round trip.
     *
     * @param trip    the world's round trip
     * @param robotId the robot
     * @return the answer added, or null when none was kept
     */
    synchronized SensorAnswer addDeferredTo(RoundTrip trip, int robotId) throws SQLException {
        Deferred d = deferred;
        if (d == null || d.robotId() != robotId) {
            return null;
        }
        write(trip, robotId, d.answer());
        return d.answer();
    }

    /**
     * The world's publication that carried the kept answer committed: it is written.
     *
     * @param robotId the robot
     * @param answer  the answer {@link #addDeferredTo} added
     */
    synchronized void deferredCommitted(int robotId, SensorAnswer answer) {
        if (deferred != null && deferred.answer() == answer) {
            deferred = null;
        }
        remember(robotId, answer);
    }

    /**
     * Commits the answer kept for the step's publication together with it, as one round trip.
     *
     * @param robotId   the robot
     * @param runId     the run the step is published for
     * @param step      the step published
     * @param statement the publication (an UPDATE), without a semicolon
     * @param parameters how many '?' it has
     * @param binder    binds them
     * @return the publication's update count, or -1 when no answer was kept (publish alone)
     */
    synchronized int commitAnswerWith(int robotId, long runId, long step, String statement, int parameters,
                                      Writes.Binder binder) throws LinkException {
        Deferred d = deferred;
        if (d == null || d.robotId() != robotId) {
            return -1;
        }
        return withConnection("writing " + d.answer().readingCount() + " reading(s) and the step", c -> {
            if (d.failedBefore() && publishedAlready(c, robotId, runId, step)) {
                deferred = null; // the failed attempt did commit (its answer was lost on the way back): never twice
                remember(robotId, d.answer());
                return -1;
            }
            RoundTrip trip = new RoundTrip();
            write(trip, robotId, d.answer());
            trip.add(statement, parameters, binder);
            int[] counts;
            try {
                counts = trip.commit(c);
            } catch (SQLException e) {
                deferred = new Deferred(robotId, d.answer(), true); // kept for the retry of the publication
                throw e;
            }
            deferred = null;
            remember(robotId, d.answer());
            return counts[counts.length - 1];
        });
    }

    /** Whether robot_clock already shows this step of this run (a commit whose outcome was not known). */
    private static boolean publishedAlready(Connection c, int robotId, long runId, long step) throws SQLException {
        try (PreparedStatement ps = c.prepareStatement("SELECT step FROM robot_clock WHERE robot_id = ? AND run_id = ?")) {
            ps.setInt(1, robotId);
            ps.setLong(2, runId);
            try (ResultSet rs = ps.executeQuery()) {
                return rs.next() && rs.getLong(1) >= step;
            }
        }
    }

    @Override
    public synchronized void answer(int robotId, SensorAnswer answer) throws LinkException {
        Deferred older = deferred;
        if (older != null) { // never two answers kept: the older commits first
            commitNow(older.robotId(), older.answer());
            deferred = null;
        }
        if (deferAnswers && Boolean.TRUE.equals(multiStatements)) {
            deferred = new Deferred(robotId, answer, false); // goes with the step's publication (commitAnswerWith)
            return;
        }
        commitNow(robotId, answer);
    }

    private void commitNow(int robotId, SensorAnswer answer) throws LinkException {
        withConnection("writing " + answer.readingCount() + " reading(s)", c -> {
            if (oneRoundTrip(c)) {
                RoundTrip trip = new RoundTrip();
                write(trip, robotId, answer);
                if (trip.statements() > 0) {
                    trip.commit(c);
                }
            } else {
                c.setAutoCommit(false);
                try {
                    write(Writes.atOnce(c, queryTimeoutS), robotId, answer);
                    c.commit();
                } catch (SQLException | RuntimeException e) {
                    rollbackQuietly(c, e);
                    throw e;
                }
            }
            remember(robotId, answer);
            return null;
        });
    }

    /** An answer's readings and the marks of the requests it answers. */
    private static void write(Writes writes, int robotId, SensorAnswer answer) throws SQLException {
        long t = answer.simTimeMs();
        if (answer.gps() != null) {
            writes.add(INSERT_GPS, 4, (ps, p) -> {
                ps.setInt(p, robotId);
                ps.setLong(p + 1, t);
                ps.setDouble(p + 2, answer.gps().xM());
                ps.setDouble(p + 3, answer.gps().yM());
            });
        }
        if (answer.iu() != null) {
            writes.add(INSERT_IU, 5, (ps, p) -> {
                ps.setInt(p, robotId);
                ps.setLong(p + 1, t);
                ps.setDouble(p + 2, answer.iu().rollRad());
                ps.setDouble(p + 3, answer.iu().pitchRad());
                ps.setDouble(p + 4, answer.iu().yawRad());
            });
        }
        writes.addRows(INSERT_DS, 6, answer.distances().size(), distanceRows(robotId, answer));
        if (answer.battery() != null) {
            writes.add(INSERT_BATTERY, 4, (ps, p) -> bindBattery(ps, p, robotId, t, answer.battery()));
        }
        if (answer.odometry() != null) {
            writes.add(INSERT_ODOMETRY, 4, (ps, p) -> {
                ps.setInt(p, robotId);
                ps.setLong(p + 1, t);
                ps.setDouble(p + 2, answer.odometry().leftM());
                ps.setDouble(p + 3, answer.odometry().rightM());
            });
        }
        long[] ids = answer.requestIds();
        if (ids.length > 0) {
            writes.add(markAnswered(ids.length), 2 + ids.length, (ps, p) -> {
                ps.setLong(p, t);
                ps.setInt(p + 1, robotId);
                for (int k = 0; k < ids.length; k++) {
                    ps.setLong(p + 2 + k, ids[k]);
                }
            });
        }
    }

    /**
     * Whether answers go as one round trip, found out on the first answer: not with a statement
     * time-out (MariaDB's driver bounds only the first statement of a multi-statement text), nor
     * on a server that refuses multi-statements (a pool not opened by {@link RobotPool}).
     */
    private boolean oneRoundTrip(Connection c) throws SQLException {
        Boolean multi = multiStatements;
        if (multi == null) {
            multi = queryTimeoutS == 0 && RoundTrip.allowed(c);
            multiStatements = multi;
        }
        return multi;
    }

    /** Binds an answer's distance readings, one row each. */
    private static MultiRow.RowBinder distanceRows(int robotId, SensorAnswer answer) {
        List<DistanceReading> distances = answer.distances();
        long t = answer.simTimeMs();
        return (ps, p, r) -> {
            DistanceReading d = distances.get(r);
            ps.setInt(p, robotId);
            ps.setLong(p + 1, t);
            ps.setInt(p + 2, d.sensorIndex());
            ps.setDouble(p + 3, d.angleRad());
            ps.setDouble(p + 4, d.distanceM());
            ps.setDouble(p + 5, d.rangeM());
        };
    }

    private void remember(int robotId, SensorAnswer answer) {
        if (!answer.distances().isEmpty()) {
            distanceTimes.computeIfAbsent(robotId, id -> new ReadingTimes()).add(answer.simTimeMs());
        }
    }

    @Override
    public void writeBattery(int robotId, long simTimeMs, BatteryReading reading) throws LinkException {
        withConnection("writing battery_level", c -> {
            try (PreparedStatement ps = prepare(c, INSERT_BATTERY)) {
                bindBattery(ps, robotId, simTimeMs, reading);
                ps.executeUpdate();
                return null;
            }
        });
    }

    @Override
    public Optional<CommandRecord> newestCommand(int robotId) throws LinkException {
        HandedOff h = handedOff;
        if (h != null && h.robotId() == robotId && !h.commandTaken()) {
            handedOff = new HandedOff(robotId, h.command(), h.pending(), true, h.pendingTaken());
            return h.command();
        }
        return withConnection("reading engine_comments", c -> {
            try (PreparedStatement ps = prepare(c, NEWEST_COMMAND)) {
                ps.setInt(1, robotId);
                try (ResultSet rs = ps.executeQuery()) {
                    if (!rs.next()) {
                        return Optional.<CommandRecord>empty();
                    }
                    return Optional.of(new CommandRecord(rs.getLong(1), rs.getLong(2), rs.getLong(3), rs.getString(4),
                            rs.getString(5)));
                }
            }
        });
    }

    @Override
    public boolean checkpointUnreachable(int robotId) throws LinkException {
        return withConnection("reading checkpoints", c -> {
            try (PreparedStatement ps = prepare(c,
                    "SELECT COUNT(*) FROM checkpoints WHERE robot_id = ? AND unreachable = TRUE")) {
                ps.setInt(1, robotId);
                try (ResultSet rs = ps.executeQuery()) {
                    return rs.next() && rs.getLong(1) > 0;
                }
            }
        });
    }

    @Override
    public boolean seedMission(int robotId, MissionSpec mission) throws LinkException {
        return withConnection("seeding the mission rows", c -> {
            c.setAutoCommit(false);
            try {
                boolean wrote = false;
                if (count(c, "checkpoints", robotId) == 0) {
                    try (PreparedStatement ps = prepare(c,
                            "INSERT INTO checkpoints (robot_id, seq, x_m, y_m, radius_m, reached) VALUES (?, ?, ?, ?, ?, ?)")) {
                        int seq = 0;
                        for (MissionSpec.Checkpoint cp : mission.checkpoints()) {
                            ps.setInt(1, robotId);
                            ps.setInt(2, seq++);
                            ps.setDouble(3, cp.xM());
                            ps.setDouble(4, cp.yM());
                            ps.setDouble(5, cp.radiusM());
                            ps.setBoolean(6, false);
                            ps.addBatch();
                        }
                        ps.executeBatch();
                    }
                    wrote = true;
                }
                if (count(c, "recharge_station", robotId) == 0) {
                    try (PreparedStatement ps = prepare(c,
                            "INSERT INTO recharge_station (robot_id, x_m, y_m, radius_m) VALUES (?, ?, ?, ?)")) {
                        ps.setInt(1, robotId);
                        ps.setDouble(2, mission.station().xM());
                        ps.setDouble(3, mission.station().yM());
                        ps.setDouble(4, mission.station().radiusM());
                        ps.executeUpdate();
                    }
                    wrote = true;
                }
                if (mission.start() != null && count(c, "initial_pose", robotId) == 0) {
                    try (PreparedStatement ps = prepare(c,
                            "INSERT INTO initial_pose (robot_id, x_m, y_m, yaw_rad) VALUES (?, ?, ?, ?)")) {
                        ps.setInt(1, robotId);
                        ps.setDouble(2, mission.start().xM());
                        ps.setDouble(3, mission.start().yM());
                        ps.setDouble(4, mission.start().yawRad());
                        ps.executeUpdate();
                    }
                    wrote = true;
                }
                if (count(c, "battery_recharged", robotId) == 0) {
                    try (PreparedStatement ps = prepare(c,
                            "INSERT INTO battery_recharged (robot_id, level_pct) VALUES (?, ?)")) {
                        ps.setInt(1, robotId);
                        ps.setDouble(2, mission.rechargeToPct());
                        ps.executeUpdate();
                    }
                    wrote = true;
                }
                c.commit();
                return wrote;
            } catch (SQLException | RuntimeException e) {
                rollbackQuietly(c, e);
                throw e;
            }
        });
    }

    @Override
    public int prune(int robotId, RetentionPolicy policy) throws LinkException {
        if (!policy.prunes()) {
            return 0;
        }
        int keep = policy.keepReadings();
        return withConnection("pruning reading history", c -> {
            int deleted = 0;
            for (String table : new String[] {"gps_stored_values", "iudata", "battery_level", "odometry"}) {
                deleted += RobotRows.pruneOlderThanNewest(c, robotId, table, "sim_time_ms", "", keep, queryTimeoutS);
            }
            // One distance reading = the rows sharing a sim_time_ms; served by idx_ds_time.
            String deleteDistances = "DELETE FROM distance_sensor_data WHERE robot_id = ? AND sim_time_ms <= ?";
            ReadingTimes written = distanceTimes.get(robotId);
            long cutoff = written == null ? -1 : written.newest(keep + 1);
            if (cutoff >= 0) {
                deleted += delete(c, robotId, deleteDistances, cutoff);
            } else { // a link that did not write them all (a restarted robot process) asks the table
                deleted += pruneBy(c, robotId,
                        "SELECT DISTINCT robot_id, sim_time_ms FROM distance_sensor_data WHERE robot_id = ? "
                                + "ORDER BY robot_id DESC, sim_time_ms DESC LIMIT 1 OFFSET " + keep,
                        deleteDistances);
            }
            // sensor_requests is the engine's table: the engine prunes its answered rows.
            return deleted;
        });
    }

    @Override
    public void close() {
        JdbcRobotClock c;
        synchronized (this) {
            c = clock;
        }
        if (c != null) {
            c.closeLocks(); // the handshake's locks are held between calls: let go of them; the pool belongs to whoever gave it
        }
    }

    /**
     * Runs work on a borrowed connection. After a failure the connections of a Hikari pool are
     * evicted rather than handed out again: some drivers (H2 over TCP) report a dead connection
     * with an SQL state Hikari does not know as fatal, and a recently used connection is not
     * validated, so the pool would hand out the dead one again and again.
     */
    private <T> T withConnection(String what, SqlWork<T> work) throws LinkException {
        Connection c;
        try {
            c = dataSource.getConnection();
        } catch (SQLException e) {
            throw failure(what, e);
        }
        try {
            return work.run(c);
        } catch (SQLException e) {
            if (dataSource instanceof HikariDataSource hikari && hikari.getHikariPoolMXBean() != null) {
                // idle connections are closed now, this one when it is given back below
                hikari.getHikariPoolMXBean().softEvictConnections();
            }
            throw failure(what, e);
        } finally {
            try {
                c.close();
            } catch (SQLException | RuntimeException ignored) {
                // broken: nothing more to release
            }
        }
    }

    /** Work on one connection. */
    @FunctionalInterface
    private interface SqlWork<T> {
        T run(Connection c) throws SQLException;
    }

    private int pruneBy(Connection c, int robotId, String findCutoff, String delete) throws SQLException {
        long cutoff;
        try (PreparedStatement ps = prepare(c, findCutoff)) {
            ps.setInt(1, robotId);
            try (ResultSet rs = ps.executeQuery()) {
                if (!rs.next()) {
                    return 0;
                }
                cutoff = rs.getLong(2); // the first column is robot_id
            }
        }
        return delete(c, robotId, delete, cutoff);
    }

    private int delete(Connection c, int robotId, String delete, long cutoff) throws SQLException {
        try (PreparedStatement ps = prepare(c, delete)) {
            ps.setInt(1, robotId);
            ps.setLong(2, cutoff);
            return ps.executeUpdate();
        }
    }

    private long count(Connection c, String table, int robotId) throws SQLException {
        try (PreparedStatement ps = prepare(c, "SELECT COUNT(*) FROM " + table + " WHERE robot_id = ?")) {
            ps.setInt(1, robotId);
            try (ResultSet rs = ps.executeQuery()) {
                rs.next();
                return rs.getLong(1);
            }
        }
    }

    private PreparedStatement prepare(Connection c, String sql) throws SQLException {
        PreparedStatement ps = c.prepareStatement(sql);
        if (queryTimeoutS > 0) {
            ps.setQueryTimeout(queryTimeoutS);
        }
        return ps;
    }

    /** @return the statement marking that many requests answered */
    private static String markAnswered(int ids) {
        String s = ids < MARK_ANSWERED_BY_COUNT.length ? MARK_ANSWERED_BY_COUNT[ids] : null;
        if (s == null) {
            s = MARK_ANSWERED + "?" + ", ?".repeat(ids - 1) + ")";
            if (ids < MARK_ANSWERED_BY_COUNT.length) {
                MARK_ANSWERED_BY_COUNT[ids] = s;
            }
        }
        return s;
    }

    private static void bindBattery(PreparedStatement ps, int robotId, long simTimeMs, BatteryReading reading)
            throws SQLException {
        bindBattery(ps, 1, robotId, simTimeMs, reading);
    }

    private static void bindBattery(PreparedStatement ps, int first, int robotId, long simTimeMs, BatteryReading reading)
            throws SQLException {
        ps.setInt(first, robotId);
        ps.setLong(first + 1, simTimeMs);
        ps.setDouble(first + 2, reading.levelPct());
        ps.setBoolean(first + 3, reading.charging());
    }

    private static void rollbackQuietly(Connection c, Exception cause) {
        try {
            c.rollback();
        } catch (SQLException rollback) {
            cause.addSuppressed(rollback);
        }
    }

    private static LinkException failure(String what, SQLException e) {
        return new LinkException(what + " failed: " + e.getMessage(), e);
    }
}
