package org.proactiverobotics.engine;

import java.util.Arrays;

/**
 * The paper's CommandArray: a 1×n array where each scenario enters its suggestion at its own
 * slot (given by the engine at start, {@link RuleContext#suggest}); the decision scenario reads
 * it in {@link PriorityArray} order.
 * Used from the engine thread only.
 */
public final class CommandArray {

    private Suggestion[] slots;

    /** For Gson, which then sets the fields from the saved JSON. */
    private CommandArray() {
        this(0);
    }

    CommandArray(int size) {
        this.slots = new Suggestion[size];
    }

    /** @return n, the number of slots */
    public int size() {
        return slots.length;
    }

    /**
     * Enters a suggestion, replacing what the slot held.
     *
     * @param slot      the scenario's slot, 0 to n-1
     * @param command   the command text
     * @param scenario  the scenario entering it
     * @param iteration the current iteration
     */
    public void enter(int slot, String command, String scenario, long iteration) {
        slots[checked(slot)] = new Suggestion(command, scenario, iteration);
    }

    /**
     * @param slot 0 to n-1
     * @return the slot's suggestion, or null when the slot is empty
     */
    public Suggestion get(int slot) {
        return slots[checked(slot)];
    }

    /** Empties one slot. */
    public void clear(int slot) {
        slots[checked(slot)] = null;
    }

    /** Empties every slot. */
    public void clear() {
        Arrays.fill(slots, null);
    }

    /** Grows to at least n slots (more scenarios than a saved state knew); never shrinks. */
    void ensureSize(int n) {
        if (n > slots.length) {
            slots = Arrays.copyOf(slots, n);
        }
    }

    private int checked(int slot) {
        if (slot < 0 || slot >= slots.length) {
            throw new IndexOutOfBoundsException("CommandArray slot " + slot + " is outside 0.." + (slots.length - 1));
        }
        return slot;
    }

    @Override
    public String toString() {
        return Arrays.toString(slots);
    }
}
