package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.Test;
import org.proactiverobotics.app.generate.GridPlanner;
import org.proactiverobotics.sim2d.WorldFiles;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * The solvability check's searches keep their arrays from search to search on a thread (a stamp
 * says which costs are the current search's): a search after others must find what a planner that
 * never searched finds, never a cost left over from an earlier search.
 */
class GridPlannerSearchTest {

    /** A wall across the arena with a gap at its top end: the way from one side to the other goes round. */
    static final String WALL = """
            { "name": "wall", "arena": {"widthM": 6.0, "heightM": 6.0},
              "robot": {"x": -2.0, "y": -2.0, "headingDeg": 0},
              "obstacles": [ {"shape": "box", "x": 0.0, "y": -0.5, "widthM": 0.2, "heightM": 5.0, "angleDeg": 0} ],
              "checkpoints": [{"x": 2.0, "y": -2.0}],
              "rechargeStation": {"x": -2.0, "y": 2.0, "radiusM": 0.35} }
            """;

    @Test
    void aSearchAfterOthersFindsWhatAFreshPlannerFinds() {
        WorldSpec world = WorldFiles.parse(WALL, "wall");
        double fresh = new GridPlanner(world, 0.05).distance(-2.0, -2.0, 2.0, -2.0);
        GridPlanner used = new GridPlanner(world, 0.05);
        double straight = used.distance(-2.0, 2.0, -2.0, -2.0); // on the start's side: 4 m straight down
        double across = used.distance(2.0, 2.0, 2.0, -2.0);
        double round = used.distance(-2.0, -2.0, 2.0, -2.0);
        assertThat(straight).isCloseTo(4.0, within(1e-9));
        assertThat(across).isCloseTo(4.0, within(1e-9));
        assertThat(round).as("the way round the wall, as the same search run first finds it").isEqualTo(fresh)
                .isGreaterThan(4.0 + 2 * 2.0); // up past the wall's top end and down again
    }
}
