package org.proactiverobotics.app.sweep;

import java.util.Locale;
import org.proactiverobotics.app.mission.NoiseLevel;
import org.proactiverobotics.engine.robot.Strategy;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * One mission of a sweep: one combination of world, strategy, noise level and seed.
 *
 * @param index    its number in the sweep, from 1, in the order the combinations are listed
 * @param world    the validated world, its seed set to {@code seed}
 * @param source   where the world came from (a file, or a bundled world's name)
 * @param strategy the strategy the engine starts with
 * @param noise    the sensors' noise level
 * @param seed     the seed of the noise (the world's own seed unless {@code --seeds} gave others)
 */
public record SweepMission(int index, WorldSpec world, String source, Strategy strategy, NoiseLevel noise, long seed) {

    /** @return the mission's own folder name in the sweep's output: number, world, strategy, noise, seed */
    public String folder() {
        return String.format(Locale.ROOT, "%04d-%s-%s-%s-s%d", index, safe(world.name()), safe(strategy.name()),
                noise.label(), seed);
    }

    /**
     * @return results.csv's worldKind: the name less a trailing number (cluttered-007 is of kind cluttered), whatever
     *         the name; summary.html trusts only generate's names ({@code WorldGenerator.kindOfName})
     */
    public String worldKind() {
        return kindOf(world.name());
    }

    /**
     * @param worldName a world's name
     * @return its kind: the name less a trailing {@code -<digits>}
     */
    static String kindOf(String worldName) {
        String kind = worldName.replaceFirst("-\\d+$", "");
        return kind.isEmpty() ? worldName : kind;
    }

    private static String safe(String name) {
        return name.replaceAll("[^A-Za-z0-9._-]", "_");
    }
}
