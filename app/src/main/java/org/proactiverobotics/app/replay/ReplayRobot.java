package org.proactiverobotics.app.replay;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import java.util.List;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * One robot of a world with several robots as replay.html and the live view show it (docs/replay.md): its id,
 * its own body, rays and checkpoints, a line on how its mission went, and its steps. The page draws every robot
 * and shows the picked one's record ({@code #robot=N&iteration=M}).
 *
 * @param id      the robot's id in the world file
 * @param outcome how its mission ended (null while it goes on)
 * @param summary one line on how its mission went (may be empty)
 * @param entry   its entry of the world's robots (start pose, radius in metres, rays, checkpoints)
 * @param steps   its steps
 */
public record ReplayRobot(int id, String outcome, String summary, WorldSpec.RobotEntry entry, ReplayData steps) {

    /**
     * @param from the first step to include ({@link ReplayData#toJson(int)})
     * @return the robot as the page reads it: metres and radians
     */
    public JsonObject toJson(int from) {
        JsonObject o = new JsonObject();
        o.addProperty("id", id);
        o.addProperty("outcome", outcome);
        o.addProperty("summary", summary);
        WorldSpec.Robot robot = entry.robot();
        o.addProperty("robotRadiusM", robot.radiusM());
        o.addProperty("sensorRangeM", robot.sensorRangeM());
        JsonArray angles = new JsonArray();
        for (double deg : robot.sensorAnglesDeg()) {
            angles.add(Math.toRadians(deg));
        }
        o.add("sensorAnglesRad", angles);
        JsonArray checkpoints = new JsonArray();
        for (WorldSpec.Checkpoint cp : entry.checkpoints()) {
            JsonObject p = new JsonObject();
            p.addProperty("x", cp.x());
            p.addProperty("y", cp.y());
            checkpoints.add(p);
        }
        o.add("checkpoints", checkpoints);
        o.add("steps", steps.toJson(from));
        return o;
    }

    /**
     * @param robots every robot, in the world's order
     * @param from   the first step of each to include
     * @return the page's {@code robots}
     */
    public static JsonArray toJson(List<ReplayRobot> robots, int from) {
        JsonArray a = new JsonArray(robots.size());
        for (ReplayRobot r : robots) {
            a.add(r.toJson(from));
        }
        return a;
    }
}
