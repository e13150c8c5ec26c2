package org.proactiverobotics.engine;

/** The parts of a {@link Rule}, in the order the engine may run them. */
public enum Part {
    /** {@link Rule#acquireGuardData}: data acquisition, the part the guards need. */
    GUARD_DATA_ACQUISITION,
    /** {@link Rule#acquireConditionData}: data acquisition, the part only conditions and actions need. */
    CONDITION_DATA_ACQUISITION,
    /** {@link Rule#activationGuards}. */
    ACTIVATION_GUARDS,
    /** {@link Rule#conditions}. */
    CONDITIONS,
    /** {@link Rule#actions}. */
    ACTIONS,
    /** {@link Rule#rulesGeneration}. */
    RULES_GENERATION
}
