package org.proactiverobotics.app.link;

import java.util.List;
import java.util.Optional;
import java.util.OptionalDouble;
import org.proactiverobotics.engine.tables.BatteryState;
import org.proactiverobotics.engine.tables.Checkpoint;
import org.proactiverobotics.engine.tables.DistanceScan;
import org.proactiverobotics.engine.tables.EngineComments;
import org.proactiverobotics.engine.tables.GpsFix;
import org.proactiverobotics.engine.tables.Heading;
import org.proactiverobotics.engine.tables.MapChunk;
import org.proactiverobotics.engine.tables.MissionTables;
import org.proactiverobotics.engine.tables.OccupancyMapTable;
import org.proactiverobotics.engine.tables.Sensor;
import org.proactiverobotics.engine.tables.SensorReadings;
import org.proactiverobotics.engine.tables.SensorRequests;
import org.proactiverobotics.engine.tables.InitialPose;
import org.proactiverobotics.engine.tables.PoseEstimate;
import org.proactiverobotics.engine.tables.PoseEstimateTable;
import org.proactiverobotics.engine.tables.Station;
import org.proactiverobotics.engine.tables.StrategyTable;
import org.proactiverobotics.engine.tables.WheelOdometry;

/**
 * The engine side of a {@link DirectLink} for one robot: the same table interfaces as
 * JdbcRobotTables, over the link's memory. Never throws for want of a database.
 */
public final class DirectEngineTables
        implements SensorReadings, SensorRequests, MissionTables, StrategyTable, EngineComments, OccupancyMapTable,
        PoseEstimateTable {

    private final DirectRows rows;

    DirectEngineTables(DirectRows rows) {
        this.rows = rows;
    }

    @Override
    public Optional<GpsFix> newestGps() {
        return Optional.ofNullable(rows.newestGps());
    }

    @Override
    public Optional<Heading> newestHeading() {
        return Optional.ofNullable(rows.newestHeading());
    }

    @Override
    public Optional<DistanceScan> newestScan() {
        return Optional.ofNullable(rows.newestScan());
    }

    @Override
    public Optional<BatteryState> newestBattery() {
        return Optional.ofNullable(rows.newestBattery());
    }

    @Override
    public Optional<WheelOdometry> newestOdometry() {
        return Optional.ofNullable(rows.newestOdometry());
    }

    @Override
    public long newestSimTimeMs(Sensor sensor) {
        return switch (sensor) {
            case GPS -> rows.newestGpsMs();
            case IU -> rows.newestIuMs();
            case DS -> rows.newestScanMs();
            case BATTERY -> rows.newestBatteryMs();
            case ODOMETRY -> rows.newestOdometryMs();
        };
    }

    @Override
    public boolean pending(Sensor sensor) {
        return rows.pending(sensor.word().name());
    }

    @Override
    public void request(Sensor sensor, long iteration) {
        rows.request(sensor.word().name());
    }

    @Override
    public List<Checkpoint> checkpoints() {
        return rows.checkpoints();
    }

    @Override
    public void markReached(int seq, long simTimeMs) {
        rows.markReached(seq);
    }

    @Override
    public void markUnreachable(int seq, long simTimeMs) {
        rows.markUnreachable(seq);
    }

    @Override
    public List<MapChunk> readMap() {
        return rows.map().readMap();
    }

    @Override
    public List<MapChunk> readMapSince(long simTimeMs) {
        return rows.map().readMapSince(simTimeMs);
    }

    @Override
    public void writeChunks(List<MapChunk> chunks, long simTimeMs) {
        rows.map().writeChunks(chunks, simTimeMs);
    }

    @Override
    public Optional<PoseEstimate> newestPose() {
        return Optional.ofNullable(rows.pose());
    }

    @Override
    public void writePose(PoseEstimate estimate) {
        rows.pose(estimate);
    }

    @Override
    public Optional<InitialPose> initialPose() {
        return Optional.ofNullable(rows.initialPose());
    }

    @Override
    public Optional<Station> rechargeStation() {
        return Optional.ofNullable(rows.station());
    }

    @Override
    public OptionalDouble rechargeLevelPct() {
        Double level = rows.rechargeLevelPct();
        return level == null ? OptionalDouble.empty() : OptionalDouble.of(level);
    }

    @Override
    public List<Entry> read() {
        return rows.strategy();
    }

    @Override
    public void write(List<Entry> entries) {
        rows.strategy(entries);
    }

    @Override
    public void send(long iteration, long simTimeMs, String scenario, String command) {
        rows.send(iteration, simTimeMs, scenario, command);
    }

    /**
     * Bounds the engine's history, as JdbcRobotTables.pruneHistory does.
     *
     * @param keepRows how many commands and answered requests to keep
     * @return the rows dropped
     */
    public int pruneHistory(int keepRows) {
        return rows.pruneHistory(keepRows);
    }
}
