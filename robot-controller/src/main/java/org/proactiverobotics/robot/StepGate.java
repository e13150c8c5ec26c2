package org.proactiverobotics.robot;

/**
 * What the standalone robot loop ({@link RobotSuperclass#run(StepGate)}) tells and waits for
 * between the halves of each control step: in lockstep with an engine process (see
 * {@link Lockstep}), the robot acts only once the engine has served the step it sensed.
 */
public interface StepGate {

    /** No gate: the robot acts right after sensing (the loop of one robot alone). */
    StepGate NONE = (step, simTimeMs) -> true;

    /**
     * Called after {@link RobotSuperclass#sense()} of a control step; returns when the robot may
     * act.
     *
     * @param step      the control step, from 1
     * @param simTimeMs the simulated time the readings were taken at, ms
     * @return true to act and step the simulation, false to end the loop (a stop was requested
     *         while waiting); the step is then not counted
     */
    boolean sensed(long step, long simTimeMs);

    /**
     * Called after the simulation stepped.
     *
     * @param step      the control step, from 1
     * @param simTimeMs the simulated time now, ms
     */
    default void stepped(long step, long simTimeMs) {
    }
}
