package org.proactiverobotics.engine.scenario.localisation;

import org.ejml.data.DMatrix3x3;
import org.ejml.dense.fixed.CommonOps_DDF3;
import org.proactiverobotics.engine.tables.DistanceScan;
import org.proactiverobotics.engine.tables.OccupancyMap;

/**
 * Matches one distance scan against the engine's own occupancy map: point-to-line ICP. Each ray
 * that hit something ends at a point; the point is paired with the occupied cells nearest to it,
 * the line through those cells (their principal direction) is the wall it hit, and Gauss-Newton
 * moves the pose until the points lie on their walls. The result is the pose with its covariance:
 * along a wall the scan says nothing (a corridor), and the covariance says so, so the filter keeps
 * odometry's word there. Chosen over a correlative search because the scan has a dozen rays, each
 * iteration must cost microseconds, and odometry predicts the pose to a few centimetres: a local
 * solver is enough, and its curvature gives the covariance. Scratch arrays are reused, nothing is
 * allocated per match.
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
    /** What the matcher assumes of a direction the scan does not constrain, 1/m^2: keeps the normal matrix invertible. */
    static final double PRIOR = 1e-3;

    private static final int REACH_CELLS = (int) Math.ceil(PAIR_M / OccupancyMap.CELL_M);

    private double[] localX = new double[16];
    private double[] localY = new double[16];
    private final DMatrix3x3 normal = new DMatrix3x3();
    private final DMatrix3x3 inverse = new DMatrix3x3();

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
        for (int step = 0; step < STEPS; step++) {
            double c = Math.cos(yaw);
            double s = Math.sin(yaw);
            double h00 = PRIOR, h01 = 0, h02 = 0, h11 = PRIOR, h12 = 0, h22 = PRIOR;
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
                double j2 = nx * -(py - y) + ny * (px - x);
                h00 += j0 * j0; h01 += j0 * j1; h02 += j0 * j2;
                h11 += j1 * j1; h12 += j1 * j2; h22 += j2 * j2;
                b0 += j0 * r; b1 += j1 * r; b2 += j2 * r;
                sumSquares += r * r;
                pairs++;
            }
            if (pairs < MIN_PAIRS) {
                return false;
            }
            normal.setTo(h00, h01, h02, h01, h11, h12, h02, h12, h22);
            if (!CommonOps_DDF3.invert(normal, inverse)) {
                return false;
            }
            double dx = -(inverse.a11 * b0 + inverse.a12 * b1 + inverse.a13 * b2);
            double dy = -(inverse.a21 * b0 + inverse.a22 * b1 + inverse.a23 * b2);
            double dt = -(inverse.a31 * b0 + inverse.a32 * b1 + inverse.a33 * b2);
            x += dx;
            y += dy;
            yaw += dt;
            if (Math.abs(dx) < 1e-4 && Math.abs(dy) < 1e-4 && Math.abs(dt) < 1e-4) {
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
        double v = SIGMA_M * SIGMA_M;
        covariance[0] = v * inverse.a11; covariance[1] = v * inverse.a12; covariance[2] = v * inverse.a13;
        covariance[3] = v * inverse.a21; covariance[4] = v * inverse.a22; covariance[5] = v * inverse.a23;
        covariance[6] = v * inverse.a31; covariance[7] = v * inverse.a32; covariance[8] = v * inverse.a33;
        return true;
    }

    private final double[] line = new double[4];

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
        double mx = sx / count;
        double my = sy / count;
        double vxx = sxx / count - mx * mx;
        double vxy = sxy / count - mx * my;
        double vyy = syy / count - my * my;
        double nx;
        double ny;
        if (count < 3 || vxx + vyy < 1e-12) {
            // a lone cell: the point's direction from it is the normal (point to point)
            double ex = px - OccupancyMap.centre(bestI);
            double ey = py - OccupancyMap.centre(bestJ);
            double len = Math.hypot(ex, ey);
            if (len < 1e-9) {
                nx = 1;
                ny = 0;
            } else {
                nx = ex / len;
                ny = ey / len;
            }
            mx = OccupancyMap.centre(bestI);
            my = OccupancyMap.centre(bestJ);
        } else {
            // the wall runs along the spread's major axis; its normal is the minor one
            double angle = 0.5 * Math.atan2(2 * vxy, vxx - vyy);
            nx = -Math.sin(angle);
            ny = Math.cos(angle);
        }
        line[0] = mx;
        line[1] = my;
        line[2] = nx;
        line[3] = ny;
        return line;
    }
}
