package org.proactiverobotics.robot;

/**
 * What a controller has done and failed to do so far; nothing the robot drops goes uncounted.
 *
 * @param controlSteps       control steps run
 * @param requestsAnswered   sensor requests answered (written and marked)
 * @param readingsWritten    readings written (a distance reading of all sensors counts once)
 * @param readingsNotWritten readings taken for a request but lost to a database failure (the
 *                           request stays pending, so the engine asks again)
 * @param failedCalls        database calls that failed
 * @param skippedCalls       database calls skipped while backing off after a failure
 * @param outages            times the database went from working to failing
 * @param commandsExecuted   new commands executed
 * @param commandsIgnored    commands ignored: malformed, unknown, or older than one executed
 * @param unknownRequests    requests for a sensor this robot does not have (left pending)
 * @param watchdogStops      times the watchdog stopped the robot
 * @param linkStops          times a failed database call stopped the robot
 * @param rowsPruned         history rows deleted by the retention policy
 */
public record RobotStats(long controlSteps, long requestsAnswered, long readingsWritten, long readingsNotWritten,
                         long failedCalls, long skippedCalls, long outages, long commandsExecuted,
                         long commandsIgnored, long unknownRequests, long watchdogStops, long linkStops,
                         long rowsPruned) {
}
