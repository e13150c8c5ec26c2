package org.proactiverobotics.engine.tables;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Arrays;
import org.junit.jupiter.api.Test;

class SensorTest {

    @Test
    void theScenariosSensorsAreExactlyTheProtocolsWords() {
        assertThat(Arrays.stream(Sensor.values()).map(Sensor::word))
                .containsExactly(org.proactiverobotics.protocol.Sensor.values());
        for (Sensor s : Sensor.values()) {
            assertThat(org.proactiverobotics.protocol.Sensor.byName(s.word().name())).contains(s.word());
        }
    }
}
