package org.proactiverobotics.app.deploy;

import java.nio.file.Path;
import picocli.CommandLine.Option;

/**
 * The options the two long-running processes ({@code engine} and {@code robot}) share: which
 * robot, how often to log, and the health-check file. A picocli mixin, beside {@link DbOptions}.
 */
public final class ProcessOptions {

    @Option(names = "--robot-id", paramLabel = "N", defaultValue = "1",
            description = "The robot's id in every table. Default: ${DEFAULT-VALUE}.")
    private int robotId;

    @Option(names = "--log-every", paramLabel = "N", defaultValue = "500",
            description = "One INFO line every N engine iterations or robot steps (details at DEBUG:"
                    + " PROACTIVE_LOG_LEVEL=DEBUG). Default: ${DEFAULT-VALUE}.")
    private long logEvery;

    @Option(names = "--heartbeat", paramLabel = "FILE",
            description = "A file touched every few seconds while the process runs (for a container health check).")
    private Path heartbeat;

    /** @return the robot's id */
    public int robotId() {
        return robotId;
    }

    /** @return one INFO line every this many iterations or steps */
    public long logEvery() {
        return logEvery;
    }

    /** @return the health-check file, touched while the process runs (none when not asked for) */
    public Heartbeat heartbeat() {
        return new Heartbeat(heartbeat);
    }

    /** @return what is wrong with these options, or null */
    public String problem() {
        if (robotId < 0) {
            return "--robot-id must be >= 0: " + robotId;
        }
        if (logEvery < 1) {
            return "--log-every must be >= 1: " + logEvery;
        }
        return null;
    }
}
