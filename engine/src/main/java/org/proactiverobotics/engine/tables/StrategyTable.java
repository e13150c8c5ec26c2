package org.proactiverobotics.engine.tables;

import java.util.List;

/**
 * The strategy ({@code strategy} rows): the PriorityArray, one priority per CommandArray slot,
 * and each slot's suggestion time-out.
 */
public interface StrategyTable {

    /**
     * One row of the strategy.
     *
     * @param slot     the CommandArray slot
     * @param scenario the scenario whose slot it is (for people reading the table)
     * @param priority higher is read first
     * @param name      the strategy's name
     * @param timeoutMs how long a suggestion in this slot is obeyed, simulated milliseconds since
     *                  it was entered (twist_mux style); 0 = only in the iteration it was entered
     */
    record Entry(int slot, String scenario, int priority, String name, long timeoutMs) {

        /** Checks the time-out. */
        public Entry {
            if (timeoutMs < 0) {
                throw new IllegalArgumentException("slot " + slot + ": timeoutMs must be >= 0: " + timeoutMs);
            }
        }

        /** A row whose suggestions live one iteration (time-out 0). */
        public Entry(int slot, String scenario, int priority, String name) {
            this(slot, scenario, priority, name, 0);
        }

        /** @return this row with another time-out, simulated milliseconds */
        public Entry withTimeoutMs(long timeoutMs) {
            return new Entry(slot, scenario, priority, name, timeoutMs);
        }
    }

    /** @return the current strategy, by slot */
    List<Entry> read();

    /** Replaces the strategy in one transaction; the next iteration obeys it. */
    void write(List<Entry> entries);
}
