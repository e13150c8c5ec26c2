package org.proactiverobotics.app.link;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.proactiverobotics.db.DatabaseKind;
import org.proactiverobotics.db.TestDatabase;
import org.proactiverobotics.db.TestDatabases;
import org.proactiverobotics.engine.robot.RobotEngine;
import org.proactiverobotics.engine.robot.ScenarioPlugins;
import org.proactiverobotics.engine.robot.Strategy;
import org.proactiverobotics.engine.tables.EngineTables;
import org.proactiverobotics.engine.tables.JdbcRobotTables;
import org.proactiverobotics.engine.tables.Sensor;
import org.proactiverobotics.robot.link.BatteryReading;
import org.proactiverobotics.robot.link.CommandRecord;
import org.proactiverobotics.robot.link.DistanceReading;
import org.proactiverobotics.robot.link.GpsReading;
import org.proactiverobotics.robot.link.IuReading;
import org.proactiverobotics.robot.link.JdbcRobotLink;
import org.proactiverobotics.robot.link.MissionSpec;
import org.proactiverobotics.robot.link.OdometryReading;
import org.proactiverobotics.robot.link.RetentionPolicy;
import org.proactiverobotics.robot.link.RobotLink;
import org.proactiverobotics.robot.link.SensorAnswer;
import org.proactiverobotics.robot.link.SensorRequest;

/** The direct link does what the JDBC tables do: one script played on both, every answer compared. */
class DirectLinkTest {

    private static final MissionSpec MISSION = new MissionSpec(
            List.of(new MissionSpec.Checkpoint(0, 3, 0.25), new MissionSpec.Checkpoint(3, -1, 0.25)),
            new MissionSpec.Station(-3, 0, 0.35), 95.0);

    /** Plays the robot and the engine side through one layer and writes down everything either sees. */
    private static List<Object> script(RobotLink robot, EngineTables engine) throws Exception {
        List<Object> seen = new ArrayList<>();
        seen.add(robot.seedMission(1, MISSION));
        seen.add(robot.seedMission(1, MISSION)); // once only
        robot.writeBattery(1, 0, new BatteryReading(100, false));
        engine.strategy().write(Strategy.named(Strategy.BATTERY_FIRST).rows(RobotEngine.freshSlots(ScenarioPlugins.none())));
        seen.add(engine.strategy().read());
        seen.add(engine.readings().newestGps());
        seen.add(engine.readings().newestSimTimeMs(Sensor.GPS));
        seen.add(engine.readings().newestBattery());
        seen.add(robot.newestCommand(1));
        for (int step = 1; step <= 6; step++) {
            long t = step * 32L;
            engine.requests().request(Sensor.GPS, step);
            if (step % 2 == 0) {
                engine.requests().request(Sensor.DS, step);
                engine.requests().request(Sensor.IU, step);
            }
            if (step % 3 != 1) {
                engine.requests().request(Sensor.ODOMETRY, step);
            }
            seen.add(engine.requests().pending(Sensor.ODOMETRY));
            seen.add(engine.requests().pending(Sensor.GPS));
            seen.add(engine.requests().pending(Sensor.BATTERY));
            List<SensorRequest> pending = robot.pendingRequests(1);
            seen.add(pending.stream().map(SensorRequest::sensor).toList());
            seen.add(pending.stream().mapToLong(SensorRequest::id).boxed().toList());
            long[] ids = pending.stream().mapToLong(SensorRequest::id).toArray();
            boolean ds = pending.stream().anyMatch(r -> r.sensor().equals("DS"));
            boolean odometry = pending.stream().anyMatch(r -> r.sensor().equals("ODOMETRY"));
            robot.answer(1, new SensorAnswer(t, new GpsReading(step * 0.1, -step * 0.2),
                    ds ? new IuReading(0, 0, step * 0.01) : null,
                    ds ? List.of(new DistanceReading(1, 0.5, 0.3 + step, 1.0), new DistanceReading(0, -0.5, 1.0, 1.0))
                            : List.of(), step == 5 ? new BatteryReading(90, true) : null,
                    odometry ? new OdometryReading(step * 0.01, -step * 0.02) : null, ids));
            robot.answer(1, new SensorAnswer(t + 1, null, null, List.of(), null, ids)); // already answered: nothing
            seen.add(engine.requests().pending(Sensor.GPS));
            seen.add(engine.readings().newestGps());
            seen.add(engine.readings().newestHeading());
            seen.add(engine.readings().newestScan().map(s -> List.of(s.simTimeMs(), List.of(s.anglesRad()[0], s.anglesRad()[1]),
                    List.of(s.distancesM()[0], s.distancesM()[1]), s.rangeM())));
            seen.add(engine.readings().newestBattery());
            seen.add(engine.readings().newestOdometry());
            for (Sensor s : Sensor.values()) {
                seen.add(engine.readings().newestSimTimeMs(s));
            }
            engine.comments().send(step, t, "ReachDestination", "DRIVE 0." + step + " 0.5");
            Optional<CommandRecord> newest = robot.newestCommand(1);
            seen.add(newest.map(c -> List.of(c.iteration(), c.simTimeMs(), c.scenario(), c.command())));
            seen.add(newest.map(CommandRecord::id).orElseThrow() > 0);
        }
        engine.mission().markReached(0, 100);
        seen.add(engine.mission().checkpoints());
        seen.add(robot.seedMission(1, MISSION));
        seen.add(engine.mission().checkpoints());
        seen.add(engine.mission().rechargeStation());
        seen.add(engine.mission().rechargeLevelPct());
        seen.add(robot.pendingRequests(1));
        // history: the robot keeps 2 readings, the engine 3 commands and answered requests; the same
        // rows go on both links (the robot prunes readings only: answered requests are the engine's)
        seen.add(robot.prune(1, new RetentionPolicy(2, 1)));
        seen.add(engine.pruneHistory().applyAsInt(3));
        seen.add(engine.readings().newestGps());
        seen.add(engine.readings().newestOdometry());
        seen.add(robot.newestCommand(1).map(CommandRecord::command));
        seen.add(robot.prune(1, RetentionPolicy.KEEP_ALL));
        return seen;
    }

    @Test
    void theDirectLinkAnswersExactlyAsTheDatabaseDoes() throws Exception {
        List<Object> overJdbc;
        try (TestDatabase db = TestDatabases.open(DatabaseKind.H2)) {
            overJdbc = script(new JdbcRobotLink(db.dataSource()), EngineTables.of(new JdbcRobotTables(db.dataSource(), 1)));
        }
        DirectLink direct = new DirectLink();
        DirectEngineTables directTables = direct.engine(1);
        List<Object> overDirect = script(direct, EngineTables.of(directTables, directTables::pruneHistory));
        assertThat(overDirect).hasSameSizeAs(overJdbc);
        for (int i = 0; i < overJdbc.size(); i++) {
            assertThat(overDirect.get(i)).as("observation %d", i).isEqualTo(overJdbc.get(i));
        }
    }

    @Test
    void robotsAreKeptApart() throws Exception {
        DirectLink direct = new DirectLink();
        direct.engine(1).send(1, 0, "ReachDestination", "STOP");
        direct.engine(1).request(Sensor.GPS, 1);
        assertThat(direct.newestCommand(2)).isEmpty();
        assertThat(direct.pendingRequests(2)).isEmpty();
        assertThat(direct.pendingRequests(1)).hasSize(1);
    }
}
