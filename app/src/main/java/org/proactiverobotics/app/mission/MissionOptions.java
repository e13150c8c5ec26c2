package org.proactiverobotics.app.mission;

import org.proactiverobotics.sim2d.WorldSpec;

/**
 * What a mission runs with.
 *
 * @param world    the validated world
 * @param jdbcUrl  the shared database
 * @param user     its user, or null
 * @param password its password, or null
 * @param strategy the named strategy to start with
 * @param robotId  the robot's id in the shared tables
 */
public record MissionOptions(WorldSpec world, String jdbcUrl, String user, String password, String strategy, int robotId) {
}
