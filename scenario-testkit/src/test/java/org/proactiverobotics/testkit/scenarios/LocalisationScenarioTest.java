package org.proactiverobotics.testkit.scenarios;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.Test;
import org.proactiverobotics.engine.tables.PoseEstimate;
import org.proactiverobotics.testkit.ScenarioKit;

/** The Localisation scenario alone (the kit always runs it): the pose every other scenario reads. */
class LocalisationScenarioTest {

    private static final double FREE = 1.0;

    @Test
    void aRobotThatReportsNoOdometryIsWhereItsFixAndHeadingSay() {
        try (ScenarioKit kit = ScenarioKit.builder().start()) {
            kit.robot().gps(1.5, -2.0);
            kit.step();
            assertThat(kit.pose()).get().satisfies(p -> {
                assertThat(p.xM()).isEqualTo(1.5);
                assertThat(p.yM()).isEqualTo(-2.0);
                assertThat(p.knowsHeading()).as("no inertial unit yet").isFalse();
            });
            kit.robot().headingDeg(90);
            kit.step();
            assertThat(kit.pose().orElseThrow().yawRad()).isEqualTo(Math.toRadians(90));
        }
    }

    @Test
    void withoutGpsTheEstimateStartsAtTheInitialPoseAndFollowsTheWheels() {
        try (ScenarioKit kit = ScenarioKit.builder().start()) {
            kit.mission().initialPose(2.0, 1.0, 0);
            // 1 cm per wheel per step, 100 steps, straight along +x; the scan sees nothing to match
            kit.robot().headingDeg(0).odometry(0.01, 0.01).scan(FREE, FREE, FREE, FREE, FREE, FREE, FREE, FREE);
            kit.step(100);
            PoseEstimate p = kit.pose().orElseThrow();
            // the wheels rolled 1 m; the filter takes 2 % of it for slip until something tells it otherwise
            assertThat(p.xM()).isCloseTo(2.0 + 0.98, within(0.011));
            assertThat(p.yM()).isCloseTo(1.0, within(1e-6));
            assertThat(p.yawRad()).isCloseTo(0.0, within(1e-6));
            assertThat(p.positionSigmaM()).as("dead reckoning grows uncertain").isGreaterThan(0.01);
        }
    }

    @Test
    void aFixCorrectsWhatTheWheelsGotWrong() {
        try (ScenarioKit kit = ScenarioKit.builder().start()) {
            kit.mission().initialPose(0, 0, 0);
            // the wheels say 1 cm a step, the GPS that the robot stands still
            kit.robot().headingDeg(0).odometry(0.01, 0.01).gps(0, 0);
            kit.step(50);
            // the wheels alone would put it 0.49 m on; the fixes hold it near them, and the scale learns to distrust the wheels
            assertThat(kit.pose().orElseThrow().xM()).as("the fixes hold it near the truth").isLessThan(0.15);
            kit.step(50);
            assertThat(kit.pose().orElseThrow().xM()).isLessThan(0.1);
        }
    }
}
