package org.proactiverobotics.e2e;

import org.junit.jupiter.api.extension.AfterAllCallback;
import org.junit.jupiter.api.extension.AfterEachCallback;
import org.junit.jupiter.api.extension.BeforeAllCallback;
import org.junit.jupiter.api.extension.BeforeEachCallback;
import org.junit.jupiter.api.extension.ExtensionContext;

/**
 * Ends every process a test started through {@link StartedProcesses}, with its tree, once the
 * test is over, however it ended (passed, failed, threw, timed out: JUnit calls the after
 * callbacks on every path); what a class started before its tests ({@code @BeforeAll}) is ended
 * after them. Registered for every test of this module (junit-platform.properties turns on the
 * extensions listed in META-INF/services), so that no test has to remember it.
 */
public final class EndsStartedProcesses implements BeforeAllCallback, AfterAllCallback, BeforeEachCallback,
        AfterEachCallback {

    private static final ExtensionContext.Namespace NAMESPACE = ExtensionContext.Namespace.create(EndsStartedProcesses.class);
    private static final String MARK = "mark";

    @Override
    public void beforeAll(ExtensionContext context) {
        context.getStore(NAMESPACE).put(MARK, StartedProcesses.mark());
    }

    @Override
    public void beforeEach(ExtensionContext context) {
        context.getStore(NAMESPACE).put(MARK, StartedProcesses.mark());
    }

    @Override
    public void afterEach(ExtensionContext context) {
        endSinceMark(context);
    }

    @Override
    public void afterAll(ExtensionContext context) {
        endSinceMark(context);
    }

    private static void endSinceMark(ExtensionContext context) {
        Integer mark = context.getStore(NAMESPACE).get(MARK, Integer.class);
        StartedProcesses.endStartedSince(mark == null ? 0 : mark);
    }
}
