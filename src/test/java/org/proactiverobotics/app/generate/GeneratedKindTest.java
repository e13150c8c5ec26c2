package org.proactiverobotics.app.generate;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/** A world's kind is read back only from the names generate gives (<kind>-<NNN>), never guessed from another name. */
class GeneratedKindTest {

    @Test
    void everyKindsGeneratedWorldReadsBackAsItsKind() {
        for (WorldGenerator.Kind kind : WorldGenerator.Kind.values()) {
            String name = new WorldGenerator(kind).world(3, 12).name();
            assertThat(name).isEqualTo(kind.label() + "-012");
            assertThat(WorldGenerator.kindOfName(name)).contains(kind.label());
        }
        assertThat(WorldGenerator.kindOfName("maze-1000")).contains("maze");
    }

    @Test
    void aNameGenerateDoesNotGiveHasNoKind() {
        for (String name : new String[] {"reference-arena", "cluttered-arena", "rooms", "rooms-01", "rooms-002b", "Rooms-002",
                "kitchen-001", "short-limit", "battery_001"}) {
            assertThat(WorldGenerator.kindOfName(name)).as(name).isEmpty();
        }
    }
}
