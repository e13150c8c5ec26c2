package org.proactiverobotics.bench.mission;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import org.proactiverobotics.sim2d.WorldFiles;
import org.proactiverobotics.sim2d.WorldSpec;

/** The worlds the mission harnesses run: the bundled ones, made endless, and varied per robot. */
final class Worlds {

    /** The bundled worlds, in the order robots take them. */
    static final List<String> BUNDLED = List.of("reference-arena", "cluttered-arena", "obstacle-across-path", "low-battery");

    private Worlds() {
    }

    /** @return the world with no time limit to speak of (10^9 s) */
    static WorldSpec endless(WorldSpec w) {
        return new WorldSpec(w.name(), w.timeStepMs(), 1e9, w.seed(), w.arena(), w.robot(), w.obstacles(),
                w.checkpoints(), w.checkpointRadiusM(), w.rechargeStation(), w.battery());
    }

    /**
     * Robot i's world: the bundled worlds in turn, and from the second round on the checkpoint
     * order rotated and the seed changed, so that no two robots of a run do the same thing.
     */
    static WorldSpec forRobot(int i) {
        WorldSpec w = WorldFiles.bundled(BUNDLED.get(i % BUNDLED.size()));
        List<WorldSpec.Checkpoint> cps = new ArrayList<>(w.checkpoints());
        Collections.rotate(cps, -(i / BUNDLED.size()) % cps.size());
        return endless(new WorldSpec(w.name(), w.timeStepMs(), w.maxSimTimeS(), w.seed() + i, w.arena(), w.robot(),
                w.obstacles(), cps, w.checkpointRadiusM(), w.rechargeStation(), w.battery()));
    }
}
