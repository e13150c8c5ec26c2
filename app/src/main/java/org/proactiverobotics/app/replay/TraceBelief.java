package org.proactiverobotics.app.replay;

import com.google.gson.stream.JsonWriter;
import java.io.IOException;

/**
 * What the engine believed at one iteration, as far as it changed since the last record: the
 * optional fields of a trace.jsonl line (schemaVersion 3, docs/replay.md). Every part may be
 * absent (null); a reader carries the last pose and route forward and applies map deltas in order.
 *
 * @param pose     the pose the scenarios used, {x, y, heading} in metres and radians; null: unchanged
 * @param route    the route's waypoints, {x0, y0, x1, y1, ...} metres; null: unchanged; empty: dropped
 * @param mapDelta the map's changed cells, {ix, iy, state, ...} sorted by (iy, ix), state 0 unknown, 1 free,
 *                 2 occupied; null: none
 * @param reason   why ObstacleAvoidance replaced the command or a checkpoint was declared unreachable; null: none
 */
public record TraceBelief(double[] pose, double[] route, int[] mapDelta, String reason) {

    /**
     * Writes the fields present, inside the line's object.
     *
     * @param w the line's writer, after another field
     * @throws IOException when the writer fails
     */
    void write(JsonWriter w) throws IOException {
        if (pose != null) {
            w.name("belief").beginObject().name("xM").jsonValue(TraceStep.mmText(pose[0]))
                    .name("yM").jsonValue(TraceStep.mmText(pose[1]))
                    .name("headingRad").jsonValue(TraceStep.mmText(pose[2])).endObject();
        }
        if (route != null) {
            w.name("route").beginArray();
            for (int k = 0; k + 1 < route.length; k += 2) {
                w.beginArray().jsonValue(TraceStep.mmText(route[k])).jsonValue(TraceStep.mmText(route[k + 1])).endArray();
            }
            w.endArray();
        }
        if (mapDelta != null) {
            w.name("mapDelta").beginArray();
            for (int k = 0; k + 2 < mapDelta.length; k += 3) {
                w.beginArray().value(mapDelta[k]).value(mapDelta[k + 1]).value(mapDelta[k + 2]).endArray();
            }
            w.endArray();
        }
        if (reason != null) {
            w.name("reason").value(reason);
        }
    }
}
