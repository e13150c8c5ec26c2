package org.proactiverobotics.engine.motion;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.Test;

/** The avoidance distances follow the robot's speed, clock, body and sensor range. */
class ClearanceTest {

    @Test
    void atTheWorldDefaultsTheyAreTheDistancesTunedBefore() {
        Clearance c = Clearance.of(DriveProfile.DEFAULT, 32, 1.0);
        assertThat(c.imminentM()).isCloseTo(0.15, within(1e-9));
        assertThat(c.engageFrontM()).isCloseTo(0.22, within(1e-9));
        assertThat(c.engageAheadM()).isCloseTo(0.30, within(1e-9));
        assertThat(c.engageSideM()).isCloseTo(0.15, within(1e-9));
        assertThat(c.wallDistanceM()).isCloseTo(0.20, within(1e-9));
        assertThat(c.releaseFrontM()).isCloseTo(0.45, within(1e-9));
        assertThat(c.releaseSideM()).isCloseTo(0.25, within(1e-9));
        assertThat(Clearance.DEFAULT).isEqualTo(c);
    }

    @Test
    void aFasterRobotOrASlowerClockLooksFurtherAhead() {
        Clearance base = Clearance.DEFAULT;
        Clearance fast = Clearance.of(new DriveProfile(1.0, 0.24), 32, 1.0);
        Clearance slowClock = Clearance.of(DriveProfile.DEFAULT, 128, 1.0);
        // 1.0 m/s over 3 periods of 32 ms and 0.2 s: 0.296 m before the robot has turned away
        assertThat(fast.imminentM()).isCloseTo(0.298, within(1e-9));
        assertThat(fast.engageAheadM()).isGreaterThan(base.engageAheadM() + 0.14);
        assertThat(slowClock.engageFrontM()).isGreaterThan(base.engageFrontM());
    }

    @Test
    void aLargerBodyKeepsItsFlanksFurtherOffAndASmallSlowOneComesCloser() {
        Clearance large = Clearance.of(new DriveProfile(0.5, 0.6), 32, 1.0);
        Clearance small = Clearance.of(new DriveProfile(0.2, 0.16), 32, 1.0);
        assertThat(large.engageSideM()).isCloseTo(0.24, within(1e-9));
        assertThat(large.wallDistanceM()).isCloseTo(0.29, within(1e-9));
        assertThat(small.engageFrontM()).isLessThan(0.15);
        assertThat(small.engageSideM()).isLessThan(Clearance.DEFAULT.engageSideM());
    }

    @Test
    void noDistanceIsBeyondWhatTheSensorsCanSee() {
        Clearance c = Clearance.of(new DriveProfile(2.0, 0.24), 64, 0.5);
        assertThat(c.releaseFrontM()).isLessThanOrEqualTo(0.45);
        assertThat(c.engageAheadM()).isLessThanOrEqualTo(0.45);
    }
}
