package org.proactiverobotics.robot;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import ch.qos.logback.classic.Level;
import ch.qos.logback.classic.Logger;
import ch.qos.logback.classic.spi.ILoggingEvent;
import ch.qos.logback.core.read.ListAppender;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.proactiverobotics.db.DatabaseKind;
import org.proactiverobotics.db.TestDatabase;
import org.proactiverobotics.db.TestDatabases;
import org.proactiverobotics.robot.link.JdbcRobotLink;
import org.proactiverobotics.robot.link.RetentionPolicy;
import org.proactiverobotics.sim2d.DistanceSensor;
import org.proactiverobotics.sim2d.SensorNoise;
import org.proactiverobotics.sim2d.SimRobot;
import org.proactiverobotics.sim2d.Simulation;
import org.proactiverobotics.sim2d.WorldSpec;
import org.slf4j.LoggerFactory;

class ProactiveControllerTest {

    /** The default robot's distance rays: a row each per scan. */
    private static final long RAYS = org.proactiverobotics.sim2d.WorldSpec.Robot.DEFAULT_SENSOR_ANGLES_DEG.size();

    private static final int ROBOT = 7;
    private static final RobotConfig CONFIG = RobotConfig.defaults(ROBOT).withWatchdogTimeoutMs(320)
            .withRealTimeFactor(0).withRetention(RetentionPolicy.KEEP_ALL);

    private static ProactiveController controller(TestDatabase db, Simulation sim, RobotConfig config) {
        return new ProactiveController(sim, new JdbcRobotLink(db.dataSource()), config);
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void atStartSeedsTheMissionWritesTheBatteryLevelAndWaits(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind)) {
            FakeEngine engine = new FakeEngine(db.dataSource(), ROBOT);
            Simulation sim = new Simulation(TestWorlds.arena());
            try (ProactiveController robot = controller(db, sim, CONFIG)) {
                robot.controlStep();
                assertThat(robot.started()).isTrue();
                assertThat(robot.mode()).isEqualTo(Mode.WAITING);
                assertThat(engine.count("checkpoints")).isEqualTo(2);
                assertThat(engine.count("recharge_station")).isEqualTo(1);
                assertThat(engine.rows("SELECT level_pct FROM battery_recharged").get(0)[0]).isEqualTo(95.0);
                assertThat(engine.rows("SELECT level_pct, sim_time_ms FROM battery_level WHERE robot_id = 7"))
                        .singleElement().satisfies(r -> {
                            assertThat(((Number) r[0]).doubleValue()).isEqualTo(80.0);
                            assertThat(((Number) r[1]).longValue()).isZero();
                        });
                for (int i = 0; i < 50; i++) {
                    robot.controlStep();
                    sim.step();
                }
                // No command yet: waiting, not a watchdog stop; nothing moved.
                assertThat(robot.mode()).isEqualTo(Mode.WAITING);
                assertThat(robot.stoppedUntilNewCommand()).isFalse();
                assertThat(sim.groundTruth().distanceM()).isZero();
            }
        }
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void withoutAGpsFixTheRequestIsAnsweredWithNoReadingAndTheOtherSensorsStillAnswer(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind)) {
            FakeEngine engine = new FakeEngine(db.dataSource(), ROBOT);
            Simulation sim = new Simulation(TestWorlds.arena(), SensorNoise.NONE.withoutGps());
            try (ProactiveController robot = controller(db, sim, CONFIG)) {
                robot.controlStep();
                engine.request("GPS");
                engine.request("IU");
                robot.sense();
                assertThat(engine.pending()).isZero(); // answered: "no fix", not left waiting
                assertThat(engine.count("gps_stored_values")).isZero();
                assertThat(engine.longValue("SELECT COUNT(*) FROM iudata WHERE robot_id = 7")).isEqualTo(1);
                assertThat(robot.stats().requestsAnswered()).isEqualTo(2);
                engine.request("GPS");
                robot.sense();
                assertThat(engine.pending()).isZero();
                assertThat(engine.count("gps_stored_values")).isZero();
            }
        }
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void answersRequestsWithTheSensorValuesTheWorldGives(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind)) {
            FakeEngine engine = new FakeEngine(db.dataSource(), ROBOT);
            Simulation sim = new Simulation(TestWorlds.arena());
            try (ProactiveController robot = controller(db, sim, CONFIG)) {
                engine.command("FORWARD 0.2");
                for (int i = 0; i < 10; i++) {
                    robot.controlStep();
                    sim.step();
                }
                engine.request("GPS");
                engine.request("IU");
                engine.request("DS");
                engine.request("BATTERY");
                engine.request("GPS"); // a duplicate: answered by the same reading
                new FakeEngine(db.dataSource(), ROBOT + 1).request("GPS"); // another robot's
                robot.sense();

                SimRobot body = sim.robot();
                long now = sim.simTimeMs();
                assertThat(engine.pending()).isZero();
                assertThat(engine.longValue("SELECT COUNT(*) FROM sensor_requests WHERE robot_id = 8 AND answered_sim_time_ms IS NULL")).isEqualTo(1);
                assertThat(engine.longValue("SELECT COUNT(*) FROM sensor_requests WHERE answered_sim_time_ms = " + now)).isEqualTo(5);

                double[] gps = body.gps().getValues();
                Object[] g = engine.rows("SELECT x_m, y_m, sim_time_ms FROM gps_stored_values WHERE robot_id = 7").get(0);
                assertThat((double) g[0]).isEqualTo(gps[0]);
                assertThat((double) g[1]).isEqualTo(gps[1]);
                assertThat(((Number) g[2]).longValue()).isEqualTo(now);
                assertThat(gps[1]).isGreaterThan(-4.0); // it did move forward (+y)

                double[] rpy = body.inertialUnit().getRollPitchYaw();
                Object[] iu = engine.rows("SELECT roll_rad, pitch_rad, yaw_rad FROM iudata WHERE robot_id = 7").get(0);
                assertThat(new double[] {(double) iu[0], (double) iu[1], (double) iu[2]}).containsExactly(rpy);
                assertThat(rpy[2]).isCloseTo(Math.PI / 2, within(1e-6));

                List<Object[]> ds = engine.rows("SELECT sensor_index, angle_rad, distance_m, range_m FROM distance_sensor_data "
                        + "WHERE robot_id = 7 ORDER BY sensor_index");
                List<DistanceSensor> sensors = body.distanceSensors();
                assertThat(ds).hasSize(sensors.size());
                for (int i = 0; i < sensors.size(); i++) {
                    DistanceSensor s = sensors.get(i);
                    assertThat(((Number) ds.get(i)[0]).intValue()).isEqualTo(s.getIndex());
                    assertThat((double) ds.get(i)[1]).isEqualTo(s.getAngleRad());
                    assertThat((double) ds.get(i)[2]).isEqualTo(s.getValue());
                    assertThat((double) ds.get(i)[3]).isEqualTo(s.getRangeM());
                }
                // the obstacle straight ahead is seen by the front sensors, closer than their range
                assertThat(sensors.stream().mapToDouble(DistanceSensor::getValue).min().orElseThrow()).isLessThan(1.0);

                Object[] battery = engine.rows("SELECT level_pct, charging FROM battery_level WHERE robot_id = 7 ORDER BY id DESC LIMIT 1").get(0);
                assertThat((double) battery[0]).isEqualTo(body.battery().getLevelPct()).isLessThan(80.0);
                assertThat(robot.stats().requestsAnswered()).isEqualTo(5);

                engine.request("SONAR"); // unknown: left pending, counted once
                robot.sense();
                robot.sense();
                assertThat(engine.pending()).isEqualTo(1);
                assertThat(robot.stats().unknownRequests()).isEqualTo(1);
            }
        }
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void theNewestCommandWinsAndBadOrOlderOnesAreIgnored(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind)) {
            FakeEngine engine = new FakeEngine(db.dataSource(), ROBOT);
            Simulation sim = new Simulation(TestWorlds.arena());
            try (ProactiveController robot = controller(db, sim, CONFIG)) {
                engine.command("DRIVE 0.1 0.1");
                long forward = engine.command("FORWARD 0.3");
                new FakeEngine(db.dataSource(), ROBOT + 1).command("TURN_LEFT 0.5"); // another robot's, newer
                robot.controlStep();
                assertThat(robot.mode()).isEqualTo(Mode.FORWARD);
                assertThat(robot.lastExecutedCommandId()).isEqualTo(forward);
                assertThat(sim.robot().leftSpeedMps()).isEqualTo(0.3);
                assertThat(sim.robot().rightSpeedMps()).isEqualTo(0.3);

                engine.command("JUMP 3");
                robot.controlStep();
                robot.controlStep(); // seen again: not counted again
                engine.command("DRIVE NaN 0");
                robot.controlStep();
                engine.command("DRIVE 9 9");
                robot.controlStep();
                assertThat(robot.mode()).isEqualTo(Mode.FORWARD);
                assertThat(sim.robot().leftSpeedMps()).isEqualTo(0.3);
                assertThat(robot.stats().commandsIgnored()).isEqualTo(3);

                long turn = engine.command("TURN_RIGHT 0.25");
                robot.controlStep();
                assertThat(robot.mode()).isEqualTo(Mode.TURN_RIGHT);
                assertThat(sim.robot().leftSpeedMps()).isEqualTo(0.25);
                assertThat(sim.robot().rightSpeedMps()).isEqualTo(-0.25);

                // The newest rows disappear: what is now newest is older than what ran; ignored once.
                engine.execute("DELETE FROM engine_comments WHERE id >= " + (turn - 3) + " AND robot_id = 7");
                robot.controlStep();
                robot.controlStep();
                assertThat(robot.mode()).isEqualTo(Mode.TURN_RIGHT);
                assertThat(robot.lastExecutedCommandId()).isEqualTo(turn);
                assertThat(robot.stats().commandsIgnored()).isEqualTo(4);
                assertThat(robot.stats().commandsExecuted()).isEqualTo(2);
            }
        }
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void aLaterIterationsCommandRunsEvenWhenItsIdIsSmaller(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind)) {
            FakeEngine engine = new FakeEngine(db.dataSource(), ROBOT);
            Simulation sim = new Simulation(TestWorlds.arena());
            try (ProactiveController robot = controller(db, sim, CONFIG)) {
                // As on a Galera cluster when the engine moved to the node whose id counter is behind.
                engine.execute("INSERT INTO engine_comments (id, robot_id, iteration, sim_time_ms, scenario, command)"
                        + " VALUES (31, " + ROBOT + ", 7, 224, 'A', 'FORWARD 0.3')");
                robot.controlStep();
                assertThat(robot.mode()).isEqualTo(Mode.FORWARD);
                engine.execute("INSERT INTO engine_comments (id, robot_id, iteration, sim_time_ms, scenario, command)"
                        + " VALUES (29, " + ROBOT + ", 8, 256, 'B', 'TURN_LEFT 0.2')");
                robot.controlStep();
                assertThat(robot.mode()).isEqualTo(Mode.TURN_LEFT);
                assertThat(robot.lastExecutedCommandId()).isEqualTo(29);
                assertThat(robot.stats().commandsIgnored()).isZero();
            }
        }
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void theWatchdogStopsTheRobotAndLetsItGoAgain(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind)) {
            FakeEngine engine = new FakeEngine(db.dataSource(), ROBOT);
            Simulation sim = new Simulation(TestWorlds.arena().withObstacles(List.of()));
            try (ProactiveController robot = controller(db, sim, CONFIG)) {
                engine.command("FORWARD 0.2");
                int steps = 0;
                while (!robot.stoppedUntilNewCommand() && steps < 100) {
                    robot.controlStep();
                    sim.step();
                    steps++;
                }
                // 320 ms time-out at 32 ms per step: stopped on the 12th step after the command
                assertThat(steps).isEqualTo(12);
                assertThat(robot.mode()).isEqualTo(Mode.STOP);
                assertThat(sim.robot().leftSpeedMps()).isZero();
                double moved = sim.groundTruth().distanceM();
                assertThat(moved).isGreaterThan(0.05);
                for (int i = 0; i < 20; i++) {
                    robot.controlStep();
                    sim.step();
                }
                assertThat(sim.groundTruth().distanceM()).isEqualTo(moved);
                assertThat(robot.stats().watchdogStops()).isEqualTo(1);
                assertThat(robot.stats().linkStops()).isZero();

                engine.command("FORWARD 0.2");
                robot.controlStep();
                assertThat(robot.stoppedUntilNewCommand()).isFalse();
                assertThat(robot.mode()).isEqualTo(Mode.FORWARD);
                sim.step();
                assertThat(sim.groundTruth().distanceM()).isGreaterThan(moved);

                // a malformed command does not feed the watchdog
                for (int i = 0; i < 5; i++) {
                    engine.command("FLY");
                    robot.controlStep();
                    sim.step();
                }
                for (int i = 0; i < 10; i++) {
                    engine.command("FLY");
                    robot.controlStep();
                    sim.step();
                }
                assertThat(robot.stoppedUntilNewCommand()).isTrue();
            }
        }
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void rechargesOnlyAtTheStation(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind)) {
            FakeEngine engine = new FakeEngine(db.dataSource(), ROBOT);
            Simulation away = new Simulation(TestWorlds.arena());
            try (ProactiveController robot = controller(db, away, CONFIG)) {
                engine.command("RECHARGE");
                robot.controlStep();
                away.step();
                assertThat(robot.mode()).isEqualTo(Mode.RECHARGE);
                assertThat(away.robot().battery().isCharging()).isFalse();
            }
            Simulation there = new Simulation(TestWorlds.atStation());
            try (ProactiveController robot = controller(db, there, CONFIG)) {
                engine.command("RECHARGE");
                robot.controlStep();
                there.step();
                assertThat(there.robot().battery().isCharging()).isTrue();
                for (int i = 0; i < 10; i++) {
                    engine.command("RECHARGE");
                    robot.controlStep();
                    there.step();
                }
                assertThat(there.robot().battery().getLevelPct()).isGreaterThan(80.0);
                engine.command("FORWARD 0.1");
                robot.controlStep();
                assertThat(there.robot().battery().isCharging()).isFalse();
            }
        }
    }

    @Test
    void aNormalRechargeIsSilentAndARefusedOneWarnsAtMostEveryTenSeconds() throws Exception {
        Logger log = (Logger) LoggerFactory.getLogger(ProactiveController.class);
        ListAppender<ILoggingEvent> seen = new ListAppender<>();
        seen.start();
        Level level = log.getLevel();
        log.setLevel(Level.WARN);
        log.addAppender(seen);
        log.setAdditive(false); // seen here, not on the console
        try (TestDatabase db = TestDatabases.open(DatabaseKind.H2)) {
            FakeEngine engine = new FakeEngine(db.dataSource(), ROBOT);
            // at the station: charges to rechargeTo, then RECHARGE keeps coming (the engine learns it is full later)
            Simulation there = new Simulation(TestWorlds.atStation());
            try (ProactiveController robot = controller(db, there, CONFIG)) {
                for (int i = 0; i < 100; i++) {
                    engine.command("RECHARGE");
                    robot.controlStep();
                    there.step();
                }
                assertThat(there.robot().battery().getLevelPct()).isEqualTo(95.0);
                assertThat(there.robot().battery().isCharging()).isFalse();
            }
            assertThat(seen.list).as("a normal recharge").isEmpty();

            // away from the station, RECHARGE every step for 25 s: refused, said at 0, 10 and 20 s
            Simulation away = new Simulation(TestWorlds.arena());
            try (ProactiveController robot = controller(db, away, CONFIG)) {
                while (away.simTimeMs() < 25_000) {
                    engine.command("RECHARGE");
                    robot.controlStep();
                    away.step();
                }
            }
            assertThat(seen.list).hasSize(3).allSatisfy(e -> {
                assertThat(e.getLevel()).isEqualTo(Level.WARN);
                assertThat(e.getFormattedMessage()).contains("RECHARGE refused: not at the recharge station");
            });
            assertThat(seen.list.get(1).getFormattedMessage()).contains("(313 refused");
        } finally {
            log.detachAppender(seen);
            log.setAdditive(true);
            log.setLevel(level);
        }
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void aRestartDoesNotSeedTheMissionTwice(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind)) {
            FakeEngine engine = new FakeEngine(db.dataSource(), ROBOT);
            for (int run = 0; run < 2; run++) {
                try (ProactiveController robot = controller(db, new Simulation(TestWorlds.arena()), CONFIG)) {
                    robot.controlStep();
                    assertThat(robot.started()).isTrue();
                }
                engine.execute("UPDATE checkpoints SET reached = TRUE WHERE seq = 0");
            }
            assertThat(engine.count("checkpoints")).isEqualTo(2);
            assertThat(engine.count("recharge_station")).isEqualTo(1);
            assertThat(engine.count("battery_recharged")).isEqualTo(1);
            // the engine's progress survived the restart
            assertThat(engine.longValue("SELECT COUNT(*) FROM checkpoints WHERE reached = TRUE")).isEqualTo(1);
        }
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void retentionKeepsTheTablesBounded(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind)) {
            FakeEngine engine = new FakeEngine(db.dataSource(), ROBOT);
            Simulation sim = new Simulation(TestWorlds.arena());
            RobotConfig config = CONFIG.withRetention(new RetentionPolicy(20, 10)).withWatchdogTimeoutMs(100_000);
            try (ProactiveController robot = controller(db, sim, config)) {
                engine.command("TURN_LEFT 0.1");
                long maxGps = 0;
                for (int i = 0; i < 300; i++) {
                    for (String s : new String[] {"GPS", "IU", "DS", "BATTERY"}) {
                        engine.request(s);
                    }
                    robot.controlStep();
                    sim.step();
                    maxGps = Math.max(maxGps, engine.count("gps_stored_values"));
                }
                assertThat(robot.stats().requestsAnswered()).isEqualTo(1200);
                // at most keep + every readings between two prunings
                assertThat(maxGps).isLessThanOrEqualTo(30);
                assertThat(engine.count("gps_stored_values")).isBetween(20L, 30L);
                assertThat(engine.count("iudata")).isBetween(20L, 30L);
                assertThat(engine.count("battery_level")).isBetween(20L, 31L);
                assertThat(engine.count("distance_sensor_data")).isBetween(20L * RAYS, 30L * RAYS);
                assertThat(engine.count("sensor_requests")).as("the engine's table: not pruned by the robot")
                        .isGreaterThanOrEqualTo(1200L);
                assertThat(robot.stats().rowsPruned()).isGreaterThan(0);
            }
        }
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void runStepsTheWorldUntilItsTimeLimitAndLeavesTheRobotStopped(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind)) {
            FakeEngine engine = new FakeEngine(db.dataSource(), ROBOT);
            WorldSpec world = TestWorlds.arena().withObstacles(List.of());
            world = new WorldSpec(world.name(), world.timeStepMs(), 0.64, world.seed(), world.arena(), world.robot(),
                    world.obstacles(), world.checkpoints(), world.checkpointRadiusM(), world.rechargeStation(),
                    world.battery());
            Simulation sim = new Simulation(world);
            try (ProactiveController robot = controller(db, sim, CONFIG.withWatchdogTimeoutMs(10_000))) {
                engine.command("FORWARD 0.3");
                assertThat(robot.run()).isEqualTo(640);
                assertThat(robot.stats().controlSteps()).isEqualTo(20);
                assertThat(sim.groundTruth().distanceM()).isCloseTo(0.3 * 0.64, within(0.02));
                assertThat(sim.robot().leftSpeedMps()).isZero();
            }
        }
    }
}
