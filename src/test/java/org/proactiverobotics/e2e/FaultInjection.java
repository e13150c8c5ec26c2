package org.proactiverobotics.e2e;

import java.lang.reflect.InvocationHandler;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Proxy;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.BooleanSupplier;
import java.util.function.UnaryOperator;
import org.proactiverobotics.engine.tables.EngineTables;
import org.proactiverobotics.engine.tables.EngineComments;
import org.proactiverobotics.engine.tables.MissionTables;
import org.proactiverobotics.engine.tables.PoseEstimateTable;
import org.proactiverobotics.engine.tables.SensorReadings;
import org.proactiverobotics.engine.tables.SensorRequests;
import org.proactiverobotics.engine.tables.StrategyTable;

/**
 * Wraps the engine's tables for end-to-end fault injection: while {@code active} says so, every
 * call made from one scenario's package throws (a database refusing that scenario's
 * statements); every command sent is recorded.
 */
final class FaultInjection implements UnaryOperator<EngineTables> {

    /** One engine_comments row as the engine sent it. */
    record Sent(long iteration, long simTimeMs, String scenario, String command) {
    }

    private static final StackWalker STACK = StackWalker.getInstance(StackWalker.Option.RETAIN_CLASS_REFERENCE);

    private final String failingPackage;
    private final BooleanSupplier active;
    final List<Sent> sent = new CopyOnWriteArrayList<>();

    /**
     * @param scenarioClass a class of the scenario to fail (its package is what fails)
     * @param active        whether the fault is on now
     */
    FaultInjection(Class<?> scenarioClass, BooleanSupplier active) {
        this.failingPackage = scenarioClass.getPackageName();
        this.active = active;
    }

    @Override
    public EngineTables apply(EngineTables t) {
        EngineComments recorded = (iteration, simTimeMs, scenario, command) -> {
            t.comments().send(iteration, simTimeMs, scenario, command);
            sent.add(new Sent(iteration, simTimeMs, scenario, command));
        };
        return new EngineTables(wrap(SensorReadings.class, t.readings()), wrap(SensorRequests.class, t.requests()),
                wrap(MissionTables.class, t.mission()), wrap(StrategyTable.class, t.strategy()),
                wrap(EngineComments.class, recorded), t.pruneHistory(),
                wrap(PoseEstimateTable.class, t.poses()));
    }

    private <T> T wrap(Class<T> type, T target) {
        InvocationHandler handler = (proxy, method, args) -> {
            if (method.getDeclaringClass() != Object.class && active.getAsBoolean() && calledFromFailingScenario()) {
                throw new IllegalStateException("injected fault: the database refuses " + failingPackage);
            }
            try {
                return method.invoke(target, args);
            } catch (InvocationTargetException e) {
                throw e.getCause();
            }
        };
        return type.cast(Proxy.newProxyInstance(type.getClassLoader(), new Class<?>[] {type}, handler));
    }

    private boolean calledFromFailingScenario() {
        return STACK.walk(frames -> frames.anyMatch(f -> f.getDeclaringClass().getPackageName().equals(failingPackage)));
    }
}
