package org.proactiverobotics.engine;

import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.ServiceLoader;
import java.util.Set;
import java.util.TreeMap;

/**
 * The scenarios known by name, found with {@link ServiceLoader} (or given, for tests). Register
 * one as a service of the engine to replace the ServiceLoader lookup {@link StartUp} makes.
 */
public final class ScenarioRegistry {

    private final Map<String, Scenario> byName;

    private ScenarioRegistry(Iterable<? extends Scenario> scenarios) {
        Map<String, Scenario> map = new TreeMap<>();
        for (Scenario s : scenarios) {
            Scenario previous = map.put(s.name(), s);
            if (previous != null) {
                throw new IllegalStateException("two scenarios are named '" + s.name() + "': "
                        + previous.getClass().getName() + " and " + s.getClass().getName());
            }
        }
        this.byName = Collections.unmodifiableMap(map);
    }

    /** @return the scenarios listed in {@code META-INF/services/org.proactiverobotics.engine.Scenario} on the class path */
    public static ScenarioRegistry load() {
        ClassLoader loader = Thread.currentThread().getContextClassLoader();
        return load(loader != null ? loader : ScenarioRegistry.class.getClassLoader());
    }

    /** @return the scenarios the class loader's ServiceLoader finds */
    public static ScenarioRegistry load(ClassLoader loader) {
        return new ScenarioRegistry(ServiceLoader.load(Scenario.class, loader));
    }

    /** @return a registry of exactly these scenarios */
    public static ScenarioRegistry of(Scenario... scenarios) {
        return new ScenarioRegistry(List.of(scenarios));
    }

    /**
     * @param scenarios the scenarios, e.g. the built-in ones and those of plug-ins
     * @return a registry of exactly these scenarios
     * @throws IllegalStateException naming both classes when two share a name
     */
    public static ScenarioRegistry of(Iterable<? extends Scenario> scenarios) {
        return new ScenarioRegistry(scenarios);
    }

    /** @return the known scenario names, sorted */
    public Set<String> names() {
        return byName.keySet();
    }

    /**
     * @param name a scenario name
     * @return the scenario
     * @throws IllegalArgumentException naming the known scenarios when there is none of that name
     */
    public Scenario get(String name) {
        Scenario s = byName.get(name);
        if (s == null) {
            throw new IllegalArgumentException("unknown scenario '" + name + "'; known scenarios: " + names());
        }
        return s;
    }

    /**
     * @param names the scenarios to start, in order
     * @return a StartUp rule for them, checked now so that a typo fails before the engine runs
     * @throws IllegalArgumentException for an unknown name
     */
    public StartUp startUp(List<String> names) {
        names.forEach(this::get);
        return new StartUp(names);
    }

    /**
     * @param name a scenario name
     * @return a new meta-rule of that scenario
     * @throws IllegalStateException when the scenario gives no meta-rule, or one of another scenario
     */
    MetaRule metaRule(String name) {
        MetaRule meta = get(name).metaRule();
        if (meta == null || !name.equals(meta.scenario())) {
            throw new IllegalStateException("scenario '" + name + "' gave a meta-rule of scenario '"
                    + (meta == null ? null : meta.scenario()) + "'");
        }
        return meta;
    }
}
