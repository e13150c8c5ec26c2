package org.proactiverobotics.protocol;

import java.util.Optional;

/**
 * The first word of a command ({@code engine_comments.command}), with how many numbers follow it;
 * speeds are wheel speeds in metres per second. The engine writes them, the robot executes them.
 */
public enum CommandWord {
    /** {@code STOP}: both wheels at 0. */
    STOP(0),
    /** {@code DRIVE <left_mps> <right_mps>}: each wheel in [-max, max]. */
    DRIVE(2),
    /** {@code FORWARD <mps>}: both wheels at mps, in [-max, max] (negative backs up). */
    FORWARD(1),
    /** {@code TURN_LEFT <mps>}: turn on the spot counter-clockwise, wheels at -mps / +mps, mps in [0, max]. */
    TURN_LEFT(1),
    /** {@code TURN_RIGHT <mps>}: turn on the spot clockwise, wheels at +mps / -mps, mps in [0, max]. */
    TURN_RIGHT(1),
    /** {@code RECHARGE}: stop and charge; charging only starts at the recharge station. */
    RECHARGE(0);

    private final int arguments;

    CommandWord(int arguments) {
        this.arguments = arguments;
    }

    /** @return how many numbers follow the word */
    public int arguments() {
        return arguments;
    }

    /**
     * @param word a command's first word, exactly (upper case)
     * @return the word, or empty when no command starts so
     */
    public static Optional<CommandWord> of(String word) {
        for (CommandWord w : values()) {
            if (w.name().equals(word)) {
                return Optional.of(w);
            }
        }
        return Optional.empty();
    }
}
