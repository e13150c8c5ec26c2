/**
 * Mapping: UpdateMap marks, for each new distance scan, the cells every ray crossed free and the
 * cell where it hit occupied, in an occupancy grid of 0.05 m cells, and writes the chunks that
 * changed to {@code occupancy_map} in the iteration's transaction. The world is known only
 * through the readings; occupied cells stay occupied (the worlds are static).
 */
package org.proactiverobotics.engine.scenario.mapping;
