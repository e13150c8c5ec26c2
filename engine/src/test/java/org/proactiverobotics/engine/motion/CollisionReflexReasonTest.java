package org.proactiverobotics.engine.motion;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Arrays;
import org.junit.jupiter.api.Test;
import org.proactiverobotics.engine.tables.DistanceScan;
import org.proactiverobotics.engine.tables.OccupancyMap;

/**
 * The reflex's veto says why in words, and only what it knows: where the hit or the map's occupied
 * cell lies from the body (distance from its rim, bearing from its heading) and the braking reach
 * it judged with; nothing when it let the command go.
 */
class CollisionReflexReasonTest {

    private static final double DEG = Math.PI / 180;
    private static final double[] ANGLES = Arrays.stream(new double[] {-90, -70, -50, -35, -20, -8, 8, 20, 35, 50, 70, 90})
            .map(a -> a * DEG).toArray();

    private static DistanceScan scan(double ahead) {
        double[] d = new double[ANGLES.length];
        Arrays.fill(d, 1.0);
        d[6] = ahead; // the ray at 8°
        return new DistanceScan(1000, ANGLES, d, 1.0);
    }

    @Test
    void aHitAheadWithinTheReachIsNamedWithItsDistanceAndBearing() {
        CollisionReflex reflex = new CollisionReflex();
        String veto = reflex.vet("DRIVE 0.5000 0.5000", scan(0.06), 0.0, 0.0, 0.0, DriveProfile.DEFAULT, Clearance.DEFAULT);
        assertThat(veto).isNotNull();
        assertThat(reflex.reason("DRIVE 0.5000 0.5000"))
                .isEqualTo("vetoed DRIVE 0.5000 0.5000: obstacle a ray hit 0.06 m away at 8°, within braking reach 0.17 m");
    }

    @Test
    void anOccupiedCellOfTheMapIsNamedAsSuch() {
        CollisionReflex reflex = new CollisionReflex();
        OccupancyMap map = OccupancyMap.empty();
        map.confirm(OccupancyMap.cell(0.20), OccupancyMap.cell(0.0)); // a wall the rays do not see now
        String veto = reflex.vet("DRIVE 0.5000 0.5000", scan(1.0), map, 0.0, 0.0, 0.0, DriveProfile.DEFAULT, Clearance.DEFAULT);
        assertThat(veto).isNotNull();
        // the cell's centre (0.225, 0.025): 0.226 m from the centre, 0.106 m from the rim (radius 0.12), at 6.3°
        assertThat(reflex.reason("DRIVE 0.5000 0.5000"))
                .isEqualTo("vetoed DRIVE 0.5000 0.5000: occupied map cell 0.11 m away at 6°, within braking reach 0.17 m");
    }

    @Test
    void aCommandLetGoHasNoReason() {
        CollisionReflex reflex = new CollisionReflex();
        assertThat(reflex.vet("DRIVE 0.5000 0.5000", scan(1.0), 0.0, 0.0, 0.0, DriveProfile.DEFAULT, Clearance.DEFAULT)).isNull();
        assertThat(reflex.reason("DRIVE 0.5000 0.5000")).isNull();
    }
}
