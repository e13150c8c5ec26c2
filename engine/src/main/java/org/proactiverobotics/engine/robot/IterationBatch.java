package org.proactiverobotics.engine.robot;

import java.sql.SQLException;
import java.util.List;
import javax.sql.DataSource;
import org.proactiverobotics.engine.persistence.CommitGroup;
import org.proactiverobotics.engine.persistence.IterationTransaction;

/**
 * The next iterations of several robots' engines that one thread runs one after the other over
 * one database server: what their rules read is read for all of them in one query before
 * ({@link RobotEngine#readAhead}), and their transactions commit as one after ({@link CommitGroup}),
 * so that they cost the server one read and one commit instead of one each. On H2, where a
 * statement costs no round trip, or for a single engine, each iteration reads and commits its own.
 *
 * <pre>{@code
 * try (IterationBatch batch = IterationBatch.start(pool, engines)) {
 *     for (RobotEngine engine : engines) {
 *         engine.iterate();
 *     }
 *     batch.commit(); // until then none of the batch's iterations is in the database
 * }
 * }</pre>
 * Only for robots whose rows nothing but the robot writes until their iteration (a robot waiting
 * in lockstep, or real-time timing, which reads one moment of the robot's writes anyway). An
 * iteration that returns is not in the database before {@link #commit()}. When one iteration of
 * the batch fails, those run before it roll back with it and those after commit alone; when the
 * commit fails, every iteration it held rolls back; {@link #rolledBack()} says which returned but
 * did not commit, and each resumes from its saved state at its next iteration. Not thread-safe.
 */
public final class IterationBatch implements AutoCloseable {

    private final List<RobotEngine> engines;
    /** The engines' common transaction, or null: each commits its own. */
    private final CommitGroup group;

    private IterationBatch(List<RobotEngine> engines, CommitGroup group) {
        this.engines = engines;
        this.group = group;
    }

    /**
     * Reads the engines' tables for their next iterations and makes those iterations one transaction.
     *
     * @param dataSource the database the engines were built over
     * @param engines    engines whose next iteration runs before {@link #commit()}
     * @return the batch; close it after {@link #commit()}
     * @throws SQLException when the read fails (nothing is kept: run the iterations without a batch)
     */
    public static IterationBatch start(DataSource dataSource, List<RobotEngine> engines) throws SQLException {
        List<RobotEngine> all = List.copyOf(engines);
        if (all.size() < 2 || !RobotEngine.readAhead(dataSource, all)) {
            return new IterationBatch(all, null);
        }
        IterationBatch batch = new IterationBatch(all, new CommitGroup(dataSource));
        try {
            all.forEach(e -> e.join(batch.group));
        } catch (RuntimeException e) {
            batch.close(); // nothing half joined
            throw e;
        }
        return batch;
    }

    /** @return whether the iterations read and commit together (false: each its own) */
    public boolean batched() {
        return group != null;
    }

    /**
     * Commits the batch's iterations that ran, in one round trip.
     *
     * @throws SQLException when one of them failed, or the commit did: {@link #rolledBack()} says
     *         which are not in the database
     */
    public void commit() throws SQLException {
        if (group != null) {
            group.commit();
        }
    }

    /**
     * @return the engines whose iteration returned in the batch but did not commit (after
     *         {@link #commit()} or {@link #close()}); one whose iteration threw is not among them
     */
    public List<RobotEngine> rolledBack() {
        if (group == null) {
            return List.of();
        }
        List<IterationTransaction> gone = group.rolledBack();
        return engines.stream().filter(e -> gone.contains(e.transaction())).toList();
    }

    /** Rolls back what was not committed; a snapshot read for an iteration that did not run is forgotten. */
    @Override
    public void close() {
        engines.forEach(RobotEngine::dropReadAhead);
        if (group != null) {
            group.close();
        }
    }
}
