package org.proactiverobotics.robot.link;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;

class ReadingTimesTest {

    @Test
    void namesTheKthNewestTimeOnceThatManyWereAdded() {
        ReadingTimes times = new ReadingTimes();
        assertThat(times.newest(1)).isEqualTo(-1);
        for (long t = 0; t < 5000; t++) {
            times.add(t * 32);
        }
        assertThat(times.newest(1)).isEqualTo(4999 * 32);
        assertThat(times.newest(1001)).isEqualTo(3999 * 32);
        assertThat(times.newest(2048)).isEqualTo((5000 - 2048) * 32);
    }

    @Test
    void theNewestTimeAgainIsTheSameReading() {
        ReadingTimes times = new ReadingTimes();
        times.add(64);
        times.add(64);
        times.add(96);
        assertThat(times.newest(1)).isEqualTo(96);
        assertThat(times.newest(2)).isEqualTo(64);
        assertThat(times.newest(3)).isEqualTo(-1);
    }

    @Test
    void anEarlierTimeIsANewRunAndForgetsTheOldOne() {
        ReadingTimes times = new ReadingTimes();
        for (long t = 1; t <= 100; t++) {
            times.add(t * 32);
        }
        times.add(0);
        times.add(32);
        assertThat(times.newest(1)).isEqualTo(32);
        assertThat(times.newest(2)).isZero();
        assertThat(times.newest(3)).isEqualTo(-1);
    }

    @Test
    void aLargerKGrowsTheRingKeepingWhatWasHeld() {
        ReadingTimes times = new ReadingTimes();
        for (long t = 1; t <= 3000; t++) {
            times.add(t);
        }
        assertThat(times.newest(5000)).as("more than it can hold: not known, room made").isEqualTo(-1);
        assertThat(times.newest(2048)).isEqualTo(3000 - 2047);
        assertThat(times.newest(2049)).as("older than what was held").isEqualTo(-1);
        for (long t = 3001; t <= 8000; t++) {
            times.add(t);
        }
        assertThat(times.newest(5000)).isEqualTo(3001);
        assertThat(times.newest(ReadingTimes.MAX_CAPACITY + 1)).isEqualTo(-1);
        assertThatThrownBy(() -> times.newest(0)).isInstanceOf(IllegalArgumentException.class);
    }
}
