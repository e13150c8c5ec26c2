package org.proactiverobotics.app.mission;

import java.sql.SQLException;
import java.util.List;
import java.util.function.UnaryOperator;
import javax.sql.DataSource;
import org.proactiverobotics.app.link.EngineTables;
import org.proactiverobotics.engine.Algorithm;
import org.proactiverobotics.engine.IterationSummary;
import org.proactiverobotics.engine.IterationTransaction;
import org.proactiverobotics.engine.JdbcStateStore;
import org.proactiverobotics.engine.ProactiveEngine;
import org.proactiverobotics.engine.ScenarioRegistry;
import org.proactiverobotics.engine.StateStore;
import org.proactiverobotics.engine.StateStoreException;
import org.proactiverobotics.engine.motion.DriveProfile;
import org.proactiverobotics.engine.scenario.decision.DecisionObserver;
import org.proactiverobotics.engine.tables.EngineComments;
import org.proactiverobotics.engine.tables.JdbcRobotTables;
import org.proactiverobotics.engine.tables.MissionTables;
import org.proactiverobotics.engine.tables.SensorReadings;
import org.proactiverobotics.engine.tables.SensorRequests;
import org.proactiverobotics.engine.tables.StrategyTable;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The engine side of one robot, wired: the Proactive Engine with the robot's scenarios, its
 * tables over the shared database, its saved state, and the pruning that keeps the engine's
 * own history bounded. Used by the one-process mission and by the engine process alike.
 */
public final class EngineSide {

    private static final Logger LOG = LoggerFactory.getLogger(EngineSide.class);

    /**
     * The scenarios StartUp creates, in the paper's order 1 → 4 → 2 → 3 → 5, with the fail-safe
     * after every scenario that suggests and before the decision, so that it withdraws a failing
     * scenario's suggestion in the iteration it failed, before anyone picks it.
     */
    public static final List<String> SCENARIOS = List.of(
            "DataAcquisition", "BatteryMonitor", "ReachDestination", "ObstacleAvoidance", "FailSafe", "DecisionMaking");
    /** Prune the engine's history every this many iterations. */
    public static final int PRUNE_EVERY = 100;
    /** Keep this many of the robot's newest commands, answered requests and rule failures. */
    public static final int KEEP_ROWS = 1000;

    private final ProactiveEngine engine;
    private final EngineTables links;
    private final IterationTransaction transaction;
    /** An iteration ran in memory but its transaction did not commit. */
    private boolean aheadOfDatabase;

    private EngineSide(ProactiveEngine engine, EngineTables links, IterationTransaction transaction) {
        this.engine = engine;
        this.links = links;
        this.transaction = transaction;
    }

    /**
     * Builds the engine of one robot over the shared database (its tables and its saved state);
     * call {@link #startFresh()} or {@link #resume()} next.
     *
     * @param dataSource the shared database (schema applied)
     * @param robotId    the robot
     * @param profile    the robot's drive as the engine assumes it
     * @param observer   told of every decision, or null
     * @return the engine side
     */
    public static EngineSide build(DataSource dataSource, int robotId, DriveProfile profile, DecisionObserver observer) {
        return build(dataSource, robotId, profile, observer, UnaryOperator.identity());
    }

    /**
     * As {@link #build(DataSource, int, DriveProfile, DecisionObserver)}, with the rules' view of
     * the tables wrapped (a test injecting a fault, a counter in a benchmark).
     *
     * @param dataSource the shared database (schema applied)
     * @param robotId    the robot
     * @param profile    the robot's drive as the engine assumes it
     * @param observer   told of every decision, or null
     * @param decorate   wraps the tables the rules see
     * @return the engine side
     */
    public static EngineSide build(DataSource dataSource, int robotId, DriveProfile profile, DecisionObserver observer,
                                   UnaryOperator<EngineTables> decorate) {
        // The rules' writes and the saved state of an iteration commit together, once.
        IterationTransaction transaction = new IterationTransaction(dataSource);
        JdbcRobotTables tables = new JdbcRobotTables(transaction, robotId);
        return build(decorate.apply(EngineTables.of(tables)), transaction, new JdbcStateStore(transaction),
                robotId, profile, observer);
    }

    /**
     * Builds the engine of one robot over any communication layer (the database, an in-process
     * link, a wrapped one in a test); call {@link #startFresh()} or {@link #resume()} next.
     *
     * @param tables   what the engine's rules read and write
     * @param store    where the engine's state is saved ({@link StateStore#none()}: nowhere)
     * @param robotId  the robot
     * @param profile  the robot's drive as the engine assumes it
     * @param observer told of every decision, or null
     * @return the engine side
     */
    public static EngineSide build(EngineTables tables, StateStore store, int robotId, DriveProfile profile,
                                   DecisionObserver observer) {
        return build(tables, null, store, robotId, profile, observer);
    }

    private static EngineSide build(EngineTables tables, IterationTransaction transaction, StateStore store,
                                    int robotId, DriveProfile profile, DecisionObserver observer) {
        ProactiveEngine.Builder builder = ProactiveEngine.builder()
                .robotId(robotId)
                .algorithm(Algorithm.LAZY)
                .store(store)
                .service(SensorReadings.class, tables.readings())
                .service(SensorRequests.class, tables.requests())
                .service(MissionTables.class, tables.mission())
                .service(StrategyTable.class, tables.strategy())
                .service(EngineComments.class, tables.comments())
                .service(DriveProfile.class, profile);
        if (observer != null) {
            builder.service(DecisionObserver.class, observer);
        }
        return new EngineSide(builder.build(), tables, transaction);
    }

    /** Starts from StartUp, discarding any saved state of this robot's engine. */
    public void startFresh() {
        engine.startFresh(ScenarioRegistry.load().startUp(SCENARIOS));
    }

    /**
     * Resumes from the saved state, or starts from StartUp when there is none.
     *
     * @return whether a saved state was resumed
     */
    public boolean resume() {
        engine.start(ScenarioRegistry.load().startUp(SCENARIOS));
        return engine.resumed();
    }

    /**
     * Runs one iteration (state saved at its end) and, every {@value #PRUNE_EVERY} iterations,
     * prunes the engine's history. Over the database, all of it is one transaction: the rules'
     * writes and the saved state commit together or not at all.
     *
     * @return the iteration's summary
     * @throws org.proactiverobotics.engine.StateStoreException when the state (or the iteration's
     *         transaction) cannot be saved; nothing of the iteration is then in the database
     */
    public IterationSummary iterate() {
        IterationSummary summary;
        if (transaction == null) {
            summary = engine.runIteration();
        } else {
            if (aheadOfDatabase) {
                resume(); // the last iteration ran in memory but never committed: the database is the truth
                aheadOfDatabase = false;
            }
            transaction.begin();
            try {
                summary = engine.runIteration();
                transaction.commit();
            } catch (SQLException e) {
                transaction.rollback();
                aheadOfDatabase = true;
                throw new StateStoreException("committing iteration " + engine.iteration() + " of robot "
                        + engine.robotId() + ": " + e.getMessage(), e);
            } catch (RuntimeException e) {
                transaction.rollback();
                aheadOfDatabase = true;
                throw e;
            }
        }
        if (engine.iteration() % PRUNE_EVERY == 0) {
            prune();
        }
        return summary;
    }

    /** Housekeeping after the iteration, in its own transactions: a failure here costs the iteration nothing. */
    private void prune() {
        try {
            links.pruneHistory().applyAsInt(KEEP_ROWS);
        } catch (RuntimeException e) {
            LOG.warn("robot {}: pruning the engine's history failed (will try again in {} iterations): {}",
                    engine.robotId(), PRUNE_EVERY, e.getMessage());
        }
    }

    /** @return the engine */
    public ProactiveEngine engine() {
        return engine;
    }

    /** @return what the engine's rules read and write, whatever the layer */
    public EngineTables links() {
        return links;
    }
}
