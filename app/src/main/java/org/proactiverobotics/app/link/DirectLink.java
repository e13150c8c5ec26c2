package org.proactiverobotics.app.link;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;
import org.proactiverobotics.robot.link.BatteryReading;
import org.proactiverobotics.robot.link.CommandRecord;
import org.proactiverobotics.robot.link.MissionSpec;
import org.proactiverobotics.robot.link.RetentionPolicy;
import org.proactiverobotics.robot.link.RobotLink;
import org.proactiverobotics.robot.link.SensorAnswer;
import org.proactiverobotics.robot.link.SensorRequest;

/**
 * An in-process communication layer (the paper's "different communication layer"): the robot
 * side's {@link RobotLink} here, the engine side's tables from {@link #engine(int)}, both over
 * the same memory, with the JDBC tables' semantics and no database. For one process only; the
 * engine and the robot may run on two threads. Nothing survives the process, so the engine's
 * state is not saved either (a one-process mission dies whole).
 *
 * <pre>{@code
 * DirectLink link = new DirectLink();
 * DirectEngineTables tables = link.engine(1);
 * RobotEngine engine = RobotEngine.builder().tables(EngineTables.of(tables, tables::pruneHistory), StateStore.none()).build();
 * ProactiveController robot = new ProactiveController(sim, link, RobotConfig.defaults(1));
 * }</pre>
 */
public final class DirectLink implements RobotLink {

    private final Map<Integer, DirectRows> robots = new ConcurrentHashMap<>();

    private DirectRows rows(int robotId) {
        return robots.computeIfAbsent(robotId, id -> new DirectRows());
    }

    /**
     * @param robotId the robot
     * @return the engine side's tables of that robot
     */
    public DirectEngineTables engine(int robotId) {
        return new DirectEngineTables(rows(robotId));
    }

    @Override
    public List<SensorRequest> pendingRequests(int robotId) {
        return rows(robotId).pendingRequests();
    }

    @Override
    public void answer(int robotId, SensorAnswer answer) {
        rows(robotId).answer(answer);
    }

    @Override
    public void writeBattery(int robotId, long simTimeMs, BatteryReading reading) {
        rows(robotId).writeBattery(simTimeMs, reading);
    }

    @Override
    public Optional<CommandRecord> newestCommand(int robotId) {
        return rows(robotId).newestCommand();
    }

    @Override
    public boolean checkpointUnreachable(int robotId) {
        return rows(robotId).checkpointUnreachable();
    }

    @Override
    public boolean seedMission(int robotId, MissionSpec mission) {
        return rows(robotId).seed(mission);
    }

    @Override
    public int prune(int robotId, RetentionPolicy policy) {
        return policy.prunes() ? rows(robotId).pruneReadings(policy.keepReadings()) : 0;
    }

    /** Nothing to release: the memory goes with the link. */
    @Override
    public void close() {
    }
}
