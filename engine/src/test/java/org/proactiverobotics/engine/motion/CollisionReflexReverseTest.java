package org.proactiverobotics.engine.motion;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Arrays;
import org.junit.jupiter.api.Test;
import org.proactiverobotics.engine.tables.DistanceScan;
import org.proactiverobotics.engine.tables.OccupancyMap;

/**
 * Backing is vetted against what the robot knows behind it, once the reflex vets reverse commands
 * (a robot that shares its world, or one with rays behind): the hits its rays saw in the last
 * seconds, wherever they point now, a ray that looks behind, and the map's occupied and never-seen
 * cells. A reflex that does not vet reverse commands lets them go, as before.
 */
class CollisionReflexReverseTest {

    private static final double DEG = Math.PI / 180;
    private static final double[] FRONT = Arrays.stream(new double[] {-90, -70, -50, -35, -20, -8, 8, 20, 35, 50, 70, 90})
            .map(a -> a * DEG).toArray();
    private static final String BACK = "DRIVE -0.3000 -0.3000";

    private static DistanceScan scan(long ms, double[] angles, int ray, double distanceM) {
        double[] d = new double[angles.length];
        Arrays.fill(d, 1.0);
        if (ray >= 0) {
            d[ray] = distanceM;
        }
        return new DistanceScan(ms, angles, d, 1.0);
    }

    @Test
    void aHitSeenAheadBeforeTheRobotTurnedRoundStopsTheBackingTowardIt() {
        CollisionReflex reflex = new CollisionReflex().vettingReverse();
        // a wall 6 cm ahead of the rim, seen by the ray at 8°; the robot then turns round on the spot
        assertThat(reflex.vet("DRIVE -0.3000 0.3000", scan(1000, FRONT, 6, 0.06), 0.0, 0.0, 0.0, DriveProfile.DEFAULT,
                Clearance.DEFAULT)).isNull();
        String veto = reflex.vet(BACK, scan(2000, FRONT, -1, 1.0), 0.0, 0.0, Math.PI, DriveProfile.DEFAULT, Clearance.DEFAULT);
        assertThat(veto).isEqualTo(Steering.STOP);
        assertThat(reflex.reason(BACK)).startsWith("vetoed " + BACK + ": backing toward an obstacle a ray hit 0.06 m away at -172°");
        // going ahead, away from it, is let go
        assertThat(reflex.vet("DRIVE 0.5000 0.5000", scan(2032, FRONT, -1, 1.0), 0.0, 0.0, Math.PI, DriveProfile.DEFAULT,
                Clearance.DEFAULT)).isNull();
    }

    @Test
    void aRayThatLooksBehindStopsTheBacking() {
        double[] withRear = Arrays.copyOf(FRONT, FRONT.length + 1);
        withRear[FRONT.length] = 180 * DEG;
        CollisionReflex reflex = new CollisionReflex().vettingReverse();
        assertThat(reflex.vet(BACK, scan(1000, withRear, FRONT.length, 0.05), 0.0, 0.0, 0.0, DriveProfile.DEFAULT,
                Clearance.DEFAULT)).isEqualTo(Steering.STOP);
        assertThat(reflex.vet(BACK, scan(1032, withRear, FRONT.length, 0.6), 5.0, 0.0, 0.0, DriveProfile.DEFAULT,
                Clearance.DEFAULT)).as("far behind, beyond the braking reach").isNull();
    }

    @Test
    void backingIntoCellsNeverSeenStopsAndOverSeenFreeCellsGoes() {
        OccupancyMap map = OccupancyMap.empty();
        CollisionReflex reflex = new CollisionReflex().vettingReverse();
        assertThat(reflex.vet(BACK, scan(1000, FRONT, -1, 1.0), map, 0.0, 0.0, 0.0, DriveProfile.DEFAULT, Clearance.DEFAULT))
                .as("nothing seen behind").isEqualTo(Steering.STOP);
        for (int i = OccupancyMap.cell(-0.6); i <= OccupancyMap.cell(0.3); i++) {
            for (int j = OccupancyMap.cell(-0.3); j <= OccupancyMap.cell(0.3); j++) {
                map.miss(i, j); // seen free
            }
        }
        assertThat(reflex.vet(BACK, scan(1032, FRONT, -1, 1.0), map, 0.0, 0.0, 0.0, DriveProfile.DEFAULT, Clearance.DEFAULT))
                .isNull();
        map.confirm(OccupancyMap.cell(-0.2), OccupancyMap.cell(0.0)); // a wall just behind
        assertThat(reflex.vet(BACK, scan(1064, FRONT, -1, 1.0), map, 0.0, 0.0, 0.0, DriveProfile.DEFAULT, Clearance.DEFAULT))
                .isEqualTo(Steering.STOP);
    }

    @Test
    void aReflexThatDoesNotVetReverseCommandsLetsThemGo() {
        CollisionReflex reflex = new CollisionReflex();
        double[] withRear = Arrays.copyOf(FRONT, FRONT.length + 1);
        withRear[FRONT.length] = 180 * DEG;
        assertThat(reflex.vet(BACK, scan(1000, withRear, FRONT.length, 0.05), OccupancyMap.empty(), 0.0, 0.0, 0.0,
                DriveProfile.DEFAULT, Clearance.DEFAULT)).isNull();
    }
}
