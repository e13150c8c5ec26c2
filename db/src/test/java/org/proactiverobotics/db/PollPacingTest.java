package org.proactiverobotics.db;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

class PollPacingTest {

    private static final long MS = 1_000_000L;

    @Test
    void beforeAnyWaitItPollsClosely() {
        PollPacing pacing = new PollPacing();
        assertThat(pacing.pauseNanos(0, 0)).isEqualTo(PollPacing.MIN_PAUSE_NANOS);
        assertThat(pacing.pauseNanos(MS, 3)).isEqualTo(PollPacing.MIN_PAUSE_NANOS);
    }

    @Test
    void theFirstPollComesBeforeTheShortestRecentWaitThenClosely() {
        PollPacing pacing = new PollPacing();
        for (long w : new long[] {6 * MS, 4 * MS, 9 * MS, 5 * MS}) {
            pacing.waited(w);
        }
        assertThat(pacing.expectedNanos()).isEqualTo(4 * MS);
        long first = pacing.pauseNanos(0, 0);
        assertThat(first).as("slept through most of the shortest wait, never past it").isGreaterThan(MS).isLessThan(4 * MS);
        assertThat(pacing.pauseNanos(MS, 0)).as("the time already waited counts").isEqualTo(first - MS);
        long next = pacing.pauseNanos(first, 1);
        assertThat(next).as("then a few polls per expected wait").isLessThan(MS).isGreaterThanOrEqualTo(PollPacing.MIN_PAUSE_NANOS);
    }

    @Test
    void aSlowTurnDoesNotMakeTheNextPollsLateAndOldWaitsAreForgotten() {
        PollPacing pacing = new PollPacing();
        pacing.waited(2 * MS);
        pacing.waited(40 * MS); // a garbage collection on the other side
        assertThat(pacing.expectedNanos()).isEqualTo(2 * MS);
        for (int k = 0; k < 8; k++) {
            pacing.waited(3 * MS);
        }
        assertThat(pacing.expectedNanos()).as("only the last waits count").isEqualTo(3 * MS);
    }

    @Test
    void whenTheOtherSideIsAwayThePausesGrowAndItsAbsenceIsNotLearnt() {
        PollPacing pacing = new PollPacing();
        pacing.waited(2 * MS);
        pacing.waited(5_000 * MS); // the other side was away: not its turn's length
        assertThat(pacing.expectedNanos()).isEqualTo(2 * MS);
        assertThat(pacing.pauseNanos(100 * MS, 50)).isEqualTo(MS);
        assertThat(pacing.pauseNanos(2_000 * MS, 500)).isEqualTo(10 * MS);
        assertThat(pacing.pauseNanos(20_000 * MS, 900)).isEqualTo(50 * MS);
    }
}
