package org.proactiverobotics.app.foxglove;

import org.proactiverobotics.app.replay.TraceStep;

/**
 * The one place where run.mcap reads what the engine believed from an iteration's step (trace.jsonl's
 * {@code belief}, {@code mapDelta} and {@code reason}, docs/report.md). Until those fields reach
 * {@link TraceStep}, the belief is the GPS fix and inertial-unit heading the engine read, new when
 * it changed to the millimetre or milliradian (as trace.jsonl writes numbers), and there are no map
 * deltas nor reasons; once they do, only this class changes: a step's {@code belief} is new
 * whenever the step carries one (trace.jsonl writes it only when it changed).
 */
final class BeliefFields {

    private long lastX = Long.MIN_VALUE;
    private long lastY;
    private long lastHeading;

    /**
     * @param s   the step
     * @param out receives x (m), y (m), heading (rad) when there is a new belief
     * @return whether the step brings a belief other than the last one
     */
    boolean newPose(TraceStep s, double[] out) {
        if (Double.isNaN(s.gpsXM()) || Double.isNaN(s.gpsYM()) || Double.isNaN(s.yawRad())) {
            return false;
        }
        long x = Math.round(s.gpsXM() * 1000);
        long y = Math.round(s.gpsYM() * 1000);
        long heading = Math.round(s.yawRad() * 1000);
        if (x == lastX && y == lastY && heading == lastHeading) {
            return false;
        }
        lastX = x;
        lastY = y;
        lastHeading = heading;
        out[0] = s.gpsXM();
        out[1] = s.gpsYM();
        out[2] = s.yawRad();
        return true;
    }

    /**
     * @param s the step
     * @return the occupancy-map cells that changed in this step as {ix, iy, state} (sorted by iy, ix), or null
     */
    int[][] mapDelta(TraceStep s) {
        return null; // trace.jsonl schemaVersion 3's mapDelta, once TraceStep carries it
    }

    /**
     * @param s the step
     * @return why ObstacleAvoidance replaced a command or a checkpoint was declared unreachable, or null
     */
    String reason(TraceStep s) {
        return null; // trace.jsonl schemaVersion 3's reason, once TraceStep carries it
    }
}
