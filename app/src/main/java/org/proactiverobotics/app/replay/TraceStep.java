package org.proactiverobotics.app.replay;

import com.google.gson.Gson;
import com.google.gson.GsonBuilder;
import com.google.gson.stream.JsonWriter;
import java.io.IOException;
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
 * @param belief       what the engine believed, as far as it changed (null: nothing known, the robot process)
 */
public record TraceStep(long iteration, long simTimeMs, Map<String, String> suggestions, String winner,
                        String command, Map<String, Integer> priorities, double xM, double yM, double headingRad,
                        double gpsXM, double gpsYM, double yawRad, double[] scanM, double seenBattery,
                        double batteryPct, boolean charging, double leftMps, double rightMps,
                        List<TraceEvent> events, TraceBelief belief) {

    /**
     * The version of trace.jsonl's line format; 1 had only iteration, simTimeS, suggestions, winner,
     * command; 3 added the optional belief, route, mapDelta and reason.
     */
    public static final int SCHEMA_VERSION = 3;

    /** A step without the engine's belief (the robot process, or a caller that has none). */
    public TraceStep(long iteration, long simTimeMs, Map<String, String> suggestions, String winner,
                     String command, Map<String, Integer> priorities, double xM, double yM, double headingRad,
                     double gpsXM, double gpsYM, double yawRad, double[] scanM, double seenBattery,
                     double batteryPct, boolean charging, double leftMps, double rightMps,
                     List<TraceEvent> events) {
        this(iteration, simTimeMs, suggestions, winner, command, priorities, xM, yM, headingRad, gpsXM, gpsYM, yawRad,
                scanM, seenBattery, batteryPct, charging, leftMps, rightMps, events, null);
    }
    /** Writes an event as JsonElement.toString() would: nulls kept, no HTML escaping. */
    private static final Gson EVENTS = new GsonBuilder().serializeNulls().disableHtmlEscaping().create();

    /**
     * Writes the line's object.
     *
     * @param w where (lenient: a NaN never reaches it, each becomes null first)
     * @throws IOException when the writer fails
     */
    public void write(JsonWriter w) throws IOException {
        write(w, null);
    }

    /**
     * Writes the line's object, with the robot's id in a world with several robots.
     *
     * @param w       where (lenient: a NaN never reaches it, each becomes null first)
     * @param robotId the robot's id, written as {@code robot} after {@code schemaVersion}; null (a one-robot
     *                world) writes no {@code robot} key
     * @throws IOException when the writer fails
     */
    public void write(JsonWriter w, Integer robotId) throws IOException {
        w.beginObject();
        w.name("schemaVersion").value(SCHEMA_VERSION);
        if (robotId != null) {
            w.name("robot").value(robotId.intValue());
        }
        w.name("iteration").value(iteration);
        w.name("simTimeS").jsonValue(Decimals.of(simTimeMs, 3));
        w.name("suggestions").beginObject();
        if (suggestions != null) {
            for (Map.Entry<String, String> e : suggestions.entrySet()) {
                w.name(e.getKey()).value(e.getValue());
            }
        }
        w.endObject();
        w.name("winner").value(winner);
        w.name("command").value(command);
        w.name("priorities").beginObject();
        if (priorities != null) {
            for (Map.Entry<String, Integer> e : priorities.entrySet()) {
                w.name(e.getKey()).value(e.getValue());
            }
        }
        w.endObject();
        w.name("pose").beginObject();
        w.name("xM").jsonValue(mmText(xM)).name("yM").jsonValue(mmText(yM)).name("headingRad").jsonValue(mmText(headingRad));
        w.endObject();
        w.name("seen").beginObject();
        w.name("gps");
        if (Double.isNaN(gpsXM)) {
            w.nullValue();
        } else {
            w.beginObject().name("xM").jsonValue(mmText(gpsXM)).name("yM").jsonValue(mmText(gpsYM)).endObject();
        }
        number(w.name("headingRad"), yawRad);
        w.name("scanM");
        if (scanM == null) {
            w.nullValue();
        } else {
            w.beginArray();
            for (double d : scanM) {
                number(w, d);
            }
            w.endArray();
        }
        w.name("batteryPct");
        if (Double.isNaN(seenBattery)) {
            w.nullValue();
        } else {
            w.jsonValue(hundredthsText(seenBattery));
        }
        w.endObject();
        w.name("batteryPct").jsonValue(hundredthsText(batteryPct));
        w.name("charging").value(charging);
        w.name("wheelsMps").beginArray().jsonValue(mmText(leftMps)).jsonValue(mmText(rightMps)).endArray();
        w.name("events").beginArray();
        for (TraceEvent e : events) {
            EVENTS.toJson(e.toJson(), w);
        }
        w.endArray();
        if (belief != null) {
            belief.write(w);
        }
        w.endObject();
    }

    private static void number(JsonWriter w, double v) throws IOException {
        if (Double.isFinite(v)) {
            w.jsonValue(mmText(v));
        } else {
            w.nullValue();
        }
    }

    /** Three decimals: a millimetre, a milliradian; keeps the line short. */
    static double mm(double v) {
        return Math.round(v * 1000.0) / 1000.0;
    }

    /** {@link #mm} as JSON writes it, without Double.toString (the trace's top cost). */
    static String mmText(double v) {
        return Decimals.of(Math.round(v * 1000.0), 3);
    }

    private static String hundredthsText(double v) {
        return Decimals.of(Math.round(v * 100.0), 2);
    }

    static double hundredths(double v) {
        return Math.round(v * 100.0) / 100.0;
    }
}
