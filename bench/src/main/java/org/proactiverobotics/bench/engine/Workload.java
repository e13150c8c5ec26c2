package org.proactiverobotics.bench.engine;

/**
 * The one workload every engine benchmark runs: a rule whose condition and action are these two
 * methods, on its own counter. The engine, Easy Rules and the plain loop all call exactly these.
 */
public final class Workload {

    private Workload() {
    }

    /** The rule's condition: true except on an impossible value, so the action runs every time. */
    public static boolean condition(long value) {
        return value != Long.MIN_VALUE;
    }

    /** The rule's action. */
    public static long action(long value) {
        return value + 1;
    }

    /** Sets every logger to WARN: logback's default (DEBUG to the console) would measure logging, not rules. */
    public static void quietLogs() {
        ((ch.qos.logback.classic.Logger) org.slf4j.LoggerFactory.getLogger(org.slf4j.Logger.ROOT_LOGGER_NAME))
                .setLevel(ch.qos.logback.classic.Level.WARN);
    }
}
