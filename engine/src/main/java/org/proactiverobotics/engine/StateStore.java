package org.proactiverobotics.engine;

import java.util.Collection;
import java.util.List;
import java.util.Optional;

/**
 * Where the engine saves its state at the end of every iteration (the paper's failsafe) and
 * finds it again on start. Keyed by the engine instance id ({@code robot_id}).
 */
public interface StateStore {

    /**
     * @param robotId the engine instance id
     * @return the last saved state, or empty when none was saved
     * @throws CorruptStateException when a saved state exists but cannot be read; the message names the row
     */
    Optional<SavedState> load(int robotId);

    /**
     * Saves, in one transaction, what the next iteration starts from: it replaces the previous
     * state and adds the iteration's failures to the failure log.
     *
     * @param robotId   the engine instance id
     * @param iteration the iteration just ended
     * @param nextQueue the rules of the next iteration, head first
     * @param memory    the shared memory
     * @param failures  the failures of the iteration just ended
     * @throws StateStoreException when saving fails; the previous state is then kept
     */
    void save(int robotId, long iteration, Collection<Rule> nextQueue, SharedMemory memory, List<RuleFailure> failures);

    /**
     * Forgets the saved state (and failure log) of an engine instance, for an explicit fresh start.
     *
     * @param robotId the engine instance id
     */
    void clear(int robotId);

    /**
     * Checks that a rule can be saved (its type loadable back, its fields writable), before the
     * engine queues it: a rule that could not be saved then fails the rule that generated it,
     * instead of every save after it. Nothing to check by default.
     *
     * @param rule a rule about to be queued
     * @throws RuntimeException naming the problem when it cannot be saved
     */
    default void checkSaveable(Rule rule) {
    }

    /** @return a store that keeps nothing: a pure in-memory engine that always starts fresh */
    static StateStore none() {
        return NoStateStore.INSTANCE;
    }
}
