package org.proactiverobotics.robot.link;

import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.util.Objects;
import javax.sql.DataSource;
import org.proactiverobotics.protocol.RunState;
import org.proactiverobotics.protocol.Timing;
import org.proactiverobotics.robot.link.RobotClock.EngineTick;

/**
 * The handshake tables ({@code robot_clock}, {@code engine_clock}) of every robot of one world at
 * once, for the robot process that hosts them all: each step's "sensed step k" of all robots in one
 * transaction, and all their engines' ticks in one query, so that a step costs two round trips
 * however many robots the world has. A run starts robot by robot as {@link JdbcRobotClock} starts it.
 * Runs with the robot user's grants. Not thread-safe: one thread (the world's loop) uses it.
 */
public final class JdbcWorldClock {

    private static final String PUBLISH = "UPDATE robot_clock SET step = ?, sim_time_ms = ?, state = ?, "
            + "updated_at = CURRENT_TIMESTAMP(3) WHERE robot_id = ? AND run_id = ?";

    private final DataSource dataSource;
    private final JdbcRobotClock single;
    private final int[] robotIds;
    private final String ticksQuery;

    /**
     * @param dataSource the shared database (not closed by this clock)
     * @param robotIds   the world's robots' ids, in the world's order
     */
    public JdbcWorldClock(DataSource dataSource, int[] robotIds) {
        this.dataSource = Objects.requireNonNull(dataSource, "dataSource");
        this.single = new JdbcRobotClock(dataSource); // no link: the world's loop polls, it holds no lock per robot
        this.robotIds = robotIds.clone();
        StringBuilder in = new StringBuilder();
        for (int i = 0; i < robotIds.length; i++) {
            in.append(i == 0 ? "?" : ", ?");
        }
        this.ticksQuery = "SELECT robot_id, run_id, step, iteration FROM engine_clock WHERE robot_id IN (" + in + ")";
    }

    /**
     * Starts a new run of one robot ({@link RobotClock#beginRun}).
     *
     * @param position the robot's position in the world's order
     * @param timing   sync or realtime
     * @return the new run id
     * @throws LinkException when nothing could be done
     */
    public long beginRun(int position, Timing timing) throws LinkException {
        return single.beginRun(robotIds[position], timing);
    }

    /**
     * Publishes the same step of several robots in one transaction.
     *
     * @param positions the robots' positions in the world's order (the first {@code count} are used)
     * @param count     how many
     * @param runIds    every robot's run id, by position
     * @param step      the control step whose sensing is done
     * @param simTimeMs the simulated time of that sensing, ms
     * @param state     RUNNING, FINISHED or STOPPED
     * @throws LinkException when it could not be written (nothing was), or a robot's row belongs to another run
     */
    public void publish(int[] positions, int count, long[] runIds, long step, long simTimeMs, RunState state)
            throws LinkException {
        if (count == 0) {
            return;
        }
        try (Connection c = dataSource.getConnection()) {
            c.setAutoCommit(false);
            try (PreparedStatement ps = c.prepareStatement(PUBLISH)) {
                for (int k = 0; k < count; k++) {
                    int p = positions[k];
                    ps.setLong(1, step);
                    ps.setLong(2, simTimeMs);
                    ps.setString(3, state.name());
                    ps.setInt(4, robotIds[p]);
                    ps.setLong(5, runIds[p]);
                    ps.addBatch();
                }
                int[] updated = ps.executeBatch();
                for (int k = 0; k < count; k++) {
                    if (updated[k] == 0) {
                        c.rollback();
                        throw new LinkException("robot_clock has no row for robot " + robotIds[positions[k]] + " run "
                                + runIds[positions[k]] + ": another robot process with the same robot id started a run", null);
                    }
                }
                c.commit();
            } catch (SQLException | RuntimeException e) {
                c.rollback();
                throw e;
            } finally {
                c.setAutoCommit(true);
            }
        } catch (SQLException e) {
            throw new LinkException("publishing step " + step + " of " + count + " robot(s) failed: " + e.getMessage(), e);
        }
    }

    /**
     * Reads what the engines last published for every robot of the world.
     *
     * @param into by position: the robot's tick, or null when no engine ever served it
     * @throws LinkException when it could not be read
     */
    public void ticks(EngineTick[] into) throws LinkException {
        java.util.Arrays.fill(into, null);
        try (Connection c = dataSource.getConnection(); PreparedStatement ps = c.prepareStatement(ticksQuery)) {
            for (int i = 0; i < robotIds.length; i++) {
                ps.setInt(i + 1, robotIds[i]);
            }
            try (ResultSet rs = ps.executeQuery()) {
                while (rs.next()) {
                    int position = position(rs.getInt(1));
                    if (position >= 0) {
                        into[position] = new EngineTick(rs.getLong(2), rs.getLong(3), rs.getLong(4));
                    }
                }
            }
        } catch (SQLException e) {
            throw new LinkException("reading engine_clock of " + robotIds.length + " robot(s) failed: " + e.getMessage(), e);
        }
    }

    private int position(int robotId) {
        for (int i = 0; i < robotIds.length; i++) {
            if (robotIds[i] == robotId) {
                return i;
            }
        }
        return -1;
    }
}
