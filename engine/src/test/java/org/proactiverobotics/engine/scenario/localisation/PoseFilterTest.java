package org.proactiverobotics.engine.scenario.localisation;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.Random;
import org.junit.jupiter.api.Test;

/** The filter's arithmetic on motions whose truth is known. */
class PoseFilterTest {

    private static final double AXLE_M = 0.24;

    @Test
    void odometryAloneMovesThePoseAlongTheArcAndItsUncertaintyGrows() {
        PoseFilter f = new PoseFilter();
        f.start(1, 2, Math.PI / 2, 0.01, 0.01);
        double before = f.covariance(0, 0) + f.covariance(1, 1);
        for (int i = 0; i < 100; i++) {
            f.predict(0.01, 0.01, AXLE_M); // 1 m rolled straight ahead, along +y: the robot goes 98 % of it
        }
        assertThat(f.x()).isCloseTo(1, within(1e-9));
        assertThat(f.y()).isCloseTo(2 + PoseFilter.SCALE_PRIOR, within(1e-9));
        assertThat(f.covariance(0, 0) + f.covariance(1, 1)).isGreaterThan(before);
        // a quarter turn on the spot: the wheels roll a quarter of the circle the axle spans, opposite ways
        double arc = Math.PI / 2 * AXLE_M / 2 / PoseFilter.SCALE_PRIOR;
        f.predict(-arc, arc, AXLE_M);
        assertThat(f.yaw()).isCloseTo(Math.PI, within(1e-9));
        assertThat(f.x()).isCloseTo(1, within(1e-9));
    }

    @Test
    void gpsFixesTeachTheScaleOfWheelsThatSlip() {
        // the wheels report 5 % more than the robot travels (they slip); the GPS sees the truth, with 1 cm noise
        Random noise = new Random(7);
        PoseFilter f = new PoseFilter();
        f.start(0, 0, 0, 0.01, 0.01);
        double trueX = 0;
        for (int i = 0; i < 3000; i++) {
            double rolled = 0.016;
            trueX += rolled * 0.95;
            f.predict(rolled, rolled, AXLE_M);
            f.correctYaw(0 + noise.nextGaussian() * 0.03, 0.035);
            f.correctPosition(trueX + noise.nextGaussian() * 0.01, noise.nextGaussian() * 0.01, 0.03);
        }
        assertThat(f.scale()).isCloseTo(0.95, within(0.005));
        assertThat(f.x()).isCloseTo(trueX, within(0.02));
        assertThat(Math.sqrt(f.covariance(0, 0))).isLessThan(0.03); // better than one fix
    }

    @Test
    void aHeadingAcrossTheHalfTurnIsCorrectedTheShortWayRound() {
        PoseFilter f = new PoseFilter();
        f.start(0, 0, Math.PI - 0.01, 0.01, 0.1);
        f.correctYaw(-Math.PI + 0.01, 0.01); // 0.02 rad away across ±pi, not 6.26 rad
        assertThat(Math.abs(PoseFilter.wrap(f.yaw() - Math.PI))).isLessThan(0.011);
    }

    @Test
    void aWholePoseMeasurementPullsOnlyAlongWhatItKnows() {
        PoseFilter f = new PoseFilter();
        f.start(0, 0, 0, 0.05, 0.01);
        // measured: x wrong by 10 cm but unknown (huge variance), y off by 4 cm and well known
        f.correctPose(0.10, 0.04, 0, new double[] {100, 0, 0, 0, 0.0001, 0, 0, 0, 0.0001});
        assertThat(f.x()).isCloseTo(0, within(0.001));
        assertThat(f.y()).isCloseTo(0.04 * 0.0025 / (0.0025 + 0.0001), within(1e-6));
    }
}
