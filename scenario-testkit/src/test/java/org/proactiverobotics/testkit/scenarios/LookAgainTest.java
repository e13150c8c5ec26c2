package org.proactiverobotics.testkit.scenarios;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import org.junit.jupiter.api.Test;
import org.proactiverobotics.engine.navigation.SharedWorld;
import org.proactiverobotics.engine.scenario.destination.ReachDestinationScenario;
import org.proactiverobotics.engine.tables.JdbcRobotTables;
import org.proactiverobotics.engine.tables.MapChunk;
import org.proactiverobotics.engine.tables.OccupancyMap;
import org.proactiverobotics.testkit.ScenarioKit;

/**
 * Issue 34: in a shared world a robot with no route to its checkpoint for 5 s asks the mapping to let go of the cells
 * other robots moved into ({@link SharedWorld#LOOK_AGAIN}), again 5 s later, at most 3 times: a blob another robot
 * left where the map does not let it fade walled corridors-011's robot 2 in, and it never went back to look. A lone
 * robot asks nothing.
 */
class LookAgainTest {

    private static final String DESTINATION = ReachDestinationScenario.NAME;
    /** 32 ms steps in a second. */
    private static final int SECOND = 32;

    /** The robot at the origin, its checkpoint at (1, 0) inside a ring of walls for good: no route. */
    private static ScenarioKit walledIn(boolean shared) {
        ScenarioKit.Builder b = ScenarioKit.builder().builtIn(DESTINATION);
        ScenarioKit kit = (shared ? b.sharedWorld() : b).start();
        OccupancyMap map = OccupancyMap.empty();
        int ci = OccupancyMap.cell(1.0);
        int cj = OccupancyMap.cell(0.0);
        for (int j = cj - 8; j <= cj + 8; j++) {
            for (int i = ci - 8; i <= ci + 8; i++) {
                if (Math.max(Math.abs(i - ci), Math.abs(j - cj)) == 8) {
                    map.set(i, j, (byte) (OccupancyMap.FREE + OccupancyMap.CONFIRMED));
                }
            }
        }
        new JdbcRobotTables(kit.database(), ScenarioKit.ROBOT_ID).writeChunks(new ArrayList<MapChunk>(map.takeChanged()), 0);
        kit.mission().checkpoint(1.0, 0.0);
        kit.robot().gps(0, 0).headingDeg(0);
        return kit;
    }

    private static String asked(ScenarioKit kit) {
        return kit.memory().values().get(SharedWorld.LOOK_AGAIN);
    }

    @Test
    void withoutARouteAmongOtherRobotsItAsksToLookAgainEvery5sAtMostThreeTimes() {
        try (ScenarioKit kit = walledIn(true)) {
            kit.step(4 * SECOND);
            assertThat(kit.suggestion(DESTINATION)).as("no route: it stands").isEqualTo("STOP");
            assertThat(asked(kit)).as("4 s without a route").isNull();
            kit.step(2 * SECOND);
            assertThat(asked(kit)).isEqualTo("1");
            kit.step(5 * SECOND);
            assertThat(asked(kit)).isEqualTo("2");
            kit.step(20 * SECOND);
            assertThat(asked(kit)).as("at most three times for one checkpoint").isEqualTo("3");
        }
    }

    @Test
    void aLoneRobotDoesNotAsk() {
        try (ScenarioKit kit = walledIn(false)) {
            kit.step(10 * SECOND);
            assertThat(asked(kit)).isNull();
        }
    }
}
