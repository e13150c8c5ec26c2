package org.proactiverobotics.app.sweep;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.Test;

/** The 95 % Wilson interval of a success rate, and how the summary shows it. */
class SuccessRateTest {

    @Test
    void matchesNewcombesPublishedWilsonIntervals() {
        // Newcombe (1998), "Two-sided confidence intervals for the single proportion", method 3, to 4 decimals
        assertBounds(new SuccessRate(81, 263), 0.2553, 0.3662);
        assertBounds(new SuccessRate(15, 148), 0.0624, 0.1605);
        assertBounds(new SuccessRate(1, 29), 0.0061, 0.1718);
        assertBounds(new SuccessRate(5, 10), 0.2366, 0.7634);
    }

    @Test
    void noSuccessStartsAtZeroAndEndsAtZSquaredOverNPlusZSquared() {
        SuccessRate none = new SuccessRate(0, 20);
        double z2 = SuccessRate.Z95 * SuccessRate.Z95;
        assertThat(none.wilsonLow()).isZero();
        assertThat(none.wilsonHigh()).isCloseTo(z2 / (20 + z2), within(1e-12)).isCloseTo(0.1611, within(5e-5));
        assertThat(none.shownCount()).isEqualTo("0/20");
        assertThat(none.shownPercent()).isEqualTo("0.0");
        assertThat(none.shownInterval()).isEqualTo("0.0–16.1");
    }

    @Test
    void everySuccessEndsAtOneAndMirrorsNoSuccess() {
        SuccessRate all = new SuccessRate(10, 10);
        assertThat(all.wilsonHigh()).isEqualTo(1.0);
        assertThat(all.wilsonLow()).isCloseTo(1 - new SuccessRate(0, 10).wilsonHigh(), within(1e-12))
                .isCloseTo(0.7225, within(5e-5));
        assertThat(all.shownPercent()).isEqualTo("100.0");
        assertThat(all.shownInterval()).isEqualTo("72.2–100.0");
    }

    @Test
    void noMissionShowsADashNotANumber() {
        SuccessRate nothing = new SuccessRate(0, 0);
        assertThat(nothing.shownCount()).isEqualTo("0/0");
        assertThat(nothing.shownPercent()).isEqualTo("—");
        assertThat(nothing.shownInterval()).isEqualTo("—");
        assertThat(nothing.rate()).isNaN();
        assertThat(nothing.wilsonLow()).isNaN();
    }

    @Test
    void showsPercentWithOneDecimal() {
        SuccessRate r = new SuccessRate(16, 24);
        assertThat(r.shownCount()).isEqualTo("16/24");
        assertThat(r.shownPercent()).isEqualTo("66.7");
        assertThat(r.shownInterval()).isEqualTo("46.7–82.0");
    }

    @Test
    void moreSuccessesThanMissionsIsRefused() {
        assertThatThrownBy(() -> new SuccessRate(3, 2)).isInstanceOf(IllegalArgumentException.class).hasMessageContaining("k=3, n=2");
        assertThatThrownBy(() -> new SuccessRate(-1, 2)).isInstanceOf(IllegalArgumentException.class);
    }

    private static void assertBounds(SuccessRate r, double low, double high) {
        assertThat(r.wilsonLow()).as("%s low", r).isCloseTo(low, within(5e-5));
        assertThat(r.wilsonHigh()).as("%s high", r).isCloseTo(high, within(5e-5));
    }
}
