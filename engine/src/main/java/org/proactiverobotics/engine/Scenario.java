package org.proactiverobotics.engine;

/**
 * A proactive scenario: a named set of rules with one goal, started by its {@link MetaRule}. A
 * scenario knows nothing of the others.
 *
 * <p>Plug one in without editing the engine: implement this interface (public, with a public
 * no-argument constructor) and list the class in
 * {@code META-INF/services/org.proactiverobotics.engine.Scenario}; {@link StartUp} then finds
 * it by {@link #name()}.
 */
public interface Scenario {

    /** @return the unique name configuration selects the scenario by, e.g. {@code "BatteryMonitor"} */
    String name();

    /** @return a new meta-rule that starts the scenario */
    MetaRule metaRule();
}
