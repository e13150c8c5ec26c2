package org.proactiverobotics.robot;

/** The mutable counters behind {@link RobotStats}; one controller thread writes them. */
final class StatsCounter {
    long controlSteps;
    long requestsAnswered;
    long readingsWritten;
    long readingsNotWritten;
    long failedCalls;
    long skippedCalls;
    long outages;
    long commandsExecuted;
    long commandsIgnored;
    long unknownRequests;
    long watchdogStops;
    long linkStops;
    long rowsPruned;

    RobotStats snapshot() {
        return new RobotStats(controlSteps, requestsAnswered, readingsWritten, readingsNotWritten, failedCalls,
                skippedCalls, outages, commandsExecuted, commandsIgnored, unknownRequests, watchdogStops, linkStops,
                rowsPruned);
    }
}
