package org.proactiverobotics.engine.scenario.traffic;

import java.util.List;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.Scenario;

/**
 * The traffic scenario: in a world shared with other robots, gives way to what comes at the
 * robot head-on and waits for a busy recharge station. {@link WatchTraffic} watches every
 * iteration and hands over to {@link GiveWay} (back off, wait a time set by the robot's own id,
 * hand back) or {@link WaitForStation} (stop until the station is seen free or the longest wait ran out, hand back). It
 * suggests only while it acts; the strategy ranks it (below the collision monitor, above the
 * battery and the destination in a shared world's default).
 */
public final class YieldScenario implements Scenario {

    /** The scenario's name in configuration, strategies and records. */
    public static final String NAME = "Yield";

    @Override
    public String name() {
        return NAME;
    }

    /** Active from the start. */
    @Override
    public List<Rule> firstRules() {
        return List.of(new WatchTraffic());
    }
}
