package org.proactiverobotics.engine.navigation;

/**
 * A planned route: waypoints from the start to the goal, each leg a straight drive. Plain arrays,
 * so a rule that follows a route saves it with its state.
 *
 * @param xs     the waypoints' x, metres, from the start to the goal
 * @param ys     their y, metres
 * @param slackM   the room the route gives up against the planner's usual clearance, metres (0: none;
 *                 a tight route, through a gap the map shows narrower than it may be)
 * @param overSeen whether the route keeps to cells the rays have seen ({@link RoutePlanner#planOverSeen})
 */
public record Route(double[] xs, double[] ys, double slackM, boolean overSeen) {

    /** @return the route's length, metres */
    public double lengthM() {
        double sum = 0;
        for (int k = 1; k < xs.length; k++) {
            sum += Math.hypot(xs[k] - xs[k - 1], ys[k] - ys[k - 1]);
        }
        return sum;
    }

    /** @return how many waypoints, the start and the goal included */
    public int size() {
        return xs.length;
    }
}
