package org.proactiverobotics.engine;

import java.util.Arrays;
import java.util.Comparator;
import java.util.stream.IntStream;

/**
 * The paper's PriorityArray, the strategy: one priority per {@link CommandArray} slot; the
 * highest is read first. Used from the engine thread only.
 */
public final class PriorityArray {

    private int[] priorities;

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
        priorities[checked(slot)] = priority;
    }

    /** @return the slots, highest priority first; equal priorities in slot order */
    public int[] slotsByPriority() {
        return IntStream.range(0, priorities.length).boxed()
                .sorted(Comparator.comparingInt((Integer s) -> -priorities[s]).thenComparingInt(s -> s))
                .mapToInt(Integer::intValue).toArray();
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
