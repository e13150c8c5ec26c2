/**
 * What the engine believed at each iteration, told to whoever traces it: the pose its scenarios
 * used, the route they follow, the occupancy map's changed chunks, and the reasons of a veto or of
 * a checkpoint declared unreachable ({@link org.proactiverobotics.engine.belief.BeliefObserver}).
 * The scenarios tell it through an optional engine service; they know nothing of traces or files.
 * Units: metres, radians.
 */
package org.proactiverobotics.engine.belief;
