package org.proactiverobotics.engine;

import java.util.Arrays;

/**
 * The paper's PriorityArray, the strategy: one priority per {@link CommandArray} slot; the
 * highest is read first. Used from the engine thread only.
 */
public final class PriorityArray {

    private int[] priorities;
    /** The slots by priority, computed when first asked after a change (read every iteration, set rarely). */
    private transient int[] order;

    /** For Gson, which then sets the fields from the saved JSON. */
    private PriorityArray() {
        this(0);
    }

    PriorityArray(int size) {
        this.priorities = new int[size];
    }

    /** @return n, the number of slots */
    public int size() {
        return priorities.length;
    }

    /** @return the priority of a slot (0 until set) */
    public int get(int slot) {
        return priorities[checked(slot)];
    }

    /** Sets the priority of a slot. */
    public void set(int slot, int priority) {
        if (priorities[checked(slot)] != priority) {
            priorities[slot] = priority;
            order = null;
        }
    }

    /**
     * @return the slots, highest priority first, equal priorities in slot order; the same array
     *         until a priority changes (read it, don't modify it)
     */
    public int[] slotsByPriority() {
        int[] sorted = order;
        if (sorted == null) {
            sorted = new int[priorities.length];
            for (int slot = 0; slot < sorted.length; slot++) { // insertion sort: n is a handful of slots, and stable
                int j = slot;
                while (j > 0 && priorities[sorted[j - 1]] < priorities[slot]) {
                    sorted[j] = sorted[j - 1];
                    j--;
                }
                sorted[j] = slot;
            }
            order = sorted;
        }
        return sorted;
    }

    /** Grows to at least n slots (more scenarios than a saved state knew); never shrinks. */
    void ensureSize(int n) {
        if (n > priorities.length) {
            priorities = Arrays.copyOf(priorities, n);
            order = null;
        }
    }

    private int checked(int slot) {
        if (slot < 0 || slot >= priorities.length) {
            throw new IndexOutOfBoundsException("PriorityArray slot " + slot + " is outside 0.." + (priorities.length - 1));
        }
        return slot;
    }

    @Override
    public String toString() {
        return Arrays.toString(priorities);
    }
}
