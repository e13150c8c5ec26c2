package org.proactiverobotics.robot.link;

import java.util.List;
import java.util.Optional;

/**
 * The robot side's one channel to the engine (docs/architecture.md): read the engine's requests and
 * commands, write readings and mission rows. The JDBC implementation is {@link JdbcRobotLink};
 * another communication layer (an in-process link, say) implements this same interface.
 *
 * <p>Every method either does all it says or throws {@link LinkException} having done nothing
 * that the other side could see half of. A link is used by one controller thread.
 */
public interface RobotLink extends AutoCloseable {

    /**
     * The requests for fresh data the engine has written and nobody answered yet, oldest first.
     *
     * @param robotId the robot
     * @return the pending requests, possibly empty
     * @throws LinkException when the engine's side cannot be read
     */
    List<SensorRequest> pendingRequests(int robotId) throws LinkException;

    /**
     * Writes the readings of an answer and marks its requests answered at the answer's
     * simulated time, atomically.
     *
     * @param robotId the robot
     * @param answer  the readings and the request ids
     * @throws LinkException when nothing could be written
     */
    void answer(int robotId, SensorAnswer answer) throws LinkException;

    /**
     * Writes one battery reading that no request asked for (the full level at start).
     *
     * @param robotId   the robot
     * @param simTimeMs the simulated time, ms
     * @param reading   the reading
     * @throws LinkException when it could not be written
     */
    void writeBattery(int robotId, long simTimeMs, BatteryReading reading) throws LinkException;

    /**
     * The newest command the engine sent to this robot.
     *
     * @param robotId the robot
     * @return the command of the latest engine iteration (the larger id between two of one
     *         iteration), or empty when none was sent yet
     * @throws LinkException when the engine's side cannot be read
     */
    Optional<CommandRecord> newestCommand(int robotId) throws LinkException;

    /**
     * Writes the mission rows ({@code checkpoints}, {@code recharge_station},
     * {@code battery_recharged}) of a robot that has none yet; a table that already holds this
     * robot's rows is left as it is, so seeding again (a restart) duplicates nothing.
     *
     * @param robotId the robot
     * @param mission the rows to write
     * @return true when anything was written, false when the mission was already there
     * @throws LinkException when it could not be checked or written
     */
    boolean seedMission(int robotId, MissionSpec mission) throws LinkException;

    /**
     * Whether the engine has marked one of this robot's checkpoints unreachable (no route leads
     * there): the mission is over.
     *
     * @param robotId the robot
     * @return true when a checkpoint row is marked unreachable
     * @throws LinkException when the checkpoints cannot be read
     */
    default boolean checkpointUnreachable(int robotId) throws LinkException {
        return false;
    }

    /**
     * Deletes this robot's reading history beyond what the policy keeps.
     *
     * @param robotId the robot
     * @param policy  what to keep
     * @return how many rows were deleted
     * @throws LinkException when it failed (nothing is lost by that: it will be tried again)
     */
    int prune(int robotId, RetentionPolicy policy) throws LinkException;

    /** Releases what the link holds (not a pool it was given). */
    @Override
    void close();
}
