package org.proactiverobotics.app.replay;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonPrimitive;
import com.google.gson.JsonNull;
import com.google.gson.JsonObject;
import java.util.List;
import java.util.Map;

/**
 * What happened at one engine iteration, as trace.jsonl writes it and replay.html shows it: the
 * decision (suggestions, winner, command, PriorityArray), the robot's ground-truth pose, wheels and
 * battery, the readings the engine saw, and the iteration's events.
 *
 * @param iteration    the engine iteration
 * @param simTimeMs    the simulated time of its control step, ms
 * @param suggestions  scenario → live suggestion at the decision; null when unknown (the robot process)
 * @param winner       the winning scenario (the robot process: the scenario of the command it executed)
 * @param command      the winning command, in the robot's grammar
 * @param priorities   scenario → priority (the PriorityArray by slot owner); null when unknown
 * @param xM           ground-truth x, m
 * @param yM           ground-truth y, m
 * @param headingRad   ground-truth heading, rad (0 = +x, counter-clockwise)
 * @param gpsXM        GPS x the engine saw, m (NaN: none)
 * @param gpsYM        GPS y the engine saw, m (NaN: none)
 * @param yawRad       inertial-unit yaw the engine saw, rad (NaN: none)
 * @param scanM        distance readings the engine saw, m, by sensor index (null: none)
 * @param seenBattery  battery reading the engine saw, % (NaN: none)
 * @param batteryPct   ground-truth battery, %
 * @param charging     whether the robot is charging (ground truth)
 * @param leftMps      ground-truth left wheel speed, m/s
 * @param rightMps     ground-truth right wheel speed, m/s
 * @param events       what happened during this iteration's control step, in order
 */
public record TraceStep(long iteration, long simTimeMs, Map<String, String> suggestions, String winner,
                        String command, Map<String, Integer> priorities, double xM, double yM, double headingRad,
                        double gpsXM, double gpsYM, double yawRad, double[] scanM, double seenBattery,
                        double batteryPct, boolean charging, double leftMps, double rightMps,
                        List<TraceEvent> events) {

    /** The version of trace.jsonl's line format; 1 had only iteration, simTimeS, suggestions, winner, command. */
    public static final int SCHEMA_VERSION = 2;

    /** @return the trace.jsonl line (without the newline) */
    public JsonObject toJson() {
        JsonObject line = new JsonObject();
        line.addProperty("schemaVersion", SCHEMA_VERSION);
        line.addProperty("iteration", iteration);
        line.addProperty("simTimeS", simTimeMs / 1000.0);
        JsonObject entered = new JsonObject();
        if (suggestions != null) {
            suggestions.forEach(entered::addProperty);
        }
        line.add("suggestions", entered);
        line.addProperty("winner", winner);
        line.addProperty("command", command);
        JsonObject pa = new JsonObject();
        if (priorities != null) {
            priorities.forEach(pa::addProperty);
        }
        line.add("priorities", pa);
        JsonObject pose = new JsonObject();
        pose.addProperty("xM", mm(xM));
        pose.addProperty("yM", mm(yM));
        pose.addProperty("headingRad", mm(headingRad));
        line.add("pose", pose);
        JsonObject seen = new JsonObject();
        if (Double.isNaN(gpsXM)) {
            seen.add("gps", JsonNull.INSTANCE);
        } else {
            JsonObject gps = new JsonObject();
            gps.addProperty("xM", mm(gpsXM));
            gps.addProperty("yM", mm(gpsYM));
            seen.add("gps", gps);
        }
        seen.add("headingRad", number(yawRad));
        if (scanM == null) {
            seen.add("scanM", JsonNull.INSTANCE);
        } else {
            JsonArray scan = new JsonArray(scanM.length);
            for (double d : scanM) {
                scan.add(number(d));
            }
            seen.add("scanM", scan);
        }
        seen.add("batteryPct", Double.isNaN(seenBattery) ? JsonNull.INSTANCE : new JsonPrimitive(hundredths(seenBattery)));
        line.add("seen", seen);
        line.addProperty("batteryPct", hundredths(batteryPct));
        line.addProperty("charging", charging);
        JsonArray wheels = new JsonArray(2);
        wheels.add(mm(leftMps));
        wheels.add(mm(rightMps));
        line.add("wheelsMps", wheels);
        JsonArray happened = new JsonArray(events.size());
        events.forEach(e -> happened.add(e.toJson()));
        line.add("events", happened);
        return line;
    }

    private static JsonElement number(double v) {
        return Double.isFinite(v) ? new JsonPrimitive(mm(v)) : JsonNull.INSTANCE;
    }

    /** Three decimals: a millimetre, a milliradian; keeps the line short. */
    static double mm(double v) {
        return Math.round(v * 1000.0) / 1000.0;
    }

    static double hundredths(double v) {
        return Math.round(v * 100.0) / 100.0;
    }
}
