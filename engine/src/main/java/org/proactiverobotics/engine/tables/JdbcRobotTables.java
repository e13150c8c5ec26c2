package org.proactiverobotics.engine.tables;

import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Optional;
import java.util.OptionalDouble;
import javax.sql.DataSource;
import org.proactiverobotics.db.MultiRow;
import org.proactiverobotics.db.RobotRows;
import org.proactiverobotics.db.Writes;
import org.proactiverobotics.engine.persistence.IterationTransaction;

/**
 * The engine side's tables over JDBC, for one robot. Every statement is plain SQL that H2
 * (MySQL mode), MariaDB and MySQL 8 all run (upserts aside: {@link MultiRow} words them for each);
 * every read goes through a {@code robot_id} index.
 *
 * <p>Over an {@link IterationTransaction}, during an iteration, the rules' reads are served from
 * an {@link IterationSnapshot} read in one query the first time a rule reads (or before the
 * iteration, with other robots' snapshots: {@link #readAhead}), the rules' requests and marks are kept and sent as batches on the iteration's connection just before it
 * commits, and the iteration's command goes on that connection at once: a constant, small number of round trips per iteration whatever the
 * rules ask. Outside an iteration every call is its own statement, as before.
 */
public final class JdbcRobotTables
        implements SensorReadings, SensorRequests, MissionTables, StrategyTable, EngineComments, OccupancyMapTable,
        PoseEstimateTable {

    private final DataSource dataSource;
    private final int robotId;
    /** The iteration's transaction when the data source is one, else null (no snapshot, no buffering). */
    private final IterationTransaction transaction;
    private IterationSnapshot snapshot;
    /** The next iteration's snapshot, read ahead with other robots' ({@link #readAhead}), or null. */
    private IterationSnapshot readAhead;
    private List<Object[]> pendingRequests = new ArrayList<>();
    private List<Object[]> pendingMarks = new ArrayList<>();
    /** The pose estimate the open iteration wrote, committed with it, or null. */
    private PoseEstimate writtenPose;
    /** The newest pose estimate as the open iteration knows it (read once, or written): every rule reads the pose. */
    private Optional<PoseEstimate> iterationPose;
    private long iterationPoseIteration = Long.MIN_VALUE;
    private long snapshotLoads;

    private static final MultiRow INSERT_REQUESTS = MultiRow.insert("sensor_requests", "robot_id", "sensor", "iteration");
    private static final String MARK_REACHED =
            "UPDATE checkpoints SET reached = TRUE, reached_sim_time_ms = ? WHERE robot_id = ? AND seq = ?";
    private static final MultiRow UPSERT_CHUNKS = MultiRow.upsert("occupancy_map", List.of("robot_id", "chunk_x", "chunk_y"),
            "robot_id", "chunk_x", "chunk_y", "cells", "updated_sim_time_ms");
    private static final String INSERT_POSE = "INSERT INTO pose_estimate (robot_id, sim_time_ms, x_m, y_m, yaw_rad,"
            + " var_x, var_y, var_yaw, cov_xy, cov_x_yaw, cov_y_yaw) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)";
    private static final String INSERT_COMMAND =
            "INSERT INTO engine_comments (robot_id, iteration, sim_time_ms, scenario, command) VALUES (?, ?, ?, ?, ?)";

    /**
     * @param dataSource the shared database
     * @param robotId    the robot whose rows are read and written
     */
    public JdbcRobotTables(DataSource dataSource, int robotId) {
        this.dataSource = dataSource;
        this.robotId = robotId;
        this.transaction = dataSource instanceof IterationTransaction t ? t : null;
        if (transaction != null) {
            transaction.beforeCommit(this::flush);
            transaction.onRollback(this::forgetIteration);
        }
    }

    /** @return how many iteration snapshots were read (one query each): a benchmark's count of logical loads */
    public long snapshotLoads() {
        return snapshotLoads;
    }

    /** @return the open iteration's snapshot (read now when this is the iteration's first read), or null outside one */
    private IterationSnapshot snapshot() {
        Connection c = transaction == null ? null : transaction.readConnection();
        if (c == null) {
            return null;
        }
        long iteration = transaction.iterationNumber();
        if (snapshot == null || snapshot.iteration != iteration) {
            if (readAhead != null) { // the iteration's first read: take up what was read ahead for it
                snapshot = readAhead;
                snapshot.iteration = iteration;
                readAhead = null;
                snapshotLoads++;
                return snapshot;
            }
            try {
                snapshot = IterationSnapshot.load(c, robotId, iteration);
                snapshotLoads++;
            } catch (SQLException e) {
                throw failure("reading the tables of robot " + robotId + " for the iteration", e);
            }
        }
        return snapshot;
    }

    /**
     * Reads the snapshot of each robot's next iteration ahead, for several robots in one query,
     * where each would otherwise read its own at its iteration's first read: for an engine that
     * runs several robots' iterations one after the other. Only where nothing but the robot
     * writes its rows until that iteration (a robot waiting in lockstep, or real-time timing,
     * which reads one moment of the robot's writes anyway); {@link #dropReadAhead} after the
     * iterations, so that a snapshot not taken up is never used later.
     *
     * @param c      a connection (outside any iteration's transaction)
     * @param tables the robots' tables, over one database
     * @return whether they were read: not on H2 (in-process, or a server of its own), where the
     *         several robots' query ran slower than their own ones (ManyRobots)
     * @throws SQLException when the query fails (nothing is kept: each iteration then reads its own)
     */
    public static boolean readAhead(Connection c, List<JdbcRobotTables> tables) throws SQLException {
        if (MultiRow.isH2(c)) {
            return false;
        }
        int[] ids = new int[tables.size()];
        for (int i = 0; i < ids.length; i++) {
            ids[i] = tables.get(i).robotId;
        }
        IterationSnapshot[] read = IterationSnapshot.loadAll(c, ids);
        for (int i = 0; i < ids.length; i++) {
            tables.get(i).readAhead = read[i];
        }
        return true;
    }

    /** Forgets a snapshot read ahead that no iteration took up. */
    public void dropReadAhead() {
        readAhead = null;
    }

    /** @return whether a write is kept for the iteration's commit (an iteration is open on this thread) */
    private boolean buffering() {
        return transaction != null && transaction.readConnection() != null;
    }

    /** The iteration's requests and marks just before its commit (with it, where writes are deferred). */
    private void flush() throws SQLException {
        try {
            writePending(transaction.writes());
        } finally {
            forgetIteration();
        }
    }

    /** The requests and marks kept so far: the requests in one statement, a statement per mark. */
    private void writePending(Writes writes) throws SQLException {
        List<Object[]> requests = pendingRequests;
        List<Object[]> marks = pendingMarks;
        pendingRequests = new ArrayList<>(); // a deferred write still binds these
        pendingMarks = new ArrayList<>();
        writes.addRows(INSERT_REQUESTS, 3, requests.size(), (ps, p, r) -> bind(ps, p, requests.get(r)));
        for (Object[] mark : marks) {
            writes.add(MARK_REACHED, 3, (ps, p) -> bind(ps, p, mark));
        }
        PoseEstimate pose = writtenPose;
        if (pose != null) {
            writes.add(INSERT_POSE, 11, (ps, p) -> bind(ps, p, poseRow(pose)));
        }
    }

    private Object[] poseRow(PoseEstimate e) {
        return new Object[] {robotId, e.simTimeMs(), e.xM(), e.yM(), e.yawRad(), e.varX(), e.varY(), e.varYaw(), e.covXY(),
            e.covXYaw(), e.covYYaw()};
    }

    /** In an iteration, read once and kept for its later reads (this engine alone writes the rows). */
    @Override
    public Optional<PoseEstimate> newestPose() {
        boolean inIteration = buffering();
        if (inIteration && iterationPoseIteration == transaction.iterationNumber()) {
            return iterationPose;
        }
        Optional<PoseEstimate> newest = queryOne("newest pose estimate", "SELECT sim_time_ms, x_m, y_m, yaw_rad, var_x, var_y,"
                + " var_yaw, cov_xy, cov_x_yaw, cov_y_yaw FROM pose_estimate WHERE robot_id = ?"
                + " ORDER BY robot_id DESC, sim_time_ms DESC, id DESC LIMIT 1",
                rs -> new PoseEstimate(rs.getLong(1), rs.getDouble(2), rs.getDouble(3), rs.getDouble(4), rs.getDouble(5),
                        rs.getDouble(6), rs.getDouble(7), rs.getDouble(8), rs.getDouble(9), rs.getDouble(10)));
        if (inIteration) {
            iterationPose = newest;
            iterationPoseIteration = transaction.iterationNumber();
        }
        return newest;
    }

    /** In an iteration, written with its commit (the iteration's later reads see it at once); else at once. */
    @Override
    public void writePose(PoseEstimate estimate) {
        if (buffering()) {
            writtenPose = estimate;
            iterationPose = Optional.of(estimate);
            iterationPoseIteration = transaction.iterationNumber();
            return;
        }
        update("writing the pose estimate", INSERT_POSE, poseRow(estimate));
    }

    @Override
    public Optional<InitialPose> initialPose() {
        return queryOne("initial pose", "SELECT x_m, y_m, yaw_rad FROM initial_pose WHERE robot_id = ?",
                rs -> new InitialPose(rs.getDouble(1), rs.getDouble(2), rs.getDouble(3)));
    }

    private void forgetIteration() {
        pendingRequests.clear();
        pendingMarks.clear();
        writtenPose = null;
        iterationPose = null;
        iterationPoseIteration = Long.MIN_VALUE;
        snapshot = null;
    }

    /** @return the robot whose rows these are */
    public int robotId() {
        return robotId;
    }

    @Override
    public Optional<GpsFix> newestGps() {
        IterationSnapshot snap = snapshot();
        if (snap != null) {
            return snap.gps();
        }
        return queryOne("newest GPS reading",
                "SELECT sim_time_ms, x_m, y_m FROM gps_stored_values WHERE robot_id = ? ORDER BY robot_id DESC, sim_time_ms DESC, id DESC LIMIT 1",
                rs -> new GpsFix(rs.getLong(1), rs.getDouble(2), rs.getDouble(3)));
    }

    @Override
    public Optional<Heading> newestHeading() {
        IterationSnapshot snap = snapshot();
        if (snap != null) {
            return snap.heading();
        }
        return queryOne("newest inertial-unit reading",
                "SELECT sim_time_ms, yaw_rad FROM iudata WHERE robot_id = ? ORDER BY robot_id DESC, sim_time_ms DESC, id DESC LIMIT 1",
                rs -> new Heading(rs.getLong(1), rs.getDouble(2)));
    }

    @Override
    public Optional<DistanceScan> newestScan() {
        IterationSnapshot snap = snapshot();
        if (snap != null) {
            return snap.scan();
        }
        String sql = "SELECT sim_time_ms, angle_rad, distance_m, range_m FROM distance_sensor_data"
                + " WHERE robot_id = ? AND sim_time_ms = (SELECT sim_time_ms FROM distance_sensor_data WHERE robot_id = ?"
                + " ORDER BY robot_id DESC, sim_time_ms DESC LIMIT 1)"
                + " ORDER BY sensor_index";
        try (Connection c = dataSource.getConnection(); PreparedStatement ps = c.prepareStatement(sql)) {
            ps.setInt(1, robotId);
            ps.setInt(2, robotId);
            try (ResultSet rs = ps.executeQuery()) {
                long time = -1;
                double range = 0;
                double[] angles = new double[8];
                double[] distances = new double[8];
                int n = 0;
                while (rs.next()) {
                    if (n == angles.length) {
                        angles = Arrays.copyOf(angles, n * 2);
                        distances = Arrays.copyOf(distances, n * 2);
                    }
                    time = rs.getLong(1);
                    angles[n] = rs.getDouble(2);
                    distances[n] = rs.getDouble(3);
                    range = Math.max(range, rs.getDouble(4));
                    n++;
                }
                if (n == 0) {
                    return Optional.empty();
                }
                return Optional.of(new DistanceScan(time, Arrays.copyOf(angles, n),
                        Arrays.copyOf(distances, n), range));
            }
        } catch (SQLException e) {
            throw failure("reading the newest distance-sensor reading of robot " + robotId, e);
        }
    }

    @Override
    public Optional<BatteryState> newestBattery() {
        IterationSnapshot snap = snapshot();
        if (snap != null) {
            return snap.battery();
        }
        return queryOne("newest battery reading",
                "SELECT sim_time_ms, level_pct, charging FROM battery_level WHERE robot_id = ? ORDER BY robot_id DESC, sim_time_ms DESC, id DESC LIMIT 1",
                rs -> new BatteryState(rs.getLong(1), rs.getDouble(2), rs.getBoolean(3)));
    }

    @Override
    public Optional<WheelOdometry> newestOdometry() {
        IterationSnapshot snap = snapshot();
        if (snap != null) {
            return snap.odometry();
        }
        return queryOne("newest odometry reading",
                "SELECT sim_time_ms, left_m, right_m FROM odometry WHERE robot_id = ? ORDER BY robot_id DESC, sim_time_ms DESC, id DESC LIMIT 1",
                rs -> new WheelOdometry(rs.getLong(1), rs.getDouble(2), rs.getDouble(3)));
    }

    @Override
    public long newestSimTimeMs(Sensor sensor) {
        IterationSnapshot snap = snapshot();
        if (snap != null) {
            return snap.newestSimTimeMs(sensor);
        }
        String sql = switch (sensor) {
            case GPS -> "SELECT sim_time_ms FROM gps_stored_values WHERE robot_id = ? ORDER BY robot_id DESC, sim_time_ms DESC, id DESC LIMIT 1";
            case IU -> "SELECT sim_time_ms FROM iudata WHERE robot_id = ? ORDER BY robot_id DESC, sim_time_ms DESC, id DESC LIMIT 1";
            case DS -> "SELECT sim_time_ms FROM distance_sensor_data WHERE robot_id = ? ORDER BY robot_id DESC, sim_time_ms DESC LIMIT 1";
            case BATTERY -> "SELECT sim_time_ms FROM battery_level WHERE robot_id = ? ORDER BY robot_id DESC, sim_time_ms DESC, id DESC LIMIT 1";
            case ODOMETRY -> "SELECT sim_time_ms FROM odometry WHERE robot_id = ? ORDER BY robot_id DESC, sim_time_ms DESC, id DESC LIMIT 1";
        };
        return queryOne("newest " + sensor + " time", sql, rs -> rs.getLong(1)).orElse(-1L);
    }

    /**
     * The exact name is compared here, not only in SQL: MySQL and MariaDB compare strings without
     * regard to case or trailing spaces by default, so a stray row {@code 'gps'} or {@code 'GPS '},
     * which the robot never answers (it knows {@code GPS} only), would count as pending and stop
     * the sensor's requests for good.
     */
    @Override
    public boolean pending(Sensor sensor) {
        IterationSnapshot snap = snapshot();
        if (snap != null) {
            return snap.pending(sensor);
        }
        try (Connection c = dataSource.getConnection(); PreparedStatement ps = c.prepareStatement(
                "SELECT sensor FROM sensor_requests WHERE robot_id = ? AND answered_sim_time_ms IS NULL AND sensor = ?")) {
            ps.setInt(1, robotId);
            ps.setString(2, sensor.word().name());
            try (ResultSet rs = ps.executeQuery()) {
                while (rs.next()) {
                    if (sensor.word().name().equals(rs.getString(1))) {
                        return true;
                    }
                }
                return false;
            }
        } catch (SQLException e) {
            throw failure("reading the pending " + sensor + " request of robot " + robotId, e);
        }
    }

    @Override
    public void request(Sensor sensor, long iteration) {
        if (buffering()) {
            IterationSnapshot snap = snapshot();
            snap.requested(sensor);
            pendingRequests.add(new Object[] {robotId, sensor.word().name(), iteration});
            return;
        }
        update("requesting " + sensor + " data",
                "INSERT INTO sensor_requests (robot_id, sensor, iteration) VALUES (?, ?, ?)", robotId, sensor.word().name(),
                iteration);
    }

    @Override
    public List<Checkpoint> checkpoints() {
        IterationSnapshot snap = snapshot();
        if (snap != null) {
            return snap.checkpoints();
        }
        return queryAll("checkpoints",
                "SELECT seq, x_m, y_m, radius_m, reached, unreachable FROM checkpoints WHERE robot_id = ? ORDER BY seq",
                rs -> new Checkpoint(rs.getInt(1), rs.getDouble(2), rs.getDouble(3), rs.getDouble(4), rs.getBoolean(5),
                        rs.getBoolean(6)));
    }

    @Override
    public void markReached(int seq, long simTimeMs) {
        if (buffering()) {
            snapshot().reached(seq);
            pendingMarks.add(new Object[] {simTimeMs, robotId, seq});
            return;
        }
        update("marking checkpoint " + seq + " reached",
                "UPDATE checkpoints SET reached = TRUE, reached_sim_time_ms = ? WHERE robot_id = ? AND seq = ?",
                simTimeMs, robotId, seq);
    }

    @Override
    public void markUnreachable(int seq, long simTimeMs) {
        if (buffering()) {
            snapshot().unreachable(seq); // the iteration's later reads see it, as on the direct link
        }
        update("marking checkpoint " + seq + " unreachable",
                "UPDATE checkpoints SET unreachable = TRUE WHERE robot_id = ? AND seq = ?", robotId, seq);
    }

    @Override
    public List<MapChunk> readMap() {
        return queryAll("occupancy map",
                "SELECT chunk_x, chunk_y, cells FROM occupancy_map WHERE robot_id = ? ORDER BY chunk_x, chunk_y",
                rs -> new MapChunk(rs.getInt(1), rs.getInt(2), rs.getBytes(3)));
    }

    @Override
    public List<MapChunk> readMapSince(long simTimeMs) {
        return read("occupancy map", "SELECT chunk_x, chunk_y, cells FROM occupancy_map"
                + " WHERE robot_id = ? AND updated_sim_time_ms >= ? ORDER BY chunk_x, chunk_y", ps -> {
                    ps.setLong(2, simTimeMs);
                    List<MapChunk> out = new ArrayList<>();
                    try (ResultSet rs = ps.executeQuery()) {
                        while (rs.next()) {
                            out.add(new MapChunk(rs.getInt(1), rs.getInt(2), rs.getBytes(3)));
                        }
                    }
                    return out;
                });
    }

    /** Replaces each chunk's row (an upsert, as H2 in MySQL mode and MySQL / MariaDB both take it). */
    @Override
    public void writeChunks(List<MapChunk> chunks, long simTimeMs) {
        if (chunks.isEmpty()) {
            return;
        }
        // on the running iteration's connection: the map commits with the iteration that drew it, or not at all
        Writes inIteration = transaction == null ? null : transaction.writes();
        try {
            if (inIteration != null) {
                writeChunks(inIteration, chunks, simTimeMs);
            } else {
                try (Connection c = dataSource.getConnection()) {
                    writeChunks(Writes.atOnce(c), chunks, simTimeMs);
                }
            }
        } catch (SQLException e) {
            throw failure("writing " + chunks.size() + " occupancy-map chunk(s) of robot " + robotId, e);
        }
    }

    private void writeChunks(Writes writes, List<MapChunk> chunks, long simTimeMs) throws SQLException {
        List<MapChunk> copies = new ArrayList<>(chunks.size()); // a deferred write binds at the commit: the cells as they are now
        for (MapChunk chunk : chunks) {
            copies.add(new MapChunk(chunk.chunkX(), chunk.chunkY(), chunk.cells().clone()));
        }
        writes.addRows(UPSERT_CHUNKS, 5, copies.size(), chunkRows(copies, simTimeMs));
    }

    /** Binds chunks, one row each. */
    private MultiRow.RowBinder chunkRows(List<MapChunk> chunks, long simTimeMs) {
        return (ps, p, r) -> {
            MapChunk chunk = chunks.get(r);
            ps.setInt(p, robotId);
            ps.setInt(p + 1, chunk.chunkX());
            ps.setInt(p + 2, chunk.chunkY());
            ps.setBytes(p + 3, chunk.cells());
            ps.setLong(p + 4, simTimeMs);
        };
    }

    @Override
    public Optional<Station> rechargeStation() {
        IterationSnapshot snap = snapshot();
        if (snap != null) {
            return snap.station();
        }
        return queryOne("recharge station",
                "SELECT x_m, y_m, radius_m FROM recharge_station WHERE robot_id = ?",
                rs -> new Station(rs.getDouble(1), rs.getDouble(2), rs.getDouble(3)));
    }

    @Override
    public OptionalDouble rechargeLevelPct() {
        IterationSnapshot snap = snapshot();
        if (snap != null) {
            return snap.rechargeLevelPct();
        }
        Optional<Double> level = queryOne("recharge level",
                "SELECT level_pct FROM battery_recharged WHERE robot_id = ?", rs -> rs.getDouble(1));
        return level.map(OptionalDouble::of).orElse(OptionalDouble.empty());
    }

    @Override
    public List<Entry> read() {
        IterationSnapshot snap = snapshot();
        if (snap != null) {
            return snap.strategy();
        }
        return queryAll("strategy",
                "SELECT slot, scenario, priority, strategy_name, timeout_ms FROM strategy WHERE robot_id = ? ORDER BY slot",
                rs -> new Entry(rs.getInt(1), rs.getString(2), rs.getInt(3), rs.getString(4), rs.getLong(5)));
    }

    @Override
    public void write(List<Entry> entries) {
        Connection inIteration = transaction == null ? null : transaction.connection();
        if (inIteration != null) {
            try {
                writePending(Writes.atOnce(inIteration)); // the iteration's writes so far go first
                writeStrategy(inIteration, entries);
                snapshot = null; // read again, with the new strategy, by the next read
                readAhead = null; // read before the write: never taken up after it
            } catch (SQLException e) {
                transaction.markRollbackOnly();
                throw failure("writing the strategy of robot " + robotId, e);
            }
            return;
        }
        try (Connection c = dataSource.getConnection()) {
            boolean autoCommit = c.getAutoCommit();
            c.setAutoCommit(false);
            try {
                writeStrategy(c, entries);
                c.commit();
            } catch (SQLException e) {
                c.rollback();
                throw e;
            } finally {
                c.setAutoCommit(autoCommit);
            }
        } catch (SQLException e) {
            throw failure("writing the strategy of robot " + robotId, e);
        }
    }

    private void writeStrategy(Connection c, List<Entry> entries) throws SQLException {
        try (PreparedStatement delete = c.prepareStatement("DELETE FROM strategy WHERE robot_id = ?");
             PreparedStatement insert = c.prepareStatement(
                     "INSERT INTO strategy (robot_id, slot, scenario, priority, strategy_name, timeout_ms)"
                             + " VALUES (?, ?, ?, ?, ?, ?)")) {
            delete.setInt(1, robotId);
            delete.executeUpdate();
            for (Entry e : entries) {
                insert.setInt(1, robotId);
                insert.setInt(2, e.slot());
                insert.setString(3, e.scenario());
                insert.setInt(4, e.priority());
                insert.setString(5, e.name());
                insert.setLong(6, e.timeoutMs());
                insert.addBatch();
            }
            insert.executeBatch();
        }
    }

    @Override
    public void send(long iteration, long simTimeMs, String scenario, String command) {
        if (buffering()) {
            // One command per iteration: sent now, in the iteration's transaction, not with its commit, so that its
            // row is written in the order the rules ran, as it always was (the robot finds the newest by iteration).
            try {
                transaction.sendNow(INSERT_COMMAND, 5, (ps, p) -> bind(ps, p, new Object[] {robotId, iteration, simTimeMs,
                        scenario, command}));
            } catch (SQLException e) {
                throw failure("sending command '" + command + "' for robot " + robotId, e);
            }
            return;
        }
        update("sending command '" + command + "'",
                "INSERT INTO engine_comments (robot_id, iteration, sim_time_ms, scenario, command) VALUES (?, ?, ?, ?, ?)",
                robotId, iteration, simTimeMs, scenario, command);
    }

    /**
     * Bounds the engine's history of this robot: keeps the newest {@code keepRows} commands,
     * answered sensor requests, rule failures and pose estimates (pending requests always stay).
     *
     * @param keepRows how many rows of each to keep
     * @return the rows deleted
     */
    public int pruneHistory(int keepRows) {
        int deleted = 0;
        try (Connection c = dataSource.getConnection()) {
            // Commands by iteration, so that the newest never goes; answered requests and rule failures are history.
            deleted += RobotRows.pruneOlderThanNewest(c, robotId, "engine_comments", "iteration", "", keepRows, 0);
            deleted += RobotRows.pruneOlderThanNewest(c, robotId, "rule_failures", "id", "", keepRows, 0);
            deleted += RobotRows.pruneOlderThanNewest(c, robotId, "pose_estimate", "sim_time_ms", "", keepRows, 0);
            deleted += RobotRows.pruneOlderThanNewest(c, robotId, "sensor_requests", "id", " AND answered_sim_time_ms IS NOT NULL",
                    keepRows, 0);
        } catch (SQLException e) {
            throw failure("pruning the engine history of robot " + robotId, e);
        }
        return deleted;
    }

    // ---- plumbing ----

    /** A failed statement: the iteration learns of it (a lost connection must not commit half of it), the caller gets why. */
    private TablesException failure(String what, SQLException e) {
        if (transaction != null) {
            transaction.statementFailed(e);
        }
        return new TablesException(what, e);
    }

    private interface RowMapper<T> {
        T map(ResultSet rs) throws SQLException;
    }

    private <T> Optional<T> queryOne(String what, String sql, RowMapper<T> mapper, Object... more) {
        return read(what, sql, ps -> {
            bind(ps, 2, more);
            try (ResultSet rs = ps.executeQuery()) {
                return rs.next() ? Optional.ofNullable(mapper.map(rs)) : Optional.empty();
            }
        });
    }

    private <T> List<T> queryAll(String what, String sql, RowMapper<T> mapper) {
        return read(what, sql, ps -> {
            List<T> out = new ArrayList<>();
            try (ResultSet rs = ps.executeQuery()) {
                while (rs.next()) {
                    out.add(mapper.map(rs));
                }
            }
            return out;
        });
    }

    /** A query with robot_id as its first parameter. */
    private interface Query<T> {
        T run(PreparedStatement ps) throws SQLException;
    }

    /**
     * Runs a query on the running iteration's connection when one runs, so that the iteration reads
     * its own writes (as the direct link does; the map a rule drew is the map the next rule plans on),
     * else on a pooled connection.
     */
    private <T> T read(String what, String sql, Query<T> query) {
        Connection inIteration = transaction == null ? null : transaction.readConnection();
        try {
            if (inIteration != null) {
                try (PreparedStatement ps = inIteration.prepareStatement(sql)) {
                    ps.setInt(1, robotId);
                    return query.run(ps);
                }
            }
            try (Connection c = dataSource.getConnection(); PreparedStatement ps = c.prepareStatement(sql)) {
                ps.setInt(1, robotId);
                return query.run(ps);
            }
        } catch (SQLException e) {
            throw failure("reading the " + what + " of robot " + robotId, e);
        }
    }

    /**
     * Runs an INSERT or UPDATE with these parameters, in order (robot_id among them where the SQL has
     * it): on the running iteration's connection, so that it commits with the iteration or not at all.
     */
    private void update(String what, String sql, Object... params) {
        try {
            if (buffering()) {
                transaction.sendNow(sql, params.length, (ps, p) -> bind(ps, p, params));
                return;
            }
            try (Connection c = dataSource.getConnection(); PreparedStatement ps = c.prepareStatement(sql)) {
                bind(ps, 1, params);
                ps.executeUpdate();
            }
        } catch (SQLException e) {
            throw failure(what + " for robot " + robotId, e);
        }
    }

    private static void bind(PreparedStatement ps, int first, Object[] values) throws SQLException {
        for (int i = 0; i < values.length; i++) {
            ps.setObject(first + i, values[i]);
        }
    }
}
