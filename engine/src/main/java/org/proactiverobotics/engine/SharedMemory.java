package org.proactiverobotics.engine;

import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The memory scenarios share, saved with the engine state at the end of every iteration: the
 * decision scenario's {@link CommandArray} and {@link PriorityArray}, and a small map of named
 * values (store JSON or plain text). Used from the engine thread only.
 */
public final class SharedMemory {

    /** The default n of the CommandArray and PriorityArray. */
    public static final int DEFAULT_SLOTS = 8;

    private final CommandArray commandArray;
    private final PriorityArray priorityArray;
    private final Map<String, String> values = new LinkedHashMap<>();

    /** For Gson, which then sets the fields from the saved JSON. */
    private SharedMemory() {
        this(DEFAULT_SLOTS);
    }

    /** @param slots n, the size of the CommandArray and the PriorityArray */
    public SharedMemory(int slots) {
        if (slots < 1) {
            throw new IllegalArgumentException("slots must be at least 1: " + slots);
        }
        this.commandArray = new CommandArray(slots);
        this.priorityArray = new PriorityArray(slots);
    }

    /** @return the CommandArray */
    public CommandArray commandArray() {
        return commandArray;
    }

    /** @return the PriorityArray */
    public PriorityArray priorityArray() {
        return priorityArray;
    }

    /** @return the named values, in insertion order; mutable */
    public Map<String, String> values() {
        return values;
    }

    @Override
    public String toString() {
        return "SharedMemory{commands=" + commandArray + ", priorities=" + priorityArray + ", values=" + values + "}";
    }
}
