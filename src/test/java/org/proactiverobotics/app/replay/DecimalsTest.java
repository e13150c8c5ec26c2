package org.proactiverobotics.app.replay;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/** The trace's fast numbers are the bytes Double.toString wrote, over every millimetre within 3 km and every hundredth of a percent. */
class DecimalsTest {

    @Test
    void millimetresAndHundredthsReadAsDoubleToStringWritesThem() {
        for (long k = -3_000_000; k <= 3_000_000; k++) {
            String expected = Double.toString(k / 1000.0);
            if (!Decimals.of(k, 3).equals(expected)) {
                assertThat(Decimals.of(k, 3)).as("units %d", k).isEqualTo(expected);
            }
        }
        for (long k = -20_000; k <= 20_000; k++) {
            assertThat(Decimals.of(k, 2)).isEqualTo(Double.toString(k / 100.0));
        }
        assertThat(Decimals.of(12_345_678_901L, 3)).isEqualTo(Double.toString(12_345_678.901));
        assertThat(Decimals.of(Long.MAX_VALUE / 2, 3)).isEqualTo(Double.toString((Long.MAX_VALUE / 2) / 1000.0));
    }
}
