package org.proactiverobotics.app.deploy;

import ch.qos.logback.classic.Level;
import ch.qos.logback.classic.LoggerContext;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The log level of the long-running commands: their status lines are INFO, while the one-shot
 * commands keep the jar's quiet WARN. The environment variable PROACTIVE_LOG_LEVEL (DEBUG for the
 * details) overrides both.
 */
public final class ServiceLogging {

    private ServiceLogging() {
    }

    /** Sets the root level to INFO unless PROACTIVE_LOG_LEVEL says otherwise. */
    public static void statusLines() {
        String wanted = System.getenv("PROACTIVE_LOG_LEVEL");
        if (wanted != null && !wanted.isBlank()) {
            return; // logback.xml already took it
        }
        if (LoggerFactory.getILoggerFactory() instanceof LoggerContext context) {
            context.getLogger(Logger.ROOT_LOGGER_NAME).setLevel(Level.INFO);
            context.getLogger("com.zaxxer.hikari").setLevel(Level.WARN); // pool start and stop lines are noise
        }
    }
}
