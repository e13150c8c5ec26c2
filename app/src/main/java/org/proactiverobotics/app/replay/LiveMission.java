package org.proactiverobotics.app.replay;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import javax.sql.DataSource;
import org.proactiverobotics.engine.robot.RobotEngine;
import org.proactiverobotics.engine.robot.ScenarioPlugins;

/**
 * A running mission as the database shows it, read only (SELECT, as {@code proactive_viewer}):
 * each command the engine sent (engine_comments) becomes a step, with the robot's readings of
 * that simulated time (GPS, inertial unit, distance sensors, battery), the PriorityArray (the
 * strategy table), the checkpoints reached and the rule failures as events. The ground truth is
 * the simulator's and is not in the database: the pose shown is the GPS reading and the heading
 * the inertial unit's. Polled by one thread; read by the HTTP server's through {@link #data()}.
 */
public final class LiveMission {

    /** The most commands read at one poll: a viewer started late catches up in a few polls. */
    private static final int BATCH = 4000;
    /** How far before a batch's first command the readings are looked for, simulated ms. */
    private static final long READINGS_BEFORE_MS = 2000;

    private final DataSource pool;
    private final int robotId;
    private volatile ReplayData data;
    /** The robot's rays as its readings say (index, angle, range): known from its first scan on. */
    private int rays;
    private volatile Map<String, Integer> slots = Map.of();
    private volatile JsonObject mission;
    /** The iteration of the last command read: rows are followed by iteration, since Galera's ids interleave. */
    private long lastCommandIteration;
    /** The smallest iteration of this run's commands seen: the engine's pruning only raises the table's, a new run lowers it. */
    private long firstCommandIteration = Long.MAX_VALUE;
    private long lastFailureIteration;
    private final TreeMap<Integer, Boolean> reportedCheckpoints = new TreeMap<>();

    /**
     * @param pool    the database (read only is enough)
     * @param robotId the robot to follow
     */
    public LiveMission(DataSource pool, int robotId) {
        this.pool = pool;
        this.robotId = robotId;
        this.data = new ReplayData(Map.of(), 0);
    }

    /** @return the steps read so far (a new object when a new run of the robot started) */
    public ReplayData data() {
        return data;
    }

    /** @return each scenario's CommandArray slot, as the strategy table has them (built-in ones before) */
    public Map<String, Integer> slots() {
        return slots.isEmpty() ? RobotEngine.freshSlots(ScenarioPlugins.none()) : slots;
    }

    /** @return the checkpoints, the station and the rays as the page draws them, or null before the robot seeded them and sent a scan */
    public JsonObject mission() {
        return mission;
    }

    /**
     * Reads what is new since the last poll.
     *
     * @return the steps added
     * @throws SQLException when the database cannot be read
     */
    public int poll() throws SQLException {
        try (Connection c = pool.getConnection()) {
            c.setReadOnly(true);
            if (mission == null && !startOver(c)) {
                return 0; // no checkpoints or no scan yet: nothing is drawn before the robot is known
            }
            Map<String, Integer> priorities = new LinkedHashMap<>();
            Map<String, Integer> strategySlots = new LinkedHashMap<>();
            try (PreparedStatement ps = c.prepareStatement(
                    "SELECT scenario, slot, priority FROM strategy WHERE robot_id = ? ORDER BY priority DESC, slot")) {
                ps.setInt(1, robotId);
                try (ResultSet rs = ps.executeQuery()) {
                    while (rs.next()) {
                        priorities.put(rs.getString(1), rs.getInt(3));
                        strategySlots.put(rs.getString(1), rs.getInt(2));
                    }
                }
            }
            slots = strategySlots;
            if (newRun(c)) { // the commands of the run followed so far were cleared: start over
                reportedCheckpoints.clear();
                lastCommandIteration = 0;
                lastFailureIteration = 0;
                firstCommandIteration = Long.MAX_VALUE;
                data = new ReplayData(Map.of(), 0);
                if (!startOver(c)) {
                    return 0;
                }
            }
            List<long[]> ids = new ArrayList<>();
            List<String[]> texts = new ArrayList<>();
            try (PreparedStatement ps = c.prepareStatement("SELECT id, iteration, sim_time_ms, scenario, command FROM"
                    + " engine_comments WHERE robot_id = ? AND iteration > ? ORDER BY robot_id, iteration, id LIMIT " + BATCH)) {
                ps.setInt(1, robotId);
                ps.setLong(2, lastCommandIteration);
                try (ResultSet rs = ps.executeQuery()) {
                    while (rs.next()) {
                        ids.add(new long[] {rs.getLong(1), rs.getLong(2), rs.getLong(3)});
                        texts.add(new String[] {rs.getString(4), rs.getString(5)});
                    }
                }
            }
            if (ids.isEmpty()) {
                return 0;
            }
            firstCommandIteration = Math.min(firstCommandIteration, ids.get(0)[1]);
            long from = ids.get(0)[2] - READINGS_BEFORE_MS;
            long to = ids.get(ids.size() - 1)[2];
            TreeMap<Long, double[]> gps = readings(c, "SELECT sim_time_ms, x_m, y_m FROM gps_stored_values", from, to, 2);
            TreeMap<Long, double[]> iu = readings(c, "SELECT sim_time_ms, yaw_rad FROM iudata", from, to, 1);
            TreeMap<Long, double[]> battery = readings(c, "SELECT sim_time_ms, level_pct, charging FROM battery_level",
                    from, to, 2);
            TreeMap<Long, double[]> scans = scans(c, from, to);
            List<TraceEvent> failures = failures(c, ids.get(ids.size() - 1)[1]);
            Map<Long, List<TraceEvent>> reached = reachedCheckpoints(c);
            for (int k = 0; k < ids.size(); k++) {
                long iteration = ids.get(k)[1];
                long t = ids.get(k)[2];
                List<TraceEvent> events = new ArrayList<>();
                reached.entrySet().removeIf(e -> {
                    if (e.getKey() <= t) {
                        events.addAll(e.getValue());
                        return true;
                    }
                    return false;
                });
                failures.removeIf(f -> {
                    if (f.detail().get("iteration").getAsLong() <= iteration) {
                        events.add(f);
                        return true;
                    }
                    return false;
                });
                if (k == ids.size() - 1) {
                    reached.values().forEach(events::addAll);
                    events.addAll(failures);
                }
                double[] g = at(gps, t);
                double[] h = at(iu, t);
                double[] b = at(battery, t);
                double[] s = at(scans, t);
                double x = g == null ? Double.NaN : g[0];
                double y = g == null ? Double.NaN : g[1];
                double yaw = h == null ? Double.NaN : h[0];
                data.add(new TraceStep(iteration, t, null, texts.get(k)[0], texts.get(k)[1], priorities, x, y, yaw,
                        x, y, yaw, s, b == null ? Double.NaN : b[0], b == null ? Double.NaN : b[0],
                        b != null && b[1] > 0, Double.NaN, Double.NaN, events));
            }
            lastCommandIteration = ids.get(ids.size() - 1)[1];
            return ids.size();
        }
    }

    /**
     * Whether the robot's commands now belong to a run after the one followed: the table's
     * iterations went below the first this run showed (a new run clears the commands and counts
     * from 1; the engine's pruning only drops old ones), or all end before the last one read.
     */
    private boolean newRun(Connection c) throws SQLException {
        if (lastCommandIteration == 0) {
            return false;
        }
        try (PreparedStatement ps = c.prepareStatement(
                "SELECT MIN(iteration), MAX(iteration) FROM engine_comments WHERE robot_id = ?")) {
            ps.setInt(1, robotId);
            try (ResultSet rs = ps.executeQuery()) {
                if (!rs.next()) {
                    return false;
                }
                long min = rs.getLong(1);
                if (rs.wasNull()) {
                    return false; // cleared, the new run's first command not written yet: keep showing the last run
                }
                return min < firstCommandIteration || rs.getLong(2) < lastCommandIteration;
            }
        }
    }

    /** Reads the robot's mission and starts its steps over; false while it has not seeded it or sent a scan. */
    private boolean startOver(Connection c) throws SQLException {
        mission = readMission(c);
        if (mission == null) {
            return false;
        }
        data = new ReplayData(Map.of(), rays);
        return true;
    }

    private static double[] at(TreeMap<Long, double[]> readings, long t) {
        Map.Entry<Long, double[]> e = readings.floorEntry(t);
        return e == null ? null : e.getValue();
    }

    private TreeMap<Long, double[]> readings(Connection c, String select, long from, long to, int columns)
            throws SQLException {
        TreeMap<Long, double[]> out = new TreeMap<>();
        try (PreparedStatement ps = c.prepareStatement(select + " WHERE robot_id = ? AND sim_time_ms BETWEEN ? AND ?"
                + " ORDER BY id")) {
            ps.setInt(1, robotId);
            ps.setLong(2, from);
            ps.setLong(3, to);
            try (ResultSet rs = ps.executeQuery()) {
                while (rs.next()) {
                    double[] v = new double[columns];
                    for (int i = 0; i < columns; i++) {
                        v[i] = rs.getDouble(2 + i);
                    }
                    out.put(rs.getLong(1), v);
                }
            }
        }
        return out;
    }

    private TreeMap<Long, double[]> scans(Connection c, long from, long to) throws SQLException {
        TreeMap<Long, double[]> out = new TreeMap<>();
        try (PreparedStatement ps = c.prepareStatement("SELECT sim_time_ms, sensor_index, distance_m FROM"
                + " distance_sensor_data WHERE robot_id = ? AND sim_time_ms BETWEEN ? AND ? ORDER BY id")) {
            ps.setInt(1, robotId);
            ps.setLong(2, from);
            ps.setLong(3, to);
            try (ResultSet rs = ps.executeQuery()) {
                while (rs.next()) {
                    int index = rs.getInt(2);
                    if (index >= 0 && index < rays) {
                        double[] scan = out.computeIfAbsent(rs.getLong(1), t -> {
                            double[] none = new double[rays];
                            Arrays.fill(none, Double.NaN);
                            return none;
                        });
                        scan[index] = rs.getDouble(3);
                    }
                }
            }
        }
        return out;
    }

    private List<TraceEvent> failures(Connection c, long upToIteration) throws SQLException {
        List<TraceEvent> out = new ArrayList<>();
        // By iteration, as the commands: an iteration's failures commit together, so none comes after its iteration was read.
        try (PreparedStatement ps = c.prepareStatement("SELECT id, iteration, scenario, rule, part, message FROM"
                + " rule_failures WHERE robot_id = ? AND iteration > ? AND iteration <= ? ORDER BY robot_id, iteration, id")) {
            ps.setInt(1, robotId);
            ps.setLong(2, lastFailureIteration);
            ps.setLong(3, upToIteration);
            lastFailureIteration = Math.max(lastFailureIteration, upToIteration);
            try (ResultSet rs = ps.executeQuery()) {
                while (rs.next()) {
                    out.add(TraceEvent.ruleFailure(rs.getLong(2), rs.getString(3), rs.getString(4), rs.getString(5),
                            rs.getString(6)));
                }
            }
        }
        return out;
    }

    private Map<Long, List<TraceEvent>> reachedCheckpoints(Connection c) throws SQLException {
        Map<Long, List<TraceEvent>> out = new TreeMap<>();
        try (PreparedStatement ps = c.prepareStatement("SELECT seq, reached_sim_time_ms FROM checkpoints"
                + " WHERE robot_id = ? AND reached = TRUE ORDER BY seq")) {
            ps.setInt(1, robotId);
            try (ResultSet rs = ps.executeQuery()) {
                while (rs.next()) {
                    int seq = rs.getInt(1);
                    if (reportedCheckpoints.put(seq, Boolean.TRUE) == null) {
                        out.computeIfAbsent(rs.getLong(2), t -> new ArrayList<>()).add(TraceEvent.checkpoint(seq));
                    }
                }
            }
        }
        return out;
    }

    /** The checkpoints (in seq order) and the station, in the page's world format (no arena, no obstacles). */
    private JsonObject readMission(Connection c) throws SQLException {
        JsonArray checkpoints = new JsonArray();
        double radius = 0.25;
        try (PreparedStatement ps = c.prepareStatement(
                "SELECT x_m, y_m, radius_m FROM checkpoints WHERE robot_id = ? ORDER BY seq")) {
            ps.setInt(1, robotId);
            try (ResultSet rs = ps.executeQuery()) {
                while (rs.next()) {
                    JsonObject p = new JsonObject();
                    p.addProperty("x", rs.getDouble(1));
                    p.addProperty("y", rs.getDouble(2));
                    radius = rs.getDouble(3);
                    checkpoints.add(p);
                }
            }
        }
        if (checkpoints.isEmpty()) {
            return null;
        }
        JsonObject w = new JsonObject();
        w.addProperty("name", "robot " + robotId);
        w.add("checkpoints", checkpoints);
        w.addProperty("checkpointRadiusM", radius);
        w.add("obstacles", new JsonArray());
        w.addProperty("robotRadiusM", 0.12); // the world file's default: the database does not hold the robot's shape
        // The rays as the robot's newest scan has them (any robot the world file draws, not the default one).
        TreeMap<Integer, double[]> scanRays = new TreeMap<>();
        try (PreparedStatement ps = c.prepareStatement("SELECT sensor_index, angle_rad, range_m FROM distance_sensor_data"
                + " WHERE robot_id = ? AND sim_time_ms = (SELECT MAX(sim_time_ms) FROM distance_sensor_data WHERE robot_id = ?)")) {
            ps.setInt(1, robotId);
            ps.setInt(2, robotId);
            try (ResultSet rs = ps.executeQuery()) {
                while (rs.next()) {
                    scanRays.put(rs.getInt(1), new double[] {rs.getDouble(2), rs.getDouble(3)});
                }
            }
        }
        if (scanRays.isEmpty() || scanRays.firstKey() < 0) {
            return null; // every robot has at least one ray: its first answer comes within a few steps
        }
        rays = scanRays.lastKey() + 1;
        JsonArray angles = new JsonArray();
        double range = 0;
        for (int k = 0; k < rays; k++) {
            double[] ray = scanRays.get(k);
            angles.add(ray == null ? 0.0 : ray[0]);
            range = Math.max(range, ray == null ? 0 : ray[1]);
        }
        w.addProperty("sensorRangeM", range);
        w.add("sensorAnglesRad", angles);
        try (PreparedStatement ps = c.prepareStatement("SELECT x_m, y_m, radius_m FROM recharge_station WHERE robot_id = ?")) {
            ps.setInt(1, robotId);
            try (ResultSet rs = ps.executeQuery()) {
                if (rs.next()) {
                    JsonObject st = new JsonObject();
                    st.addProperty("x", rs.getDouble(1));
                    st.addProperty("y", rs.getDouble(2));
                    st.addProperty("radiusM", rs.getDouble(3));
                    w.add("station", st);
                }
            }
        }
        return w;
    }
}
