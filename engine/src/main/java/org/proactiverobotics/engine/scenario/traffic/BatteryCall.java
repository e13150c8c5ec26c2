package org.proactiverobotics.engine.scenario.traffic;

import org.proactiverobotics.engine.RuleContext;
import org.proactiverobotics.engine.Suggestion;

/**
 * Whether the battery scenario calls the robot to its recharge station now: it entered a drive
 * this iteration (it starts before Yield, so its suggestion of this iteration is in the
 * CommandArray when Yield's rules run). It suggests only once its own check says a recharge is
 * needed (the next leg and the way back are beyond what is left, or the point of no return), so a
 * back-off that drives it away then spends battery the robot no longer has to spare: the battery
 * outranks the back-off, and the robot gives way only by stopping (which costs nothing).
 */
final class BatteryCall {

    /** The battery scenario's name, as the strategy and the CommandArray know it. */
    static final String BATTERY_SCENARIO = StationView.BATTERY_DRIVES.trim();

    private BatteryCall() {
    }

    /** @return whether the battery scenario suggested a drive (not RECHARGE, not STOP) this iteration */
    static boolean callsNow(RuleContext ctx) {
        int slot = ctx.memory().slotOf(BATTERY_SCENARIO);
        if (slot < 0) {
            return false;
        }
        Suggestion s = ctx.memory().commandArray().get(slot);
        return s != null && s.iteration() == ctx.iteration() && BATTERY_SCENARIO.equals(s.scenario())
                && s.command().startsWith("DRIVE");
    }
}
