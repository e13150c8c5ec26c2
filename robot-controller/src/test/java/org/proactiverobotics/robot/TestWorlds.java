package org.proactiverobotics.robot;

import java.util.List;
import org.proactiverobotics.sim2d.WorldSpec;

/** Small worlds for the controller's tests. */
final class TestWorlds {

    private TestWorlds() {
    }

    /** A 5 m arena, the robot at (0, -4) facing +y, an obstacle 0.6 m ahead, two checkpoints. */
    static WorldSpec arena() {
        return new WorldSpec("test-arena", 32, 600, 1, new WorldSpec.Arena(5.0),
                new WorldSpec.Robot(0.0, -4.0, 90.0, 0.12, 0.5, 1.0),
                List.of(WorldSpec.Obstacle.circle(0.0, -3.2, 0.2)),
                List.of(new WorldSpec.Checkpoint(0.0, 3.0), new WorldSpec.Checkpoint(3.0, -1.0)), 0.25,
                new WorldSpec.RechargeStation(-3.0, 0.0, 0.35), new WorldSpec.Battery(80.0, 1.0, 95.0, 10.0));
    }

    /** {@link #arena()} with the robot starting on the recharge station. */
    static WorldSpec atStation() {
        return arena().withRobot(new WorldSpec.Robot(-3.0, 0.0, 0.0, 0.12, 0.5, 1.0));
    }
}
