package org.proactiverobotics.app.sweep;

import com.google.gson.GsonBuilder;
import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import java.util.List;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * A {@link WorldSpec} as a world file (docs/world-file.md), every key written out: what
 * {@code generate} writes and what {@code sweep} leaves in each mission's folder, so that
 * {@code run --world .../world.json} runs the same mission again.
 */
public final class WorldJson {

    private WorldJson() {
    }

    /**
     * @param world the world
     * @return its world file, pretty-printed, ending with a newline
     */
    public static String of(WorldSpec world) {
        JsonObject root = new JsonObject();
        root.addProperty("name", world.name());
        root.addProperty("timeStepMs", world.timeStepMs());
        root.addProperty("maxSimTimeS", world.maxSimTimeS());
        root.addProperty("seed", world.seed());
        JsonObject arena = new JsonObject();
        WorldSpec.Arena a = world.arena();
        if (a.isCircle()) {
            arena.addProperty("radiusM", a.radiusM());
        } else {
            arena.addProperty("widthM", a.widthM());
            arena.addProperty("heightM", a.heightM());
            arena.addProperty("x", a.x());
            arena.addProperty("y", a.y());
        }
        root.add("arena", arena);
        boolean fleet = isFleet(world);
        if (fleet) {
            JsonArray robots = new JsonArray();
            for (WorldSpec.RobotEntry e : world.robots()) {
                JsonObject robot = new JsonObject();
                robot.addProperty("id", e.id());
                robotProperties(robot, e.robot());
                robot.add("checkpoints", checkpoints(e.checkpoints()));
                robots.add(robot);
            }
            root.add("robots", robots);
        } else {
            JsonObject robot = new JsonObject();
            robotProperties(robot, world.robot());
            root.add("robot", robot);
        }
        JsonArray obstacles = new JsonArray();
        for (WorldSpec.Obstacle o : world.obstacles()) {
            JsonObject ob = new JsonObject();
            ob.addProperty("shape", o.shape());
            ob.addProperty("x", o.x());
            ob.addProperty("y", o.y());
            if (o.isCircle()) {
                ob.addProperty("radiusM", o.radiusM());
            } else {
                ob.addProperty("widthM", o.widthM());
                ob.addProperty("heightM", o.heightM());
                ob.addProperty("angleDeg", o.angleDeg());
            }
            obstacles.add(ob);
        }
        root.add("obstacles", obstacles);
        if (!fleet) {
            root.add("checkpoints", checkpoints(world.checkpoints()));
        }
        root.addProperty("checkpointRadiusM", world.checkpointRadiusM());
        if (world.rechargeStations().size() > 1) {
            JsonArray stations = new JsonArray();
            world.rechargeStations().forEach(st -> stations.add(station(st)));
            root.add("rechargeStations", stations);
        } else {
            root.add("rechargeStation", station(world.rechargeStation()));
        }
        WorldSpec.Battery b = world.battery();
        JsonObject battery = new JsonObject();
        battery.addProperty("initial", b.initial());
        battery.addProperty("drainPerMeter", b.drainPerMeter());
        battery.addProperty("rechargeTo", b.rechargeTo());
        battery.addProperty("rechargeRatePerS", b.rechargeRatePerS());
        root.add("battery", battery);
        return new GsonBuilder().setPrettyPrinting().create().toJson(root) + "\n";
    }

    /**
     * @return whether the world is written with {@code robots}: several robots, or one whose id is not the
     *         one-robot file's (a one-robot world is written as it always was)
     */
    private static boolean isFleet(WorldSpec world) {
        return world.hasSeveralRobots() || world.robots().get(0).id() != WorldSpec.SINGLE_ROBOT_ID;
    }

    /** Writes a robot's pose and properties into an object ({@code robot}, or a {@code robots} entry after its id). */
    private static void robotProperties(JsonObject robot, WorldSpec.Robot r) {
        robot.addProperty("x", r.x());
        robot.addProperty("y", r.y());
        robot.addProperty("headingDeg", r.headingDeg());
        robot.addProperty("radiusM", r.radiusM());
        robot.addProperty("maxSpeedMps", r.maxSpeedMps());
        robot.addProperty("sensorRangeM", r.sensorRangeM());
        if (!r.sensorAnglesDeg().equals(WorldSpec.Robot.DEFAULT_SENSOR_ANGLES_DEG)) { // a default world's file stays as it was
            JsonArray angles = new JsonArray();
            r.sensorAnglesDeg().forEach(angles::add);
            robot.add("sensorAnglesDeg", angles);
        }
    }

    private static JsonArray checkpoints(List<WorldSpec.Checkpoint> list) {
        JsonArray checkpoints = new JsonArray();
        for (WorldSpec.Checkpoint c : list) {
            JsonObject cp = new JsonObject();
            cp.addProperty("x", c.x());
            cp.addProperty("y", c.y());
            checkpoints.add(cp);
        }
        return checkpoints;
    }

    private static JsonObject station(WorldSpec.RechargeStation st) {
        JsonObject station = new JsonObject();
        station.addProperty("x", st.x());
        station.addProperty("y", st.y());
        station.addProperty("radiusM", st.radiusM());
        return station;
    }

    /**
     * @param world a world
     * @param seed  another seed
     * @return the same world drawing its noise from that seed
     */
    public static WorldSpec withSeed(WorldSpec world, long seed) {
        return new WorldSpec(world.name(), world.timeStepMs(), world.maxSimTimeS(), seed, world.arena(), world.robot(),
                world.obstacles(), world.checkpoints(), world.checkpointRadiusM(), world.rechargeStation(), world.battery(),
                world.robots(), world.rechargeStations());
    }
}
