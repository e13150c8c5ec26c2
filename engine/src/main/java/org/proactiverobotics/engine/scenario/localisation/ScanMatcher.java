package org.proactiverobotics.engine.scenario.localisation;

import java.util.Arrays;
import org.ejml.data.DMatrixRMaj;
import org.ejml.dense.row.factory.DecompositionFactory_DDRM;
import org.ejml.interfaces.decomposition.EigenDecomposition_F64;
import org.proactiverobotics.engine.tables.DistanceScan;
import org.proactiverobotics.engine.tables.OccupancyMap;

/**
 * Matches one distance scan against the engine's own occupancy map: point-to-line ICP. Each ray
 * that hit something ends at a point; the point is paired with the occupied cells nearest to it,
 * and the line through those cells (their principal direction) is the wall it hit. A point past
 * the cells' end, or near fewer than {@value #MIN_WALL_CELLS} cells, is paired with the nearest
 * cell where the map has seen its place free, and left unpaired where the map knows nothing.
 * Gauss-Newton moves the pose until the points lie on their walls, in the directions the walls pin
 * only. The result is the pose with its covariance: along a wall the scan says nothing (a
 * corridor), and the covariance says so, so the filter keeps odometry's word there. Chosen over a
 * correlative search because the scan has a dozen rays, each iteration must cost microseconds, and
 * odometry predicts the pose to a few millimetres: a local solver is enough, and its curvature
 * gives the covariance. The matrices and arrays are reused from match to match.
 */
final class ScanMatcher {

    /** A ray's end is paired with an occupied cell at most this far away, metres. */
    static final double PAIR_M = 0.15;
    /** Gauss-Newton steps per match. */
    static final int STEPS = 6;
    /** How far a matched ray's end lies from its wall, one standard deviation, metres (the map's cells and the range error). */
    static final double SIGMA_M = 0.03;
    /** Fewer paired rays than this say nothing. */
    static final int MIN_PAIRS = 3;
    /** A match whose rays' ends lie further from their walls than this, root mean square, is not taken, metres. */
    static final double FIT_M = 0.035;
    /** A match that moves the pose further than this from the prediction is not taken (a wrong wall), metres. */
    static final double MAX_SHIFT_M = 0.2;
    /** Nor one that turns it further than this, radians. */
    static final double MAX_TURN_RAD = 0.15;
    /** A wall is at least this many occupied cells around the one nearest a point: fewer give no line. */
    static final int MIN_WALL_CELLS = 3;
    /**
     * A direction of the pose the scan constrains less than this (an eigenvalue of the normal
     * matrix: about the number of rays that pin it) is left as predicted, with no information:
     * along a corridor the walls' cells, tilted a little by the grid, would otherwise pull the pose
     * a few millimetres the same way at every scan, and that adds up (degeneracy-aware ICP).
     */
    static final double MIN_INFORMATION = 3.0;
    /** The heading is scaled by this lever arm to weigh it with the position, metres (about a ray's reach). */
    static final double LEVER_M = 1.0;
    /** The standard deviation given to a direction the scan does not constrain, metres (or radians times the lever). */
    static final double UNCONSTRAINED_M = 10.0;

    private static final int REACH_CELLS = (int) Math.ceil(PAIR_M / OccupancyMap.CELL_M);

    private double[] localX = new double[16];
    private double[] localY = new double[16];
    private final DMatrixRMaj normal = new DMatrixRMaj(3, 3);
    private final EigenDecomposition_F64<DMatrixRMaj> eigen = DecompositionFactory_DDRM.eig(3, true, true);
    /** The step's and the covariance's scaled form (x, y, heading times the lever). */
    private final double[] step = new double[3];
    private final double[] scaledCovariance = new double[9];

    /** The matched pose and its covariance (x, y, heading; 3 x 3 row by row), after {@link #match} returned true. */
    double xM;
    double yM;
    double yawRad;
    final double[] covariance = new double[9];
    /** Rays paired in the last match. */
    int pairs;

    /**
     * @param map       the map the scan is matched against
     * @param x0        the predicted x, metres
     * @param y0        the predicted y, metres
     * @param yaw0      the predicted heading, radians
     * @param radiusM   the robot's radius: the rays start at its rim, metres
     * @param scan      the scan
     * @param hitShare  a reading under this share of the range hit something
     * @return whether the scan matched the map well enough to say where the robot is
     */
    boolean match(OccupancyMap map, double x0, double y0, double yaw0, double radiusM, DistanceScan scan, double hitShare) {
        int n = 0;
        double[] angles = scan.anglesRad();
        double[] distances = scan.distancesM();
        if (localX.length < angles.length) {
            localX = new double[angles.length];
            localY = new double[angles.length];
        }
        for (int k = 0; k < angles.length; k++) {
            double d = distances[k];
            if (d >= 0 && d < scan.rangeM() * hitShare) {
                double reach = radiusM + d;
                localX[n] = reach * Math.cos(angles[k]);
                localY[n] = reach * Math.sin(angles[k]);
                n++;
            }
        }
        if (n < MIN_PAIRS) {
            return false;
        }
        double x = x0;
        double y = y0;
        double yaw = yaw0;
        double sumSquares = 0;
        for (int iteration = 0; iteration < STEPS; iteration++) {
            double c = Math.cos(yaw);
            double s = Math.sin(yaw);
            double h00 = 0, h01 = 0, h02 = 0, h11 = 0, h12 = 0, h22 = 0;
            double b0 = 0, b1 = 0, b2 = 0;
            pairs = 0;
            sumSquares = 0;
            for (int k = 0; k < n; k++) {
                double px = x + localX[k] * c - localY[k] * s;
                double py = y + localX[k] * s + localY[k] * c;
                double[] line = wallNear(map, px, py);
                if (line == null) {
                    continue;
                }
                double nx = line[2];
                double ny = line[3];
                double r = nx * (px - line[0]) + ny * (py - line[1]);
                double j0 = nx;
                double j1 = ny;
                double j2 = (nx * -(py - y) + ny * (px - x)) / LEVER_M;
                h00 += j0 * j0; h01 += j0 * j1; h02 += j0 * j2;
                h11 += j1 * j1; h12 += j1 * j2; h22 += j2 * j2;
                b0 += j0 * r; b1 += j1 * r; b2 += j2 * r;
                sumSquares += r * r;
                pairs++;
            }
            if (pairs < MIN_PAIRS || !solve(h00, h01, h02, h11, h12, h22, b0, b1, b2)) {
                return false;
            }
            x += step[0];
            y += step[1];
            yaw += step[2] / LEVER_M;
            if (Math.abs(step[0]) < 1e-4 && Math.abs(step[1]) < 1e-4 && Math.abs(step[2]) < 1e-4) {
                break;
            }
        }
        if (Math.sqrt(sumSquares / pairs) > FIT_M
                || Math.hypot(x - x0, y - y0) > MAX_SHIFT_M || Math.abs(PoseFilter.wrap(yaw - yaw0)) > MAX_TURN_RAD) {
            return false;
        }
        xM = x;
        yM = y;
        yawRad = PoseFilter.wrap(yaw);
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                covariance[i * 3 + j] = scaledCovariance[i * 3 + j] / (i == 2 ? LEVER_M : 1) / (j == 2 ? LEVER_M : 1);
            }
        }
        return true;
    }

    /**
     * The Gauss-Newton step in the directions the scan constrains, nothing in the others, and the
     * covariance to match (both scaled: the heading times {@link #LEVER_M}).
     *
     * @return false when the scan constrains no direction at all
     */
    private boolean solve(double h00, double h01, double h02, double h11, double h12, double h22,
                          double b0, double b1, double b2) {
        normal.set(0, 0, h00); normal.set(0, 1, h01); normal.set(0, 2, h02);
        normal.set(1, 0, h01); normal.set(1, 1, h11); normal.set(1, 2, h12);
        normal.set(2, 0, h02); normal.set(2, 1, h12); normal.set(2, 2, h22);
        if (!eigen.decompose(normal)) {
            return false;
        }
        Arrays.fill(step, 0);
        Arrays.fill(scaledCovariance, 0);
        boolean constrained = false;
        for (int e = 0; e < 3; e++) {
            double lambda = eigen.getEigenvalue(e).real;
            DMatrixRMaj v = eigen.getEigenVector(e);
            double v0 = v.get(0);
            double v1 = v.get(1);
            double v2 = v.get(2);
            double variance;
            if (lambda >= MIN_INFORMATION) {
                double along = -(v0 * b0 + v1 * b1 + v2 * b2) / lambda;
                step[0] += along * v0;
                step[1] += along * v1;
                step[2] += along * v2;
                variance = SIGMA_M * SIGMA_M / lambda;
                constrained = true;
            } else {
                variance = UNCONSTRAINED_M * UNCONSTRAINED_M;
            }
            for (int i = 0; i < 3; i++) {
                for (int j = 0; j < 3; j++) {
                    scaledCovariance[i * 3 + j] += variance * v.get(i) * v.get(j);
                }
            }
        }
        return constrained;
    }

    private final double[] line = new double[4];

    /** The point paired with one cell: the normal is the point's direction from it (point to point). */
    private double[] pointToCell(double px, double py, int i, int j) {
        double cx = OccupancyMap.centre(i);
        double cy = OccupancyMap.centre(j);
        double len = Math.hypot(px - cx, py - cy);
        if (len < 1e-9) {
            return null;
        }
        line[0] = cx;
        line[1] = cy;
        line[2] = (px - cx) / len;
        line[3] = (py - cy) / len;
        return line;
    }

    /**
     * The wall nearest a point: the occupied cells within {@value #PAIR_M} m of it, their centre
     * and the normal of the line through them (toward nothing in particular: the sign does not
     * matter to a squared distance).
     *
     * @return {centre x, centre y, normal x, normal y} (reused), or null when no occupied cell is near
     */
    private double[] wallNear(OccupancyMap map, double px, double py) {
        int ci = OccupancyMap.cell(px);
        int cj = OccupancyMap.cell(py);
        int bestI = 0;
        int bestJ = 0;
        double best = PAIR_M * PAIR_M;
        boolean found = false;
        for (int i = ci - REACH_CELLS; i <= ci + REACH_CELLS; i++) {
            for (int j = cj - REACH_CELLS; j <= cj + REACH_CELLS; j++) {
                if (map.get(i, j) == OccupancyMap.OCCUPIED) {
                    double ex = OccupancyMap.centre(i) - px;
                    double ey = OccupancyMap.centre(j) - py;
                    double d2 = ex * ex + ey * ey;
                    if (d2 < best) {
                        best = d2;
                        bestI = i;
                        bestJ = j;
                        found = true;
                    }
                }
            }
        }
        if (!found) {
            return null;
        }
        // the wall's cells around the nearest: their mean and spread give the line
        double sx = 0, sy = 0, sxx = 0, sxy = 0, syy = 0;
        int count = 0;
        for (int i = bestI - 2; i <= bestI + 2; i++) {
            for (int j = bestJ - 2; j <= bestJ + 2; j++) {
                if (map.get(i, j) == OccupancyMap.OCCUPIED) {
                    double cx = OccupancyMap.centre(i);
                    double cy = OccupancyMap.centre(j);
                    sx += cx; sy += cy; sxx += cx * cx; sxy += cx * cy; syy += cy * cy;
                    count++;
                }
            }
        }
        boolean seenFree = map.get(ci, cj) == OccupancyMap.FREE;
        if (count < MIN_WALL_CELLS) {
            // a lone cell or two gives no line. Where the point lies in space the rays have seen free, the map says
            // the wall ends before it (a door, a wall's end): the pose is off, and the nearest cell says by how much.
            // Where it lies in the unknown, it is a part of the wall the map has not drawn yet: pairing it with the
            // wall's last known cell pulled the pose back along the way it came, step after step.
            return seenFree ? pointToCell(px, py, bestI, bestJ) : null;
        }
        double mx = sx / count;
        double my = sy / count;
        double vxx = sxx / count - mx * mx;
        double vxy = sxy / count - mx * my;
        double vyy = syy / count - my * my;
        // the wall runs along the spread's major axis; its normal is the minor one
        double angle = 0.5 * Math.atan2(2 * vxy, vxx - vyy);
        double ux = Math.cos(angle);
        double uy = Math.sin(angle);
        // a point beyond the cells' end along the wall may lie on a part of it the map has not seen, or on another
        // wall: not paired (half the window's reach past the centre)
        double along = (px - mx) * ux + (py - my) * uy;
        if (Math.abs(along) > 2.5 * OccupancyMap.CELL_M) {
            return seenFree ? pointToCell(px, py, bestI, bestJ) : null;
        }
        double nx = -uy;
        double ny = ux;
        line[0] = mx;
        line[1] = my;
        line[2] = nx;
        line[3] = ny;
        return line;
    }
}
