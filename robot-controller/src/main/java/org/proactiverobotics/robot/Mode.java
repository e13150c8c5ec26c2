package org.proactiverobotics.robot;

import java.util.Optional;
import org.proactiverobotics.protocol.CommandWord;

/**
 * What the robot is doing: the paper's {@code mode} enumeration, switched on every control
 * step. Every mode but {@link #WAITING} is also a command the engine can send (see
 * {@link Command} for the grammar); speeds are wheel speeds in metres per second.
 */
public enum Mode {
    /** Before the first command: stopped, waiting for instructions. Not a command. */
    WAITING(null),
    /** {@link CommandWord#STOP}. */
    STOP(CommandWord.STOP),
    /** {@link CommandWord#DRIVE}. */
    DRIVE(CommandWord.DRIVE),
    /** {@link CommandWord#FORWARD}. */
    FORWARD(CommandWord.FORWARD),
    /** {@link CommandWord#TURN_LEFT}. */
    TURN_LEFT(CommandWord.TURN_LEFT),
    /** {@link CommandWord#TURN_RIGHT}. */
    TURN_RIGHT(CommandWord.TURN_RIGHT),
    /** {@link CommandWord#RECHARGE}. */
    RECHARGE(CommandWord.RECHARGE);

    private final CommandWord word;

    Mode(CommandWord word) {
        this.word = word;
    }

    /** @return how many numbers the command takes, or -1 when this mode is not a command */
    public int arguments() {
        return word == null ? -1 : word.arguments();
    }

    /** @return whether the engine can send this mode as a command */
    public boolean isCommand() {
        return word != null;
    }

    /**
     * The command mode of this exact name (upper case).
     *
     * @param name a word of a command
     * @return the mode, or empty when no command has that name
     */
    public static Optional<Mode> command(String name) {
        return CommandWord.of(name).map(w -> valueOf(w.name()));
    }
}
