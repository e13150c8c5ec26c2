package org.proactiverobotics.engine.tables;

import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.EnumSet;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.OptionalDouble;
import java.util.Set;

/**
 * What the engine's rules read of one robot's tables during one iteration, read in one query
 * (one round trip) the first time a rule reads anything (or just before the iteration, in one
 * query with other robots': {@link #loadAll}), and kept up to date with the
 * iteration's own writes (a request makes its sensor pending, a mark makes its checkpoint
 * reached). In lockstep nothing else writes these rows while the iteration runs, so every rule
 * sees what it would have read row by row; in real-time timing the iteration sees one
 * consistent moment of the robot's writes instead of several.
 */
final class IterationSnapshot {

    // One UNION ALL of ten columns: kind, three integers, four doubles, two strings. The "newest"
    // subqueries keep their ORDER BY robot_id DESC, sim_time_ms DESC, id DESC LIMIT 1 (the
    // (robot_id, sim_time_ms, id) index, read backwards): newest by simulated time, not by id.
    // Wrapped in a plain SELECT because H2 caches a prepared SELECT but re-parses a bare UNION at
    // every prepare (the parse was a quarter of an H2 mission's time, JFR). %d is the row's kind:
    // the part (1-10) plus KINDS_PER_ROBOT times the robot's place in a query for several robots.
    private static final String[] PARTS = {
        "(SELECT %d AS k, sim_time_ms AS n1, 0 AS n2, 0 AS n3, x_m AS d1, y_m AS d2, CAST(0 AS DOUBLE) AS d3,"
            + " CAST(0 AS DOUBLE) AS d4, '' AS s1, '' AS s2 FROM gps_stored_values WHERE robot_id = ? ORDER BY robot_id DESC, sim_time_ms DESC, id DESC LIMIT 1)",
        "(SELECT %d, sim_time_ms, 0, 0, yaw_rad, CAST(0 AS DOUBLE), CAST(0 AS DOUBLE), CAST(0 AS DOUBLE), '', '' FROM iudata WHERE robot_id = ?"
            + " ORDER BY robot_id DESC, sim_time_ms DESC, id DESC LIMIT 1)",
        "(SELECT %d, sim_time_ms, CASE WHEN charging THEN 1 ELSE 0 END, 0, level_pct, CAST(0 AS DOUBLE), CAST(0 AS DOUBLE), CAST(0 AS DOUBLE), '', ''"
            + " FROM battery_level WHERE robot_id = ? ORDER BY robot_id DESC, sim_time_ms DESC, id DESC LIMIT 1)",
        "(SELECT %d, sim_time_ms, sensor_index, 0, angle_rad, distance_m, range_m, CAST(0 AS DOUBLE), '', ''"
            + " FROM distance_sensor_data WHERE robot_id = ? AND sim_time_ms = (SELECT sim_time_ms FROM distance_sensor_data"
            + " WHERE robot_id = ? ORDER BY robot_id DESC, sim_time_ms DESC LIMIT 1))",
        "(SELECT %d, id, 0, 0, CAST(0 AS DOUBLE), CAST(0 AS DOUBLE), CAST(0 AS DOUBLE), CAST(0 AS DOUBLE), sensor, '' FROM sensor_requests"
            + " WHERE robot_id = ? AND answered_sim_time_ms IS NULL)",
        "(SELECT %d, seq, CASE WHEN reached THEN 1 ELSE 0 END, CASE WHEN unreachable THEN 1 ELSE 0 END, x_m, y_m, radius_m, CAST(0 AS DOUBLE), '', ''"
            + " FROM checkpoints WHERE robot_id = ?)",
        "(SELECT %d, 0, 0, 0, x_m, y_m, radius_m, CAST(0 AS DOUBLE), '', '' FROM recharge_station WHERE robot_id = ?)",
        "(SELECT %d, 0, 0, 0, level_pct, CAST(0 AS DOUBLE), CAST(0 AS DOUBLE), CAST(0 AS DOUBLE), '', '' FROM battery_recharged WHERE robot_id = ?)",
        "(SELECT %d, slot, priority, timeout_ms, CAST(0 AS DOUBLE), CAST(0 AS DOUBLE), CAST(0 AS DOUBLE), CAST(0 AS DOUBLE), scenario, strategy_name FROM strategy"
            + " WHERE robot_id = ?)",
        "(SELECT %d, sim_time_ms, 0, 0, left_m, right_m, CAST(0 AS DOUBLE), CAST(0 AS DOUBLE), '', '' FROM odometry WHERE robot_id = ?"
            + " ORDER BY robot_id DESC, sim_time_ms DESC, id DESC LIMIT 1)"};
    private static final int ROBOT_ID_PARAMETERS = 11;
    /** The kinds one robot's rows take (parts 1 to {@code PARTS.length}), so that a kind names its robot too. */
    private static final int KINDS_PER_ROBOT = 20;
    /** The most robots read in one query (a longer text costs the server more to parse than a round trip saves). */
    static final int MAX_ROBOTS_PER_QUERY = 16;
    /** The query for one robot, then for two, ..., {@value #MAX_ROBOTS_PER_QUERY}: index k - 1. */
    private static final String[] QUERIES = new String[MAX_ROBOTS_PER_QUERY];

    static {
        for (int robots = 1; robots <= MAX_ROBOTS_PER_QUERY; robots++) {
            StringBuilder sql = new StringBuilder("SELECT * FROM (");
            for (int r = 0; r < robots; r++) {
                for (int part = 0; part < PARTS.length; part++) {
                    if (r > 0 || part > 0) {
                        sql.append(" UNION ALL ");
                    }
                    sql.append(String.format(Locale.ROOT, PARTS[part], KINDS_PER_ROBOT * r + part + 1));
                }
            }
            QUERIES[robots - 1] = sql.append(") snapshot").toString();
        }
    }

    /** The iteration the snapshot belongs to (-1: read ahead, not yet taken up by an iteration). */
    long iteration;
    private GpsFix gps;
    private Heading heading;
    private BatteryState battery;
    private DistanceScan scan;
    private WheelOdometry odometry;
    /** Sensors with a request not answered yet (exact names only: see JdbcRobotTables#pending). */
    private final Set<Sensor> pending = EnumSet.noneOf(Sensor.class);
    private List<Checkpoint> checkpoints = new ArrayList<>();
    private Station station;
    private Double rechargeLevelPct;
    private List<StrategyTable.Entry> strategy = new ArrayList<>();
    /** The distance readings while the rows are read: sensor index, angle, distance, range; and their time. */
    private final List<double[]> distanceRows = new ArrayList<>();
    private long distanceTimeMs = -1;

    private IterationSnapshot(long iteration) {
        this.iteration = iteration;
    }

    /**
     * @param c         the iteration's connection
     * @param robotId   the robot
     * @param iteration the iteration number the snapshot belongs to
     * @return everything the rules read, as the tables hold it now
     */
    static IterationSnapshot load(Connection c, int robotId, long iteration) throws SQLException {
        IterationSnapshot s = new IterationSnapshot(iteration);
        read(c, new int[] {robotId}, 0, 1, new IterationSnapshot[] {s});
        return s;
    }

    /**
     * The snapshots of several robots, read ahead of their iterations in one query per
     * {@value #MAX_ROBOTS_PER_QUERY} robots.
     *
     * @param c        a connection
     * @param robotIds the robots
     * @return their snapshots, in the order of the ids, each not yet taken up by an iteration
     * @throws SQLException when a query fails
     */
    static IterationSnapshot[] loadAll(Connection c, int[] robotIds) throws SQLException {
        IterationSnapshot[] all = new IterationSnapshot[robotIds.length];
        for (int i = 0; i < all.length; i++) {
            all[i] = new IterationSnapshot(-1);
        }
        for (int from = 0; from < robotIds.length; from += MAX_ROBOTS_PER_QUERY) {
            read(c, robotIds, from, Math.min(MAX_ROBOTS_PER_QUERY, robotIds.length - from), all);
        }
        return all;
    }

    private static void read(Connection c, int[] robotIds, int from, int count, IterationSnapshot[] into)
            throws SQLException {
        try (PreparedStatement ps = c.prepareStatement(QUERIES[count - 1])) {
            int p = 1;
            for (int r = from; r < from + count; r++) {
                for (int i = 0; i < ROBOT_ID_PARAMETERS; i++) {
                    ps.setInt(p++, robotIds[r]);
                }
            }
            try (ResultSet rs = ps.executeQuery()) {
                while (rs.next()) {
                    int kind = rs.getInt(1);
                    into[from + kind / KINDS_PER_ROBOT].row(kind % KINDS_PER_ROBOT, rs);
                }
            }
        }
        for (int r = from; r < from + count; r++) {
            into[r].finish();
        }
    }

    private void row(int part, ResultSet rs) throws SQLException {
        switch (part) {
            case 1 -> gps = new GpsFix(rs.getLong(2), rs.getDouble(5), rs.getDouble(6));
            case 2 -> heading = new Heading(rs.getLong(2), rs.getDouble(5));
            case 3 -> battery = new BatteryState(rs.getLong(2), rs.getDouble(5), rs.getInt(3) != 0);
            case 4 -> {
                distanceTimeMs = rs.getLong(2);
                distanceRows.add(new double[] {rs.getInt(3), rs.getDouble(5), rs.getDouble(6), rs.getDouble(7)});
            }
            case 5 -> {
                String name = rs.getString(9);
                for (Sensor sensor : Sensor.values()) {
                    if (sensor.word().name().equals(name)) {
                        pending.add(sensor);
                    }
                }
            }
            case 6 -> checkpoints.add(new Checkpoint(rs.getInt(2), rs.getDouble(5), rs.getDouble(6),
                    rs.getDouble(7), rs.getInt(3) != 0, rs.getInt(4) != 0));
            case 7 -> station = new Station(rs.getDouble(5), rs.getDouble(6), rs.getDouble(7));
            case 8 -> rechargeLevelPct = rs.getDouble(5);
            case 9 -> strategy.add(new StrategyTable.Entry(rs.getInt(2), rs.getString(9), rs.getInt(3),
                    rs.getString(10), rs.getLong(4)));
            case 10 -> odometry = new WheelOdometry(rs.getLong(2), rs.getDouble(5), rs.getDouble(6));
            default -> throw new IllegalStateException("unknown snapshot row kind " + rs.getInt(1));
        }
    }

    private void finish() {
        if (!distanceRows.isEmpty()) {
            distanceRows.sort((a, b) -> Double.compare(a[0], b[0]));
            double[] angles = new double[distanceRows.size()];
            double[] distances = new double[distanceRows.size()];
            double range = 0;
            for (int i = 0; i < distanceRows.size(); i++) {
                angles[i] = distanceRows.get(i)[1];
                distances[i] = distanceRows.get(i)[2];
                range = Math.max(range, distanceRows.get(i)[3]);
            }
            scan = new DistanceScan(distanceTimeMs, angles, distances, range);
            distanceRows.clear();
        }
        checkpoints.sort((a, b) -> Integer.compare(a.seq(), b.seq()));
        strategy.sort((a, b) -> Integer.compare(a.slot(), b.slot()));
    }

    Optional<GpsFix> gps() {
        return Optional.ofNullable(gps);
    }

    Optional<Heading> heading() {
        return Optional.ofNullable(heading);
    }

    Optional<BatteryState> battery() {
        return Optional.ofNullable(battery);
    }

    Optional<WheelOdometry> odometry() {
        return Optional.ofNullable(odometry);
    }

    Optional<DistanceScan> scan() {
        return scan == null ? Optional.empty() : Optional.of(new DistanceScan(scan.simTimeMs(),
                Arrays.copyOf(scan.anglesRad(), scan.anglesRad().length),
                Arrays.copyOf(scan.distancesM(), scan.distancesM().length), scan.rangeM()));
    }

    long newestSimTimeMs(Sensor sensor) {
        return switch (sensor) {
            case GPS -> gps == null ? -1 : gps.simTimeMs();
            case IU -> heading == null ? -1 : heading.simTimeMs();
            case DS -> scan == null ? -1 : scan.simTimeMs();
            case BATTERY -> battery == null ? -1 : battery.simTimeMs();
            case ODOMETRY -> odometry == null ? -1 : odometry.simTimeMs();
        };
    }

    boolean pending(Sensor sensor) {
        return pending.contains(sensor);
    }

    void requested(Sensor sensor) {
        pending.add(sensor);
    }

    List<Checkpoint> checkpoints() {
        return new ArrayList<>(checkpoints);
    }

    void reached(int seq) {
        checkpoints.replaceAll(cp -> cp.seq() == seq
                ? new Checkpoint(cp.seq(), cp.xM(), cp.yM(), cp.radiusM(), true, cp.unreachable()) : cp);
    }

    void unreachable(int seq) {
        checkpoints.replaceAll(cp -> cp.seq() == seq
                ? new Checkpoint(cp.seq(), cp.xM(), cp.yM(), cp.radiusM(), cp.reached(), true) : cp);
    }

    Optional<Station> station() {
        return Optional.ofNullable(station);
    }

    OptionalDouble rechargeLevelPct() {
        return rechargeLevelPct == null ? OptionalDouble.empty() : OptionalDouble.of(rechargeLevelPct);
    }

    List<StrategyTable.Entry> strategy() {
        return new ArrayList<>(strategy);
    }
}
