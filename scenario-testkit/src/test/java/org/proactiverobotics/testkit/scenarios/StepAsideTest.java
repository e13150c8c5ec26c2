package org.proactiverobotics.testkit.scenarios;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.proactiverobotics.engine.scenario.destination.ReachDestinationScenario;
import org.proactiverobotics.engine.scenario.destination.ReturnToStart;
import org.proactiverobotics.engine.tables.JdbcRobotTables;
import org.proactiverobotics.engine.tables.MapChunk;
import org.proactiverobotics.engine.tables.OccupancyMap;
import org.proactiverobotics.testkit.ScenarioKit;

/**
 * Issue 34: a robot that is done and stands at its parking place ({@link ReturnToStart}, in a shared world) steps
 * aside when something comes to stand beside it for 8 s (another robot waiting for the way it stands in), and
 * stays put for what stands there less long, or for what was already there when it stopped.
 */
class StepAsideTest {

    private static final String DESTINATION = ReachDestinationScenario.NAME;
    /** 32 ms steps in a second. */
    private static final int SECOND = 32;
    /** How long something must stand beside it, steps of 32 ms (8 s). */
    private static final int STEP_ASIDE_STEPS = 8_000 / 32;
    /** The start and the checkpoint: a cell's centre, so that the parking place is the start itself. */
    private static final double START = OccupancyMap.centre(0);
    private static final double[] NOTHING = {1, 1, 1, 1, 1, 1, 1, 1};
    /** The rays at -90° and -45° (right, the robot facing +x) read something 0.2 and 0.3 m from the rim. */
    private static final double[] SOMETHING_ON_THE_RIGHT = {0.2, 0.3, 1, 1, 1, 1, 1, 1};
    /** The rays at 90° and 45° (left) read something 0.2 and 0.3 m from the rim. */
    private static final double[] SOMETHING_ON_THE_LEFT = {1, 1, 1, 1, 1, 1, 0.3, 0.2};
    /** Where the -90° ray of the robot at the start hits it (0.12 m radius + 0.2 m), metres. */
    private static final double THING_X = START;
    private static final double THING_Y = START - 0.32;

    /**
     * A room of 4 m × 4 m round the origin, seen free, walls for good on its rim; the mission's only checkpoint is
     * where the robot starts and stands, facing +x: the first steps reach it and ReturnToStart parks there.
     */
    private static ScenarioKit parkedAtTheStart(double[] scanWhenItStops) {
        ScenarioKit kit = ScenarioKit.builder().sharedWorld().builtIn(DESTINATION).start();
        OccupancyMap map = OccupancyMap.empty();
        for (int j = -40; j < 40; j++) {
            for (int i = -40; i < 40; i++) {
                boolean rim = i == -40 || i == 39 || j == -40 || j == 39;
                map.set(i, j, rim ? (byte) (OccupancyMap.FREE + OccupancyMap.CONFIRMED) : OccupancyMap.FREE);
            }
        }
        new JdbcRobotTables(kit.database(), ScenarioKit.ROBOT_ID).writeChunks(new ArrayList<MapChunk>(map.takeChanged()), 0);
        kit.mission().initialPose(START, START, 0).checkpoint(START, START);
        kit.robot().gps(START, START).headingDeg(0).scan(scanWhenItStops);
        kit.step(SECOND);
        assertThat(kit.reachedCheckpoints()).containsExactly(0);
        assertThat(rule(kit).parked()).as("parked at its start").isTrue();
        assertThat(kit.suggestion(DESTINATION)).isEqualTo("STOP");
        return kit;
    }

    private static ReturnToStart rule(ScenarioKit kit) {
        return kit.engine().engine().nextQueue().stream().filter(ReturnToStart.class::isInstance)
                .map(ReturnToStart.class::cast).findFirst().orElseThrow();
    }

    /** @return what ReachDestination suggested in the last {@code steps} steps */
    private static List<String> last(ScenarioKit kit, int steps) {
        List<String> all = kit.suggestions(DESTINATION);
        return all.subList(all.size() - steps, all.size());
    }

    @Test
    void somethingStandingBesideItFor8sMakesItStepAsideAwayFromItThenParkThere() {
        try (ScenarioKit kit = parkedAtTheStart(NOTHING)) {
            kit.robot().scan(SOMETHING_ON_THE_RIGHT);
            kit.step(STEP_ASIDE_STEPS);
            assertThat(last(kit, STEP_ASIDE_STEPS)).as("for 8 s less a step it stands").containsOnly("STOP");
            assertThat(rule(kit).place()).containsExactly(START, START);
            kit.step();
            assertThat(kit.suggestion(DESTINATION)).as("8 s: it sets out").startsWith("DRIVE");
            assertThat(rule(kit).parked()).isFalse();
            double[] place = rule(kit).place();
            double moved = Math.hypot(place[0] - START, place[1] - START);
            assertThat(moved).as("a new place, 0.8 m off (the nearest cell's centre)").isBetween(0.7, 0.9);
            assertThat(Math.hypot(place[0] - THING_X, place[1] - THING_Y)).as("away from what stands beside it")
                    .isGreaterThan(0.32 + 0.7);
            assertThat(place[1]).as("to its left, the side away from it").isGreaterThan(START + 0.5);

            // it got there: the thing now 0.8 m off and out of its rays' reach, it parks and stays
            kit.robot().gps(place[0], place[1]).scan(NOTHING);
            kit.step(SECOND);
            assertThat(rule(kit).parked()).isTrue();
            assertThat(rule(kit).place()).containsExactly(place);
            assertThat(last(kit, SECOND)).containsOnly("STOP");
        }
    }

    /**
     * Something stands beside the parked robot for 8 s and a step; then the robot is put at the place it drives for.
     *
     * @return the place it was at when the thing came, and the place it has after
     */
    private static double[][] standsBesideFor8s(ScenarioKit kit, double[] scan) {
        double[] before = rule(kit).place();
        kit.robot().scan(scan);
        kit.step(STEP_ASIDE_STEPS + 1);
        double[] after = rule(kit).place();
        kit.robot().gps(after[0], after[1]).scan(NOTHING);
        kit.step(SECOND);
        assertThat(rule(kit).parked()).isTrue();
        return new double[][] {before, after};
    }

    @Test
    void itStepsAsideAtMostThreeTimes() {
        try (ScenarioKit kit = parkedAtTheStart(NOTHING)) {
            // two robots that are done would chase each other round the floor: right, left, right, then it stays
            double[][] first = standsBesideFor8s(kit, SOMETHING_ON_THE_RIGHT);
            assertThat(first[1][1] - first[0][1]).as("first: up, away from the right").isGreaterThan(0.5);
            double[][] second = standsBesideFor8s(kit, SOMETHING_ON_THE_LEFT);
            assertThat(second[1][1] - second[0][1]).as("second: down, away from the left").isLessThan(-0.5);
            double[][] third = standsBesideFor8s(kit, SOMETHING_ON_THE_RIGHT);
            assertThat(third[1][1] - third[0][1]).as("third: up again").isGreaterThan(0.5);
            kit.robot().scan(SOMETHING_ON_THE_LEFT);
            kit.step(2 * STEP_ASIDE_STEPS);
            assertThat(last(kit, 2 * STEP_ASIDE_STEPS)).as("the fourth time: it stays").containsOnly("STOP");
            assertThat(rule(kit).place()).containsExactly(third[1]);
        }
    }

    @Test
    void somethingBesideItForLessThan8sAtATimeLeavesItWhereItIs() {
        try (ScenarioKit kit = parkedAtTheStart(NOTHING)) {
            // 7 s beside it, 1 s gone, 7 s again: 14 s in all, never 8 s on end
            kit.robot().scan(SOMETHING_ON_THE_RIGHT);
            kit.step(7 * SECOND);
            kit.robot().scan(NOTHING);
            kit.step(SECOND);
            kit.robot().scan(SOMETHING_ON_THE_RIGHT);
            kit.step(7 * SECOND);
            kit.robot().scan(NOTHING);
            kit.step(10 * SECOND);
            assertThat(last(kit, 25 * SECOND)).containsOnly("STOP");
            assertThat(rule(kit).parked()).isTrue();
            assertThat(rule(kit).place()).containsExactly(START, START);
        }
    }

    @Test
    void whatItAlreadySawWhenItStoppedOrWhatStandsFartherThanHalfAMetreLeavesItWhereItIs() {
        // a wall 0.2 m to its right when it stopped, there all along
        try (ScenarioKit kit = parkedAtTheStart(SOMETHING_ON_THE_RIGHT)) {
            kit.step(20 * SECOND);
            // something 0.55 m ahead (beyond 0.5 m of the rim), for 20 s more
            kit.robot().scan(0.2, 0.3, 1, 0.55, 0.55, 1, 1, 1);
            kit.step(20 * SECOND);
            assertThat(last(kit, 40 * SECOND)).containsOnly("STOP");
            assertThat(rule(kit).parked()).isTrue();
            assertThat(rule(kit).place()).containsExactly(START, START);
        }
    }
}
