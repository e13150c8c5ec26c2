package org.proactiverobotics.robot;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.proactiverobotics.db.DatabaseKind;
import org.proactiverobotics.db.TestDatabase;
import org.proactiverobotics.db.TestDatabases;
import org.proactiverobotics.robot.link.JdbcRobotLink;
import org.proactiverobotics.robot.link.RetentionPolicy;
import org.proactiverobotics.sim2d.Simulation;

/**
 * The robot answers an ODOMETRY request with each wheel's travel since its previous odometry
 * reading, written to {@code odometry}: real database, real dyn4j world.
 */
class OdometryTest {

    private static final int ROBOT = 7;
    /** No watchdog stop within these tests: the fake engine sends one command and stays quiet. */
    private static final RobotConfig CONFIG = RobotConfig.defaults(ROBOT).withWatchdogTimeoutMs(600_000)
            .withRealTimeFactor(0).withRetention(RetentionPolicy.KEEP_ALL);

    private static ProactiveController controller(TestDatabase db, Simulation sim, RobotConfig config) {
        return new ProactiveController(sim, new JdbcRobotLink(db.dataSource()), config);
    }

    /** Steps the robot (sense, act) and the world n times. */
    private static void drive(ProactiveController robot, Simulation sim, int steps) {
        for (int i = 0; i < steps; i++) {
            robot.controlStep();
            sim.step();
        }
    }

    /** @return the robot's odometry rows, oldest first: {sim_time_ms, left_m, right_m} */
    private static List<double[]> readings(FakeEngine engine) throws Exception {
        return engine.rows("SELECT sim_time_ms, left_m, right_m FROM odometry WHERE robot_id = " + ROBOT
                + " ORDER BY sim_time_ms, id").stream()
                .map(r -> new double[] {((Number) r[0]).doubleValue(), ((Number) r[1]).doubleValue(), ((Number) r[2]).doubleValue()})
                .toList();
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void drivingStraightBothWheelsTravelSpeedTimesTime(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind)) {
            FakeEngine engine = new FakeEngine(db.dataSource(), ROBOT);
            Simulation sim = new Simulation(TestWorlds.arena());
            try (ProactiveController robot = controller(db, sim, CONFIG)) {
                engine.command("DRIVE 0.3 0.3");
                engine.request("ODOMETRY");
                drive(robot, sim, 15); // answered at 0 ms, before the wheels turn
                engine.request("ODOMETRY");
                robot.sense();

                assertThat(engine.pending()).isZero();
                List<double[]> rows = readings(engine);
                assertThat(rows).hasSize(2);
                assertThat(rows.get(0)).containsExactly(0.0, 0.0, 0.0);
                double seconds = (rows.get(1)[0] - rows.get(0)[0]) / 1000.0;
                assertThat(seconds).isEqualTo(15 * 0.032, within(1e-9));
                assertThat(rows.get(1)[1]).isCloseTo(0.3 * seconds, within(1e-9));
                assertThat(rows.get(1)[2]).isCloseTo(0.3 * seconds, within(1e-9));
                // nothing in the way: the wheels' travel is the body's
                assertThat(sim.groundTruth().distanceM()).isCloseTo(0.3 * seconds, within(1e-3));
                assertThat(robot.stats().requestsAnswered()).isEqualTo(2);
            }
        }
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void turningOnTheSpotTheWheelsTravelOppositeWays(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind)) {
            FakeEngine engine = new FakeEngine(db.dataSource(), ROBOT);
            Simulation sim = new Simulation(TestWorlds.arena());
            try (ProactiveController robot = controller(db, sim, CONFIG)) {
                double yawBefore = sim.robot().inertialUnit().getRollPitchYaw()[2];
                engine.command("DRIVE -0.2 0.2");
                engine.request("ODOMETRY");
                drive(robot, sim, 10);
                engine.request("ODOMETRY");
                robot.sense();

                double[] turn = readings(engine).get(1);
                double seconds = 10 * 0.032;
                assertThat(turn[1]).isCloseTo(-0.2 * seconds, within(1e-9));
                assertThat(turn[2]).isCloseTo(0.2 * seconds, within(1e-9));
                // counter-clockwise by the wheels' difference over the axle
                double yawAfter = sim.robot().inertialUnit().getRollPitchYaw()[2];
                assertThat(yawAfter - yawBefore).isCloseTo((turn[2] - turn[1]) / sim.robot().axleWidthM(), within(1e-3));
                assertThat(sim.groundTruth().distanceM()).isCloseTo(0.0, within(1e-3));
            }
        }
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void theReadingsAddUpToTheWholeTravelEvenAcrossAFailedWrite(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind)) {
            FakeEngine engine = new FakeEngine(db.dataSource(), ROBOT);
            Simulation sim = new Simulation(TestWorlds.arena());
            String[] commands = {"DRIVE 0.3 0.1", "DRIVE -0.2 0.2", "STOP", "DRIVE 0.25 0.25", "DRIVE -0.1 -0.15"};
            try (ProactiveController robot = controller(db, sim, CONFIG)) {
                for (int step = 0; step < 60; step++) {
                    if (step % 7 == 0) {
                        engine.command(commands[step / 7 % commands.length]);
                    }
                    if (step % 3 == 0 || step % 5 == 0) {
                        engine.request("ODOMETRY");
                    }
                    if (step == 30) { // this step's reading cannot be written: its travel goes with the next one
                        engine.execute("ALTER TABLE odometry RENAME TO odometry_away");
                        robot.sense();
                        engine.execute("ALTER TABLE odometry_away RENAME TO odometry");
                        assertThat(engine.pending()).isEqualTo(1);
                    }
                    drive(robot, sim, 1);
                }
                engine.request("ODOMETRY");
                long deadline = System.nanoTime() + 30_000_000_000L; // the back-off after the failure lets a call through
                while (engine.pending() > 0 && System.nanoTime() < deadline) {
                    robot.sense();
                    Thread.sleep(20);
                }
                assertThat(engine.pending()).isZero();

                List<double[]> rows = readings(engine);
                double left = 0;
                double right = 0;
                for (double[] r : rows) {
                    left += r[1];
                    right += r[2];
                }
                double[] total = sim.robot().odometer().getTravelM();
                assertThat(total[0]).isNotZero();
                assertThat(total[1]).isNotEqualTo(total[0]);
                assertThat(left).isCloseTo(total[0], within(1e-9));
                assertThat(right).isCloseTo(total[1], within(1e-9));
                assertThat(rows).hasSizeGreaterThan(10); // many readings, some covering several steps (the back-off)
            }
        }
    }

    @ParameterizedTest
    @EnumSource(DatabaseKind.class)
    void pruningKeepsTheNewestOdometryReadings(DatabaseKind kind) throws Exception {
        try (TestDatabase db = TestDatabases.open(kind)) {
            FakeEngine engine = new FakeEngine(db.dataSource(), ROBOT);
            Simulation sim = new Simulation(TestWorlds.arena());
            try (ProactiveController robot = controller(db, sim, CONFIG.withRetention(new RetentionPolicy(5, 10)))) {
                engine.command("DRIVE 0.2 0.2");
                for (int step = 0; step < 40; step++) {
                    engine.request("ODOMETRY");
                    drive(robot, sim, 1);
                }
                // pruned at the 40th step, before its reading: the five newest of the 39 before
                List<double[]> rows = readings(engine);
                assertThat(rows).hasSize(6);
                assertThat(rows.get(0)[0]).isEqualTo(34 * 32.0);
                assertThat(rows.get(rows.size() - 1)[0]).isEqualTo(39 * 32.0);
                assertThat(robot.stats().rowsPruned()).isEqualTo(4 + 10 + 10 + 10);
            }
        }
    }
}
