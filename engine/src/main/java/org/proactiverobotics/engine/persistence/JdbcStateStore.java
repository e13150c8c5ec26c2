package org.proactiverobotics.engine.persistence;

import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;
import javax.sql.DataSource;
import org.proactiverobotics.db.MultiRow;
import org.proactiverobotics.db.RobotRows;
import org.proactiverobotics.db.Writes;
import org.proactiverobotics.engine.CorruptStateException;
import org.proactiverobotics.engine.Part;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.RuleFailure;
import org.proactiverobotics.engine.SavedState;
import org.proactiverobotics.engine.SharedMemory;
import org.proactiverobotics.engine.StateStore;
import org.proactiverobotics.engine.StateStoreException;

/**
 * Saves the engine state through JDBC in the tables {@code engine_state}, {@code engine_queue}
 * and {@code rule_failures} of schema.sql; the same SQL runs on H2 (MySQL mode), MariaDB and
 * MySQL 8. Each save is one transaction: nextQueue's rows are rewritten in place, the size
 * difference inserted or deleted; a row whose rule type and JSON are what this store last saved
 * there is left alone (most rules keep their state from one iteration to the next). Over an
 * {@link IterationTransaction} the save joins the iteration's transaction, and a rollback of it
 * makes this store forget what it believed saved.
 */
public final class JdbcStateStore implements StateStore {

    private static final int BATCH = 1_000;

    private final DataSource dataSource;
    /** The iteration's transaction when the data source is one, else null. */
    private final IterationTransaction transaction;
    private final StateCodec codec;
    /** Per robot, "type NUL json" of each queue row as last committed; absent = unknown, read the table. */
    private final Map<Integer, List<String>> savedRows = new ConcurrentHashMap<>();
    /** The state row, inserted or replaced, in MySQL's and MariaDB's words ... */
    private static final String SAVE_STATE = "INSERT INTO engine_state (robot_id, iteration, memory_json) VALUES (?, ?, ?)"
            + " ON DUPLICATE KEY UPDATE iteration = VALUES(iteration), memory_json = VALUES(memory_json), saved_at = CURRENT_TIMESTAMP(3)";
    /** ... and in H2's (which runs the former as a failed insert and an update). */
    private static final String SAVE_STATE_H2 = "MERGE INTO engine_state (robot_id, iteration, memory_json, saved_at) KEY (robot_id)"
            + " VALUES (?, ?, ?, CURRENT_TIMESTAMP(3))";
    private static final MultiRow UPSERT_QUEUE = MultiRow.upsert("engine_queue", List.of("robot_id", "position"),
            "robot_id", "position", "rule_type", "rule_json");

    /** @param dataSource the database (a HikariCP pool, typically) */
    public JdbcStateStore(DataSource dataSource) {
        this(dataSource, new StateCodec());
    }

    /** @param dataSource the database @param codec how rules and memory become JSON */
    public JdbcStateStore(DataSource dataSource, StateCodec codec) {
        this.dataSource = Objects.requireNonNull(dataSource);
        this.codec = Objects.requireNonNull(codec);
        this.transaction = dataSource instanceof IterationTransaction t ? t : null;
        if (transaction != null) {
            transaction.onRollback(savedRows::clear);
        }
    }

    @Override
    public Optional<SavedState> load(int robotId) {
        try (Connection c = dataSource.getConnection()) {
            c.setAutoCommit(false);
            try {
                Optional<SavedState> state = load(c, robotId);
                c.commit();
                return state;
            } catch (SQLException | RuntimeException e) {
                c.rollback();
                throw e;
            }
        } catch (SQLException e) {
            throw new StateStoreException("could not load the engine state of robot_id=" + robotId + ": " + e.getMessage(), e);
        }
    }

    private Optional<SavedState> load(Connection c, int robotId) throws SQLException {
        long iteration;
        String memoryJson;
        try (PreparedStatement ps = c.prepareStatement("SELECT iteration, memory_json FROM engine_state WHERE robot_id = ?")) {
            ps.setInt(1, robotId);
            try (ResultSet rs = ps.executeQuery()) {
                if (!rs.next()) {
                    long orphans = countQueueRows(c, robotId);
                    if (orphans > 0) {
                        throw new CorruptStateException("engine_queue holds " + orphans + " rows for robot_id=" + robotId
                                + " but engine_state has no row for it: the saved state is incomplete");
                    }
                    return Optional.empty();
                }
                iteration = rs.getLong(1);
                memoryJson = rs.getString(2);
            }
        }
        SharedMemory memory;
        try {
            memory = codec.memory(memoryJson);
        } catch (RuntimeException e) {
            throw new CorruptStateException("engine_state row (robot_id=" + robotId + ", iteration=" + iteration + "): "
                    + problem(e, "corrupt memory_json"), e);
        }
        List<Rule> queue = new ArrayList<>();
        try (PreparedStatement ps = c.prepareStatement(
                "SELECT position, rule_type, rule_json FROM engine_queue WHERE robot_id = ? ORDER BY position")) {
            ps.setInt(1, robotId);
            ps.setFetchSize(BATCH);
            try (ResultSet rs = ps.executeQuery()) {
                while (rs.next()) {
                    int position = rs.getInt(1);
                    String type = rs.getString(2);
                    String row = "engine_queue row (robot_id=" + robotId + ", position=" + position + ", rule_type=" + type + ")";
                    if (position != queue.size()) {
                        throw new CorruptStateException(row + ": expected position " + queue.size()
                                + " (positions run 0..n-1 without gaps)");
                    }
                    try {
                        queue.add(codec.rule(type, rs.getString(3)));
                    } catch (RuntimeException e) {
                        throw new CorruptStateException(row + ": " + problem(e, "corrupt rule_json"), e);
                    }
                }
            }
        }
        List<RuleFailure> failures = new ArrayList<>();
        try (PreparedStatement ps = c.prepareStatement("SELECT id, rule, scenario, part, message FROM rule_failures"
                + " WHERE robot_id = ? AND iteration = ? ORDER BY id")) {
            ps.setInt(1, robotId);
            ps.setLong(2, iteration);
            try (ResultSet rs = ps.executeQuery()) {
                while (rs.next()) {
                    Part part;
                    try {
                        part = Part.valueOf(rs.getString(4));
                    } catch (IllegalArgumentException e) {
                        throw new CorruptStateException("rule_failures row (id=" + rs.getLong(1) + ", robot_id=" + robotId
                                + "): unknown part " + rs.getString(4), e);
                    }
                    failures.add(new RuleFailure(iteration, rs.getString(2), rs.getString(3), part, rs.getString(5), null));
                }
            }
        }
        return Optional.of(new SavedState(iteration, List.copyOf(queue), memory, List.copyOf(failures)));
    }

    private static String problem(RuntimeException e, String fallback) {
        return e instanceof IllegalArgumentException ? e.getMessage() : fallback + ": " + e;
    }

    private static long countQueueRows(Connection c, int robotId) throws SQLException {
        try (PreparedStatement ps = c.prepareStatement("SELECT COUNT(*) FROM engine_queue WHERE robot_id = ?")) {
            ps.setInt(1, robotId);
            try (ResultSet rs = ps.executeQuery()) {
                rs.next();
                return rs.getLong(1);
            }
        }
    }

    @Override
    public void save(int robotId, long iteration, Collection<Rule> nextQueue, SharedMemory memory, List<RuleFailure> failures) {
        List<String> previous = savedRows.remove(robotId); // a failed save leaves nothing believed saved
        Connection inIteration = transaction == null ? null : transaction.readConnection(); // reads only: the writes go with the commit
        if (inIteration != null) {
            try {
                savedRows.put(robotId, save(transaction.writes(), inIteration, robotId, iteration, nextQueue, memory, failures,
                        previous));
                return; // committed with the iteration (a rollback of it clears savedRows)
            } catch (SQLException | RuntimeException e) {
                transaction.markRollbackOnly();
                savedRows.remove(robotId);
                if (e instanceof SQLException sql) {
                    transaction.statementFailed(sql); // a lost connection: no later write of the iteration may run bare
                    throw new StateStoreException("could not save the engine state of robot_id=" + robotId
                            + " after iteration " + iteration + ": " + sql.getMessage(), sql);
                }
                throw (RuntimeException) e;
            }
        }
        try (Connection c = dataSource.getConnection()) {
            c.setAutoCommit(false);
            try {
                List<String> rows = save(Writes.atOnce(c), c, robotId, iteration, nextQueue, memory, failures, previous);
                c.commit();
                savedRows.put(robotId, rows);
            } catch (SQLException | RuntimeException e) {
                c.rollback();
                throw e;
            }
        } catch (SQLException e) {
            throw new StateStoreException("could not save the engine state of robot_id=" + robotId + " after iteration "
                    + iteration + ": " + e.getMessage(), e);
        }
    }

    /**
     * The state row (an upsert: no row count is needed, so the writes may go with the iteration's
     * commit), then only the queue rows that differ from the saved ones, as one upsert; only a
     * shrink deletes.
     */
    private List<String> save(Writes writes, Connection c, int robotId, long iteration, Collection<Rule> nextQueue,
                              SharedMemory memory, List<RuleFailure> failures, List<String> previous) throws SQLException {
        String memoryJson = codec.memoryJson(memory);
        writes.add(MultiRow.isH2(c) ? SAVE_STATE_H2 : SAVE_STATE, 3, (ps, p) -> {
            ps.setInt(p, robotId);
            ps.setLong(p + 1, iteration);
            ps.setString(p + 2, memoryJson);
        });
        long saved = previous != null ? previous.size() : countQueueRows(c, robotId);
        QueueDiff diff = diff(nextQueue, previous, saved);
        writes.addRows(UPSERT_QUEUE, 4, diff.changed().size(), queueRows(robotId, diff.changed()));
        int size = diff.rows().size();
        if (saved > size) {
            writes.add("DELETE FROM engine_queue WHERE robot_id = ? AND position >= ?", 2, (ps, p) -> {
                ps.setInt(p, robotId);
                ps.setInt(p + 1, size);
            });
        }
        for (RuleFailure f : List.copyOf(failures)) {
            writes.add("INSERT INTO rule_failures (robot_id, iteration, rule, scenario, part, message) VALUES (?, ?, ?, ?, ?, ?)",
                    6, (ps, p) -> {
                        ps.setInt(p, robotId);
                        ps.setLong(p + 1, f.iteration());
                        ps.setString(p + 2, cut(f.rule(), 255));
                        ps.setString(p + 3, cut(f.scenario(), 64));
                        ps.setString(p + 4, f.part().name());
                        ps.setString(p + 5, cut(f.message(), 1000));
                    });
        }
        return diff.rows();
    }

    /** Binds queue rows, one row each. */
    private static MultiRow.RowBinder queueRows(int robotId, List<QueueRow> rows) {
        return (ps, p, r) -> {
            QueueRow q = rows.get(r);
            ps.setInt(p, robotId);
            ps.setInt(p + 1, q.position());
            ps.setString(p + 2, q.type());
            ps.setString(p + 3, q.json());
        };
    }

    /** nextQueue's rows (type and fields) and those that differ from the saved ones. */
    private record QueueDiff(List<String> rows, List<QueueRow> changed) {
    }

    private QueueDiff diff(Collection<Rule> nextQueue, List<String> previous, long saved) {
        List<String> rows = new ArrayList<>(nextQueue.size());
        List<QueueRow> changed = new ArrayList<>();
        int position = 0;
        for (Rule rule : nextQueue) {
            String type = codec.ruleType(rule);
            String json = codec.ruleJson(rule);
            String row = type + '\u0000' + json;
            rows.add(row);
            if (!(position < saved && previous != null && row.equals(previous.get(position)))) {
                changed.add(new QueueRow(position, type, json));
            }
            position++;
        }
        return new QueueDiff(rows, changed);
    }

    /** A queue row to write: the rule at a position, by type and fields. */
    private record QueueRow(int position, String type, String json) {
    }

    private static String cut(String s, int max) {
        return s == null ? "" : s.length() <= max ? s : s.substring(0, max);
    }

    /** Round-trips the rule through its JSON, as a save and a resume would. */
    @Override
    public void checkSaveable(Rule rule) {
        codec.rule(codec.ruleType(rule), codec.ruleJson(rule));
    }

    @Override
    public void clear(int robotId) {
        savedRows.remove(robotId);
        try (Connection c = dataSource.getConnection()) {
            c.setAutoCommit(false);
            try {
                RobotRows.delete(c, robotId, List.of("engine_queue", "engine_state", "rule_failures"));
                c.commit();
            } catch (SQLException | RuntimeException e) {
                c.rollback();
                throw e;
            }
        } catch (SQLException e) {
            throw new StateStoreException("could not clear the engine state of robot_id=" + robotId + ": " + e.getMessage(), e);
        }
    }
}
