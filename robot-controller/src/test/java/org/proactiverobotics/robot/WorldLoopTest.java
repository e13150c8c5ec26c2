package org.proactiverobotics.robot;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.proactiverobotics.db.DatabaseKind;
import org.proactiverobotics.db.TestDatabase;
import org.proactiverobotics.db.TestDatabases;
import org.proactiverobotics.robot.link.JdbcRobotLink;
import org.proactiverobotics.robot.link.RetentionPolicy;
import org.proactiverobotics.sim2d.Simulation;
import org.proactiverobotics.sim2d.WorldSpec;

/** One controller per robot of one world: each seeds its own mission and drives its own robot. */
class WorldLoopTest {

    private static WorldSpec twoRobots() {
        List<WorldSpec.RobotEntry> robots = List.of(
                new WorldSpec.RobotEntry(3, new WorldSpec.Robot(-2.0, 0.0, 90.0, 0.12, 0.5, 1.0),
                        List.of(new WorldSpec.Checkpoint(-2.0, 1.0))),
                new WorldSpec.RobotEntry(8, new WorldSpec.Robot(2.0, 0.0, 90.0, 0.12, 0.5, 1.0),
                        List.of(new WorldSpec.Checkpoint(2.0, 3.0), new WorldSpec.Checkpoint(0.0, 3.0))));
        return WorldSpec.fleet("two", 32, 600, 1, new WorldSpec.Arena(5.0), robots, List.of(), 0.25,
                List.of(new WorldSpec.RechargeStation(0.0, -3.0, 0.35)), WorldSpec.Battery.DEFAULT);
    }

    private static ProactiveController controller(TestDatabase db, Simulation sim, int index) {
        int id = sim.spec().robots().get(index).id();
        RobotConfig config = RobotConfig.defaults(id).withRealTimeFactor(0).withRetention(RetentionPolicy.KEEP_ALL)
                .withWatchdogTimeoutMs(100_000);
        return new ProactiveController(sim, index, new JdbcRobotLink(db.dataSource()), config);
    }

    @Test
    void everyRobotSeedsItsOwnMissionAndARobotWhoseMissionIsOverStopsWhereItIs() throws Exception {
        try (TestDatabase db = TestDatabases.open(DatabaseKind.H2)) {
            Simulation sim = new Simulation(twoRobots());
            FakeEngine first = new FakeEngine(db.dataSource(), 3);
            FakeEngine second = new FakeEngine(db.dataSource(), 8);
            try (ProactiveController a = controller(db, sim, 0); ProactiveController b = controller(db, sim, 1)) {
                assertThat(a.robotIndex()).isZero();
                assertThat(b.robotIndex()).isEqualTo(1);
                WorldLoop loop = new WorldLoop(sim, List.of(a, b), 0);
                loop.step(StepGate.NONE);
                assertThat(first.count("checkpoints")).isEqualTo(1);
                assertThat(second.count("checkpoints")).isEqualTo(2);
                first.command("FORWARD 0.5");
                second.command("FORWARD 0.25");
                for (int i = 0; i < 100; i++) { // 1.6 m for robot 3 at full speed: past its checkpoint at 1 m
                    loop.step(StepGate.NONE);
                }
                assertThat(loop.done(0)).isTrue();
                assertThat(loop.done(1)).isFalse();
                // Robot 3 stopped as soon as it reached (-2, 1): within one step of it.
                assertThat(sim.groundTruth(0).y()).isCloseTo(1.0 - 0.25, within(0.5 * 0.032 + 1e-9));
                assertThat(sim.robot(0).leftSpeedMps()).isZero();
                // Robot 8 drove on at its own command's speed.
                assertThat(sim.groundTruth(1).y()).isCloseTo(100 * 0.032 * 0.25, within(0.05));
                assertThat(a.stats().controlSteps()).isLessThan(b.stats().controlSteps());
            }
        }
    }

    @Test
    void aControllerOfAnotherWorldIsRefused() {
        Simulation sim = new Simulation(twoRobots());
        Simulation other = new Simulation(twoRobots());
        try (TestDatabase db = TestDatabases.open(DatabaseKind.H2)) {
            ProactiveController a = controller(db, sim, 0);
            ProactiveController b = controller(db, other, 1);
            org.assertj.core.api.Assertions.assertThatThrownBy(() -> new WorldLoop(sim, List.of(a, b), 0))
                    .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("robot 8");
        } catch (Exception e) {
            throw new AssertionError(e);
        }
    }
}
