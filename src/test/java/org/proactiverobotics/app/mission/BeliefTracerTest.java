package org.proactiverobotics.app.mission;

import static org.assertj.core.api.Assertions.assertThat;

import com.google.gson.Strictness;
import com.google.gson.stream.JsonWriter;
import java.io.IOException;
import java.io.StringWriter;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.proactiverobotics.app.replay.TraceBelief;
import org.proactiverobotics.app.replay.TraceEvent;
import org.proactiverobotics.app.replay.TraceStep;
import org.proactiverobotics.engine.tables.OccupancyMap;

/**
 * What the engine said it believed becomes trace deltas: map cells whose state changed, sorted by
 * (iy, ix) with negative indices in their place, the evidence bytes of occupied cells as state 2;
 * a pose or route only when it changed at the trace's resolution; a veto's reason only at an
 * iteration ObstacleAvoidance won; a checkpoint declared unreachable as reason and event.
 */
class BeliefTracerTest {

    private final BeliefTracer tracer = new BeliefTracer();
    private final List<TraceEvent> events = new ArrayList<>();

    @Test
    void mapDeltasAreTheCellsWhoseStateChangedSortedByRowThenColumn() throws IOException {
        OccupancyMap map = OccupancyMap.empty();
        map.miss(3, -1);   // chunk (0, -1): free
        map.hit(-2, -1);   // chunk (-1, -1): occupied, evidence 3
        map.miss(-17, 5);  // chunk (-2, 0)
        map.confirm(0, 0); // chunk (0, 0): evidence 6, still state 2
        tracer.mapChanged(5, map.takeChanged());
        TraceBelief b = tracer.take(5, "ReachDestination", events);
        assertThat(b.mapDelta()).containsExactly(-2, -1, 2, 3, -1, 1, 0, 0, 2, -17, 5, 1);

        map.hit(-2, -1); // more evidence, the same state: no delta
        map.miss(4, -1);
        tracer.mapChanged(6, map.takeChanged());
        assertThat(tracer.take(6, "ReachDestination", events).mapDelta()).containsExactly(4, -1, 1);
        assertThat(line(tracer.take(7, "ReachDestination", events))).as("nothing changed").isNull();
    }

    @Test
    void aPoseOrARouteIsWrittenOnlyWhenItChangedAtTheTracesResolution() {
        tracer.pose(3, 1.0, 2.0, 0.5);
        tracer.route(3, "ReachDestination", new double[] {1.0, 3.0}, new double[] {2.0, 2.0});
        TraceBelief first = tracer.take(3, "ReachDestination", events);
        assertThat(first.pose()).containsExactly(1.0, 2.0, 0.5);
        assertThat(first.route()).containsExactly(1.0, 2.0, 3.0, 2.0);

        tracer.pose(4, 1.0002, 2.0, 0.5); // under a millimetre
        tracer.route(4, "ReachDestination", new double[] {1.0, 3.0}, new double[] {2.0, 2.0}); // planned again, the same
        assertThat(tracer.take(4, "ReachDestination", events)).isNull();

        tracer.route(5, "ReachDestination", new double[0], new double[0]);
        assertThat(tracer.take(5, "ReachDestination", events).route()).isEmpty();
        tracer.route(6, "ReachDestination", new double[0], new double[0]);
        assertThat(tracer.take(6, "ReachDestination", events)).as("dropped once").isNull();
    }

    @Test
    void theRouteTracedIsTheOneOfTheScenarioWhoseCommandWon() {
        tracer.route(3, "BatteryMonitor", new double[] {0.0, -3.0}, new double[] {0.0, 0.0}); // to the station
        tracer.route(3, "ReachDestination", new double[] {0.0, 2.0}, new double[] {0.0, 1.0}); // to a checkpoint
        assertThat(tracer.take(3, "BatteryMonitor", events).route()).containsExactly(0.0, 0.0, -3.0, 0.0);
        assertThat(tracer.take(4, "ObstacleAvoidance", events)).as("a veto follows no route of its own").isNull();
        assertThat(tracer.take(5, "ReachDestination", events).route()).containsExactly(0.0, 0.0, 2.0, 1.0);
    }

    @Test
    void aVetosReasonGoesWithTheIterationObstacleAvoidanceWon() {
        tracer.vetoed(8, "vetoed DRIVE 0.50 0.50: obstacle a ray hit 0.08 m away at 15°, within braking reach 0.11 m");
        assertThat(tracer.take(8, "ReachDestination", events)).as("outranked: it replaced nothing").isNull();
        tracer.vetoed(9, "vetoed DRIVE 0.50 0.50: x");
        assertThat(tracer.take(9, "ObstacleAvoidance", events).reason()).isEqualTo("vetoed DRIVE 0.50 0.50: x");
        assertThat(events).isEmpty();
    }

    @Test
    void aCheckpointDeclaredUnreachableGivesAReasonAndAnEvent() throws IOException {
        tracer.checkpointUnreachable(12, 1, "no route to checkpoint 2 (index 1)");
        TraceBelief b = tracer.take(12, "ReachDestination", events);
        assertThat(b.reason()).isEqualTo("no route to checkpoint 2 (index 1)");
        assertThat(events).singleElement().extracting(e -> e.toJson().toString())
                .isEqualTo("{\"type\":\"checkpointUnreachable\",\"index\":1}");
        String json = line(new TraceBelief(new double[] {1.23456, -0.5, 0.31}, new double[] {0.0, -4.0, 0.1, 3.0},
                new int[] {-2, -1, 2}, "r"));
        assertThat(json).endsWith(",\"events\":[],\"belief\":{\"xM\":1.235,\"yM\":-0.5,\"headingRad\":0.31},"
                + "\"route\":[[0.0,-4.0],[0.1,3.0]],\"mapDelta\":[[-2,-1,2]],\"reason\":\"r\"}");
    }

    /** A trace line holding the belief, as trace.jsonl writes it (null for none). */
    private static String line(TraceBelief belief) throws IOException {
        if (belief == null) {
            return null;
        }
        StringWriter out = new StringWriter();
        JsonWriter w = new JsonWriter(out);
        w.setStrictness(Strictness.LENIENT);
        new TraceStep(3, 64, Map.of(), "DecisionMaking", "STOP", Map.of(), 0, 0, 0, Double.NaN, Double.NaN, Double.NaN,
                null, Double.NaN, 100, false, 0, 0, List.of(), belief).write(w);
        w.flush();
        return out.toString();
    }
}
