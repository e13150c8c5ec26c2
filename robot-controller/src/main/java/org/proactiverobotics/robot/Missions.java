package org.proactiverobotics.robot;

import java.util.ArrayList;
import java.util.List;
import org.proactiverobotics.robot.link.MissionSpec;
import org.proactiverobotics.sim2d.WorldSpec;

/** Turns a world file into the mission rows the robot seeds. */
public final class Missions {

    private Missions() {
    }

    /**
     * @param world the parsed world file
     * @return its checkpoints (each with the world's checkpoint radius), station, recharge level and start pose
     */
    public static MissionSpec of(WorldSpec world) {
        List<MissionSpec.Checkpoint> checkpoints = new ArrayList<>(world.checkpoints().size());
        for (WorldSpec.Checkpoint c : world.checkpoints()) {
            checkpoints.add(new MissionSpec.Checkpoint(c.x(), c.y(), world.checkpointRadiusM()));
        }
        WorldSpec.RechargeStation s = world.rechargeStation();
        return new MissionSpec(checkpoints, new MissionSpec.Station(s.x(), s.y(), s.radiusM()),
                world.battery().rechargeTo(),
                new MissionSpec.Start(world.robot().x(), world.robot().y(), Math.toRadians(world.robot().headingDeg())));
    }
}
