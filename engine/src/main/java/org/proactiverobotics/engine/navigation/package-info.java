/**
 * How the engine finds its way on the occupancy map it has built from the robot's scans: a
 * library the scenarios share, not a scenario. The map known so far ({@link
 * org.proactiverobotics.engine.navigation.KnownMap}, read from the {@code occupancy_map} rows), A*
 * on the robot's footprint with unknown cells taken as free ({@link
 * org.proactiverobotics.engine.navigation.RoutePlanner}) and a follower that re-plans as walls
 * appear ({@link org.proactiverobotics.engine.navigation.RouteFollower}). Units: metres, radians.
 */
package org.proactiverobotics.engine.navigation;
