package org.proactiverobotics.engine;

/**
 * The figures of one iteration.
 *
 * @param iteration      the iteration
 * @param rulesRun       rules taken from currentQueue and run
 * @param rulesGenerated rules generated into nextQueue (a failed rule's are not counted)
 * @param rulesFailed    rules a part of which threw
 * @param rulesSubmitted rules submitted from outside that joined nextQueue
 * @param nextQueueSize  rules in nextQueue at the end, to run in the next iteration
 * @param durationNanos  wall time of the whole iteration, saving included
 * @param saveNanos      wall time of saving the state
 */
public record IterationSummary(long iteration, int rulesRun, int rulesGenerated, int rulesFailed, int rulesSubmitted,
                               int nextQueueSize, long durationNanos, long saveNanos) {
}
