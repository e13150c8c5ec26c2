package org.proactiverobotics.engine;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;

/**
 * What a rule's parts see of the engine: the iteration, the shared memory, the failures, the
 * services, and {@link #generate} to create rules for the next iteration. One per engine,
 * reused for every rule (so running a rule allocates nothing); valid only during the part it is
 * given to.
 */
public final class RuleContext {

    /** The longest command {@link #suggest} takes: what engine_comments holds. */
    public static final int MAX_COMMAND_LENGTH = 255;

    private final ProactiveEngine engine;
    private final Map<Class<?>, Object> services;

    RuleContext(ProactiveEngine engine, Map<Class<?>, Object> services) {
        this.engine = engine;
        this.services = services;
    }

    /** @return the number of the iteration running (the first is 1) */
    public long iteration() {
        return engine.iteration();
    }

    /** @return the engine instance id: the {@code robot_id} of the engine's tables */
    public int robotId() {
        return engine.robotId();
    }

    /**
     * Appends a rule to nextQueue, after those generated before it. {@code generate(this)} is
     * how a rule clones itself to run again in the next iteration, its state kept. Generate a
     * given instance at most once per iteration (two entries would share one state).
     *
     * @param rule the rule to run in the next iteration
     */
    public void generate(Rule rule) {
        engine.generate(Objects.requireNonNull(rule, "generated rule"));
    }

    /**
     * Suggests a command to the robot: enters it in the CommandArray slot of the running rule's
     * scenario, where the decision scenario weighs it against the others by the strategy. The
     * engine gave the scenario its slot at start; a scenario never picks one. Only the newest
     * suggestion of an iteration counts.
     *
     * @param command a command in the robot's grammar: {@code STOP}, {@code DRIVE l r} (wheel
     *                speeds, m/s), {@code FORWARD v}, {@code TURN_LEFT v}, {@code TURN_RIGHT v}
     *                (m/s), {@code RECHARGE}; at most {@value #MAX_COMMAND_LENGTH} characters
     * @throws IllegalArgumentException when the command is empty or too long
     * @throws IllegalStateException    when the rule's scenario has no slot (it was not given one)
     */
    public void suggest(String command) {
        if (command == null || command.isBlank() || command.length() > MAX_COMMAND_LENGTH) {
            throw new IllegalArgumentException("not a command: " + (command == null ? "null"
                    : "'" + command.substring(0, Math.min(command.length(), 40)) + "' (" + command.length() + " characters)"));
        }
        int slot = engine.slotOfRunningRule();
        engine.memory().commandArray().enter(slot, command, engine.runningRule().scenario(), engine.iteration());
    }

    /** @return the memory scenarios share (CommandArray, PriorityArray, named values) */
    public SharedMemory memory() {
        return engine.memory();
    }

    /**
     * @return the failures of the previous iteration followed by those of this iteration so far,
     *         oldest first (what a fail-safe scenario reads)
     */
    public List<RuleFailure> failures() {
        List<RuleFailure> previous = engine.previousFailures();
        List<RuleFailure> current = engine.currentFailures();
        if (current.isEmpty()) {
            return previous;
        }
        List<RuleFailure> all = new ArrayList<>(previous.size() + current.size());
        all.addAll(previous);
        all.addAll(current);
        return Collections.unmodifiableList(all);
    }

    /**
     * Whether a rule of a scenario is queued to run: still waiting in currentQueue this
     * iteration, generated into nextQueue, or submitted from outside. A scenario with none is
     * gone (a failed rule is not regenerated); a fail-safe scenario asks this before restarting
     * one, so that a scenario still running is never started twice.
     *
     * @param scenario a scenario name
     * @return true when at least one of its rules is queued
     */
    public boolean scheduled(String scenario) {
        return engine.scheduled(Objects.requireNonNull(scenario, "scenario"));
    }

    /**
     * Whether a rule of this name and scenario runs in this iteration or is queued for the next.
     *
     * @param scenario the scenario's name
     * @param rule     the rule's {@link Rule#name()}
     * @return whether such a rule is scheduled
     */
    public boolean scheduled(String scenario, String rule) {
        return engine.scheduled(Objects.requireNonNull(scenario, "scenario"), Objects.requireNonNull(rule, "rule"));
    }

    /**
     * A service given to the engine's builder (a DAO, a clock, ...).
     *
     * @param type the type it was registered under
     * @return the service
     * @throws IllegalStateException naming the registered types when there is none of this type
     */
    public <T> T service(Class<T> type) {
        return findService(type).orElseThrow(() -> new IllegalStateException(
                "no service of type " + type.getName() + " was given to the engine; registered: "
                        + services.keySet().stream().map(Class::getName).sorted().toList()));
    }

    /**
     * @param type the type it was registered under
     * @return the service, or empty when none was registered
     */
    public <T> Optional<T> findService(Class<T> type) {
        return Optional.ofNullable(type.cast(services.get(type)));
    }
}
