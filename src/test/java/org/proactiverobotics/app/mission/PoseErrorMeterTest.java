package org.proactiverobotics.app.mission;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.Test;

/**
 * The pose error's accumulator: known poses give known means and maxima, a heading difference is
 * taken the short way round (across ±π, and whatever whole turns either heading carries), and a
 * mission with no pose has no figures at all rather than zeros.
 */
class PoseErrorMeterTest {

    private final PoseErrorMeter meter = new PoseErrorMeter();

    @Test
    void knownPosesGiveTheirMeanAndMaximumDistance() {
        meter.add(0.0, 0.0, 0.0, 0.03, 0.04, 0.0); // 5 cm off
        meter.add(1.0, 1.0, 0.0, 1.0, 1.0, 0.0);   // on the spot
        meter.add(-2.0, 3.0, 0.0, -2.0, 3.01, 0.0); // 1 cm off
        PoseError e = meter.result();
        assertThat(e.samples()).isEqualTo(3);
        assertThat(e.meanM()).isEqualTo(0.02);
        assertThat(e.maxM()).isEqualTo(0.05);
        assertThat(e.meanHeadingRad()).isZero();
        assertThat(e.maxHeadingRad()).isZero();
    }

    @Test
    void headingsEitherSideOfPlusMinusPiAreCloseNotAFullTurnApart() {
        meter.add(0, 0, Math.PI - 0.01, 0, 0, -Math.PI + 0.02); // 0.03 rad across the cut
        meter.add(0, 0, -Math.PI + 0.01, 0, 0, Math.PI - 0.01); // 0.02 rad the other way
        PoseError e = meter.result();
        assertThat(e.meanHeadingRad()).isEqualTo(0.025);
        assertThat(e.maxHeadingRad()).isEqualTo(0.03);
    }

    @Test
    void aHeadingDifferenceIsAtMostPiWhateverTheTurnsEitherCarries() {
        meter.add(0, 0, 0.3 + 4 * Math.PI, 0, 0, 0.1); // two whole turns more: 0.2 rad
        assertThat(meter.result().maxHeadingRad()).isEqualTo(0.2);
        meter.add(0, 0, 0.0, 0, 0, Math.PI);            // opposite: the largest there is
        meter.add(0, 0, 0.0, 0, 0, -3 * Math.PI / 2);   // a quarter turn, not three
        PoseError e = meter.result();
        assertThat(e.maxHeadingRad()).isCloseTo(Math.PI, within(1e-4));
        assertThat(e.meanHeadingRad()).isCloseTo((0.2 + Math.PI + Math.PI / 2) / 3, within(1e-4));
    }

    @Test
    void figuresAreRoundedToATenthOfAMillimetreAndOfAMilliradian() {
        meter.add(0.0, 0.0, 0.000_04, 0.012_345_6, 0.0, 0.0);
        PoseError e = meter.result();
        assertThat(e.meanM()).isEqualTo(0.0123);
        assertThat(e.maxHeadingRad()).isZero();
    }

    @Test
    void noSampleGivesNoFiguresNotZeros() {
        assertThat(meter.result()).isNull();
        assertThat(meter.samples()).isZero();
    }
}
