package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.proactiverobotics.engine.robot.Strategy;

/** The in-process direct link: the same engine and robot, another transport, the same run. */
class DirectLinkEndToEndTest {

    @ParameterizedTest
    @ValueSource(strings = {"reference-arena", "low-battery"})
    void theDirectLinkGivesTheSameGroundTruthAndTraceAsH2(String world) throws Exception {
        Missions.Run direct = Missions.direct(world, Strategy.SAFETY_FIRST);
        Missions.Run h2 = Missions.onH2(world);
        assertThat(direct.report().database()).isEqualTo("direct");
        assertThat(direct.deterministicPart()).isEqualTo(h2.deterministicPart());
        assertThat(Files.readString(direct.outDir().resolve("trace.jsonl")))
                .isEqualTo(Files.readString(h2.outDir().resolve("trace.jsonl")));
        assertThat(Files.readString(direct.outDir().resolve("trajectory.svg")))
                .isEqualTo(Files.readString(h2.outDir().resolve("trajectory.svg")));
    }
}
