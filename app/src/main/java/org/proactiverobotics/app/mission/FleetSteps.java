package org.proactiverobotics.app.mission;

/**
 * Which robots of a world with several robots take steps, in every runner of such a world (the one-process
 * fleet mission and the robot process): a robot whose mission goes on, and one that accomplished its mission
 * while another's still goes on (its engine drives it out of the others' way, back to where it started, and
 * gives way there; docs/engine.md, "The traffic scenario (Yield)"). A robot whose mission ended otherwise
 * (battery flat, a checkpoint unreachable, the time limit) stands still, a body the others see. The run ends
 * when no robot's mission goes on.
 */
public final class FleetSteps {

    private FleetSteps() {
    }

    /**
     * @param outcome    how the robot's mission ended, or null while it goes on
     * @param anyGoesOn  whether any robot's mission in the world still goes on
     * @return whether the robot takes the next step
     */
    public static boolean steps(Outcome outcome, boolean anyGoesOn) {
        return outcome == null || outcome == Outcome.MISSION_ACCOMPLISHED && anyGoesOn;
    }
}
