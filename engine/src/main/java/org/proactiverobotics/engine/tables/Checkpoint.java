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

    /** A checkpoint not marked unreachable. */
    public Checkpoint(int seq, double xM, double yM, double radiusM, boolean reached) {
        this(seq, xM, yM, radiusM, reached, false);
    }
}
