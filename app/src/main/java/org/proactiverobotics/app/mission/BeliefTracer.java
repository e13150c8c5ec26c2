package org.proactiverobotics.app.mission;

import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.proactiverobotics.app.replay.TraceBelief;
import org.proactiverobotics.app.replay.TraceEvent;
import org.proactiverobotics.engine.belief.BeliefObserver;
import org.proactiverobotics.engine.scenario.avoidance.ObstacleAvoidanceScenario;
import org.proactiverobotics.engine.tables.MapChunk;
import org.proactiverobotics.engine.tables.OccupancyMap;

/**
 * Gathers what the engine's scenarios said they believed, between two trace lines, and hands it
 * over as deltas ({@link #take}): the pose when it moved by a millimetre or a milliradian, the route
 * of the scenario whose command won when its waypoints changed, the map's cells whose state changed (kept in a mirror of the map's
 * states, one byte per cell), the veto's reason at an iteration ObstacleAvoidance won, a place a
 * route follower closed (reason), and a checkpoint declared unreachable (reason and event). It also keeps the newest pose the engine
 * had, for the pose error ({@link #hasPose}). Engine thread only.
 */
final class BeliefTracer implements BeliefObserver {

    private static final int CHUNK = OccupancyMap.CHUNK_CELLS;

    // the newest of the iteration, not yet written
    private boolean poseSaid;
    /** Whether any scenario has told of a pose yet: from then on {@link #pose} is the engine's newest. */
    private boolean hasPose;
    private final double[] pose = new double[3];
    /** The newest route each scenario told of, {x0, y0, x1, y1, ...}: the winner's is the one the robot follows. */
    private final Map<String, double[]> routes = new HashMap<>();
    private long vetoIteration = -1;
    private String vetoReason;
    private String unreachableReason;
    private int unreachableIndex = -1;
    /** A place a route follower closed since the last line: "scenario reason". */
    private String closedReason;
    /** The map's cell states as the trace has them so far, by chunk. */
    private final Map<Long, byte[]> mirror = new HashMap<>();
    /** Changed cells not yet written, keyed for sorting by (iy, ix) ({@link #key}). */
    private long[] changed = new long[256];
    private int changedCount;
    // what the trace holds: only a change is written
    private final long[] writtenPose = {Long.MIN_VALUE, Long.MIN_VALUE, Long.MIN_VALUE};
    private double[] writtenRoute = new double[0];

    @Override
    public void pose(long iteration, double xM, double yM, double headingRad) {
        poseSaid = true;
        hasPose = true;
        pose[0] = xM;
        pose[1] = yM;
        pose[2] = headingRad;
    }

    @Override
    public void route(long iteration, String scenario, double[] xs, double[] ys) {
        double[] r = new double[2 * xs.length];
        for (int k = 0; k < xs.length; k++) {
            r[2 * k] = xs[k];
            r[2 * k + 1] = ys[k];
        }
        routes.put(scenario, r);
    }

    @Override
    public void mapChanged(long iteration, List<MapChunk> chunks) {
        for (MapChunk c : chunks) {
            long at = chunkKey(c.chunkX(), c.chunkY());
            byte[] known = mirror.computeIfAbsent(at, k -> new byte[CHUNK * CHUNK]);
            byte[] cells = c.cells();
            for (int q = 0; q < cells.length; q++) {
                byte state = cells[q] >= OccupancyMap.OCCUPIED ? OccupancyMap.OCCUPIED : cells[q];
                if (state != known[q]) {
                    known[q] = state;
                    add(key(c.chunkX() * CHUNK + q % CHUNK, c.chunkY() * CHUNK + q / CHUNK));
                }
            }
        }
    }

    @Override
    public void vetoed(long iteration, String reason) {
        vetoIteration = iteration;
        vetoReason = reason;
    }

    @Override
    public void wayClosed(long iteration, String scenario, String reason) {
        closedReason = scenario + " " + reason;
    }

    @Override
    public void checkpointUnreachable(long iteration, int seq, String reason) {
        unreachableIndex = seq;
        unreachableReason = reason;
    }

    /** @return whether the engine has had a pose yet (it has none before its first GPS and heading readings) */
    boolean hasPose() {
        return hasPose;
    }

    /** @return the newest pose's x the engine had, metres (meaningful once {@link #hasPose}) */
    double poseXM() {
        return pose[0];
    }

    /** @return the newest pose's y, metres */
    double poseYM() {
        return pose[1];
    }

    /** @return the newest pose's heading, radians */
    double poseHeadingRad() {
        return pose[2];
    }

    /** Sorts as (iy, ix): the row in the high half, the column with its sign bit flipped so that it sorts as signed. */
    private static long key(int ix, int iy) {
        return ((long) iy << 32) | ((ix ^ 0x80000000) & 0xffffffffL);
    }

    /** A chunk's key in {@link #mirror}: its column in the high half, its row in the low. */
    private static long chunkKey(int cx, int cy) {
        return ((long) cx << 32) ^ (cy & 0xffffffffL);
    }

    private void add(long k) {
        if (changedCount == changed.length) {
            changed = Arrays.copyOf(changed, 2 * changed.length);
        }
        changed[changedCount++] = k;
    }

    /**
     * The belief for the trace line of an iteration, and forgets what it hands over.
     *
     * @param iteration the iteration the line records
     * @param winner    the scenario whose command won it
     * @param events    where a checkpoint declared unreachable goes
     * @return the changes since the last line, or null when there are none
     */
    TraceBelief take(long iteration, String winner, List<TraceEvent> events) {
        double[] newPose = null;
        if (poseSaid) {
            poseSaid = false;
            long x = Math.round(pose[0] * 1000.0);
            long y = Math.round(pose[1] * 1000.0);
            long h = Math.round(pose[2] * 1000.0);
            if (x != writtenPose[0] || y != writtenPose[1] || h != writtenPose[2]) {
                writtenPose[0] = x;
                writtenPose[1] = y;
                writtenPose[2] = h;
                newPose = pose.clone();
            }
        }
        double[] newRoute = null;
        double[] followed = routes.get(winner); // a winner without a route (a veto, a stop) leaves the last one shown
        if (followed != null && followed != writtenRoute && !sameAsWritten(followed)) {
            writtenRoute = followed;
            newRoute = followed;
        }
        int[] delta = null;
        if (changedCount > 0) {
            Arrays.sort(changed, 0, changedCount);
            int[] d = new int[3 * changedCount];
            int m = 0;
            for (int k = 0; k < changedCount; k++) {
                if (k > 0 && changed[k] == changed[k - 1]) {
                    continue;
                }
                int iy = (int) (changed[k] >> 32);
                int ix = (int) changed[k] ^ 0x80000000;
                d[m++] = ix;
                d[m++] = iy;
                d[m++] = state(ix, iy);
            }
            delta = m == d.length ? d : Arrays.copyOf(d, m);
            changedCount = 0;
        }
        String reason = null;
        if (vetoReason != null && vetoIteration == iteration && ObstacleAvoidanceScenario.NAME.equals(winner)) {
            reason = vetoReason; // it replaced the command only when it won
        }
        vetoReason = null;
        if (closedReason != null) {
            reason = reason == null ? closedReason : reason + "; " + closedReason;
            closedReason = null;
        }
        if (unreachableReason != null) {
            reason = reason == null ? unreachableReason : reason + "; " + unreachableReason;
            events.add(TraceEvent.checkpointUnreachable(unreachableIndex));
            unreachableReason = null;
        }
        if (newPose == null && newRoute == null && delta == null && reason == null) {
            return null;
        }
        return new TraceBelief(newPose, newRoute, delta, reason);
    }

    /** Whether a route equals the one written, to the millimetre the trace writes. */
    private boolean sameAsWritten(double[] r) {
        if (r.length != writtenRoute.length) {
            return false;
        }
        for (int k = 0; k < r.length; k++) {
            if (Math.round(r[k] * 1000.0) != Math.round(writtenRoute[k] * 1000.0)) {
                return false;
            }
        }
        return true;
    }

    private byte state(int ix, int iy) {
        byte[] c = mirror.get(chunkKey(Math.floorDiv(ix, CHUNK), Math.floorDiv(iy, CHUNK)));
        return c[Math.floorMod(iy, CHUNK) * CHUNK + Math.floorMod(ix, CHUNK)];
    }
}
