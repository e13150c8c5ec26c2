package org.proactiverobotics.app.replay;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * The steps of a mission in columns, as replay.html reads them: one primitive array per field
 * (integers in mm, mrad, mm/s, hundredths of %), strings (scenarios, commands, PriorityArrays,
 * reasons) once in a dictionary; the engine's belief as a pose column carried forward and, where
 * they changed, rows of [step, ...] for routes (mm), map deltas (cells) and reasons. A 20-minute mission (37 500 iterations) is a few MB, read by the page at once.
 * Thread-safe: the live view appends while the HTTP server reads.
 */
public final class ReplayData {

    /** Distance readings per step: the robot's rays. */
    private final int rays;

    private final List<String> strings = new ArrayList<>();
    private final Map<String, Integer> stringIds = new HashMap<>();
    private final List<String> slotScenarios = new ArrayList<>();
    private final List<JsonObject> events = new ArrayList<>();
    /** The engine's belief, where it changed: [step, x0, y0, x1, y1, ...] in mm per new route. */
    private final List<int[]> routes = new ArrayList<>();
    /** [step, ix, iy, state, ...] per step whose map cells changed. */
    private final List<int[]> mapDeltas = new ArrayList<>();
    /** [step, string id] per step with a reason. */
    private final List<int[]> reasons = new ArrayList<>();
    /** The pose the engine believed, carried forward (mm, mrad; NONE: not said yet). */
    private int lastBeliefX = NONE;
    private int lastBeliefY = NONE;
    private int lastBeliefHeading = NONE;
    /** Whether any step carried a believed pose: pages without one (the robot process, the live view) leave the columns out. */
    private boolean anyBelief;
    private int[] beliefX = new int[1024];
    private int[] beliefY = new int[1024];
    private int[] beliefHeading = new int[1024];
    private int size;
    private long[] iteration = new long[1024];
    private long[] simTimeMs = new long[1024];
    private int[] x = new int[1024];
    private int[] y = new int[1024];
    private int[] heading = new int[1024];
    private int[] gpsX = new int[1024];
    private int[] gpsY = new int[1024];
    private int[] yaw = new int[1024];
    private int[] scan;
    private int[] seenBattery = new int[1024];
    private int[] battery = new int[1024];
    private int[] charging = new int[1024];
    private int[] left = new int[1024];
    private int[] right = new int[1024];
    private int[] winner = new int[1024];
    private int[] command = new int[1024];
    private int[] priorities = new int[1024];
    /** Per slot scenario, its suggestion's string id (-1: none) by step. */
    private final Map<String, int[]> suggestions = new LinkedHashMap<>();

    /** Marker of a missing integer value (a reading not seen yet). */
    public static final int NONE = Integer.MIN_VALUE;

    /**
     * A replay of a robot with the default distance rays.
     *
     * @param slots each suggesting scenario's CommandArray slot (the columns of suggestions, in slot order)
     */
    public ReplayData(Map<String, Integer> slots) {
        this(slots, WorldSpec.Robot.DEFAULT_SENSOR_ANGLES_DEG.size());
    }

    /**
     * @param slots each suggesting scenario's CommandArray slot (the columns of suggestions, in slot order)
     * @param rays  the robot's distance rays (readings kept per step)
     */
    public ReplayData(Map<String, Integer> slots, int rays) {
        this.rays = rays;
        this.scan = new int[1024 * rays];
        slots.entrySet().stream().sorted(Map.Entry.comparingByValue()).forEach(e -> slotScenarios.add(e.getKey()));
        for (String s : slotScenarios) {
            suggestions.put(s, new int[1024]);
        }
    }

    /** @return steps recorded */
    public synchronized int size() {
        return size;
    }

    /** @return the last iteration recorded, or -1 */
    public synchronized long lastIteration() {
        return size == 0 ? -1 : iteration[size - 1];
    }

    /** Appends one step. */
    public synchronized void add(TraceStep s) {
        grow();
        int i = size;
        iteration[i] = s.iteration();
        simTimeMs[i] = s.simTimeMs();
        x[i] = milli(s.xM());
        y[i] = milli(s.yM());
        heading[i] = milli(s.headingRad());
        gpsX[i] = milli(s.gpsXM());
        gpsY[i] = milli(s.gpsYM());
        yaw[i] = milli(s.yawRad());
        for (int k = 0; k < rays; k++) {
            scan[i * rays + k] = s.scanM() == null || k >= s.scanM().length ? NONE : milli(s.scanM()[k]);
        }
        seenBattery[i] = centi(s.seenBattery());
        battery[i] = centi(s.batteryPct());
        charging[i] = s.charging() ? 1 : 0;
        left[i] = milli(s.leftMps());
        right[i] = milli(s.rightMps());
        winner[i] = id(s.winner());
        command[i] = id(s.command());
        priorities[i] = s.priorities() == null ? -1 : id(prioritiesText(s.priorities()));
        for (Map.Entry<String, int[]> e : suggestions.entrySet()) {
            String text = s.suggestions() == null ? null : s.suggestions().get(e.getKey());
            e.getValue()[i] = text == null ? -1 : id(text);
        }
        TraceBelief b = s.belief();
        if (b != null && b.pose() != null) {
            lastBeliefX = milli(b.pose()[0]);
            lastBeliefY = milli(b.pose()[1]);
            lastBeliefHeading = milli(b.pose()[2]);
            anyBelief = true;
        }
        beliefX[i] = lastBeliefX;
        beliefY[i] = lastBeliefY;
        beliefHeading[i] = lastBeliefHeading;
        if (b != null && b.route() != null) {
            int[] r = new int[1 + b.route().length];
            r[0] = i;
            for (int k = 0; k < b.route().length; k++) {
                r[k + 1] = milli(b.route()[k]);
            }
            routes.add(r);
        }
        if (b != null && b.mapDelta() != null) {
            int[] d = new int[1 + b.mapDelta().length];
            d[0] = i;
            System.arraycopy(b.mapDelta(), 0, d, 1, b.mapDelta().length);
            mapDeltas.add(d);
        }
        if (b != null && b.reason() != null) {
            reasons.add(new int[] {i, id(b.reason())});
        }
        for (TraceEvent ev : s.events()) {
            JsonObject o = ev.toJson();
            o.addProperty("step", i);
            events.add(o);
        }
        size++;
    }

    /**
     * @param from the first step to include
     * @return the steps from {@code from} on, in columns, with the whole string dictionary and the events
     */
    public synchronized JsonObject toJson(int from) {
        int n = Math.max(0, size - from);
        JsonObject o = new JsonObject();
        o.addProperty("from", from);
        o.addProperty("count", n);
        o.add("strings", strings(strings));
        o.add("slots", strings(slotScenarios));
        o.add("iteration", longs(iteration, from, n));
        o.add("simTimeMs", longs(simTimeMs, from, n));
        o.add("x", ints(x, from, n));
        o.add("y", ints(y, from, n));
        o.add("heading", ints(heading, from, n));
        o.add("gpsX", ints(gpsX, from, n));
        o.add("gpsY", ints(gpsY, from, n));
        o.add("yaw", ints(yaw, from, n));
        o.addProperty("rays", rays);
        o.add("scan", ints(scan, from * rays, n * rays));
        o.add("seenBattery", ints(seenBattery, from, n));
        o.add("battery", ints(battery, from, n));
        o.add("charging", ints(charging, from, n));
        o.add("left", ints(left, from, n));
        o.add("right", ints(right, from, n));
        o.add("winner", ints(winner, from, n));
        o.add("command", ints(command, from, n));
        o.add("priorities", ints(priorities, from, n));
        JsonObject sug = new JsonObject();
        suggestions.forEach((scenario, ids) -> sug.add(scenario, ints(ids, from, n)));
        o.add("suggestions", sug);
        if (anyBelief) {
            o.add("beliefX", ints(beliefX, from, n));
            o.add("beliefY", ints(beliefY, from, n));
            o.add("beliefHeading", ints(beliefHeading, from, n));
        }
        o.add("routes", since(routes, from));
        o.add("mapDeltas", since(mapDeltas, from));
        o.add("reasons", since(reasons, from));
        JsonArray ev = new JsonArray();
        events.stream().filter(e -> e.get("step").getAsInt() >= from).forEach(ev::add);
        o.add("events", ev);
        return o;
    }

    /** The sparse rows ([step, ...]) of the steps from {@code from} on. */
    private static JsonArray since(List<int[]> rows, int from) {
        JsonArray a = new JsonArray();
        for (int[] r : rows) {
            if (r[0] >= from) {
                JsonArray row = new JsonArray(r.length);
                for (int v : r) {
                    row.add(v);
                }
                a.add(row);
            }
        }
        return a;
    }

    private int id(String s) {
        Integer known = stringIds.get(s);
        if (known != null) {
            return known;
        }
        strings.add(s);
        stringIds.put(s, strings.size() - 1);
        return strings.size() - 1;
    }

    /** The PriorityArray as text, highest first: "ObstacleAvoidance=3 BatteryMonitor=2 ...". */
    private static String prioritiesText(Map<String, Integer> p) {
        StringBuilder b = new StringBuilder();
        p.entrySet().stream().sorted((a, c) -> Integer.compare(c.getValue(), a.getValue())).forEach(e -> {
            if (b.length() > 0) {
                b.append(' ');
            }
            b.append(e.getKey()).append('=').append(e.getValue());
        });
        return b.toString();
    }

    private void grow() {
        if (size < iteration.length) {
            return;
        }
        int n = iteration.length * 2;
        iteration = Arrays.copyOf(iteration, n);
        simTimeMs = Arrays.copyOf(simTimeMs, n);
        x = Arrays.copyOf(x, n);
        y = Arrays.copyOf(y, n);
        heading = Arrays.copyOf(heading, n);
        gpsX = Arrays.copyOf(gpsX, n);
        gpsY = Arrays.copyOf(gpsY, n);
        yaw = Arrays.copyOf(yaw, n);
        scan = Arrays.copyOf(scan, n * rays);
        seenBattery = Arrays.copyOf(seenBattery, n);
        battery = Arrays.copyOf(battery, n);
        charging = Arrays.copyOf(charging, n);
        left = Arrays.copyOf(left, n);
        right = Arrays.copyOf(right, n);
        winner = Arrays.copyOf(winner, n);
        command = Arrays.copyOf(command, n);
        priorities = Arrays.copyOf(priorities, n);
        beliefX = Arrays.copyOf(beliefX, n);
        beliefY = Arrays.copyOf(beliefY, n);
        beliefHeading = Arrays.copyOf(beliefHeading, n);
        suggestions.replaceAll((k, v) -> Arrays.copyOf(v, n));
    }

    private static int milli(double v) {
        return Double.isFinite(v) ? (int) Math.round(v * 1000.0) : NONE;
    }

    private static int centi(double v) {
        return Double.isFinite(v) ? (int) Math.round(v * 100.0) : NONE;
    }

    private static JsonArray strings(List<String> list) {
        JsonArray a = new JsonArray(list.size());
        list.forEach(a::add);
        return a;
    }

    private static JsonArray longs(long[] values, int from, int n) {
        JsonArray a = new JsonArray(n);
        for (int i = from; i < from + n; i++) {
            a.add(values[i]);
        }
        return a;
    }

    /** Missing values become JSON null. */
    private static JsonArray ints(int[] values, int from, int n) {
        JsonArray a = new JsonArray(n);
        for (int i = from; i < from + n; i++) {
            if (values[i] == NONE) {
                a.add((Number) null);
            } else {
                a.add(values[i]);
            }
        }
        return a;
    }
}
