/**
 * The fail-safe scenario (the paper's future work, section VII): when a rule of a scenario
 * fails, {@link org.proactiverobotics.engine.scenario.failsafe.WatchFailures} clears that
 * scenario's suggestions from the CommandArray, so that no command of a failing scenario
 * reaches the robot; a scenario left with no rule at all is stood in for by STOP (in its own
 * slot, so the strategy still decides; the top-priority slot for a scenario without one) and
 * restarted from its meta-rule after a delay that doubles with each restart. Started after
 * every suggesting scenario and before the decision: 1 → 4 → 2 → 3 → FailSafe → 5.
 */
package org.proactiverobotics.engine.scenario.failsafe;
