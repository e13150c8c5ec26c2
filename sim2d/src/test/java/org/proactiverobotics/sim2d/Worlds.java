package org.proactiverobotics.sim2d;

import java.util.List;

/** Small worlds built in code for tests. */
final class Worlds {

    private Worlds() {
    }

    /** An empty arena of the given radius; robot at (x, y) facing headingDeg. */
    static WorldSpec empty(double arenaRadiusM, double x, double y, double headingDeg) {
        return new WorldSpec("test", 32, 600, 7, new WorldSpec.Arena(arenaRadiusM),
                new WorldSpec.Robot(x, y, headingDeg, 0.12, 0.5, 1.0), List.of(),
                List.of(new WorldSpec.Checkpoint(0.0, 0.0)), 0.25,
                new WorldSpec.RechargeStation(0.0, 0.0, 0.35), WorldSpec.Battery.DEFAULT);
    }

    /** Steps n times. */
    static void run(Simulation sim, int n) {
        for (int i = 0; i < n; i++) {
            sim.step();
        }
    }
}
