package org.proactiverobotics.engine.scenario.decision;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.proactiverobotics.engine.tables.StrategyTable;

/**
 * The named strategies: PriorityArrays a user picks with {@code --strategy}. Slots are the
 * scenarios' default indexes: 0 ReachDestination, 1 BatteryMonitor, 2 ObstacleAvoidance.
 */
public final class Strategies {

    /** The default: obstacle avoidance over the battery over the destination. */
    public static final String SAFETY_FIRST = "safety-first";
    /** The destination over avoidance over the battery: a reckless robot, for comparison. */
    public static final String DESTINATION_FIRST = "destination-first";
    /** The battery over avoidance over the destination. */
    public static final String BATTERY_FIRST = "battery-first";

    private static final String[] SLOT_SCENARIOS = {"ReachDestination", "BatteryMonitor", "ObstacleAvoidance"};
    private static final Map<String, int[]> PRIORITIES = new LinkedHashMap<>();

    static {
        // priority per slot: {ReachDestination, BatteryMonitor, ObstacleAvoidance}
        PRIORITIES.put(SAFETY_FIRST, new int[] {1, 2, 3});
        PRIORITIES.put(DESTINATION_FIRST, new int[] {3, 1, 2});
        PRIORITIES.put(BATTERY_FIRST, new int[] {1, 3, 2});
    }

    private Strategies() {
    }

    /** @return the names, default first */
    public static Set<String> names() {
        return PRIORITIES.keySet();
    }

    /**
     * The rows of a named strategy.
     *
     * @param name one of {@link #names()}
     * @return its strategy-table rows
     * @throws IllegalArgumentException naming the known strategies when the name is unknown
     */
    public static List<StrategyTable.Entry> named(String name) {
        int[] priorities = PRIORITIES.get(name);
        if (priorities == null) {
            throw new IllegalArgumentException("unknown strategy '" + name + "'; known: " + String.join(", ", names()));
        }
        StrategyTable.Entry[] rows = new StrategyTable.Entry[priorities.length];
        for (int slot = 0; slot < priorities.length; slot++) {
            rows[slot] = new StrategyTable.Entry(slot, SLOT_SCENARIOS[slot], priorities[slot], name);
        }
        return List.of(rows);
    }
}
