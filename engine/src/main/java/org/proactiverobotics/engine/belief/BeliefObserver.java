package org.proactiverobotics.engine.belief;

import java.util.List;
import org.proactiverobotics.engine.tables.MapChunk;

/**
 * Told what the engine's scenarios believed in an iteration, for traces and replays. Register one
 * as an engine service ({@code BeliefObserver.class}); none is needed, and without one the
 * scenarios build no reason texts at all. Called on the engine thread during the iteration: keep
 * it quick, and copy what must outlive the call. Every method does nothing by default.
 */
public interface BeliefObserver {

    /**
     * The pose a scenario steered or vetted by in this iteration (today the newest GPS reading and
     * inertial-unit heading the engine read; a localiser's estimate later).
     *
     * @param iteration  the iteration
     * @param xM         x, metres
     * @param yM         y, metres
     * @param headingRad heading, radians (0 = +x, counter-clockwise)
     */
    default void pose(long iteration, double xM, double yM, double headingRad) {
    }

    /**
     * A route was planned (possibly the same as before) or dropped. Several scenarios may each
     * follow a route of their own: the robot follows the one of the scenario whose command wins.
     *
     * @param iteration the iteration
     * @param scenario  the scenario whose rule follows the route
     * @param xs        the waypoints' x, metres, from the robot to the goal; empty when the route was dropped
     *                  (valid during the call only)
     * @param ys        their y, metres
     */
    default void route(long iteration, String scenario, double[] xs, double[] ys) {
    }

    /**
     * Chunks of the occupancy map changed (as written to {@code occupancy_map}).
     *
     * @param iteration the iteration
     * @param chunks    the changed chunks, whole, with their new cells
     */
    default void mapChanged(long iteration, List<MapChunk> chunks) {
    }

    /**
     * The collision monitor replaced the command that would have won.
     *
     * @param iteration the iteration
     * @param reason    why, in words ({@code "vetoed DRIVE 0.50 0.50: obstacle 0.08 m away at 15°, within braking reach 0.11 m"})
     */
    default void vetoed(long iteration, String reason) {
    }

    /**
     * A scenario's route follower closed a narrow place on its map after the robot made no progress
     * there, and plans round it from now on.
     *
     * @param iteration the iteration
     * @param scenario  the scenario whose rule follows the route
     * @param reason    where and why, in words
     */
    default void wayClosed(long iteration, String scenario, String reason) {
    }

    /**
     * A checkpoint was declared unreachable: the mission ends there.
     *
     * @param iteration the iteration
     * @param seq       the checkpoint's place in the visiting order, from 0
     * @param reason    why, in words
     */
    default void checkpointUnreachable(long iteration, int seq, String reason) {
    }
}
