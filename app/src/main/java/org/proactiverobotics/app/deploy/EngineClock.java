package org.proactiverobotics.app.deploy;

import java.sql.SQLException;
import java.util.Optional;
import org.proactiverobotics.db.Writes;
import org.proactiverobotics.protocol.RunState;
import org.proactiverobotics.protocol.Timing;

/**
 * The engine's side of the lockstep handshake with a robot process: the robot's clock
 * ({@code robot_clock}) read, the engine's ({@code engine_clock}) published, and the engine's rows
 * reset when a new robot run starts. The robot's side is {@code robot.link.RobotClock}; the JDBC
 * implementation is {@link JdbcEngineClock}.
 */
public interface EngineClock {

    /**
     * What the robot last published.
     *
     * @param runId     its run (one robot process)
     * @param step      the control step whose sensing is done
     * @param simTimeMs the simulated time of that sensing, ms
     * @param timing    sync or realtime, or null for a word this version does not know (never served)
     * @param state     running, finished or stopped, or null for a word this version does not know (not running)
     */
    public record RobotTick(long runId, long step, long simTimeMs, Timing timing, RunState state) {
        /** @return whether the robot waits for one iteration per step */
        public boolean sync() {
            return timing == Timing.SYNC;
        }

        /** @return whether the run goes on (in a timing this version knows: else it is not served) */
        public boolean running() {
            return state == RunState.RUNNING && timing != null;
        }

        /** @return the timing as robot_clock has it, for a log line */
        public String timingLabel() {
            return timing == null ? "unknown" : timing.label();
        }

        /** @return the state in lower case, for a log line */
        public String stateLabel() {
            return state == null ? "unknown" : state.name().toLowerCase(java.util.Locale.ROOT);
        }
    }

    /**
     * What the engine last published.
     *
     * @param runId     the run it serves
     * @param step      the last robot step it ran an iteration for
     * @param iteration that iteration
     */
    public record Served(long runId, long step, long iteration) {
    }

    /**
     * @return what the engine last published for this robot, or empty
     * @throws SQLException when it could not be read
     */
    Optional<Served> served() throws SQLException;

    /**
     * Publishes that the engine has served this run up to this step, only while it holds the
     * robot's lease: an engine that lost it (paused past its expiry) cannot move the robot's clock
     * back under the engine that took over.
     *
     * @param runId     the run
     * @param step      the robot step served
     * @param iteration the iteration that served it
     * @param lease     the robot's lease, as this engine holds it
     * @throws EngineLease.LostException when the lease is another engine's
     * @throws SQLException              when it could not be written
     */
    void publish(long runId, long step, long iteration, EngineLease lease) throws SQLException;

    /**
     * Publishes that the engine has served this run up to this step, in the transaction of the
     * iteration that served it (which has confirmed the robot's lease): the robot sees the step
     * served exactly when the iteration's rows are there, and a server that flushes its log at
     * every commit flushes once for both.
     *
     * @param writes    the iteration's writes
     * @param runId     the run
     * @param step      the robot step served
     * @param iteration the iteration that served it
     * @throws SQLException when it could not be kept
     */
    void publish(Writes writes, long runId, long step, long iteration) throws SQLException;

    /**
     * A new robot run starts from a clean slate on the engine's side, as the one-process mission
     * does: its commands and sensor requests go, its checkpoints are neither reached nor
     * unreachable any more, its map is gone. The mission rows and the strategy stay (a strategy
     * set with the strategy command survives).
     *
     * @throws SQLException when it could not be done (nothing is)
     */
    void resetForNewRun() throws SQLException;
}
