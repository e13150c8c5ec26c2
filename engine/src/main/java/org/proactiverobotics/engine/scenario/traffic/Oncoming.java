package org.proactiverobotics.engine.scenario.traffic;

import org.proactiverobotics.engine.tables.DistanceScan;
import org.proactiverobotics.engine.tables.PoseEstimate;

/**
 * Tells something that comes at the robot from a wall or a pillar, in two steps. First a
 * <em>sighting</em>: the scans of the last {@value #SAMPLES} iterations are remembered with the
 * robot's pose, and something a front ray (±25°) hits within {@value #ALERT_M} m of the rim moved
 * in when an earlier ray passed through the place {@value #DEPTH_M} m behind that point, inside
 * what the ray hit now (within {@value #LATERAL_M} m of it), and went on {@value #SEEN_BEYOND_M} m
 * or more: the place was seen free then. Behind, not at, the hit point: a ray grazing past the edge
 * of something that stands still (a parked robot, a wall's corner) passes close to its rim, never
 * through it. Then it <em>comes</em> only when a later front hit, within {@value #TRACK_MS} ms of a
 * sighting, lies {@value #APPROACH_M} m or more nearer along that sighting's line of sight (in the
 * world frame, within {@value #TRACK_LATERAL_M} m of the line): what moved in keeps coming. A
 * sighting alone is not enough: a ray sweeping over a pillar's round edge or a thin wall's end as
 * the robot turns finds a place an earlier ray passed beside (the 4 cm behind a hit near a pillar's
 * edge is outside the pillar), and the robot gave way to it; 73 % of the give-ways in the generated
 * pillars worlds of four robots began with no other robot within 1.2 m. Hits on a thing that stands
 * still lie on its outline, which along one line of sight spans no more than the thing's own radius
 * (6 cm for the generated pillars); a robot at 0.5 m/s comes {@value #APPROACH_M} m nearer in
 * 0.14 s. A confirmed hit is a sighting too, so a robot that keeps coming keeps being seen coming.
 * Kept in plain fields: saved with the rule that holds it.
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
    /** A sighting is followed this long, simulated ms (12 steps of 32 ms). */
    static final long TRACK_MS = 400;
    /** A later hit this much nearer along a sighting's line of sight confirms it, metres (more than a pillar's radius). */
    static final double APPROACH_M = 0.07;
    /** ... and this close to that line, metres. */
    static final double TRACK_LATERAL_M = 0.03;
    /** ... and this close to the sighting's point at most, metres. */
    static final double TRACK_M = 0.25;
    /** Sightings followed at once (the oldest makes way). */
    static final int SIGHTINGS = 32;

    private final long[] timeMs = new long[SAMPLES];
    private final double[] xs = new double[SAMPLES];
    private final double[] ys = new double[SAMPLES];
    private final double[] yaws = new double[SAMPLES];
    private final double[][] readings = new double[SAMPLES][];
    private double[] anglesRad;
    private double rangeM;
    private int count;
    private int next;
    /** Each sighting's scan time (simulated ms), hit point and unit line of sight in the world frame, metres. */
    private final long[] sightedMs = new long[SIGHTINGS];
    private final double[] sightX = new double[SIGHTINGS];
    private final double[] sightY = new double[SIGHTINGS];
    private final double[] sightUx = new double[SIGHTINGS];
    private final double[] sightUy = new double[SIGHTINGS];
    private int sightings;
    private int nextSighting;
    /** This scan's front hits (point, unit line of sight, sighted), scratch reused from scan to scan: not saved. */
    private transient double[] hitX;
    private transient double[] hitY;
    private transient double[] hitUx;
    private transient double[] hitUy;
    private transient boolean[] sighted;

    /**
     * Remembers a scan (a scan already seen is not added again) and tells whether something ahead comes.
     *
     * @param pose    the robot's pose at the scan
     * @param scan    the scan
     * @param radiusM the robot's radius (the rays start at its rim), metres
     * @return whether a front ray hits, within {@value #ALERT_M} m, {@value #APPROACH_M} m or more nearer along the
     *         line of sight of a sighting of the last {@value #TRACK_MS} ms
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
        long now = scan.simTimeMs();
        int front = 0;
        if (hitX == null || hitX.length != scan.anglesRad().length) {
            int n = scan.anglesRad().length;
            hitX = new double[n];
            hitY = new double[n];
            hitUx = new double[n];
            hitUy = new double[n];
            sighted = new boolean[n];
        }
        boolean coming = false;
        for (int k = 0; k < scan.anglesRad().length; k++) {
            double d = scan.distancesM()[k];
            if (Math.abs(scan.anglesRad()[k]) > FRONT_RAD || !(d >= 0) || d >= ALERT_M || d >= rangeM * (1 - FREE_MARGIN)) {
                continue;
            }
            double a = pose.yawRad() + scan.anglesRad()[k];
            double ux = Math.cos(a);
            double uy = Math.sin(a);
            double px = pose.xM() + ux * (radiusM + d);
            double py = pose.yM() + uy * (radiusM + d);
            boolean confirmed = comesNearer(px, py, now);
            coming |= confirmed;
            sighted[front] = confirmed || seenFreeBefore(px + ux * DEPTH_M, py + uy * DEPTH_M, radiusM);
            hitX[front] = px;
            hitY[front] = py;
            hitUx[front] = ux;
            hitUy[front] = uy;
            front++;
        }
        for (int h = 0; h < front; h++) {
            if (sighted[h]) {
                sightedMs[nextSighting] = now;
                sightX[nextSighting] = hitX[h];
                sightY[nextSighting] = hitY[h];
                sightUx[nextSighting] = hitUx[h];
                sightUy[nextSighting] = hitUy[h];
                nextSighting = (nextSighting + 1) % SIGHTINGS;
                sightings = Math.min(SIGHTINGS, sightings + 1);
            }
        }
        timeMs[next] = now;
        xs[next] = pose.xM();
        ys[next] = pose.yM();
        yaws[next] = pose.yawRad();
        if (readings[next] == null || readings[next].length != scan.distancesM().length) {
            readings[next] = new double[scan.distancesM().length];
        }
        System.arraycopy(scan.distancesM(), 0, readings[next], 0, readings[next].length); // the slot's array is reused
        next = (next + 1) % SAMPLES;
        count = Math.min(SAMPLES, count + 1);
        return coming;
    }

    /** Whether a point hit now lies well nearer along the line of sight of a recent sighting, close to that line. */
    private boolean comesNearer(double px, double py, long nowMs) {
        for (int n = 0; n < sightings; n++) {
            long age = nowMs - sightedMs[n];
            if (age <= 0 || age > TRACK_MS) {
                continue;
            }
            double wx = sightX[n] - px;
            double wy = sightY[n] - py;
            if (Math.hypot(wx, wy) > TRACK_M) {
                continue;
            }
            double nearer = wx * sightUx[n] + wy * sightUy[n];
            double lateral = Math.abs(wx * sightUy[n] - wy * sightUx[n]);
            if (nearer >= APPROACH_M && lateral <= TRACK_LATERAL_M) {
                return true;
            }
        }
        return false;
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
