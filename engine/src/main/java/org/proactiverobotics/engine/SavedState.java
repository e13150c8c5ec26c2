package org.proactiverobotics.engine;

import java.util.List;

/**
 * What a {@link StateStore} gives back on start: the engine resumes with the next iteration.
 *
 * @param iteration    the last iteration saved
 * @param nextQueue    the rules of the next iteration, head first
 * @param memory       the shared memory
 * @param lastFailures the failures of the last iteration saved (rules see them as the previous iteration's)
 */
public record SavedState(long iteration, List<Rule> nextQueue, SharedMemory memory, List<RuleFailure> lastFailures) {
}
