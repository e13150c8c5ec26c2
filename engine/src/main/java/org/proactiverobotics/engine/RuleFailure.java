package org.proactiverobotics.engine;

import java.util.function.Supplier;

/**
 * A part of a rule that threw.
 *
 * @param iteration the iteration it happened in
 * @param rule      the rule's {@link Rule#name()}
 * @param scenario  the rule's scenario
 * @param part      the part that threw
 * @param message   the exception's type and message
 * @param cause     the exception, or null when the failure was loaded from a saved state
 */
public record RuleFailure(long iteration, String rule, String scenario, Part part, String message, Throwable cause) {

    /** Builds the record of a part that threw. */
    static RuleFailure of(long iteration, Rule rule, Part part, Throwable e) {
        String text = e.getMessage() == null ? e.getClass().getName() : e.getClass().getSimpleName() + ": " + e.getMessage();
        return new RuleFailure(iteration, safely(rule::name, rule.getClass().getSimpleName()),
                safely(rule::scenario, "?"), part, text, e);
    }

    /** A plug-in's name() or scenario() that throws must not turn one failure into the engine's. */
    private static String safely(Supplier<String> value, String fallback) {
        try {
            String v = value.get();
            return v == null ? fallback : v;
        } catch (RuntimeException e) {
            return fallback;
        }
    }

    @Override
    public String toString() {
        return "iteration " + iteration + ": " + scenario + "/" + rule + " failed in " + part + ": " + message;
    }
}
