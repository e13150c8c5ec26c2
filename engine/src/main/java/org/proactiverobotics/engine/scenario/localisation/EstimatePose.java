package org.proactiverobotics.engine.scenario.localisation;

import org.proactiverobotics.engine.Outcome;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.RuleContext;
import org.proactiverobotics.engine.belief.BeliefObserver;
import org.proactiverobotics.engine.motion.DriveProfile;
import org.proactiverobotics.engine.navigation.KnownMap;
import org.proactiverobotics.engine.tables.DistanceScan;
import org.proactiverobotics.engine.tables.GpsFix;
import org.proactiverobotics.engine.tables.Heading;
import org.proactiverobotics.engine.tables.InitialPose;
import org.proactiverobotics.engine.tables.MissionTables;
import org.proactiverobotics.engine.tables.PoseEstimate;
import org.proactiverobotics.engine.tables.PoseEstimateTable;
import org.proactiverobotics.engine.tables.SensorReadings;
import org.proactiverobotics.engine.tables.WheelOdometry;

/**
 * Brings the pose estimate up to date with every reading newer than the last it took, and writes
 * it to {@code pose_estimate}: each odometry reading moves it, each inertial-unit reading and GPS
 * fix corrects it, and while the GPS has given no fix for {@value #GPS_LOST_MS} ms each new scan
 * matched against the map corrects it. The filter starts where the robot is known to be (see
 * {@link #start}). A robot that reports no odometry at
 * all (a scripted test robot) has no motion to predict from: its estimate is then its newest fix
 * and heading as they are. Clones itself every iteration.
 */
public final class EstimatePose extends Rule {

    /** The GPS fix's error assumed, one standard deviation per axis, metres (an RTK receiver's stated 1-3 cm). */
    static final double GPS_SIGMA_M = 0.03;
    /** The inertial unit's heading error assumed, one standard deviation, radians (a consumer fused heading's 2°). */
    static final double YAW_SIGMA_RAD = Math.toRadians(2);
    /** How well the mission's initial pose is known: position, metres. */
    static final double START_SIGMA_M = 0.01;
    /** And heading, radians. */
    static final double START_SIGMA_RAD = Math.toRadians(1);
    /** With no GPS fix for this long, simulated ms, the scan matched against the map corrects the pose. */
    static final long GPS_LOST_MS = 1_000;
    /** A reading under this share of its range hit something (as the map takes it). */
    static final double HIT_SHARE = 0.9;

    private PoseFilter filter = new PoseFilter();
    private long odometryMs = -1;
    private long headingMs = -1;
    private long gpsMs = -1;
    private long scanMs = -1;

    private transient GpsFix gps;
    private transient Heading heading;
    private transient WheelOdometry odometry;
    private transient ScanMatcher matcher;

    @Override
    public String scenario() {
        return LocalisationScenario.NAME;
    }

    @Override
    protected void acquireGuardData(RuleContext ctx) {
        SensorReadings readings = ctx.service(SensorReadings.class);
        gps = readings.newestGps().orElse(null);
        heading = readings.newestHeading().orElse(null);
        odometry = readings.newestOdometry().orElse(null);
    }

    /** Guard: a reading the estimate does not include yet. */
    @Override
    protected boolean activationGuards(RuleContext ctx) {
        return (gps != null && gps.simTimeMs() > gpsMs) || (heading != null && heading.simTimeMs() > headingMs)
                || (odometry != null && odometry.simTimeMs() > odometryMs);
    }

    @Override
    protected void actions(RuleContext ctx) {
        if (odometry == null && odometryMs < 0) {
            writeReadingsAsTheyAre(ctx);
            return;
        }
        if (!filter.started() && !start(ctx)) {
            return;
        }
        double axleM = ctx.findService(DriveProfile.class).orElse(DriveProfile.DEFAULT).axleWidthM();
        if (odometry != null && odometry.simTimeMs() > odometryMs) {
            filter.predict(odometry.leftM(), odometry.rightM(), axleM);
            odometryMs = odometry.simTimeMs();
        }
        if (heading != null && heading.simTimeMs() > headingMs) {
            filter.correctYaw(heading.yawRad(), YAW_SIGMA_RAD);
            headingMs = heading.simTimeMs();
        }
        if (gps != null && gps.simTimeMs() > gpsMs) {
            filter.correctPosition(gps.xM(), gps.yM(), GPS_SIGMA_M);
            gpsMs = gps.simTimeMs();
        }
        long newest = Math.max(Math.max(odometryMs, headingMs), gpsMs); // the times only grow: this step's newest reading
        // the scan is read only without a fix: with one, a scan that cannot be read costs the estimate nothing
        DistanceScan scan = newest - gpsMs >= GPS_LOST_MS ? ctx.service(SensorReadings.class).newestScan().orElse(null) : null;
        if (scan != null && scan.simTimeMs() > scanMs) {
            scanMs = scan.simTimeMs();
            if (matcher == null) {
                matcher = new ScanMatcher();
            }
            var map = ctx.service(KnownMap.class).current(ctx.iteration(), newest);
            if (matcher.match(map, filter.x(), filter.y(), filter.yaw(), axleM / 2, scan, HIT_SHARE)) {
                filter.correctPose(matcher.xM, matcher.yM, matcher.yawRad, matcher.covariance);
            }
        }
        write(ctx, new PoseEstimate(newest, filter.x(), filter.y(), filter.yaw(),
                filter.covariance(0, 0), filter.covariance(1, 1), filter.covariance(2, 2),
                filter.covariance(0, 1), filter.covariance(0, 2), filter.covariance(1, 2)));
    }

    /**
     * Starts the filter where the robot is known to be: at the newest estimate stored (an engine
     * started afresh in the middle of a run), else at the mission's initial pose, else at the first
     * fix and heading; false when none is there.
     */
    private boolean start(RuleContext ctx) {
        PoseEstimate stored = ctx.service(PoseEstimateTable.class).newestPose().orElse(null);
        if (stored != null && stored.knowsHeading()) {
            filter.start(stored.xM(), stored.yM(), stored.yawRad(), Math.max(START_SIGMA_M, stored.positionSigmaM()),
                    Math.max(START_SIGMA_RAD, Math.sqrt(stored.varYaw())));
            return true;
        }
        InitialPose initial = ctx.service(MissionTables.class).initialPose().orElse(null);
        if (initial != null) {
            filter.start(initial.xM(), initial.yM(), initial.yawRad(), START_SIGMA_M, START_SIGMA_RAD);
            return true;
        }
        if (gps != null && heading != null) {
            filter.start(gps.xM(), gps.yM(), heading.yawRad(), GPS_SIGMA_M, YAW_SIGMA_RAD);
            gpsMs = gps.simTimeMs();
            headingMs = heading.simTimeMs();
            return true;
        }
        return false;
    }

    /** No odometry: the newest fix and heading are the estimate (nothing to predict a motion from); no heading yet, NaN. */
    private void writeReadingsAsTheyAre(RuleContext ctx) {
        if (gps == null) {
            return;
        }
        gpsMs = gps.simTimeMs();
        headingMs = heading == null ? -1 : heading.simTimeMs();
        double v = GPS_SIGMA_M * GPS_SIGMA_M;
        write(ctx, new PoseEstimate(Math.max(gpsMs, headingMs), gps.xM(), gps.yM(), heading == null ? Double.NaN : heading.yawRad(),
                v, v, heading == null ? Double.NaN : YAW_SIGMA_RAD * YAW_SIGMA_RAD, 0, 0, 0));
    }

    private void write(RuleContext ctx, PoseEstimate estimate) {
        ctx.service(PoseEstimateTable.class).writePose(estimate);
        ctx.findService(BeliefObserver.class)
                .ifPresent(b -> b.pose(ctx.iteration(), estimate.xM(), estimate.yM(), estimate.yawRad()));
    }

    @Override
    protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
        ctx.generate(this);
    }
}
