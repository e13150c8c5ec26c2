package org.proactiverobotics.engine.motion;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.Test;

/** The braking reach follows the robot's speed, clock and sensor range. */
class ClearanceTest {

    @Test
    void atTheWorldDefaultsItIsTheDistanceTunedBefore() {
        Clearance c = Clearance.of(DriveProfile.DEFAULT, 32, 1.0);
        assertThat(c.imminentM()).isCloseTo(0.15, within(1e-9));
        assertThat(Clearance.DEFAULT).isEqualTo(c);
    }

    @Test
    void aFasterRobotOrASlowerClockLooksFurtherAheadASlowOneComesCloser() {
        // 1.0 m/s over 3 periods of 32 ms and 0.2 s: 0.296 m before the robot has turned away
        assertThat(Clearance.of(new DriveProfile(1.0, 0.24), 32, 1.0).imminentM()).isCloseTo(0.298, within(1e-9));
        assertThat(Clearance.of(DriveProfile.DEFAULT, 128, 1.0).imminentM()).isGreaterThan(Clearance.DEFAULT.imminentM());
        assertThat(Clearance.of(new DriveProfile(0.2, 0.16), 32, 1.0).imminentM()).isLessThan(0.07);
        assertThat(Clearance.of(new DriveProfile(0.01, 0.16), 32, 1.0).imminentM()).isEqualTo(0.05);
    }

    @Test
    void theReachIsNeverBeyondWhatTheSensorsCanSee() {
        assertThat(Clearance.of(new DriveProfile(2.0, 0.24), 64, 0.5).imminentM()).isCloseTo(0.45, within(1e-9));
    }
}
