package org.proactiverobotics.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.Test;

/** The guess at a mistyped option or command: a letter or two away, closest first, never a guess at one letter. */
class SuggestionsTest {

    private static final List<String> RUN = List.of("--world", "--wait-s", "--db", "--db-user", "--db-password",
            "--strategy", "--strategy-file", "--force", "-h", "-V");

    @Test
    void aTypoGetsTheNameALetterOrTwoAwayClosestFirst() {
        assertThat(Suggestions.closest("--wrld", RUN)).containsExactly("--world");
        assertThat(Suggestions.closest("--wrld=x.json", RUN)).containsExactly("--world");
        assertThat(Suggestions.closest("--dv", RUN)).containsExactly("--db");
        assertThat(Suggestions.closest("--stratgey", RUN)).containsExactly("--strategy");
        assertThat(Suggestions.closest("--FORCE", RUN)).containsExactly("--force");
        assertThat(Suggestions.closest("swep", List.of("run", "sweep", "strategy", "watch"))).containsExactly("sweep");
    }

    @Test
    void somethingFarFromEveryNameOrOneLetterGetsNoGuess() {
        assertThat(Suggestions.closest("--colour", RUN)).isEmpty();
        assertThat(Suggestions.closest("-x", RUN)).isEmpty();
        assertThat(Suggestions.closest("fly", List.of("run", "sweep", "strategy", "watch"))).isEmpty();
    }

    @Test
    void editsCountsASwapOfNeighboursAsOne() {
        assertThat(Suggestions.edits("nosie", "noise")).isEqualTo(1);
        assertThat(Suggestions.edits("wrld", "world")).isEqualTo(1);
        assertThat(Suggestions.edits("", "abc")).isEqualTo(3);
    }
}
