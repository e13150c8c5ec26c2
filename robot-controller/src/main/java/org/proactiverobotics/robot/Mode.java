package org.proactiverobotics.robot;

import java.util.Optional;

/**
 * What the robot is doing: the paper's {@code mode} enumeration, switched on every control
 * step. Every mode but {@link #WAITING} is also a command the engine can send (see
 * {@link Command} for the grammar); speeds are wheel speeds in metres per second.
 */
public enum Mode {
    /** Before the first command: stopped, waiting for instructions. Not a command. */
    WAITING(-1),
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

    Mode(int arguments) {
        this.arguments = arguments;
    }

    /** @return how many numbers the command takes, or -1 when this mode is not a command */
    public int arguments() {
        return arguments;
    }

    /** @return whether the engine can send this mode as a command */
    public boolean isCommand() {
        return arguments >= 0;
    }

    /**
     * The command mode of this exact name (upper case).
     *
     * @param name a word of a command
     * @return the mode, or empty when no command has that name
     */
    public static Optional<Mode> command(String name) {
        for (Mode m : values()) {
            if (m.isCommand() && m.name().equals(name)) {
                return Optional.of(m);
            }
        }
        return Optional.empty();
    }
}
