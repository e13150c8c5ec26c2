package org.proactiverobotics.robot.link;

import java.util.Optional;
import org.proactiverobotics.protocol.RunState;
import org.proactiverobotics.protocol.Timing;

/**
 * The robot's side of the lockstep handshake with an engine process (tables
 * {@code robot_clock}, written by the robot, and {@code engine_clock}, read by it). The JDBC
 * implementation is {@link JdbcRobotClock}.
 */
public interface RobotClock {

    /**
     * What the engine last published for a robot.
     *
     * @param runId     the robot run it serves
     * @param step      the last robot step it ran an iteration for (0: the run is acknowledged)
     * @param iteration that iteration's number
     */
    record EngineTick(long runId, long step, long iteration) {
    }

    /**
     * Starts a new run of this robot: deletes its readings of earlier runs and publishes step 0 of
     * a new run id (larger than any before), in one transaction.
     *
     * @param robotId the robot
     * @param timing  sync or realtime
     * @return the new run id
     * @throws LinkException when nothing could be done
     */
    long beginRun(int robotId, Timing timing) throws LinkException;

    /**
     * Publishes the robot's progress.
     *
     * @param robotId   the robot
     * @param runId     its run
     * @param step      the control step whose sensing is done
     * @param simTimeMs the simulated time of that sensing, ms
     * @param state     RUNNING, FINISHED or STOPPED
     * @throws LinkException when it could not be written
     */
    void publish(int robotId, long runId, long step, long simTimeMs, RunState state) throws LinkException;

    /**
     * @param robotId the robot
     * @return what the engine last published for it, or empty when no engine ever did
     * @throws LinkException when it could not be read
     */
    Optional<EngineTick> engineTick(int robotId) throws LinkException;

    /**
     * Whether {@link #awaitServed} waits in the database until the engine serves a step (then the
     * robot need not poll first); false for a database that cannot.
     *
     * @return true when waiting in the server is possible now
     */
    default boolean waitsInServer() {
        return false;
    }

    /**
     * Waits in the database, for a bounded time, until the engine has served the step or may have,
     * then reads as {@link #engineTick} does (the step may not be served yet: poll then).
     *
     * @param robotId the robot
     * @param step    the step just published
     * @return what the engine last published for it, or empty when no engine ever did
     * @throws LinkException when it could not be read
     */
    default Optional<EngineTick> awaitServed(int robotId, long step) throws LinkException {
        return engineTick(robotId);
    }
}
