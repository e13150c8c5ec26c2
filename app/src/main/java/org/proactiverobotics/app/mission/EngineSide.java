package org.proactiverobotics.app.mission;

import java.util.List;
import javax.sql.DataSource;
import org.proactiverobotics.engine.Algorithm;
import org.proactiverobotics.engine.IterationSummary;
import org.proactiverobotics.engine.JdbcStateStore;
import org.proactiverobotics.engine.ProactiveEngine;
import org.proactiverobotics.engine.ScenarioRegistry;
import org.proactiverobotics.engine.motion.DriveProfile;
import org.proactiverobotics.engine.scenario.decision.DecisionObserver;
import org.proactiverobotics.engine.tables.EngineComments;
import org.proactiverobotics.engine.tables.JdbcRobotTables;
import org.proactiverobotics.engine.tables.MissionTables;
import org.proactiverobotics.engine.tables.SensorReadings;
import org.proactiverobotics.engine.tables.SensorRequests;
import org.proactiverobotics.engine.tables.StrategyTable;

/**
 * The engine side of one robot, wired: the Proactive Engine with the robot's scenarios, its
 * tables over the shared database, its saved state, and the pruning that keeps the engine's
 * own history bounded. Used by the one-process mission and by the engine process alike.
 */
public final class EngineSide {

    /** The scenarios StartUp creates, in the paper's order 1 → 4 → 2 → 3 → 5. */
    public static final List<String> SCENARIOS = List.of(
            "DataAcquisition", "BatteryMonitor", "ReachDestination", "ObstacleAvoidance", "DecisionMaking");
    /** Prune the engine's history every this many iterations. */
    public static final int PRUNE_EVERY = 100;
    /** Keep this many of the robot's newest commands, answered requests and rule failures. */
    public static final int KEEP_ROWS = 1000;

    private final ProactiveEngine engine;
    private final JdbcRobotTables tables;

    private EngineSide(ProactiveEngine engine, JdbcRobotTables tables) {
        this.engine = engine;
        this.tables = tables;
    }

    /**
     * Builds the engine of one robot; call {@link #startFresh()} or {@link #resume()} next.
     *
     * @param dataSource the shared database (schema applied)
     * @param robotId    the robot
     * @param profile    the robot's drive as the engine assumes it
     * @param observer   told of every decision, or null
     * @return the engine side
     */
    public static EngineSide build(DataSource dataSource, int robotId, DriveProfile profile, DecisionObserver observer) {
        JdbcRobotTables tables = new JdbcRobotTables(dataSource, robotId);
        ProactiveEngine.Builder builder = ProactiveEngine.builder()
                .robotId(robotId)
                .algorithm(Algorithm.LAZY)
                .store(new JdbcStateStore(dataSource))
                .service(SensorReadings.class, tables)
                .service(SensorRequests.class, tables)
                .service(MissionTables.class, tables)
                .service(StrategyTable.class, tables)
                .service(EngineComments.class, tables)
                .service(DriveProfile.class, profile);
        if (observer != null) {
            builder.service(DecisionObserver.class, observer);
        }
        return new EngineSide(builder.build(), tables);
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
     * prunes the engine's history.
     *
     * @return the iteration's summary
     */
    public IterationSummary iterate() {
        IterationSummary summary = engine.runIteration();
        if (engine.iteration() % PRUNE_EVERY == 0) {
            tables.pruneHistory(KEEP_ROWS);
        }
        return summary;
    }

    /** @return the engine */
    public ProactiveEngine engine() {
        return engine;
    }

    /** @return the robot's tables as the engine sees them */
    public JdbcRobotTables tables() {
        return tables;
    }
}
