package org.proactiverobotics.engine.scenario.traffic;

import org.proactiverobotics.engine.motion.Steering;
import org.proactiverobotics.engine.tables.DistanceScan;
import org.proactiverobotics.engine.tables.PoseEstimate;

/**
 * Tells something coming at the robot from a wall it drives at: the nearest thing the front rays
 * see, remembered over the last {@value #SAMPLES} scans with the robot's pose; the thing comes
 * when, within {@value #ALERT_M} m, it drew nearer by {@value #COMING_M} m more than the robot's
 * own travel toward it explains. A wall only draws nearer as fast as the robot drives. Kept in
 * plain fields: saved with the rule that holds it.
 */
final class Oncoming {

    /** Rays within this angle of the heading look ahead, radians (±25°). */
    static final double FRONT_RAD = Math.toRadians(25);
    /** Something nearer than this, from the rim, metres, may be coming at the robot. */
    static final double ALERT_M = 0.7;
    /** Drawing nearer by this much more than the robot's own travel is coming, metres (readings stray a centimetre or two). */
    static final double COMING_M = 0.05;
    /** A reading within this share of the range is no hit (a free ray reads a little under it). */
    static final double FREE_MARGIN = 0.1;
    /** Scans remembered: about a quarter of a second at the 32 ms step. */
    static final int SAMPLES = 8;
    /** A sample taken while the heading turned more than this since is not compared, radians (the rays swept elsewhere). */
    static final double TURNED_RAD = Math.toRadians(8);

    private final long[] timeMs = new long[SAMPLES];
    private final double[] front = new double[SAMPLES];
    private final double[] xs = new double[SAMPLES];
    private final double[] ys = new double[SAMPLES];
    private final double[] yaws = new double[SAMPLES];
    private int count;
    private int next;

    /** @return the nearest distance the front rays read (from the rim, metres), or +∞ when none hit */
    static double front(DistanceScan scan) {
        double nearest = Double.POSITIVE_INFINITY;
        for (int k = 0; k < scan.anglesRad().length; k++) {
            double d = scan.distancesM()[k];
            if (Math.abs(scan.anglesRad()[k]) <= FRONT_RAD && d >= 0 && d < scan.rangeM() * (1 - FREE_MARGIN)) {
                nearest = Math.min(nearest, d);
            }
        }
        return nearest;
    }

    /**
     * Remembers a scan (once per scan: a scan already seen is not added again).
     *
     * @param pose the robot's pose at the scan
     * @param scan the scan
     * @return whether something ahead comes at the robot
     */
    boolean observe(PoseEstimate pose, DistanceScan scan) {
        int newest = (next + SAMPLES - 1) % SAMPLES;
        if (count > 0 && timeMs[newest] == scan.simTimeMs()) {
            return coming(newest);
        }
        timeMs[next] = scan.simTimeMs();
        front[next] = front(scan);
        xs[next] = pose.xM();
        ys[next] = pose.yM();
        yaws[next] = pose.yawRad();
        int now = next;
        next = (next + 1) % SAMPLES;
        count = Math.min(SAMPLES, count + 1);
        return coming(now);
    }

    private boolean coming(int now) {
        if (!(front[now] < ALERT_M)) {
            return false;
        }
        for (int n = 1; n < count; n++) {
            int then = (now + SAMPLES - n) % SAMPLES;
            if (!Double.isFinite(front[then]) || Math.abs(Steering.wrap(yaws[now] - yaws[then])) > TURNED_RAD) {
                continue;
            }
            // the robot's own travel toward what it sees ahead (negative when it backs away)
            double own = (xs[now] - xs[then]) * Math.cos(yaws[now]) + (ys[now] - ys[then]) * Math.sin(yaws[now]);
            if (front[then] - front[now] - own > COMING_M) {
                return true;
            }
        }
        return false;
    }

    /** Forgets what was seen (the robot backed off: the old readings are from elsewhere). */
    void forget() {
        count = 0;
        next = 0;
    }
}
