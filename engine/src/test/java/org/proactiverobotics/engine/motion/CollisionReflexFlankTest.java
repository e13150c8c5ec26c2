package org.proactiverobotics.engine.motion;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.Arrays;
import org.junit.jupiter.api.Test;
import org.proactiverobotics.engine.tables.DistanceScan;
import org.proactiverobotics.engine.tables.OccupancyMap;

/**
 * A wall the body closes on beside it: the newest reading is nearer than the hit remembered a
 * few centimetres away (the memory keeps one hit per 4 cm), and it is the newest reading the
 * arcs are judged against. Before, an arc that kept closing on the guarded flank was let go
 * because only the older, farther hit was checked (issue 33: a wall contact on the 100 x 100 m
 * floor, seed 1, at 95.7 s).
 */
class CollisionReflexFlankTest {

    private static final double DEG = Math.PI / 180;
    private static final double[] FRONT = Arrays.stream(new double[] {-90, -70, -50, -35, -20, -8, 8, 20, 35, 50, 70, 90})
            .map(a -> a * DEG).toArray();
    private static final int LEFT_70 = 10;
    private static final int LEFT_90 = 11;
    private static final String AHEAD = "DRIVE 0.5000 0.5000";

    private static DistanceScan scan(long ms, int ray, double distanceM) {
        double[] d = new double[FRONT.length];
        Arrays.fill(d, 1.0);
        d[ray] = distanceM;
        return new DistanceScan(ms, FRONT, d, 1.0);
    }

    /** A map whose cells round the robot the rays have all seen free (so only the hits can veto). */
    private static OccupancyMap seenFree() {
        OccupancyMap map = OccupancyMap.empty();
        for (int i = OccupancyMap.cell(-1.0); i <= OccupancyMap.cell(1.0); i++) {
            for (int j = OccupancyMap.cell(-1.0); j <= OccupancyMap.cell(1.0); j++) {
                map.miss(i, j);
            }
        }
        return map;
    }

    @Test
    void aFlankWallReadNearerThanItsRememberedHitTurnsTheRobotAwayOnTheSpot() {
        OccupancyMap map = seenFree();
        CollisionReflex reflex = new CollisionReflex();
        // the ray at 90° sees the wall 3 cm off the rim: remembered at (0, 0.15)
        reflex.vet(AHEAD, scan(1000, LEFT_90, 0.03), map, 0.0, 0.0, 0.0, DriveProfile.DEFAULT, Clearance.DEFAULT);
        // a moment later the ray at 70° reads it 1 cm off the rim, under 3 cm from the remembered hit
        // (so not remembered itself); the remembered hit, 3.5 cm off the rim, is one straight ahead passes
        String veto = reflex.vet(AHEAD, scan(1032, LEFT_70, 0.01), map, -0.04, 0.0, 0.0, DriveProfile.DEFAULT,
                Clearance.DEFAULT);
        double[] wheels = Steering.wheelSpeeds(veto);
        assertThat(wheels).as("a forward arc brings the body onto the wall read at 70°: " + veto).isNotNull();
        assertThat(wheels[0] + wheels[1]).as("no forward speed: " + veto).isCloseTo(0.0, within(1e-9));
        assertThat(wheels[0]).as("turning right, away from the left flank: " + veto).isGreaterThan(wheels[1]);
    }

    @Test
    void aFlankWallThatKeepsItsDistanceLetsAnArcGoOn() {
        OccupancyMap map = seenFree();
        CollisionReflex reflex = new CollisionReflex();
        reflex.vet(AHEAD, scan(1000, LEFT_90, 0.05), map, 0.0, 0.0, 0.0, DriveProfile.DEFAULT, Clearance.DEFAULT);
        // beside a wall 5 cm off the rim that does not converge, going straight on is let go
        assertThat(reflex.vet(AHEAD, scan(1032, LEFT_90, 0.05), map, 0.016, 0.0, 0.0, DriveProfile.DEFAULT,
                Clearance.DEFAULT)).isNull();
    }
}
