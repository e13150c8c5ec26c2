package org.proactiverobotics.engine.tables;

import java.util.Objects;
import java.util.function.IntUnaryOperator;

/**
 * The engine side of one robot's communication layer: the table interfaces the scenarios ask
 * the engine for, and how the engine's own history (commands sent, requests answered) is kept
 * bounded. One record whatever the layer, so that a test can wrap one of them (fault injection).
 *
 * @param readings     the newest sensor readings
 * @param requests     the requests for fresh data
 * @param mission      checkpoints, station, recharge level
 * @param strategy     the PriorityArray and time-outs
 * @param comments     where decided commands go
 * @param pruneHistory keeps the newest n rows of the engine's history; returns how many went
 * @param poses        the pose estimate's rows
 */
public record EngineTables(SensorReadings readings, SensorRequests requests, MissionTables mission,
                           StrategyTable strategy, EngineComments comments, IntUnaryOperator pruneHistory,
                           PoseEstimateTable poses) {

    /** Checks that every part is there. */
    public EngineTables {
        Objects.requireNonNull(readings, "readings");
        Objects.requireNonNull(requests, "requests");
        Objects.requireNonNull(mission, "mission");
        Objects.requireNonNull(strategy, "strategy");
        Objects.requireNonNull(comments, "comments");
        Objects.requireNonNull(pruneHistory, "pruneHistory");
        Objects.requireNonNull(poses, "poses");
    }

    /**
     * The parts without a pose-estimate table of their own: the mission tables' when they are one
     * (the database's rows), else an estimate kept in memory.
     *
     * @param readings     the newest sensor readings
     * @param requests     the requests for fresh data
     * @param mission      checkpoints, station, recharge level
     * @param strategy     the PriorityArray and time-outs
     * @param comments     where decided commands go
     * @param pruneHistory keeps the newest n rows of the engine's history; returns how many went
     */
    public EngineTables(SensorReadings readings, SensorRequests requests, MissionTables mission,
                        StrategyTable strategy, EngineComments comments, IntUnaryOperator pruneHistory) {
        this(readings, requests, mission, strategy, comments, pruneHistory,
                mission instanceof PoseEstimateTable p ? p : PoseEstimateTable.inMemory());
    }

    /** @return the engine side over the shared database */
    public static EngineTables of(JdbcRobotTables tables) {
        return of(tables, tables::pruneHistory);
    }

    /**
     * @param tables       one object that is every table (a communication layer's engine side)
     * @param pruneHistory keeps the newest n rows of the engine's history; returns how many went
     * @return the engine side of that layer
     */
    public static <T extends SensorReadings & SensorRequests & MissionTables & StrategyTable & EngineComments>
            EngineTables of(T tables, IntUnaryOperator pruneHistory) {
        return new EngineTables(tables, tables, tables, tables, tables, pruneHistory);
    }
}
