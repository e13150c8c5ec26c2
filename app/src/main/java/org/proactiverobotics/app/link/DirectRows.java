package org.proactiverobotics.app.link;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.Iterator;
import java.util.List;
import java.util.Optional;
import org.proactiverobotics.engine.tables.BatteryState;
import org.proactiverobotics.engine.tables.Checkpoint;
import org.proactiverobotics.engine.tables.DistanceScan;
import org.proactiverobotics.engine.tables.GpsFix;
import org.proactiverobotics.engine.tables.Heading;
import org.proactiverobotics.engine.tables.OccupancyMapTable;
import org.proactiverobotics.engine.tables.InitialPose;
import org.proactiverobotics.engine.tables.PoseEstimate;
import org.proactiverobotics.engine.tables.Station;
import org.proactiverobotics.engine.tables.StrategyTable;
import org.proactiverobotics.engine.tables.WheelOdometry;
import org.proactiverobotics.robot.link.BatteryReading;
import org.proactiverobotics.robot.link.CommandRecord;
import org.proactiverobotics.robot.link.DistanceReading;
import org.proactiverobotics.robot.link.MissionSpec;
import org.proactiverobotics.robot.link.SensorAnswer;
import org.proactiverobotics.robot.link.SensorRequest;

/**
 * One robot's rows of schema.sql, in memory, with the JDBC tables' semantics: ids grow per
 * table, the newest row wins (kept in the order written, which in one process is the order of
 * simulated time and iteration the tables sort by), a request is pending until answered, an answer is
 * atomic, mission rows are seeded once, history is pruned to the newest n. Readings are kept in
 * the engine's record types, so a read allocates nothing. Every method holds this object's lock:
 * the robot and the engine may run on two threads. Units as in the tables: simulated
 * milliseconds, metres, radians, percent.
 */
final class DirectRows {

    /** A sensor_requests row. */
    private static final class Request {
        final long id;
        final String sensor;
        long answeredSimTimeMs = -1;

        Request(long id, String sensor) {
            this.id = id;
            this.sensor = sensor;
        }
    }

    private final ArrayDeque<GpsFix> gps = new ArrayDeque<>();
    private final ArrayDeque<Heading> iu = new ArrayDeque<>();
    private final ArrayDeque<DistanceScan> scans = new ArrayDeque<>();
    private final ArrayDeque<BatteryState> battery = new ArrayDeque<>();
    private final ArrayDeque<WheelOdometry> odometry = new ArrayDeque<>();
    private final ArrayList<Request> pending = new ArrayList<>();
    private final ArrayDeque<Request> answered = new ArrayDeque<>();
    private final ArrayDeque<CommandRecord> commands = new ArrayDeque<>();
    private List<Checkpoint> checkpoints = List.of();
    private Station station;
    private InitialPose initialPose;
    private PoseEstimate pose;
    private Double rechargeLevelPct;
    private List<StrategyTable.Entry> strategy = List.of();
    /** occupancy_map's rows: the engine side alone writes and reads them. */
    private final OccupancyMapTable map = OccupancyMapTable.inMemory();
    private long requestIds;
    private long commandIds;

    // ---------------------------------------------------------------- robot side

    synchronized List<SensorRequest> pendingRequests() {
        if (pending.isEmpty()) {
            return List.of();
        }
        List<SensorRequest> out = new ArrayList<>(pending.size());
        for (Request r : pending) {
            out.add(new SensorRequest(r.id, r.sensor));
        }
        return out;
    }

    synchronized void answer(SensorAnswer a) {
        long t = a.simTimeMs();
        if (a.gps() != null) {
            gps.addLast(new GpsFix(t, a.gps().xM(), a.gps().yM()));
        }
        if (a.iu() != null) {
            iu.addLast(new Heading(t, a.iu().yawRad()));
        }
        if (!a.distances().isEmpty()) {
            scans.addLast(scan(t, a.distances()));
        }
        if (a.battery() != null) {
            battery.addLast(new BatteryState(t, a.battery().levelPct(), a.battery().charging()));
        }
        if (a.odometry() != null) {
            odometry.addLast(new WheelOdometry(t, a.odometry().leftM(), a.odometry().rightM()));
        }
        for (long id : a.requestIds()) {
            for (Iterator<Request> it = pending.iterator(); it.hasNext(); ) {
                Request r = it.next();
                if (r.id == id) {
                    it.remove();
                    r.answeredSimTimeMs = t;
                    answered.addLast(r);
                    break;
                }
            }
        }
    }

    /** As JdbcRobotTables reads it back: by sensor index, the range the largest of the rows'. */
    private static DistanceScan scan(long t, List<DistanceReading> readings) {
        List<DistanceReading> sorted = new ArrayList<>(readings);
        sorted.sort(Comparator.comparingInt(DistanceReading::sensorIndex));
        double[] angles = new double[sorted.size()];
        double[] distances = new double[sorted.size()];
        double range = 0;
        for (int i = 0; i < angles.length; i++) {
            angles[i] = sorted.get(i).angleRad();
            distances[i] = sorted.get(i).distanceM();
            range = Math.max(range, sorted.get(i).rangeM());
        }
        return new DistanceScan(t, angles, distances, range);
    }

    synchronized void writeBattery(long simTimeMs, BatteryReading reading) {
        battery.addLast(new BatteryState(simTimeMs, reading.levelPct(), reading.charging()));
    }

    synchronized Optional<CommandRecord> newestCommand() {
        return Optional.ofNullable(commands.peekLast());
    }

    synchronized boolean seed(MissionSpec mission) {
        boolean wrote = false;
        if (checkpoints.isEmpty()) {
            List<Checkpoint> rows = new ArrayList<>();
            int seq = 0;
            for (MissionSpec.Checkpoint c : mission.checkpoints()) {
                rows.add(new Checkpoint(seq++, c.xM(), c.yM(), c.radiusM(), false));
            }
            checkpoints = List.copyOf(rows);
            wrote = true;
        }
        if (station == null) {
            station = new Station(mission.station().xM(), mission.station().yM(), mission.station().radiusM());
            wrote = true;
        }
        if (rechargeLevelPct == null) {
            rechargeLevelPct = mission.rechargeToPct();
            wrote = true;
        }
        if (initialPose == null && mission.start() != null) {
            initialPose = new InitialPose(mission.start().xM(), mission.start().yM(), mission.start().yawRad());
            wrote = true;
        }
        return wrote;
    }

    /** The robot's retention: readings beyond the newest n; rows deleted (answered requests are the engine's to prune, as over JDBC). */
    synchronized int pruneReadings(int keep) {
        int deleted = trim(gps, keep) + trim(iu, keep) + trim(battery, keep) + trim(odometry, keep);
        while (scans.size() > keep) {
            deleted += scans.pollFirst().anglesRad().length; // one row per sensor, as in the table
        }
        return deleted;
    }

    // ---------------------------------------------------------------- engine side

    synchronized GpsFix newestGps() {
        return gps.peekLast();
    }

    synchronized Heading newestHeading() {
        return iu.peekLast();
    }

    synchronized DistanceScan newestScan() {
        return scans.peekLast();
    }

    synchronized BatteryState newestBattery() {
        return battery.peekLast();
    }

    synchronized WheelOdometry newestOdometry() {
        return odometry.peekLast();
    }

    synchronized long newestGpsMs() {
        return gps.isEmpty() ? -1 : gps.peekLast().simTimeMs();
    }

    synchronized long newestIuMs() {
        return iu.isEmpty() ? -1 : iu.peekLast().simTimeMs();
    }

    synchronized long newestScanMs() {
        return scans.isEmpty() ? -1 : scans.peekLast().simTimeMs();
    }

    synchronized long newestBatteryMs() {
        return battery.isEmpty() ? -1 : battery.peekLast().simTimeMs();
    }

    synchronized long newestOdometryMs() {
        return odometry.isEmpty() ? -1 : odometry.peekLast().simTimeMs();
    }

    synchronized boolean pending(String sensor) {
        for (Request r : pending) {
            if (r.sensor.equals(sensor)) {
                return true;
            }
        }
        return false;
    }

    synchronized void request(String sensor) {
        pending.add(new Request(++requestIds, sensor));
    }

    synchronized List<Checkpoint> checkpoints() {
        return checkpoints; // immutable: replaced, never changed
    }

    synchronized void markReached(int seq) {
        List<Checkpoint> rows = new ArrayList<>(checkpoints);
        for (int i = 0; i < rows.size(); i++) {
            Checkpoint c = rows.get(i);
            if (c.seq() == seq) {
                rows.set(i, new Checkpoint(c.seq(), c.xM(), c.yM(), c.radiusM(), true, c.unreachable()));
            }
        }
        checkpoints = List.copyOf(rows);
    }

    synchronized void markUnreachable(int seq) {
        List<Checkpoint> rows = new ArrayList<>(checkpoints);
        for (int i = 0; i < rows.size(); i++) {
            Checkpoint c = rows.get(i);
            if (c.seq() == seq) {
                rows.set(i, new Checkpoint(c.seq(), c.xM(), c.yM(), c.radiusM(), c.reached(), true));
            }
        }
        checkpoints = List.copyOf(rows);
    }

    synchronized boolean checkpointUnreachable() {
        for (Checkpoint c : checkpoints) {
            if (c.unreachable()) {
                return true;
            }
        }
        return false;
    }

    /** @return occupancy_map's rows, kept in memory */
    OccupancyMapTable map() {
        return map;
    }

    synchronized InitialPose initialPose() {
        return initialPose;
    }

    /** @return the newest pose estimate the engine side wrote, or null */
    synchronized PoseEstimate pose() {
        return pose;
    }

    synchronized void pose(PoseEstimate estimate) {
        pose = estimate;
    }

    synchronized Station station() {
        return station;
    }

    synchronized Double rechargeLevelPct() {
        return rechargeLevelPct;
    }

    synchronized List<StrategyTable.Entry> strategy() {
        return strategy; // immutable: replaced whole
    }

    synchronized void strategy(List<StrategyTable.Entry> entries) {
        List<StrategyTable.Entry> sorted = new ArrayList<>(entries);
        sorted.sort(Comparator.comparingInt(StrategyTable.Entry::slot));
        strategy = List.copyOf(sorted);
    }

    synchronized void send(long iteration, long simTimeMs, String scenario, String command) {
        commands.addLast(new CommandRecord(++commandIds, iteration, simTimeMs, scenario, command));
    }

    /** The engine's retention: commands and answered requests beyond the newest n; rows deleted. */
    synchronized int pruneHistory(int keep) {
        return trim(commands, keep) + trim(answered, keep);
    }

    private static int trim(ArrayDeque<?> rows, int keep) {
        int deleted = 0;
        while (rows.size() > keep) {
            rows.pollFirst();
            deleted++;
        }
        return deleted;
    }
}
