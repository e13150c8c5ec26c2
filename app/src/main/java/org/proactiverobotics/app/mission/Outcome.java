package org.proactiverobotics.app.mission;

/** How a mission ended, as written in report.json's {@code outcome}. */
public enum Outcome {
    /** Every checkpoint reached, in order. */
    MISSION_ACCOMPLISHED,
    /** The world's maxSimTimeS ran out first. */
    TIME_LIMIT,
    /** The battery ran flat. */
    BATTERY_DEPLETED,
    /** The robot process was stopped (SIGTERM / Ctrl-C) before the mission ended. */
    STOPPED
}
