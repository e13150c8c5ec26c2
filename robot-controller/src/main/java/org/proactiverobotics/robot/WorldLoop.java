package org.proactiverobotics.robot;

import java.util.List;
import java.util.Objects;
import java.util.concurrent.locks.LockSupport;

import org.proactiverobotics.sim2d.Simulation;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The loop of a world with several robots, Webots-style: one controller per robot, one simulation for all.
 * Each step every controller whose mission is not over senses, the {@link StepGate} is told (in one process
 * the engines iterate there), every such controller acts, then the world steps once. A robot whose mission is
 * over ({@link RobotSuperclass#missionOver()}) stops its wheels and is left alone: it stays where it is, a body
 * the others see. The loop ends when every robot's mission is over, the world's time limit is reached or
 * {@link #requestStop()} is called. A one-robot world keeps {@link RobotSuperclass#run(StepGate)}.
 * Controllers are called in the list's order, on the caller's thread.
 */
public final class WorldLoop {

    private static final Logger LOG = LoggerFactory.getLogger(WorldLoop.class);

    private final Simulation simulation;
    private final List<? extends RobotSuperclass> controllers;
    private final boolean[] done;
    private final double realTimeFactor;
    private volatile boolean stopRequested;
    private long steps;

    /**
     * @param simulation     the world every controller's robot lives in
     * @param controllers    one per robot of the world, any order (each controls {@code robotIndex()})
     * @param realTimeFactor pace: simulated seconds per wall-clock second; 0 or less runs as fast as it goes
     */
    public WorldLoop(Simulation simulation, List<? extends RobotSuperclass> controllers, double realTimeFactor) {
        this.simulation = Objects.requireNonNull(simulation, "simulation");
        this.controllers = List.copyOf(controllers);
        for (RobotSuperclass c : this.controllers) {
            if (c.simulation != simulation) {
                throw new IllegalArgumentException("robot " + c.config().robotId() + "'s controller drives another simulation");
            }
        }
        this.done = new boolean[this.controllers.size()];
        this.realTimeFactor = realTimeFactor;
    }

    /**
     * Runs until every mission is over, the time limit or a stop.
     *
     * @param gate told after every robot sensed and after the world stepped; may hold the step back or end it
     * @return the simulated time at the end, ms
     */
    public long run(StepGate gate) {
        LOG.info("world: {} robot controller(s), time step {} ms", controllers.size(), simulation.timeStepMs());
        long startNanos = System.nanoTime();
        long startSimMs = simulation.simTimeMs();
        while (!stopRequested && !allDone() && !simulation.timeLimitReached()) {
            if (!step(gate)) {
                break;
            }
            pace(startNanos, simulation.simTimeMs() - startSimMs);
        }
        for (RobotSuperclass c : controllers) {
            c.robot.setWheelSpeeds(0.0, 0.0);
        }
        LOG.info("world: stopped at {} ms simulated", simulation.simTimeMs());
        return simulation.simTimeMs();
    }

    /**
     * One control step of every robot whose mission is not over, then one world step.
     *
     * @param gate told after sensing (return false to end the loop before acting) and after the world stepped
     * @return false when the gate ended the loop
     */
    public boolean step(StepGate gate) {
        markDone();
        for (int i = 0; i < controllers.size(); i++) {
            if (!done[i]) {
                controllers.get(i).sense();
            }
        }
        if (!gate.sensed(steps + 1, simulation.simTimeMs())) {
            return false;
        }
        steps++;
        for (int i = 0; i < controllers.size(); i++) {
            if (!done[i]) {
                RobotSuperclass c = controllers.get(i);
                c.act();
                c.stats.controlSteps++;
            }
        }
        simulation.step();
        gate.stepped(steps, simulation.simTimeMs());
        return true;
    }

    /** Stops the wheels of every robot whose mission just ended; it takes no further control step. */
    private void markDone() {
        for (int i = 0; i < controllers.size(); i++) {
            if (!done[i] && controllers.get(i).missionOver()) {
                done[i] = true;
                controllers.get(i).robot.setWheelSpeeds(0.0, 0.0);
            }
        }
    }

    /** @return whether every robot's mission is over (as of the last step) */
    public boolean allDone() {
        markDone();
        for (boolean d : done) {
            if (!d) {
                return false;
            }
        }
        return true;
    }

    /**
     * @param position the controller's position in the list given
     * @return whether that robot's mission is over (it no longer takes control steps)
     */
    public boolean done(int position) {
        return done[position];
    }

    /** @return the world steps taken by this loop */
    public long steps() {
        return steps;
    }

    /** Asks {@link #run} to return after the current step; safe from any thread. */
    public void requestStop() {
        stopRequested = true;
    }

    private void pace(long startNanos, long simElapsedMs) {
        if (realTimeFactor <= 0) {
            return;
        }
        long dueNanos = startNanos + (long) (simElapsedMs * 1_000_000L / realTimeFactor);
        long wait = dueNanos - System.nanoTime();
        if (wait > 0) {
            LockSupport.parkNanos(wait);
        }
    }
}
