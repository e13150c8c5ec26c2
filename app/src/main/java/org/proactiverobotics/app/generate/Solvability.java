package org.proactiverobotics.app.generate;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * Whether a world can be done at all, by the {@link GridPlanner}: every checkpoint reachable in
 * order, and the battery enough for the tour, recharging at the station whenever the next leg and
 * the way back to the station would not fit in what is left (a greedy plan, so a yes is a proof).
 *
 * @param solvable  whether the plan exists
 * @param lengthM   the plan's length, metres (infinite when not solvable)
 * @param recharges how many stops at the station the plan makes
 * @param reason    why not, empty when solvable
 */
public record Solvability(boolean solvable, double lengthM, int recharges, String reason) {

    /** Clearance the planner keeps between the robot's rim and anything, metres. */
    public static final double CLEARANCE_M = 0.05;

    /**
     * @param world the world
     * @return the verdict
     */
    public static Solvability of(WorldSpec world) {
        return of(world, new GridPlanner(world, CLEARANCE_M));
    }

    /**
     * Each robot's mission on its own, in {@link WorldSpec#robots()}'s order: its start, its checkpoints and
     * the station nearest its start (as the crow flies), the other robots left out. A yes for each is what a
     * world with several robots can promise: robots that meet must still make way for each other.
     *
     * @param world a world, with one robot or several
     * @return one verdict per robot
     */
    public static List<Solvability> ofEachRobot(WorldSpec world) {
        Map<Double, GridPlanner> planners = new HashMap<>(); // one grid per body size: robots may differ
        List<Solvability> verdicts = new ArrayList<>();
        for (int i = 0; i < world.robots().size(); i++) {
            WorldSpec mission = missionOf(world, i);
            GridPlanner planner = planners.computeIfAbsent(mission.robot().radiusM(), r -> new GridPlanner(mission, CLEARANCE_M));
            verdicts.add(of(mission, planner));
        }
        return verdicts;
    }

    /**
     * @param world a world
     * @param index a robot's position in {@link WorldSpec#robots()}
     * @return that robot's mission as a one-robot world whose station is the one nearest its start
     */
    public static WorldSpec missionOf(WorldSpec world, int index) {
        WorldSpec.RobotEntry entry = world.robots().get(index);
        WorldSpec.RechargeStation nearest = world.nearestStation(entry.robot()); // the station its mission charges at
        return new WorldSpec(world.name(), world.timeStepMs(), world.maxSimTimeS(), world.seed(), world.arena(), entry.robot(),
                world.obstacles(), entry.checkpoints(), world.checkpointRadiusM(), nearest, world.battery());
    }

    /**
     * @param world   the world
     * @param planner the world's planner, built with {@link #CLEARANCE_M} (one already built for the world, to reuse)
     * @return the verdict
     */
    public static Solvability of(WorldSpec world, GridPlanner planner) {
        WorldSpec.Battery b = world.battery();
        WorldSpec.RechargeStation st = world.rechargeStation();
        List<double[]> stops = new ArrayList<>();
        for (WorldSpec.Checkpoint c : world.checkpoints()) {
            stops.add(new double[] {c.x(), c.y()});
        }
        double x = world.robot().x();
        double y = world.robot().y();
        double battery = b.initial();
        double length = 0;
        int recharges = 0;
        for (int k = 0; k < stops.size(); k++) {
            double[] next = stops.get(k);
            double leg = planner.distance(x, y, next[0], next[1]);
            if (Double.isInfinite(leg)) {
                return new Solvability(false, Double.POSITIVE_INFINITY, recharges, "checkpoints[" + k + "] cannot be reached");
            }
            boolean last = k == stops.size() - 1;
            // the way back to the station counts for every checkpoint but the last: not searched for the last
            double back = last ? 0 : planner.distance(next[0], next[1], st.x(), st.y());
            double need = b.drainPerMeter() * (leg + (last ? 0 : back));
            if (battery - need < 0) { // recharge first
                double toStation = planner.distance(x, y, st.x(), st.y());
                if (Double.isInfinite(toStation) || battery - b.drainPerMeter() * toStation < 0) {
                    return new Solvability(false, Double.POSITIVE_INFINITY, recharges,
                            "the battery cannot last to checkpoints[" + k + "] nor to the station");
                }
                length += toStation;
                recharges++;
                battery = b.rechargeTo();
                x = st.x();
                y = st.y();
                leg = planner.distance(x, y, next[0], next[1]);
                if (battery - b.drainPerMeter() * (leg + (last ? 0 : back)) < 0) {
                    return new Solvability(false, Double.POSITIVE_INFINITY, recharges,
                            "checkpoints[" + k + "] is too far from the station for a full charge");
                }
            }
            battery -= b.drainPerMeter() * leg;
            length += leg;
            x = next[0];
            y = next[1];
        }
        return new Solvability(true, length, recharges, "");
    }
}
