package org.proactiverobotics.robot;

/**
 * Where the wall-clock time of {@link RobotSuperclass#run(StepGate)} went, in mean milliseconds
 * per control step.
 *
 * @param steps     the control steps run
 * @param senseMs   answering the engine's requests
 * @param waitMs    waiting in the {@link StepGate} (for the engine, in lockstep)
 * @param actMs     reading the newest command and setting the wheels
 * @param physicsMs the simulation step
 */
public record LoopTimes(long steps, double senseMs, double waitMs, double actMs, double physicsMs) {
}
