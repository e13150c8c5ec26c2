package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.List;
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

    /**
     * A length is kept as counts of straight and diagonal steps, so it is the same number whichever of the
     * shortest ways the search meets and from either end; where nothing is in the way it is the octile
     * distance itself (a diagonal step along the shorter side, straight ones for the rest).
     */
    @Test
    void aLengthIsTheSameBothWaysAndTheOctileDistanceInTheOpen() {
        WorldSpec world = WorldFiles.parse(WALL, "wall");
        GridPlanner planner = new GridPlanner(world, 0.05);
        double there = planner.distance(-2.0, -2.0, 2.0, -2.0);
        double back = new GridPlanner(world, 0.05).distance(2.0, -2.0, -2.0, -2.0);
        assertThat(back).as("the way round the wall searched from its other end").isEqualTo(there);
        // 1.0 m across and 0.4 m up on the start's side: 8 diagonal cells and 12 straight ones
        double open = new GridPlanner(world, 0.05).distance(-2.0, -2.0, -1.0, -1.6);
        assertThat(open).isEqualTo((12 + 8 * Math.sqrt(2)) * GridPlanner.CELL_M);
        assertThat(planner.distance(-2.0, -2.0, -2.0, -2.0)).isZero();
    }

    /** The searches made on both cores beforehand answer as a planner searching one pair at a time would. */
    @Test
    void prefetchedLengthsAreThoseSearchedOneByOne() {
        WorldSpec world = WorldFiles.parse(WALL, "wall");
        List<double[]> pairs = List.of(new double[] {-2.0, -2.0, 2.0, -2.0}, new double[] {2.0, -2.0, -2.0, 2.0},
                new double[] {-2.0, 2.0, 2.0, -2.0}, new double[] {-2.0, -2.0, 2.0, -2.0});
        GridPlanner prefetched = new GridPlanner(world, 0.05);
        prefetched.prefetch(pairs);
        for (double[] p : pairs) {
            double alone = new GridPlanner(world, 0.05).distance(p[0], p[1], p[2], p[3]);
            assertThat(prefetched.distance(p[0], p[1], p[2], p[3])).isEqualTo(alone).isFinite();
        }
    }
}
