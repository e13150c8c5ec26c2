package org.proactiverobotics.engine.tables;

/**
 * A checkpoint of the mission ({@code checkpoints} row).
 *
 * @param seq         its place in the visiting order, from 0
 * @param xM          x, metres
 * @param yM          y, metres
 * @param radiusM     how close counts as reached, metres
 * @param reached     whether the engine has marked it reached
 * @param unreachable whether the engine has found that no route leads to it (the mission ends)
 */
public record Checkpoint(int seq, double xM, double yM, double radiusM, boolean reached, boolean unreachable) {

    /**
     * The engine counts a checkpoint reached inside this share of its radius, so that the simulator,
     * which judges the true position, agrees even when the GPS errs by several centimetres: at 0.8,
     * realistic noise (5 cm) marked checkpoints the robot had passed 0.25 m from (radius 0.25 m).
     */
    public static final double REACHED_FRACTION = 0.5;

    /**
     * @param radiusM a checkpoint's radius, metres
     * @return how far from its centre a route to it may end, metres: a little inside where it counts as reached
     */
    public static double routeReachM(double radiusM) {
        return radiusM * REACHED_FRACTION * 0.9;
    }

    /** A checkpoint not marked unreachable. */
    public Checkpoint(int seq, double xM, double yM, double radiusM, boolean reached) {
        this(seq, xM, yM, radiusM, reached, false);
    }
}
