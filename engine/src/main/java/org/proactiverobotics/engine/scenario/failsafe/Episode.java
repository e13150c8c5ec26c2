package org.proactiverobotics.engine.scenario.failsafe;

/**
 * What the fail-safe knows of one scenario's trouble, from its first failure until it has run
 * cleanly again. Iterations are engine iterations; 0 means "not yet". Saved with the rule.
 */
final class Episode {

    /** The iteration of the first failure of the episode. */
    long since;
    /** The iteration of the newest failure seen. */
    long lastFailure;
    /** The newest failure, as text: rule, part, message. */
    String failure = "";
    /** Whether the scenario runs before the fail-safe in an iteration (its failures are seen the same iteration). */
    boolean before = true;
    /** The iteration the scenario was found with no rule left; 0 while it has some. */
    long goneSince;
    /** The iteration its meta-rule is due to be generated again. */
    long restartDue;
    /** The iteration its meta-rule was last generated. */
    long restartedAt;
    /** How many times it was restarted in this episode. */
    int restarts;
    /** How many lost rules were restored in this episode. */
    int restoredRules;

    private Episode() {
    }

    Episode(long iteration, boolean before) {
        this.since = iteration;
        this.lastFailure = iteration;
        this.before = before;
    }

    /** @return whether STOP stands in for the scenario: it is gone, or restarted and not yet running its own rules */
    boolean standIn() {
        return goneSince != 0;
    }
}
