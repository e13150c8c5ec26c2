package org.proactiverobotics.engine.motion;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/**
 * A target straight behind: a command acts a step after the heading it was worked out from, and
 * without a kept side the go-to-point law turned left and right by turns for good.
 */
class SteeringBehindTest {

    private static final DriveProfile PROFILE = DriveProfile.DEFAULT;
    private static final double STEP_S = 0.032;

    /** The turn rate a command asks for, radians per second (counter-clockwise positive). */
    private static double turnRate(String command) {
        double[] w = Steering.wheelSpeeds(command);
        return (w[1] - w[0]) / PROFILE.axleWidthM();
    }

    /**
     * Turns the robot on the spot toward a target behind it, the wheels a step behind the commands
     * and still turning left as they were.
     *
     * @return the heading error left after the steps, radians
     */
    private static double turnWithLag(double headingRad, boolean keepSide, int steps) {
        double targetX = -1.0;
        double targetY = 0.0; // straight behind a robot heading 0
        int side = 0;
        String acting = Steering.drive(0.0, 2.5, PROFILE);
        for (int k = 0; k < steps; k++) {
            String command;
            if (keepSide) {
                side = Steering.turnSide(0, 0, headingRad, targetX, targetY, side);
                command = Steering.goTo(0, 0, headingRad, targetX, targetY, PROFILE, side);
            } else {
                command = Steering.goTo(0, 0, headingRad, targetX, targetY, PROFILE);
            }
            headingRad += turnRate(acting) * STEP_S; // last step's command is what the wheels do now
            acting = command;
        }
        return Math.abs(Steering.wrap(Math.PI - headingRad));
    }

    @Test
    void withTheSideKeptATargetBehindIsFacedDespiteTheWheelsLag() {
        double start = -0.02; // the target a hair off straight behind, on the right; the wheels turning left
        assertThat(turnWithLag(start, true, 60)).as("faced within a few degrees").isLessThan(Math.toRadians(5));
    }

    @Test
    void withoutTheSideKeptTheRobotRocksOnTheSpot() {
        // what the robot did before (rooms, seed 17, radius 0.2 m, number 12): the same start never turns round
        assertThat(turnWithLag(-0.02, false, 60)).isGreaterThan(Math.toRadians(170));
    }

    @Test
    void theKeptSideMattersOnlyForATargetNearlyBehind() {
        // 90° to the left: turned to on the left whatever side was kept
        assertThat(turnRate(Steering.goTo(0, 0, 0, 0, 1, PROFILE, -1))).isPositive();
        assertThat(Steering.turnSide(0, 0, 0, 0, 1, -1)).isEqualTo(+1);
        // 175° to the right: the kept side (left) wins
        double a = Math.toRadians(-175);
        assertThat(turnRate(Steering.goTo(0, 0, 0, Math.cos(a), Math.sin(a), PROFILE, +1))).isPositive();
        assertThat(turnRate(Steering.goTo(0, 0, 0, Math.cos(a), Math.sin(a), PROFILE, 0))).isNegative();
    }
}
