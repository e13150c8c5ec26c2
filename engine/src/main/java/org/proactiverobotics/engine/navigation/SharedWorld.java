package org.proactiverobotics.engine.navigation;

import java.util.Map;

/**
 * Whether the robot shares its world with other robots, which it knows only as its sensors see
 * them: obstacles that move. An engine service ({@code ctx.findService(SharedWorld.class)}), given
 * only to the engines of a world with several robots; absent, the robot is alone and every
 * scenario behaves as it always did (one-robot runs stay byte for byte the same).
 *
 * <p>In a shared world the map lets a cell go free again when rays see through it, however often
 * it was hit (a robot that stood there left), and a checkpoint is declared unreachable only after
 * {@link #noRouteMs()} of simulated time without a route, not the lone robot's 3 s (a robot
 * standing in the only door is not a wall).
 *
 * @param noRouteMs how long no plan may find a route before a checkpoint is unreachable, simulated ms
 */
public record SharedWorld(long noRouteMs) {

    /** The default wait for a route in a shared world: long enough for a robot in a door to charge and leave, simulated ms. */
    public static final long NO_ROUTE_MS = 60_000;

    /**
     * The shared memory's named value by which a rule that has found no route for a while asks the
     * mapping to let go of the cells that moved in (another robot stood there) and that the map still
     * holds occupied: a count, raised by one per request, so that the robot goes to look again.
     */
    public static final String LOOK_AGAIN = "lookAgain";

    /** The service as a fleet world's engines get it. */
    public static final SharedWorld DEFAULT = new SharedWorld(NO_ROUTE_MS);

    /**
     * Asks the mapping to look again ({@link #LOOK_AGAIN}): raises the count by one.
     *
     * @param values the shared memory's named values ({@code ctx.memory().values()})
     */
    public static void askToLookAgain(Map<String, String> values) {
        values.put(LOOK_AGAIN, Integer.toString(lookAgainAsked(values) + 1));
    }

    /**
     * @param values the shared memory's named values
     * @return how often a rule asked to look again ({@link #LOOK_AGAIN}), 0 when none did
     */
    public static int lookAgainAsked(Map<String, String> values) {
        String asked = values.get(LOOK_AGAIN);
        return asked == null ? 0 : Integer.parseInt(asked);
    }

    /** Checks the wait. */
    public SharedWorld {
        if (noRouteMs < 0) {
            throw new IllegalArgumentException("noRouteMs must be >= 0: " + noRouteMs);
        }
    }
}
