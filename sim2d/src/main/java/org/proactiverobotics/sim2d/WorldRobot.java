package org.proactiverobotics.sim2d;

import java.util.ArrayList;
import java.util.List;
import java.util.function.ToDoubleFunction;

import org.dyn4j.dynamics.Body;
import org.dyn4j.dynamics.BodyFixture;
import org.dyn4j.dynamics.contact.ContactConstraint;
import org.dyn4j.geometry.Geometry;
import org.dyn4j.geometry.MassType;
import org.dyn4j.geometry.Ray;
import org.dyn4j.geometry.Transform;
import org.dyn4j.geometry.Vector2;
import org.dyn4j.world.DetectFilter;
import org.dyn4j.world.World;
import org.dyn4j.world.result.RaycastResult;

/**
 * One robot of a {@link Simulation}'s world: its dyn4j body, the back-ends of its devices, its battery, its
 * checkpoints and its ground truth. The simulation applies its wheels before the world steps
 * ({@link #applyWheels}) and updates the rest after ({@link #afterStep}).
 * <p>
 * Robot index 0 draws its noise from the world's seed itself, so a one-robot world reads exactly what it read
 * before fleets; robot {@code i > 0} from a seed of its own ({@link SensorNoise#robotSeed}). Its body's fixture
 * carries this object as user data, so that other robots know what they touched. Not thread-safe.
 */
final class WorldRobot {

    private final Simulation sim;
    private final WorldSpec spec;
    private final World<Body> world;
    private final WorldSpec.Robot robotSpec;
    private final List<WorldSpec.Checkpoint> checkpoints;
    private final SensorNoise noise;
    private final long seed;
    private final SensorErrors errors;
    private final double dt;
    private final Body body;
    private final SimRobot robot;
    private final GroundTruth truth;
    private final DetectFilter<Body, BodyFixture> notSelf;
    /** Only the other robots (the static bodies are cast against in {@link #rays}). */
    private final DetectFilter<Body, BodyFixture> otherMoving;
    private final StaticRayIndex.Query rays;
    /** Where {@link #obstacleGap} measures from, metres (set before each use: no lambda allocated per step). */
    private double clearanceX;
    private double clearanceY;
    /** The rim's gap to a static fixture's obstacle, metres; infinite for the arena wall's fixtures. */
    private final ToDoubleFunction<Object> obstacleGap = this::obstacleGap;
    private final Ray ray = new Ray(0.0);
    private final double[] distanceCache;
    private final List<Object> touching = new ArrayList<>();
    private final List<Object> engaged = new ArrayList<>();
    private long sampledStep = -1;
    /** Each wheel's travel since the start, metres: the applied wheel speeds times the steps' length. */
    private double leftTravelM;
    private double rightTravelM;
    private double level;
    private boolean charging;
    private boolean atStation;
    private double x0;
    private double y0;

    /**
     * Builds the robot's body and adds it to the world.
     *
     * @param sim   the simulation (for the step count)
     * @param world the dyn4j world
     * @param index the robot's position in {@link WorldSpec#robots()}
     */
    WorldRobot(Simulation sim, World<Body> world, int index) {
        this.sim = sim;
        this.spec = sim.spec();
        this.world = world;
        WorldSpec.RobotEntry entry = spec.robots().get(index);
        this.robotSpec = entry.robot();
        this.checkpoints = entry.checkpoints();
        this.noise = sim.noise();
        this.dt = spec.timeStepS();
        this.seed = SensorNoise.robotSeed(spec.seed(), index);
        this.errors = new SensorErrors(noise, seed, dt);
        this.body = new Body();
        BodyFixture fixture = body.addFixture(Geometry.createCircle(robotSpec.radiusM()), 1.0, 0.0, 0.0);
        fixture.setRestitution(0.0);
        fixture.setUserData(this);
        body.setMass(MassType.NORMAL);
        body.setLinearDamping(0.0);
        body.setAngularDamping(0.0);
        body.setAtRestDetectionEnabled(false);
        body.getTransform().setRotation(robotSpec.headingRad());
        body.getTransform().setTranslation(robotSpec.x(), robotSpec.y());
        world.addBody(body);
        Body self = body;
        this.notSelf = new DetectFilter<>(true, true, null) {
            @Override
            public boolean isAllowed(Body b, BodyFixture f) {
                return b != self;
            }
        };
        this.otherMoving = new DetectFilter<>(true, true, null) {
            @Override
            public boolean isAllowed(Body b, BodyFixture f) {
                return b != self && !b.isStatic();
            }
        };
        this.rays = sim.staticRays().new Query();
        this.robot = new SimRobot(this, robotSpec);
        this.distanceCache = new double[robot.distanceSensors().size()];
        this.truth = new GroundTruth(checkpoints.size());
        this.level = spec.battery().initial();
        truth.minBatteryPct = level;
    }

    /** Sets the first clearance and the ground truth at step 0 (once every robot's body is in the world). */
    void start() {
        truth.minClearanceM = initialClearance();
        afterStep(0L, 0.0);
    }

    /**
     * Turns the wheel speeds into the body's velocities for the coming step (none when the battery is flat).
     *
     * @param step the step about to be taken (0 for the first)
     */
    void applyWheels(long step) {
        Transform t = body.getTransform();
        x0 = t.getTranslationX();
        y0 = t.getTranslationY();
        if (level > 0.0) {
            double left = robot.leftSpeedMps();
            double right = robot.rightSpeedMps();
            if (!noise.wheelSlip().isNone()) {
                left *= errors.slipFactor(step, 0);
                right *= errors.slipFactor(step, 1);
            }
            double v = (left + right) / 2.0;
            double w = (right - left) / robot.axleWidthM();
            double heading = t.getRotationAngle();
            body.setLinearVelocity(v * Math.cos(heading), v * Math.sin(heading));
            body.setAngularVelocity(w);
            leftTravelM += robot.leftSpeedMps() * dt;
            rightTravelM += robot.rightSpeedMps() * dt;
        } else {
            body.setLinearVelocity(0.0, 0.0);
            body.setAngularVelocity(0.0);
        }
    }

    /**
     * Updates the errors, battery, station, checkpoints, clearance, collisions and ground truth after the world
     * stepped.
     *
     * @param steps the steps taken so far (1 after the first)
     */
    void afterWorldStep(long steps) {
        errors.advance(steps);
        Transform t = body.getTransform();
        double dx = t.getTranslationX() - x0;
        double dy = t.getTranslationY() - y0;
        afterStep(steps, Math.sqrt(dx * dx + dy * dy));
    }

    private void afterStep(long steps, double movedM) {
        Transform t = body.getTransform();
        double x = t.getTranslationX();
        double y = t.getTranslationY();
        WorldSpec.Battery b = spec.battery();
        truth.distanceM += movedM;
        level = Math.max(0.0, level - movedM * b.drainPerMeter());

        atStation = false;
        List<WorldSpec.RechargeStation> stations = spec.rechargeStations();
        for (int i = 0; i < stations.size() && !atStation; i++) {
            WorldSpec.RechargeStation s = stations.get(i);
            double sx = x - s.x();
            double sy = y - s.y();
            atStation = sx * sx + sy * sy <= s.radiusM() * s.radiusM();
        }
        if (charging && !atStation) {
            charging = false;
        }
        if (charging) {
            level = Math.min(b.rechargeTo(), level + b.rechargeRatePerS() * dt);
            if (level >= b.rechargeTo()) {
                charging = false;
            }
        }

        int k = truth.checkpointsReached;
        if (k < checkpoints.size()) {
            WorldSpec.Checkpoint c = checkpoints.get(k);
            double cx = x - c.x();
            double cy = y - c.y();
            double cr = spec.checkpointRadiusM();
            if (cx * cx + cy * cy <= cr * cr) {
                truth.checkpointsReached = k + 1;
            }
        }

        updateClearance(x, y);
        countCollisions(steps, x, y);

        truth.x = x;
        truth.y = y;
        truth.headingRad = Simulation.normalizeAngle(t.getRotationAngle());
        truth.batteryPct = level;
        truth.minBatteryPct = Math.min(truth.minBatteryPct, level);
    }

    /**
     * Counts a collision when the wall, an obstacle or another robot touches this robot and was not already
     * engaged; it stays engaged until the rim is {@value Simulation#RELEASE_M} m clear of it, so that the
     * solver's touch-and-release while the robot pushes, turns or slides against it is one collision, not dozens.
     * The whole wall is one thing; each other robot is one thing (and counts in {@link GroundTruth#robotCollisions()}
     * too: the other robot counts the same contact on its side).
     */
    private void countCollisions(long steps, double x, double y) {
        touching.clear();
        if (steps > 0) {
            for (ContactConstraint<Body> cc : world.getContacts(body)) {
                if (cc.isSensor()) {
                    continue;
                }
                Object tag = (cc.getBody1() == body ? cc.getFixture2() : cc.getFixture1()).getUserData();
                if (!containsSame(touching, tag)) {
                    touching.add(tag);
                }
            }
        }
        for (Object tag : touching) {
            if (!containsSame(engaged, tag)) {
                engaged.add(tag);
                truth.collisions++;
                if (tag instanceof WorldRobot) {
                    truth.robotCollisions++;
                }
            }
        }
        for (int i = engaged.size() - 1; i >= 0; i--) {
            Object tag = engaged.get(i);
            if (!containsSame(touching, tag) && clearanceTo(tag, x, y) > Simulation.RELEASE_M) {
                engaged.remove(i);
            }
        }
    }

    /** Identity, not equality: two obstacles may be equal records yet distinct things. */
    private static boolean containsSame(List<Object> list, Object o) {
        for (int i = 0; i < list.size(); i++) {
            if (list.get(i) == o) {
                return true;
            }
        }
        return false;
    }

    /** @return the gap between the robot's rim and the wall, an obstacle or another robot's rim, metres */
    private double clearanceTo(Object tag, double x, double y) {
        if (tag instanceof WorldSpec.Obstacle o) {
            return o.distanceTo(x, y) - robotSpec.radiusM();
        }
        if (tag instanceof WorldRobot other) {
            Vector2 p = other.body.getTransform().getTranslation();
            double dx = p.x - x;
            double dy = p.y - y;
            return Math.sqrt(dx * dx + dy * dy) - robotSpec.radiusM() - other.robotSpec.radiusM();
        }
        return wallClearance(x, y);
    }

    /** The clearance at the start, against every obstacle (later steps look only nearby). */
    private double initialClearance() {
        Transform t = body.getTransform();
        double x = t.getTranslationX();
        double y = t.getTranslationY();
        double c = wallClearance(x, y);
        for (WorldSpec.Obstacle o : spec.obstacles()) {
            c = Math.min(c, Math.max(0.0, o.distanceTo(x, y) - robotSpec.radiusM()));
        }
        return c;
    }

    private double wallClearance(double x, double y) {
        return Math.max(0.0, spec.arena().inside(x, y) - robotSpec.radiusM());
    }

    /**
     * Lowers the minimum clearance to the wall and the obstacles (other robots are not counted: they are
     * {@link GroundTruth#robotCollisions()}); only obstacles within the current minimum can lower it, so ask
     * the broadphase.
     */
    private void updateClearance(double x, double y) {
        double min = Math.min(truth.minClearanceM, wallClearance(x, y));
        double reach = robotSpec.radiusM() + min;
        if (min > 0.0 && !spec.obstacles().isEmpty()) {
            // An obstacle nearer than min reaches into the box round the disc of radius reach: the grid's cells
            // there hold it, so this is the minimum dyn4j's box query gave, without walking its tree.
            clearanceX = x;
            clearanceY = y;
            min = sim.staticRays().least(x - reach, y - reach, x + reach, y + reach, min, obstacleGap);
        }
        truth.minClearanceM = min;
    }

    private double obstacleGap(Object fixtureData) {
        return fixtureData instanceof WorldSpec.Obstacle o
                ? Math.max(0.0, o.distanceTo(clearanceX, clearanceY) - robotSpec.radiusM())
                : Double.POSITIVE_INFINITY;
    }

    // ---- device back-ends (package-private: devices call these) ----

    double[] gpsValues() {
        if (!noise.gpsFix()) {
            return new double[] {Double.NaN, Double.NaN};
        }
        Vector2 p = body.getTransform().getTranslation();
        double x = p.x;
        double y = p.y;
        if (!noise.gpsBias().isNone()) {
            x += errors.gpsBiasXM();
            y += errors.gpsBiasYM();
        }
        if (noise.gpsSigmaM() > 0.0) {
            long steps = sim.steps();
            x += noise.gpsSigmaM() * SensorNoise.gaussian(seed, steps, 0);
            y += noise.gpsSigmaM() * SensorNoise.gaussian(seed, steps, 1);
        }
        return new double[] {x, y};
    }

    boolean gpsFix() {
        return noise.gpsFix();
    }

    double yawValue() {
        double yaw = body.getTransform().getRotationAngle();
        if (!noise.headingDrift().isNone()) {
            yaw += errors.headingErrorRad();
        }
        if (noise.yawSigmaRad() > 0.0) {
            yaw += noise.yawSigmaRad() * SensorNoise.gaussian(seed, sim.steps(), 2);
        }
        return Simulation.normalizeAngle(yaw);
    }

    double[] wheelTravelM() {
        return new double[] {leftTravelM, rightTravelM};
    }

    double distanceValue(int index) {
        long steps = sim.steps();
        if (sampledStep != steps) {
            sampleDistances(steps);
            sampledStep = steps;
        }
        return distanceCache[index];
    }

    /** Casts every distance sensor's ray once for this step; they see the wall, the obstacles and other robots. */
    private void sampleDistances(long steps) {
        Transform t = body.getTransform();
        double heading = t.getRotationAngle();
        double radius = robotSpec.radiusM();
        ray.setStart(t.getTranslation());
        List<DistanceSensor> sensors = robot.distanceSensors();
        for (int i = 0; i < sensors.size(); i++) {
            DistanceSensor s = sensors.get(i);
            double range = s.getRangeM();
            ray.setDirection(heading + s.getAngleRad());
            // Cast from the centre so that a ray starting inside a touching obstacle still hits it.
            double hitM = closestHit(radius + range);
            double d = hitM < 0.0 ? range : Math.min(range, Math.max(0.0, hitM - radius));
            double sigma = noise.distanceSigmaAtM(d);
            if (sigma > 0.0) {
                d += sigma * SensorNoise.gaussian(seed, steps, 3 + i);
                d = Math.max(0.0, Math.min(range, d));
            }
            distanceCache[i] = d;
        }
    }

    /**
     * The distance along {@link #ray} to the nearest body but this robot, as dyn4j's {@code raycastClosest}
     * with {@link #notSelf} finds it: the static bodies through the grid, then the other robots (if any)
     * through dyn4j within that distance.
     *
     * @param maxLength how far to look, metres
     * @return the distance, metres, or -1 when nothing lies within maxLength
     */
    private double closestHit(double maxLength) {
        double best = rays.closest(ray, maxLength);
        if (best != 0.0 && sim.robotCount() > 1) {
            RaycastResult<Body, BodyFixture> hit = world.raycastClosest(ray, best < 0.0 ? maxLength : best, otherMoving);
            if (hit != null) {
                best = hit.getRaycast().getDistance();
            }
        }
        if (best == 0.0) {
            // After a hit at 0 dyn4j reads its bound as no bound at all: leave that case to dyn4j's own cast.
            RaycastResult<Body, BodyFixture> hit = world.raycastClosest(ray, maxLength, notSelf);
            return hit == null ? -1.0 : hit.getRaycast().getDistance();
        }
        return best;
    }

    double batteryLevel() {
        return level;
    }

    boolean isCharging() {
        return charging;
    }

    boolean isAtStation() {
        return atStation;
    }

    boolean startCharging() {
        if (!charging && atStation && level < spec.battery().rechargeTo()) {
            charging = true;
            truth.recharges++;
        }
        return charging;
    }

    void stopCharging() {
        charging = false;
    }

    // ---- accessors for the simulation ----

    Body body() {
        return body;
    }

    SimRobot robot() {
        return robot;
    }

    GroundTruth truth() {
        return truth;
    }

    WorldSpec.Robot spec() {
        return robotSpec;
    }
}
