package org.proactiverobotics.app.foxglove;

import java.util.ArrayList;
import java.util.List;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * The world as one foxglove.SceneUpdate, written once at time 0 from the world the app loaded:
 * the arena's wall, the obstacles (boxes and cylinders 0.3 m tall), the checkpoints (flat discs of
 * the checkpoint radius, numbered in their order), the recharge station, and the robot's body
 * locked to the {@code base_link} frame that /tf moves. Also the pose and quaternion helpers the
 * other messages use.
 */
final class Scene {

    /** Obstacles drawn this tall, m: the simulation is flat, the view is not. */
    private static final double OBSTACLE_HEIGHT_M = 0.3;

    private Scene() {
    }

    static void write(JsonText j, WorldSpec world) {
        write(j, world, false);
    }

    /**
     * The scene of a world with several robots: every robot's checkpoints (labelled "id.k"), every station, and
     * each robot's body locked to its own frame {@link #baseLink(int) robot_N/base_link}.
     */
    static void writeFleet(JsonText j, WorldSpec world) {
        write(j, world, true);
    }

    /** @return the frame of robot {@code id}'s body in a world of several robots */
    static String baseLink(int id) {
        return "robot_" + id + "/base_link";
    }

    private static void write(JsonText j, WorldSpec world, boolean fleet) {
        j.begin().open().name("deletions").openArray().closeArray().name("entities").openArray();

        entity(j, "arena", "world", false);
        j.name("cubes").openArray().closeArray().name("cylinders").openArray().closeArray();
        j.name("lines").openArray().open().name("type").integer(1).name("pose");
        pose(j, 0, 0, 0, 0);
        j.name("thickness").number(0.05, 3).name("scale_invariant").bool(false).name("points").openArray();
        WorldSpec.Arena arena = world.arena();
        if (arena.isCircle()) {
            double r = arena.radiusM();
            for (int k = 0; k < 72; k++) {
                double a = 2 * Math.PI * k / 72;
                point(j, r * StrictMath.cos(a), r * StrictMath.sin(a), 0);
            }
        } else { // the rectangle's corners, counter-clockwise (a line loop, as the circle's points)
            point(j, arena.minX(), arena.minY(), 0);
            point(j, arena.maxX(), arena.minY(), 0);
            point(j, arena.maxX(), arena.maxY(), 0);
            point(j, arena.minX(), arena.maxY(), 0);
        }
        j.closeArray().name("color");
        color(j, 0.4, 0.4, 0.4, 1);
        j.name("colors").openArray().closeArray().name("indices").openArray().closeArray().close().closeArray();
        endEntity(j, List.of());

        entity(j, "obstacles", "world", false);
        j.name("cubes").openArray();
        for (WorldSpec.Obstacle o : world.obstacles()) {
            if (o.isBox()) {
                j.open().name("pose");
                pose(j, o.x(), o.y(), OBSTACLE_HEIGHT_M / 2, o.angleRad());
                j.name("size");
                vector(j, o.widthM(), o.heightM(), OBSTACLE_HEIGHT_M);
                j.name("color");
                color(j, 0.55, 0.35, 0.2, 1);
                j.close();
            }
        }
        j.closeArray().name("cylinders").openArray();
        for (WorldSpec.Obstacle o : world.obstacles()) {
            if (o.isCircle()) {
                cylinder(j, o.x(), o.y(), OBSTACLE_HEIGHT_M / 2, 2 * o.radiusM(), OBSTACLE_HEIGHT_M, 0.55, 0.35, 0.2, 1);
            }
        }
        j.closeArray().name("lines").openArray().closeArray();
        endEntity(j, List.of());

        entity(j, "checkpoints", "world", false);
        j.name("cubes").openArray().closeArray().name("cylinders").openArray();
        List<Label> labels = new ArrayList<>();
        for (WorldSpec.RobotEntry r : fleet ? world.robots() : world.robots().subList(0, 1)) {
            for (int i = 0; i < r.checkpoints().size(); i++) {
                WorldSpec.Checkpoint c = r.checkpoints().get(i);
                cylinder(j, c.x(), c.y(), 0.005, 2 * world.checkpointRadiusM(), 0.01, 1.0, 0.6, 0.0, 0.6);
                labels.add(new Label(c.x(), c.y(), fleet ? r.id() + "." + (i + 1) : Integer.toString(i + 1)));
            }
        }
        j.closeArray().name("lines").openArray().closeArray();
        endEntity(j, labels);

        entity(j, "station", "world", false);
        j.name("cubes").openArray().closeArray().name("cylinders").openArray();
        List<WorldSpec.RechargeStation> stations = fleet ? world.rechargeStations() : List.of(world.rechargeStation());
        for (WorldSpec.RechargeStation s : stations) {
            cylinder(j, s.x(), s.y(), 0.005, 2 * s.radiusM(), 0.01, 0.1, 0.7, 0.2, 0.6);
        }
        j.closeArray().name("lines").openArray().closeArray();
        List<Label> stationLabels = new ArrayList<>();
        for (WorldSpec.RechargeStation s : stations) {
            stationLabels.add(new Label(s.x(), s.y(), "station"));
        }
        endEntity(j, stationLabels);

        if (!fleet) {
            body(j, world.robot().radiusM(), "robot", "base_link");
        } else {
            for (WorldSpec.RobotEntry r : world.robots()) {
                body(j, r.robot().radiusM(), "robot_" + r.id(), baseLink(r.id()));
            }
        }

        j.closeArray().close().end();
    }

    /** A robot's body, a disc with a line to its front, locked to its frame. */
    private static void body(JsonText j, double body, String id, String frame) {
        entity(j, id, frame, true);
        j.name("cubes").openArray().closeArray().name("cylinders").openArray();
        cylinder(j, 0, 0, 0.05, 2 * body, 0.1, 0.2, 0.4, 0.9, 0.9);
        j.closeArray().name("lines").openArray().open().name("type").integer(0).name("pose");
        pose(j, 0, 0, 0, 0);
        j.name("thickness").number(0.02, 3).name("scale_invariant").bool(false).name("points").openArray();
        point(j, 0, 0, 0.11);
        point(j, body, 0, 0.11);
        j.closeArray().name("color");
        color(j, 1, 1, 1, 1);
        j.name("colors").openArray().closeArray().name("indices").openArray().closeArray().close().closeArray();
        endEntity(j, List.of());
    }

    /** A text label at a point of the world. */
    private record Label(double x, double y, String text) {
    }

    private static void entity(JsonText j, String id, String frame, boolean locked) {
        j.open().name("timestamp").time(0).name("frame_id").string(frame).name("id").string(id);
        j.name("lifetime").open().name("sec").integer(0).name("nsec").integer(0).close();
        j.name("frame_locked").bool(locked).name("metadata").openArray().closeArray();
        j.name("arrows").openArray().closeArray().name("spheres").openArray().closeArray();
        j.name("triangles").openArray().closeArray().name("models").openArray().closeArray();
    }

    private static void endEntity(JsonText j, List<Label> labels) {
        j.name("texts").openArray();
        for (Label l : labels) {
            j.open().name("pose");
            pose(j, l.x(), l.y(), 0.35, 0);
            j.name("billboard").bool(true).name("font_size").integer(14).name("scale_invariant").bool(true).name("color");
            color(j, 1, 1, 1, 1);
            j.name("text").string(l.text()).close();
        }
        j.closeArray().close();
    }

    private static void cylinder(JsonText j, double x, double y, double z, double diameter, double height,
                                 double red, double green, double blue, double alpha) {
        j.open().name("pose");
        pose(j, x, y, z, 0);
        j.name("size");
        vector(j, diameter, diameter, height);
        j.name("bottom_scale").integer(1).name("top_scale").integer(1).name("color");
        color(j, red, green, blue, alpha);
        j.close();
    }

    /** A foxglove.Pose: position in m (mm kept), orientation a rotation of {@code yawRad} about z. */
    static void pose(JsonText j, double x, double y, double z, double yawRad) {
        j.open().name("position");
        vector(j, x, y, z);
        j.name("orientation");
        quaternion(j, yawRad);
        j.close();
    }

    static void vector(JsonText j, double x, double y, double z) {
        j.open().name("x").number(x, 3).name("y").number(y, 3).name("z").number(z, 3).close();
    }

    private static void point(JsonText j, double x, double y, double z) {
        vector(j, x, y, z);
    }

    /** A rotation about z, to 6 decimals; StrictMath so that every machine writes the same digits. */
    static void quaternion(JsonText j, double yawRad) {
        j.open().name("x").integer(0).name("y").integer(0).name("z").number(StrictMath.sin(yawRad / 2), 6)
                .name("w").number(StrictMath.cos(yawRad / 2), 6).close();
    }

    private static void color(JsonText j, double r, double g, double b, double a) {
        j.open().name("r").number(r, 3).name("g").number(g, 3).name("b").number(b, 3).name("a").number(a, 3).close();
    }
}
