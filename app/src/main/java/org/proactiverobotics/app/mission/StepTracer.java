package org.proactiverobotics.app.mission;

import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.proactiverobotics.app.foxglove.McapRecorder;
import org.proactiverobotics.app.replay.ReplayData;
import org.proactiverobotics.app.replay.SeenReadings;
import org.proactiverobotics.app.replay.TraceBelief;
import org.proactiverobotics.app.replay.TraceEvent;
import org.proactiverobotics.app.replay.TraceStep;
import org.proactiverobotics.engine.CommandArray;
import org.proactiverobotics.engine.PriorityArray;
import org.proactiverobotics.engine.RuleFailure;
import org.proactiverobotics.engine.SharedMemory;
import org.proactiverobotics.engine.Suggestion;
import org.proactiverobotics.engine.scenario.failsafe.WatchFailures;
import org.proactiverobotics.engine.tables.DistanceScan;
import org.proactiverobotics.sim2d.GroundTruth;
import org.proactiverobotics.sim2d.Simulation;

/**
 * Puts together, for each control step of the one-process mission, the engine's decision, what
 * its rules saw and believed ({@link BeliefTracer}), the robot's ground truth and the step's events, and hands the
 * {@link TraceStep} to trace.jsonl, to the replay and, with --mcap, to run.mcap.
 */
final class StepTracer {

    private final Simulation sim;
    /** The robot's position in the world's robots. */
    private final int index;
    /** The robot's id written on each line, or null in a one-robot world (no {@code robot} key). */
    private final Integer robotId;
    private final TraceWriter trace;
    private final ReplayData replay;
    private final BeliefTracer belief;
    /** run.mcap's recorder, or null without --mcap. */
    private final McapRecorder mcap;
    private SeenReadings seen;
    private Map<String, Integer> slots = Map.of();
    private Map<String, Integer> priorities = Map.of();
    private int[] priorityOrder;
    private Map<String, Integer> prioritySlots;
    private final Map<String, String> failSafeRecords = new HashMap<>();
    private final List<TraceEvent> pending = new ArrayList<>();
    private int checkpoints;
    private int recharges;
    private int collisions;
    private boolean charging;
    // the decision of the running iteration, copied (the CommandArray is valid during the call only)
    private long decidedIteration = -1;
    private Map<String, String> suggestions;
    private String winner;
    private String command;
    private long simTimeMs;
    private double x;
    private double y;
    private double heading;
    private double battery;
    private boolean chargingAtStep;
    private double left;
    private double right;

    StepTracer(Simulation sim, TraceWriter trace, ReplayData replay, BeliefTracer belief, McapRecorder mcap) {
        this(sim, 0, null, trace, replay, belief, mcap);
    }

    /**
     * @param sim     the simulation
     * @param index   the robot's position in the world's robots
     * @param robotId its id on each trace line, or null for none (a one-robot world)
     * @param trace   trace.jsonl
     * @param replay  the replay's columns of this robot
     * @param belief  this robot's engine's belief
     * @param mcap    run.mcap's recorder, or null
     */
    StepTracer(Simulation sim, int index, Integer robotId, TraceWriter trace, ReplayData replay, BeliefTracer belief,
               McapRecorder mcap) {
        this.sim = sim;
        this.index = index;
        this.robotId = robotId;
        this.trace = trace;
        this.replay = replay;
        this.belief = belief;
        this.mcap = mcap;
        GroundTruth t = sim.groundTruth(index);
        this.checkpoints = t.checkpointsReached();
        this.recharges = t.recharges();
        this.collisions = t.collisions();
        this.charging = sim.robot(index).battery().isCharging();
    }

    void seen(SeenReadings readings) {
        this.seen = readings;
    }

    void slots(Map<String, Integer> engineSlots) {
        this.slots = engineSlots;
    }

    /** The decision rule's observer: copies the CommandArray and the winner. */
    void decided(long iteration, CommandArray array, Suggestion won) {
        Map<String, String> entered = new LinkedHashMap<>();
        for (int slot = 0; slot < array.size(); slot++) {
            Suggestion s = array.get(slot);
            if (s != null) {
                entered.put(s.scenario(), s.command());
            }
        }
        decidedIteration = iteration;
        suggestions = entered;
        winner = won.scenario();
        command = won.command();
    }

    /** After the robot acted, before the world steps: the pose the iteration saw, the wheels it set. */
    void beforePhysics() {
        GroundTruth t = sim.groundTruth(index);
        simTimeMs = sim.simTimeMs();
        x = t.x();
        y = t.y();
        heading = t.headingRad();
        battery = t.batteryPct();
        chargingAtStep = sim.robot(index).battery().isCharging();
        left = sim.robot(index).leftSpeedMps();
        right = sim.robot(index).rightSpeedMps();
    }

    /**
     * After the world stepped: the step's events; writes the step when its iteration decided.
     *
     * @param memory   the engine's shared memory at the end of the iteration
     * @param failures the iteration's rule failures
     */
    void afterPhysics(SharedMemory memory, List<RuleFailure> failures) {
        for (RuleFailure f : failures) {
            pending.add(TraceEvent.ruleFailure(f.iteration(), f.scenario(), f.rule(), String.valueOf(f.part()), f.message()));
        }
        for (Map.Entry<String, String> e : memory.values().entrySet()) {
            if (e.getKey().startsWith(WatchFailures.RECORD_PREFIX)
                    && !e.getValue().equals(failSafeRecords.put(e.getKey(), e.getValue()))) {
                pending.add(TraceEvent.failSafe(e.getKey().substring(WatchFailures.RECORD_PREFIX.length()), e.getValue()));
            }
        }
        GroundTruth t = sim.groundTruth(index);
        while (checkpoints < t.checkpointsReached()) {
            pending.add(TraceEvent.checkpoint(checkpoints++));
        }
        if (t.recharges() > recharges) {
            recharges = t.recharges();
            pending.add(TraceEvent.of(TraceEvent.RECHARGE_STARTED));
        }
        boolean nowCharging = sim.robot(index).battery().isCharging();
        if (charging && !nowCharging) {
            pending.add(TraceEvent.of(TraceEvent.RECHARGE_FINISHED));
        }
        charging = nowCharging;
        if (t.collisions() > collisions) {
            collisions = t.collisions();
            pending.add(TraceEvent.of(TraceEvent.COLLISION));
        }
        if (decidedIteration < 0) {
            return; // StartUp's and the meta-rules' iterations decide nothing: their events go with the next line
        }
        TraceBelief believed = belief.take(decidedIteration, winner, pending);
        TraceStep step = new TraceStep(decidedIteration, simTimeMs, suggestions, winner, command,
                priorities(memory.priorityArray()), x, y, heading,
                seen == null || seen.gps() == null ? Double.NaN : seen.gps().xM(),
                seen == null || seen.gps() == null ? Double.NaN : seen.gps().yM(),
                seen == null || seen.heading() == null ? Double.NaN : seen.heading().yawRad(),
                seen == null || seen.scan() == null ? null : scan(seen.scan()),
                seen == null || seen.battery() == null ? Double.NaN : seen.battery().levelPct(),
                battery, chargingAtStep, left, right, List.copyOf(pending), believed);
        pending.clear();
        decidedIteration = -1;
        trace.write(step, robotId);
        replay.add(step);
        if (mcap != null) {
            mcap.record(step);
        }
    }

    /** Highest priority first, as the decision reads it; built again only when the PriorityArray changed. */
    private Map<String, Integer> priorities(PriorityArray array) {
        int[] order = array.slotsByPriority(); // the same array until a priority changes
        if (order != priorityOrder || slots != prioritySlots) {
            Map<String, Integer> p = new LinkedHashMap<>();
            slots.entrySet().stream().filter(e -> e.getValue() < array.size())
                    .sorted((a, b) -> Integer.compare(array.get(b.getValue()), array.get(a.getValue())))
                    .forEach(e -> p.put(e.getKey(), array.get(e.getValue())));
            priorities = Collections.unmodifiableMap(p);
            priorityOrder = order;
            prioritySlots = slots;
        }
        return priorities;
    }

    private static double[] scan(DistanceScan s) {
        return s.distancesM();
    }
}
