package org.proactiverobotics.app.foxglove;

import org.proactiverobotics.app.replay.TraceBelief;
import org.proactiverobotics.app.replay.TraceStep;

/**
 * The one place where run.mcap reads what the engine believed from an iteration's step: trace.jsonl's
 * {@code belief}, {@code mapDelta} and {@code reason} (docs/report.md), written only when they changed.
 * Each pose the step carries is new (the tracer writes it only when it moved). A step with no belief at all (the robot process, which cannot see the engine's) falls back to the
 * GPS fix and inertial-unit heading the engine read, new when it changed to the millimetre or
 * milliradian (as trace.jsonl writes numbers).
 */
final class BeliefFields {

    private long lastX = Long.MIN_VALUE;
    private long lastY;
    private long lastHeading;
    /** Whether the steps carry the engine's belief (the one-process mission): then only it is used. */
    private boolean engineBelief;

    /**
     * @param s   the step
     * @param out receives x (m), y (m), heading (rad) when there is a new belief
     * @return whether the step brings a belief other than the last one
     */
    boolean newPose(TraceStep s, double[] out) {
        TraceBelief belief = s.belief();
        if (belief != null) {
            engineBelief = true;
            if (belief.pose() == null) {
                return false;
            }
            System.arraycopy(belief.pose(), 0, out, 0, 3); // trace.jsonl wrote it because it changed
            return true;
        }
        if (engineBelief || Double.isNaN(s.gpsXM()) || Double.isNaN(s.gpsYM()) || Double.isNaN(s.yawRad())) {
            return false;
        }
        return take(s.gpsXM(), s.gpsYM(), s.yawRad(), out);
    }

    private boolean take(double xM, double yM, double headingRad, double[] out) {
        long x = Math.round(xM * 1000);
        long y = Math.round(yM * 1000);
        long heading = Math.round(headingRad * 1000);
        if (x == lastX && y == lastY && heading == lastHeading) {
            return false;
        }
        lastX = x;
        lastY = y;
        lastHeading = heading;
        out[0] = xM;
        out[1] = yM;
        out[2] = headingRad;
        return true;
    }

    /**
     * @param s the step
     * @return the occupancy-map cells that changed in this step as {ix, iy, state, ...} (sorted by iy, ix), or null
     */
    int[] mapDelta(TraceStep s) {
        return s.belief() == null ? null : s.belief().mapDelta();
    }

    /**
     * @param s the step
     * @return why ObstacleAvoidance replaced a command or a checkpoint was declared unreachable, or null
     */
    String reason(TraceStep s) {
        return s.belief() == null ? null : s.belief().reason();
    }
}
