package org.proactiverobotics.engine;

/** How the engine orders data acquisition around the activation guards. */
public enum Algorithm {
    /** All data acquisition first, then guards, conditions, actions, rules generation. */
    STANDARD,
    /**
     * Zampunieris 2008: the data only conditions and actions need is acquired after the guards
     * held, which saves reads for rules that are not activated.
     */
    LAZY
}
