package org.proactiverobotics.engine.scenario.traffic;

import org.proactiverobotics.engine.tables.DistanceScan;
import org.proactiverobotics.engine.tables.PoseEstimate;

/**
 * Tells something that moved into the robot's way from a wall: the scans of the last
 * {@value #SAMPLES} iterations are remembered with the robot's pose, and something a front ray
 * (±25°) hits within {@value #ALERT_M} m of the rim now comes when an earlier ray passed through
 * the place {@value #DEPTH_M} m behind that point, inside what the ray hit now (within {@value #LATERAL_M} m
 * of it), and went on {@value #SEEN_BEYOND_M} m or more: the place was seen free then. Behind, not at,
 * the hit point: a ray grazing past the edge of something that stands still (a parked robot, a wall's
 * corner) passes close to its rim, never through it; judged at the rim, a robot driving or turning
 * toward a parked one gave way to it again and again (generated worlds of four robots, none accomplished). A wall's point was never seen through, however the robot
 * drove or turned toward it; comparing distances instead took an oblique wall the robot turned
 * along for a robot coming. Kept in plain fields: saved with the rule that holds it.
 */
final class Oncoming {

    /** Rays within this angle of the heading look ahead, radians (±25°). */
    static final double FRONT_RAD = Math.toRadians(25);
    /** Something nearer than this, from the rim, metres, may be coming at the robot. */
    static final double ALERT_M = 0.7;
    /** A reading within this share of the range is no hit (a free ray reads a little under it). */
    static final double FREE_MARGIN = 0.1;
    /** Scans remembered: a quarter of a second at the 32 ms step. */
    static final int SAMPLES = 8;
    /** An earlier ray passing this close to a point, metres, saw the point. */
    static final double LATERAL_M = 0.02;
    /** It saw the point free when it went on this far beyond it, metres (readings stray a centimetre or two). */
    static final double SEEN_BEYOND_M = 0.08;
    /** How far behind the hit point, along the ray, an earlier ray must have seen free space, metres. */
    static final double DEPTH_M = 0.04;

    private final long[] timeMs = new long[SAMPLES];
    private final double[] xs = new double[SAMPLES];
    private final double[] ys = new double[SAMPLES];
    private final double[] yaws = new double[SAMPLES];
    private final double[][] readings = new double[SAMPLES][];
    private double[] anglesRad;
    private double rangeM;
    private int count;
    private int next;

    /**
     * Remembers a scan (a scan already seen is not added again) and tells whether something ahead moved in.
     *
     * @param pose    the robot's pose at the scan
     * @param scan    the scan
     * @param radiusM the robot's radius (the rays start at its rim), metres
     * @return whether a front ray hits, within {@value #ALERT_M} m, a point an earlier ray saw free
     */
    boolean observe(PoseEstimate pose, DistanceScan scan, double radiusM) {
        int newest = (next + SAMPLES - 1) % SAMPLES;
        if (count > 0 && timeMs[newest] == scan.simTimeMs()) {
            return false; // this scan was judged already
        }
        if (anglesRad == null || anglesRad.length != scan.anglesRad().length) {
            anglesRad = scan.anglesRad().clone();
            count = 0; // another sensor layout: the old scans do not compare
        }
        rangeM = scan.rangeM();
        boolean coming = false;
        for (int k = 0; k < scan.anglesRad().length && !coming; k++) {
            double d = scan.distancesM()[k];
            if (Math.abs(scan.anglesRad()[k]) > FRONT_RAD || !(d >= 0) || d >= ALERT_M || d >= rangeM * (1 - FREE_MARGIN)) {
                continue;
            }
            double a = pose.yawRad() + scan.anglesRad()[k];
            double behind = radiusM + d + DEPTH_M;
            coming = seenFreeBefore(pose.xM() + Math.cos(a) * behind, pose.yM() + Math.sin(a) * behind, radiusM);
        }
        timeMs[next] = scan.simTimeMs();
        xs[next] = pose.xM();
        ys[next] = pose.yM();
        yaws[next] = pose.yawRad();
        readings[next] = scan.distancesM().clone();
        next = (next + 1) % SAMPLES;
        count = Math.min(SAMPLES, count + 1);
        return coming;
    }

    /** Whether a remembered ray passed through the point and went on beyond it. */
    private boolean seenFreeBefore(double px, double py, double radiusM) {
        for (int n = 0; n < count; n++) {
            double[] then = readings[n];
            for (int k = 0; k < anglesRad.length; k++) {
                double d = then[k];
                if (!(d >= 0)) {
                    continue; // an unreadable distance saw nothing
                }
                double a = yaws[n] + anglesRad[k];
                double ux = Math.cos(a);
                double uy = Math.sin(a);
                double wx = px - xs[n];
                double wy = py - ys[n];
                double along = wx * ux + wy * uy;
                double lateral = Math.abs(wx * uy - wy * ux);
                if (lateral < LATERAL_M && along > radiusM && radiusM + Math.min(d, rangeM) >= along + SEEN_BEYOND_M) {
                    return true;
                }
            }
        }
        return false;
    }
}
