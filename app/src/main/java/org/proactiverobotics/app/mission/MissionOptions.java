package org.proactiverobotics.app.mission;

import java.util.Objects;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * What a mission runs with.
 *
 * @param world    the validated world
 * @param jdbcUrl  the shared database (unused over the direct link)
 * @param user     its user, or null
 * @param password its password, or null
 * @param strategy the named strategy to start with
 * @param robotId  the robot's id in the shared tables
 * @param link     how the engine and the robot talk
 */
public record MissionOptions(WorldSpec world, String jdbcUrl, String user, String password, String strategy, int robotId,
                             Link link) {

    /** The communication layer between the engine and the robot. */
    public enum Link {
        /** The shared database (the paper's layer): each side with a pool of its own. */
        JDBC,
        /** In-process memory ({@link org.proactiverobotics.app.link.DirectLink}): no database at all. */
        DIRECT
    }

    /** Checks the link. */
    public MissionOptions {
        Objects.requireNonNull(link, "link");
    }

    /** A mission through the shared database. */
    public MissionOptions(WorldSpec world, String jdbcUrl, String user, String password, String strategy, int robotId) {
        this(world, jdbcUrl, user, password, strategy, robotId, Link.JDBC);
    }

    /** @return these options over another link */
    public MissionOptions withLink(Link other) {
        return new MissionOptions(world, jdbcUrl, user, password, strategy, robotId, other);
    }
}
