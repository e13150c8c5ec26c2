package org.proactiverobotics.app.foxglove;

import org.proactiverobotics.app.replay.TraceStep;

/**
 * The one place where run.mcap reads what the engine believed from an iteration's step (trace.jsonl's
 * {@code belief}, {@code mapDelta} and {@code reason}, docs/report.md). Until those fields
 * reach {@link TraceStep}, the belief is the GPS fix and inertial-unit heading the engine read, and
 * there are no map deltas nor reasons; once they do, only this class changes.
 */
final class BeliefFields {

    private BeliefFields() {
    }

    /**
     * @param s   the step
     * @param out receives x (m), y (m), heading (rad)
     * @return false when the engine had no pose to believe in this step
     */
    static boolean pose(TraceStep s, double[] out) {
        if (Double.isNaN(s.gpsXM()) || Double.isNaN(s.gpsYM()) || Double.isNaN(s.yawRad())) {
            return false;
        }
        out[0] = s.gpsXM();
        out[1] = s.gpsYM();
        out[2] = s.yawRad();
        return true;
    }

    /**
     * @param s the step
     * @return the occupancy-map cells that changed in this step as {ix, iy, state} (sorted by iy, ix), or null
     */
    static int[][] mapDelta(TraceStep s) {
        return null; // trace.jsonl schemaVersion 3's mapDelta, once TraceStep carries it
    }

    /**
     * @param s the step
     * @return why ObstacleAvoidance replaced a command or a checkpoint was declared unreachable, or null
     */
    static String reason(TraceStep s) {
        return null; // trace.jsonl schemaVersion 3's reason, once TraceStep carries it
    }
}
