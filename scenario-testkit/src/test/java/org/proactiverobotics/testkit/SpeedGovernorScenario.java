package org.proactiverobotics.testkit;

import java.util.List;
import org.proactiverobotics.engine.Outcome;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.RuleContext;
import org.proactiverobotics.engine.Scenario;
import org.proactiverobotics.engine.tables.DistanceScan;
import org.proactiverobotics.engine.tables.Sensor;
import org.proactiverobotics.engine.tables.SensorReadings;

/**
 * A small scenario of a user's own, the kind the kit is for: slow down near an obstacle ahead,
 * and stop rather than drive blind when the distance sensors have gone quiet.
 */
public final class SpeedGovernorScenario implements Scenario {

    /** The scenario's name. */
    public static final String NAME = "SpeedGovernor";
    /** Closer than this ahead, metres: creep. */
    static final double NEAR_M = 0.5;
    /** A scan older than this, simulated milliseconds behind the GPS clock, is too old to drive on. */
    static final long STALE_MS = 100;

    @Override
    public String name() {
        return NAME;
    }

    @Override
    public List<Rule> firstRules() {
        return List.of(new Govern());
    }

    /** Each iteration: STOP without a recent scan, FORWARD 0.1 with an obstacle near ahead, else nothing. */
    public static final class Govern extends Rule {

        private transient DistanceScan scan;
        private transient long nowMs;

        @Override
        public String scenario() {
            return NAME;
        }

        @Override
        protected void acquireConditionData(RuleContext ctx) {
            SensorReadings readings = ctx.service(SensorReadings.class);
            scan = readings.newestScan().orElse(null);
            nowMs = readings.newestSimTimeMs(Sensor.GPS);
        }

        @Override
        protected void actions(RuleContext ctx) {
            if (scan == null || nowMs - scan.simTimeMs() > STALE_MS) {
                ctx.suggest("STOP");
            } else if (scan.min(Math.toRadians(-20), Math.toRadians(20)) < NEAR_M) {
                ctx.suggest("FORWARD 0.1");
            }
        }

        @Override
        protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
            ctx.generate(this);
        }
    }
}
