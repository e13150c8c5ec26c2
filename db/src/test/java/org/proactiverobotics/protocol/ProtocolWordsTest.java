package org.proactiverobotics.protocol;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

class ProtocolWordsTest {

    @Test
    void eachWordReadsBackAsWrittenAndNothingElseIsOne() {
        for (Timing t : Timing.values()) {
            assertThat(Timing.of(t.label())).contains(t);
        }
        assertThat(Timing.of("sync")).contains(Timing.SYNC);
        assertThat(Timing.of("SYNC")).as("robot_clock holds the lower-case word").isEmpty();
        for (RunState s : RunState.values()) {
            assertThat(RunState.of(s.name())).contains(s);
        }
        assertThat(RunState.of("running")).isEmpty();
        assertThat(Sensor.byName("DS")).contains(Sensor.DS);
        assertThat(Sensor.byName(" GPS")).isEmpty();
        assertThat(CommandWord.of("DRIVE").map(CommandWord::arguments)).contains(2);
        assertThat(CommandWord.of("TURN_LEFT").map(CommandWord::arguments)).contains(1);
        assertThat(CommandWord.of("WAITING")).as("not a command").isEmpty();
        assertThat(CommandWord.of(null)).isEmpty();
    }
}
