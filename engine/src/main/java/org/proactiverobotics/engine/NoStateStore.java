package org.proactiverobotics.engine;

import java.util.Collection;
import java.util.List;
import java.util.Optional;

/** The store of a pure in-memory engine: saves nothing, so it never has anything to resume. */
enum NoStateStore implements StateStore {
    INSTANCE;

    @Override
    public Optional<SavedState> load(int robotId) {
        return Optional.empty();
    }

    @Override
    public void save(int robotId, long iteration, Collection<Rule> nextQueue, SharedMemory memory, List<RuleFailure> failures) {
        // nothing kept, by design
    }

    @Override
    public void clear(int robotId) {
        // nothing to clear
    }
}
