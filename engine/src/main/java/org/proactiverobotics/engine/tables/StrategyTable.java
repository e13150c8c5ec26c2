package org.proactiverobotics.engine.tables;

import java.util.List;

/** The strategy ({@code strategy} rows): the PriorityArray, one priority per CommandArray slot. */
public interface StrategyTable {

    /**
     * One row of the strategy.
     *
     * @param slot     the CommandArray slot
     * @param scenario the scenario whose slot it is (for people reading the table)
     * @param priority higher is read first
     * @param name     the strategy's name
     */
    record Entry(int slot, String scenario, int priority, String name) {
    }

    /** @return the current strategy, by slot */
    List<Entry> read();

    /** Replaces the strategy in one transaction; the next iteration obeys it. */
    void write(List<Entry> entries);
}
