package org.proactiverobotics.app.mission;

import java.util.Objects;
import org.proactiverobotics.engine.robot.ScenarioPlugins;
import org.proactiverobotics.engine.robot.Strategy;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * What a mission runs with.
 *
 * @param world    the validated world
 * @param jdbcUrl  the shared database (unused over the direct link)
 * @param user     its user, or null
 * @param password its password, or null
 * @param strategy the strategy to start with
 * @param robotId  the robot's id in the shared tables
 * @param link     how the engine and the robot talk
 * @param plugins  scenarios from outside, started where RobotEngine.startOrder puts them (before ObstacleAvoidance)
 * @param noise    the sensors' noise, drawn from the world's seed
 */
public record MissionOptions(WorldSpec world, String jdbcUrl, String user, String password, Strategy strategy, int robotId,
                             Link link, ScenarioPlugins plugins, NoiseLevel noise) {

    /** The communication layer between the engine and the robot. */
    public enum Link {
        /** The shared database (the paper's layer): each side with a pool of its own. */
        JDBC,
        /** In-process memory ({@link org.proactiverobotics.app.link.DirectLink}): no database at all. */
        DIRECT;

        /**
         * @param word {@code jdbc} or {@code direct}, in any case
         * @return the link, or null for another word
         */
        public static Link of(String word) {
            for (Link link : values()) {
                if (link.name().equalsIgnoreCase(word)) {
                    return link;
                }
            }
            return null;
        }
    }

    /** Checks the link. */
    public MissionOptions {
        Objects.requireNonNull(strategy, "strategy");
        Objects.requireNonNull(link, "link");
        Objects.requireNonNull(plugins, "plugins");
        Objects.requireNonNull(noise, "noise");
    }

    /** Options without sensor noise. */
    public MissionOptions(WorldSpec world, String jdbcUrl, String user, String password, Strategy strategy, int robotId,
                          Link link, ScenarioPlugins plugins) {
        this(world, jdbcUrl, user, password, strategy, robotId, link, plugins, NoiseLevel.NONE);
    }

    /** A mission through the shared database, with a bundled strategy and no plug-ins. */
    public MissionOptions(WorldSpec world, String jdbcUrl, String user, String password, String strategy, int robotId) {
        this(world, jdbcUrl, user, password, Strategy.named(strategy), robotId, Link.JDBC, ScenarioPlugins.none());
    }

    /** @return these options over another link */
    public MissionOptions withLink(Link other) {
        return new MissionOptions(world, jdbcUrl, user, password, strategy, robotId, other, plugins, noise);
    }

    /** @return these options with these plug-ins and this strategy */
    public MissionOptions withScenarios(ScenarioPlugins others, Strategy otherStrategy) {
        return new MissionOptions(world, jdbcUrl, user, password, otherStrategy, robotId, link, others, noise);
    }

    /** @return these options with this sensor noise */
    public MissionOptions withNoise(NoiseLevel level) {
        return new MissionOptions(world, jdbcUrl, user, password, strategy, robotId, link, plugins, level);
    }

    /** @return these options in another world (the same mission elsewhere, or with another seed) */
    public MissionOptions withWorld(WorldSpec other) {
        return new MissionOptions(other, jdbcUrl, user, password, strategy, robotId, link, plugins, noise);
    }

    /** @return these options on another database */
    public MissionOptions withDatabase(String otherJdbcUrl, String otherUser, String otherPassword) {
        return new MissionOptions(world, otherJdbcUrl, otherUser, otherPassword, strategy, robotId, link, plugins, noise);
    }
}
