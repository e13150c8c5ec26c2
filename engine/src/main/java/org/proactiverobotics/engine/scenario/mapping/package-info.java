/**
 * Mapping: UpdateMap adds each new distance scan to an occupancy grid of 0.05 m cells (a ray
 * takes evidence of a wall from the cells it crossed and adds some to the cell where it hit; see
 * {@link org.proactiverobotics.engine.tables.OccupancyMap}) and writes the chunks that changed to
 * {@code occupancy_map} in the iteration's transaction. The world is known only through the
 * readings; a wall seen twice, or once from close by, stays.
 */
package org.proactiverobotics.engine.scenario.mapping;
