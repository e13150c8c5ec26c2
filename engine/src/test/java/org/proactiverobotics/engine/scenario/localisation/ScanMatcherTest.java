package org.proactiverobotics.engine.scenario.localisation;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.Test;
import org.proactiverobotics.engine.tables.DistanceScan;
import org.proactiverobotics.engine.tables.OccupancyMap;

/** Scans cast against a map drawn cell by cell, matched from a pose that is a little wrong. */
class ScanMatcherTest {

    private static final double RADIUS_M = 0.12;
    private static final double RANGE_M = 1.0;
    private static final double[] ANGLES_DEG = {-90, -60, -35, -20, -10, -3, 3, 10, 20, 35, 60, 90};

    // Walls face the robot at cell centres: the map knows a wall to the cell that a ray ended in, so a
    // face on a cell's edge would be off by half a cell wherever the map puts it (the mean offset is 0).

    /** A wall along x = 0.625 m and one along y = -0.525 m: a corner ahead and to the right. */
    private static boolean cornerWall(double x, double y) {
        return (x >= 0.625 && x < 0.675) || (y <= -0.525 && y > -0.575);
    }

    /** Two walls along y = ±0.425 m: a corridor along x. */
    private static boolean corridorWall(double x, double y) {
        return Math.abs(y) >= 0.425 && Math.abs(y) < 0.475;
    }

    private interface Walls {
        boolean at(double x, double y);
    }

    private static OccupancyMap draw(Walls walls) {
        OccupancyMap map = OccupancyMap.empty();
        for (int i = -40; i <= 40; i++) {
            for (int j = -40; j <= 40; j++) {
                if (walls.at(OccupancyMap.centre(i), OccupancyMap.centre(j))) {
                    map.set(i, j, OccupancyMap.OCCUPIED);
                }
            }
        }
        return map;
    }

    /** The scan a robot at (x, y, yaw) reads: each ray marched in 1 mm steps from the rim. */
    private static DistanceScan cast(Walls walls, double x, double y, double yaw) {
        double[] angles = new double[ANGLES_DEG.length];
        double[] distances = new double[ANGLES_DEG.length];
        for (int k = 0; k < angles.length; k++) {
            angles[k] = Math.toRadians(ANGLES_DEG[k]);
            double a = yaw + angles[k];
            double d = 0;
            while (d < RANGE_M && !walls.at(x + Math.cos(a) * (RADIUS_M + d), y + Math.sin(a) * (RADIUS_M + d))) {
                d += 0.001;
            }
            distances[k] = Math.min(d, RANGE_M);
        }
        return new DistanceScan(0, angles, distances, RANGE_M);
    }

    @Test
    void aScanSeeingACornerPutsThePoseBackWhereItWas() {
        OccupancyMap map = draw(ScanMatcherTest::cornerWall);
        // near enough to both walls that at least three rays pin each
        DistanceScan scan = cast(ScanMatcherTest::cornerWall, 0.1, -0.25, 0.05);
        ScanMatcher matcher = new ScanMatcher();
        assertThat(matcher.match(map, 0.13, -0.27, 0.05 + Math.toRadians(2), RADIUS_M, scan, 0.9)).isTrue();
        assertThat(matcher.pairs).isGreaterThanOrEqualTo(6);
        assertThat(matcher.xM).isCloseTo(0.1, within(0.015));
        assertThat(matcher.yM).isCloseTo(-0.25, within(0.015));
        // a dozen rays of 1 m pin the heading poorly (the lever arms are short): the matcher leaves it, about, to the
        // inertial unit; it must not make it worse than the prediction's 2°
        assertThat(matcher.yawRad).isCloseTo(0.05, within(Math.toRadians(3)));
    }

    @Test
    void inACorridorTheScanFixesTheSideButSaysNothingAlongIt() {
        OccupancyMap map = draw(ScanMatcherTest::corridorWall);
        DistanceScan scan = cast(ScanMatcherTest::corridorWall, 0.0, 0.05, 0.0);
        ScanMatcher matcher = new ScanMatcher();
        assertThat(matcher.match(map, 0.03, 0.08, 0.0, RADIUS_M, scan, 0.9)).isTrue();
        assertThat(matcher.yM).isCloseTo(0.05, within(0.015));
        double alongVar = matcher.covariance[0];
        // across, given the heading (which a dozen short rays pin poorly, the inertial unit well): the
        // variance of y once the heading is known, from the covariance's y-heading block
        double acrossGivenHeading = matcher.covariance[4] - matcher.covariance[5] * matcher.covariance[7] / matcher.covariance[8];
        assertThat(acrossGivenHeading).isLessThan(0.001);
        assertThat(alongVar).as("along the corridor the scan knows nothing").isGreaterThan(1000 * acrossGivenHeading);
    }

    @Test
    void aScanThatHitsNothingOrFitsNoWallIsNotTaken() {
        OccupancyMap map = draw(ScanMatcherTest::cornerWall);
        double[] free = new double[ANGLES_DEG.length];
        java.util.Arrays.fill(free, RANGE_M);
        double[] angles = new double[ANGLES_DEG.length];
        for (int k = 0; k < angles.length; k++) {
            angles[k] = Math.toRadians(ANGLES_DEG[k]);
        }
        ScanMatcher matcher = new ScanMatcher();
        assertThat(matcher.match(map, 0, 0, 0, RADIUS_M, new DistanceScan(0, angles, free, RANGE_M), 0.9)).isFalse();
        // walls seen where the map has none nearby
        assertThat(matcher.match(OccupancyMap.empty(), 0, 0, 0, RADIUS_M,
                cast(ScanMatcherTest::cornerWall, 0.1, -0.1, 0), 0.9)).isFalse();
    }
}
