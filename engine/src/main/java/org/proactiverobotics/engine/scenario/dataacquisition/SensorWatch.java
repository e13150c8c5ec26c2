package org.proactiverobotics.engine.scenario.dataacquisition;

import org.proactiverobotics.engine.Outcome;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.RuleContext;
import org.proactiverobotics.engine.tables.Sensor;
import org.proactiverobotics.engine.tables.SensorReadings;
import org.proactiverobotics.engine.tables.SensorRequests;

/**
 * What GetGPS, GetDS, GetIU, GetBattery and GetOdometry share: when no request for the sensor is pending
 * (guard) and its newest reading is older than the interval (condition), request a new one.
 * The engine's "now" is the robot's clock as the engine sees it ({@link SensorReadings#robotClockMs()}).
 * Under the lazy algorithm the readings are not even looked at while a request is pending.
 */
public abstract class SensorWatch extends Rule {

    /** How old the newest reading may be, simulated milliseconds; 0 = a fresh one every iteration. */
    private long intervalMs;

    private transient boolean pending;
    private transient long newestMs;
    private transient long nowMs;

    protected SensorWatch(long intervalMs) {
        this.intervalMs = intervalMs;
    }

    /** @return the sensor this rule watches */
    protected abstract Sensor sensor();

    /** @return the longest age of a reading before a new one is requested, simulated ms */
    public long intervalMs() {
        return intervalMs;
    }

    @Override
    public String scenario() {
        return DataAcquisitionScenario.NAME;
    }

    @Override
    protected void acquireGuardData(RuleContext ctx) {
        pending = ctx.service(SensorRequests.class).pending(sensor());
    }

    /** With an interval of 0 any reading is too old: nothing to read. */
    @Override
    protected void acquireConditionData(RuleContext ctx) {
        if (intervalMs == 0) {
            return;
        }
        SensorReadings readings = ctx.service(SensorReadings.class);
        newestMs = readings.newestSimTimeMs(sensor());
        nowMs = readings.robotClockMs();
    }

    @Override
    protected boolean activationGuards(RuleContext ctx) {
        return !pending;
    }

    @Override
    protected boolean conditions(RuleContext ctx) {
        return intervalMs == 0 || newestMs < 0 || nowMs - newestMs >= intervalMs;
    }

    @Override
    protected void actions(RuleContext ctx) {
        ctx.service(SensorRequests.class).request(sensor(), ctx.iteration());
    }

    @Override
    protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
        ctx.generate(this);
    }
}
