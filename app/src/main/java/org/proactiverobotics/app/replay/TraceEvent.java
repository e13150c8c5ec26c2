package org.proactiverobotics.app.replay;

import com.google.gson.JsonObject;
import java.util.Objects;

/**
 * Something that happened at one iteration and that a replay can jump to: a checkpoint reached or
 * declared unreachable, a recharge started or finished, a collision, a rule failure, a fail-safe action.
 *
 * @param type   one of the {@code TYPE_} constants
 * @param detail the event's own fields (index, scenario, rule, part, message, action), never null
 */
public record TraceEvent(String type, JsonObject detail) {

    /** The robot's centre came within a checkpoint's radius, in order (ground truth). */
    public static final String CHECKPOINT = "checkpointReached";
    /** The engine declared a checkpoint unreachable (no route to it on its map): the mission ends. */
    public static final String CHECKPOINT_UNREACHABLE = "checkpointUnreachable";
    /** The robot started charging at the station. */
    public static final String RECHARGE_STARTED = "rechargeStarted";
    /** The robot stopped charging. */
    public static final String RECHARGE_FINISHED = "rechargeFinished";
    /** A new contact with the wall or an obstacle (ground truth). */
    public static final String COLLISION = "collision";
    /** A rule part threw. */
    public static final String RULE_FAILURE = "ruleFailure";
    /** The fail-safe recorded an action for a scenario. */
    public static final String FAIL_SAFE = "failSafe";

    /** Checks the parts. */
    public TraceEvent {
        Objects.requireNonNull(type, "type");
        detail = detail == null ? new JsonObject() : detail;
    }

    /** @return checkpoint {@code index} (from 0, in the world's order) reached */
    public static TraceEvent checkpoint(int index) {
        JsonObject d = new JsonObject();
        d.addProperty("index", index);
        return new TraceEvent(CHECKPOINT, d);
    }

    /** @return checkpoint {@code index} (from 0, in the world's order) declared unreachable by the engine */
    public static TraceEvent checkpointUnreachable(int index) {
        JsonObject d = new JsonObject();
        d.addProperty("index", index);
        return new TraceEvent(CHECKPOINT_UNREACHABLE, d);
    }

    /** @return an event with no fields of its own */
    public static TraceEvent of(String type) {
        return new TraceEvent(type, new JsonObject());
    }

    /** @return a rule failure as the engine recorded it */
    public static TraceEvent ruleFailure(long iteration, String scenario, String rule, String part, String message) {
        JsonObject d = new JsonObject();
        d.addProperty("iteration", iteration);
        d.addProperty("scenario", scenario);
        d.addProperty("rule", rule);
        d.addProperty("part", part);
        d.addProperty("message", message);
        return new TraceEvent(RULE_FAILURE, d);
    }

    /** @return the fail-safe's record for a scenario (its {@code FailSafe.<scenario>} value) */
    public static TraceEvent failSafe(String scenario, String action) {
        JsonObject d = new JsonObject();
        d.addProperty("scenario", scenario);
        d.addProperty("action", action);
        return new TraceEvent(FAIL_SAFE, d);
    }

    /** @return {"type": ..., the detail's fields...} */
    public JsonObject toJson() {
        JsonObject o = new JsonObject();
        o.addProperty("type", type);
        detail.entrySet().forEach(e -> o.add(e.getKey(), e.getValue()));
        return o;
    }
}
