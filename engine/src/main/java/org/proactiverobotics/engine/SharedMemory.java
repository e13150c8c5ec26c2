package org.proactiverobotics.engine;

import java.util.Collections;
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
    /** The named value that holds the command of the last decision, as "scenario command". */
    public static final String LAST_DECISION = "lastDecision";

    private final CommandArray commandArray;
    private final PriorityArray priorityArray;
    private final Map<String, String> values = new LinkedHashMap<>();
    /** Each suggesting scenario's CommandArray slot, given by the engine at start; absent in states saved before slots were given. */
    private Map<String, Integer> slots = new LinkedHashMap<>();

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

    /** @return each suggesting scenario's CommandArray slot, by scenario name, in the order given (read only) */
    public Map<String, Integer> slots() {
        return Collections.unmodifiableMap(slots);
    }

    /**
     * @param scenario a scenario's name
     * @return its CommandArray slot, or -1 when it has none (it does not suggest)
     */
    public int slotOf(String scenario) {
        Integer slot = slots.get(scenario);
        return slot == null ? -1 : slot;
    }

    /**
     * Gives scenarios their slots, keeping every slot already given (saved states stay readable):
     * a scenario without one gets its preferred slot when that is free, else the lowest free
     * slot. The arrays grow to hold every slot.
     *
     * @param preferred scenario names with their preferred slot (-1: none), in the order to give them
     */
    void assignSlots(Map<String, Integer> preferred) {
        if (slots == null) {
            slots = new LinkedHashMap<>(); // a state saved with "slots": null
        }
        for (Map.Entry<String, Integer> e : preferred.entrySet()) {
            if (slots.containsKey(e.getKey())) {
                continue;
            }
            int slot = e.getValue();
            if (slot < 0 || slots.containsValue(slot)) {
                slot = 0;
                while (slots.containsValue(slot)) {
                    slot++;
                }
            }
            slots.put(e.getKey(), slot);
        }
        int needed = slots.values().stream().mapToInt(Integer::intValue).max().orElse(-1) + 1;
        commandArray.ensureSize(needed);
        priorityArray.ensureSize(needed);
    }

    @Override
    public String toString() {
        return "SharedMemory{commands=" + commandArray + ", priorities=" + priorityArray + ", values=" + values
                + ", slots=" + slots + "}";
    }
}
