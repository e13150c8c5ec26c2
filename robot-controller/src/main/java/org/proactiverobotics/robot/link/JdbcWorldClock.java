package org.proactiverobotics.robot.link;

import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
import javax.sql.DataSource;
import org.proactiverobotics.db.RoundTrip;
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
    /** Each robot's link, by position, or null: no reads with the ticks. */
    private final JdbcRobotLink[] links;
    private final String readsQuery;
    /** What the last {@link #ticks} read besides the ticks, by position (with links only). */
    private final List<Optional<CommandRecord>> commands;
    private final List<List<SensorRequest>> pending;
    /** The step whose publication with answers failed with an unknown outcome, or -1. */
    private long failedStep = -1;

    /**
     * @param dataSource the shared database (not closed by this clock)
     * @param robotIds   the world's robots' ids, in the world's order
     */
    public JdbcWorldClock(DataSource dataSource, int[] robotIds) {
        this(dataSource, robotIds, null);
    }

    /**
     * A clock that, in sync timing, reads every robot's newest command and pending requests with the
     * engines' ticks, in the same query, and hands them to each robot's link once its engine served
     * the step ({@link #handOff}): the robots' next {@code newestCommand} and {@code pendingRequests}
     * are then no round trips, as {@link JdbcRobotLink#clock()} does for one robot (nothing writes them
     * between an engine's iteration and its robot's next step).
     *
     * @param dataSource the shared database (not closed by this clock)
     * @param robotIds   the world's robots' ids, in the world's order
     * @param links      each robot's link, in the same order, or null
     */
    public JdbcWorldClock(DataSource dataSource, int[] robotIds, JdbcRobotLink[] links) {
        this.dataSource = Objects.requireNonNull(dataSource, "dataSource");
        this.links = links == null ? null : links.clone();
        if (links != null) {
            for (JdbcRobotLink link : links) {
                link.deferAnswers(true); // each robot's answer commits with the world's publication: one flush a step
            }
        }
        this.commands = new ArrayList<>();
        this.pending = new ArrayList<>();
        StringBuilder reads = new StringBuilder("(SELECT 1 AS k, robot_id AS r, run_id AS a, step AS b, iteration AS c,"
                + " '' AS s1, '' AS s2 FROM engine_clock WHERE robot_id IN (");
        for (int i = 0; i < robotIds.length; i++) {
            reads.append(i == 0 ? "?" : ", ?");
            commands.add(Optional.empty());
            pending.add(new ArrayList<>(4));
        }
        reads.append("))");
        for (int i = 0; i < robotIds.length; i++) {
            reads.append(" UNION ALL (SELECT 2, robot_id, id, iteration, sim_time_ms, scenario, command FROM engine_comments"
                    + " WHERE robot_id = ? ORDER BY robot_id DESC, iteration DESC, id DESC LIMIT 1)");
        }
        reads.append(" UNION ALL (SELECT 3, robot_id, id, 0, 0, sensor, '' FROM sensor_requests WHERE robot_id IN (");
        for (int i = 0; i < robotIds.length; i++) {
            reads.append(i == 0 ? "?" : ", ?");
        }
        reads.append(") AND answered_sim_time_ms IS NULL)");
        this.readsQuery = reads.toString();
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
        if (links != null) {
            for (int k = 0; k < count; k++) {
                links[positions[k]].dropHandOff(); // its engine may write once it sees this step
            }
        }
        if (links != null && state == RunState.RUNNING && publishWithAnswers(positions, count, runIds, step, simTimeMs)) {
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
     * The robots' kept answers and their steps in one multi-statement round trip and one commit.
     * After a failure whose outcome was unknown, a step found published already is not written twice.
     *
     * @return false when no robot kept an answer (or the database takes no multi-statements): publish alone
     */
    private boolean publishWithAnswers(int[] positions, int count, long[] runIds, long step, long simTimeMs)
            throws LinkException {
        try (Connection c = dataSource.getConnection()) {
            if (!RoundTrip.allowed(c)) {
                return false;
            }
            SensorAnswer[] answers = new SensorAnswer[count];
            if (failedStep == step && publishedAlready(c, robotIds[positions[0]], runIds[positions[0]], step)) {
                for (int k = 0; k < count; k++) { // it did commit: the answers are written
                    SensorAnswer a = links[positions[k]].addDeferredTo(new RoundTrip(), robotIds[positions[k]]);
                    if (a != null) {
                        links[positions[k]].deferredCommitted(robotIds[positions[k]], a);
                    }
                }
                failedStep = -1;
                return true;
            }
            RoundTrip trip = new RoundTrip();
            boolean any = false;
            for (int k = 0; k < count; k++) {
                answers[k] = links[positions[k]].addDeferredTo(trip, robotIds[positions[k]]);
                any |= answers[k] != null;
            }
            if (!any) {
                return false;
            }
            int statementsBefore = trip.statements();
            for (int k = 0; k < count; k++) {
                int p = positions[k];
                trip.add(PUBLISH, 5, (ps, i) -> {
                    ps.setLong(i, step);
                    ps.setLong(i + 1, simTimeMs);
                    ps.setString(i + 2, RunState.RUNNING.name());
                    ps.setInt(i + 3, robotIds[p]);
                    ps.setLong(i + 4, runIds[p]);
                });
            }
            int[] counts;
            try {
                counts = trip.commit(c);
            } catch (SQLException e) {
                failedStep = step;
                throw e;
            }
            failedStep = -1;
            for (int k = 0; k < count; k++) {
                if (counts[counts.length - count + k] == 0) {
                    throw new LinkException("robot_clock has no row for robot " + robotIds[positions[k]] + " run "
                            + runIds[positions[k]] + ": another robot process with the same robot id started a run", null);
                }
            }
            for (int k = 0; k < count; k++) {
                if (answers[k] != null) {
                    links[positions[k]].deferredCommitted(robotIds[positions[k]], answers[k]);
                }
            }
            return statementsBefore >= 0;
        } catch (SQLException e) {
            throw new LinkException("publishing step " + step + " of " + count + " robot(s) with their answers failed: "
                    + e.getMessage(), e);
        }
    }

    private static boolean publishedAlready(Connection c, int robotId, long runId, long step) throws SQLException {
        try (PreparedStatement ps = c.prepareStatement("SELECT step FROM robot_clock WHERE robot_id = ? AND run_id = ?")) {
            ps.setInt(1, robotId);
            ps.setLong(2, runId);
            try (ResultSet rs = ps.executeQuery()) {
                return rs.next() && rs.getLong(1) >= step;
            }
        }
    }

    /**
     * Reads what the engines last published for every robot of the world.
     *
     * @param into by position: the robot's tick, or null when no engine ever served it
     * @throws LinkException when it could not be read
     */
    public void ticks(EngineTick[] into) throws LinkException {
        if (links != null) {
            ticksWithReads(into);
            return;
        }
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

    private void ticksWithReads(EngineTick[] into) throws LinkException {
        java.util.Arrays.fill(into, null);
        for (int i = 0; i < robotIds.length; i++) {
            commands.set(i, Optional.empty());
            pending.get(i).clear();
        }
        try (Connection c = dataSource.getConnection(); PreparedStatement ps = c.prepareStatement(readsQuery)) {
            int p = 1;
            for (int pass = 0; pass < 3; pass++) {
                for (int id : robotIds) {
                    ps.setInt(p++, id);
                }
            }
            try (ResultSet rs = ps.executeQuery()) {
                while (rs.next()) {
                    int position = position(rs.getInt(2));
                    if (position < 0) {
                        continue;
                    }
                    switch (rs.getInt(1)) {
                        case 1 -> into[position] = new EngineTick(rs.getLong(3), rs.getLong(4), rs.getLong(5));
                        case 2 -> commands.set(position, Optional.of(new CommandRecord(rs.getLong(3), rs.getLong(4),
                                rs.getLong(5), rs.getString(6), rs.getString(7))));
                        case 3 -> pending.get(position).add(new SensorRequest(rs.getLong(3), rs.getString(6)));
                        default -> throw new SQLException("unknown row kind " + rs.getInt(1));
                    }
                }
            }
        } catch (SQLException e) {
            throw new LinkException("reading engine_clock of " + robotIds.length + " robot(s) failed: " + e.getMessage(), e);
        }
    }

    /**
     * Hands what the last {@link #ticks} read with the ticks to the links of robots whose engines
     * served the step they wait for (sync timing only; nothing without links).
     *
     * @param positions the robots' positions (the first {@code count} are used)
     * @param count     how many
     */
    public void handOff(int[] positions, int count) {
        if (links == null) {
            return;
        }
        for (int k = 0; k < count; k++) {
            int p = positions[k];
            List<SensorRequest> requests = pending.get(p);
            requests.sort(Comparator.comparingLong(SensorRequest::id)); // as pendingRequests reads them: ORDER BY id
            links[p].handOff(robotIds[p], commands.get(p), requests);
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
