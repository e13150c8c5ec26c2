package org.proactiverobotics.engine.tables;

/**
 * A checkpoint of the mission ({@code checkpoints} row).
 *
 * @param seq     its place in the visiting order, from 0
 * @param xM      x, metres
 * @param yM      y, metres
 * @param radiusM how close counts as reached, metres
 * @param reached whether the engine has marked it reached
 */
public record Checkpoint(int seq, double xM, double yM, double radiusM, boolean reached) {
}
