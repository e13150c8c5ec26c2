package org.proactiverobotics.sim2d;

import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;

import org.dyn4j.collision.broadphase.CollisionItemBroadphaseDetectorAdapter;
import org.dyn4j.dynamics.Body;
import org.dyn4j.dynamics.BodyFixture;
import org.dyn4j.dynamics.ContinuousDetectionMode;
import org.dyn4j.dynamics.Settings;
import org.dyn4j.dynamics.contact.ContactConstraint;
import org.dyn4j.geometry.AABB;
import org.dyn4j.geometry.Convex;
import org.dyn4j.geometry.Geometry;
import org.dyn4j.geometry.MassType;
import org.dyn4j.geometry.Ray;
import org.dyn4j.geometry.Transform;
import org.dyn4j.geometry.Vector2;
import org.dyn4j.world.DetectFilter;
import org.dyn4j.world.World;
import org.dyn4j.world.result.DetectResult;
import org.dyn4j.world.result.RaycastResult;

/**
 * A headless, deterministic dyn4j world built from a {@link WorldSpec}: the arena wall (a ring of boxes round a
 * circle, or four round a rectangle), static obstacles,
 * a differential-drive robot, its sensors and battery, and the ground truth.
 * <p>
 * Each {@link #step()} advances exactly {@code timeStepMs}: the wheel speeds become the body's linear and
 * angular velocity, dyn4j integrates and resolves contacts, then the battery, checkpoints, clearance and
 * collisions are updated. Same spec, same noise, same commands: same trajectory, bit for bit.
 * Checkpoints and the recharge station are markers only; nothing collides with them. Not thread-safe.
 */
public final class Simulation {

    /** Thickness of the arena wall, metres (outside the arena's radius). */
    static final double WALL_THICKNESS_M = 0.2;
    /** Longest wall segment, metres; the wall is a ring of boxes at least this fine. */
    private static final double WALL_SEGMENT_M = 0.25;
    /** How far, in metres, the rim must get from a body before touching it again counts as a new collision. */
    static final double RELEASE_M = 0.02;

    private final WorldSpec spec;
    private final SensorNoise noise;
    private final SensorErrors errors;
    private final double dt;
    private final World<Body> world;
    private final Body robotBody;
    private final Body wallBody;
    private final SimRobot robot;
    private final GroundTruth truth;
    private final DetectFilter<Body, BodyFixture> staticOnly;
    private final Ray ray = new Ray(0.0);
    private final double[] distanceCache;
    private final List<Object> touching = new ArrayList<>();
    private final List<Object> engaged = new ArrayList<>();
    private long steps;
    private long sampledStep = -1;
    /** Each wheel's travel since the start, metres: the applied wheel speeds times the steps' length. */
    private double leftTravelM;
    private double rightTravelM;
    private double level;
    private boolean charging;
    private boolean atStation;

    /** A simulation with perfect sensors. */
    public Simulation(WorldSpec spec) {
        this(spec, SensorNoise.NONE);
    }

    /**
     * @param spec  the world
     * @param noise the sensors' errors and the wheels' slip, drawn from the world's seed
     */
    public Simulation(WorldSpec spec, SensorNoise noise) {
        this.spec = spec;
        this.noise = noise;
        this.dt = spec.timeStepS();
        this.errors = new SensorErrors(noise, spec.seed(), dt);
        this.world = new World<>();
        Settings settings = world.getSettings();
        // dyn4j names it a frequency but takes the step period in seconds.
        settings.setStepFrequency(dt);
        settings.setAtRestDetectionEnabled(false);
        world.setGravity(0.0, 0.0);
        // Static bodies never move: refresh only the robot's AABB each step (see MovingOnlyBroadphase).
        world.setBroadphaseDetector(new CollisionItemBroadphaseDetectorAdapter<>(
                new MovingOnlyBroadphase(world.getBroadphaseDetector().getDecoratedBroadphaseDetector())));
        WorldSpec.Robot r = spec.robot();
        // Continuous collision detection sweeps every body each step; it is needed only when one step can
        // carry the robot farther than half its radius (a fast robot or a long time step).
        boolean fast = r.maxSpeedMps() * dt > r.radiusM() / 2.0;
        settings.setContinuousDetectionMode(fast ? ContinuousDetectionMode.ALL : ContinuousDetectionMode.NONE);

        this.wallBody = spec.arena().isCircle() ? createWall(spec.arena().radiusM()) : createRectangleWall(spec.arena());
        world.addBody(wallBody);
        if (!spec.obstacles().isEmpty()) {
            world.addBody(createObstacles(spec.obstacles()));
        }
        this.robotBody = new Body();
        BodyFixture fixture = robotBody.addFixture(Geometry.createCircle(r.radiusM()), 1.0, 0.0, 0.0);
        fixture.setRestitution(0.0);
        robotBody.setMass(MassType.NORMAL);
        robotBody.setLinearDamping(0.0);
        robotBody.setAngularDamping(0.0);
        robotBody.setAtRestDetectionEnabled(false);
        robotBody.getTransform().setRotation(r.headingRad());
        robotBody.getTransform().setTranslation(r.x(), r.y());
        world.addBody(robotBody);

        Body self = robotBody;
        this.staticOnly = new DetectFilter<>(true, true, null) {
            @Override
            public boolean isAllowed(Body body, BodyFixture f) {
                return body != self;
            }
        };
        this.robot = new SimRobot(this, r);
        this.distanceCache = new double[robot.distanceSensors().size()];
        this.truth = new GroundTruth(spec.checkpoints().size());
        this.level = spec.battery().initial();
        truth.minBatteryPct = level;
        truth.minClearanceM = initialClearance();
        afterStep(0.0);
    }

    /** Builds the circular wall as one static body: a ring of boxes whose inner faces touch the arena circle. */
    private static Body createWall(double radiusM) {
        Body wall = new Body();
        int n = Math.max(64, (int) Math.ceil(2 * Math.PI * radiusM / WALL_SEGMENT_M));
        // 2% overlap so that no crack opens between neighbouring boxes.
        double length = 2.0 * radiusM * Math.tan(Math.PI / n) * 1.02;
        double centre = radiusM + WALL_THICKNESS_M / 2.0;
        for (int i = 0; i < n; i++) {
            double phi = 2.0 * Math.PI * i / n;
            Convex box = Geometry.createRectangle(WALL_THICKNESS_M, length);
            box.rotate(phi);
            box.translate(centre * Math.cos(phi), centre * Math.sin(phi));
            wall.addFixture(box, 1.0, 0.0, 0.0).setUserData(WallTag.INSTANCE);
        }
        wall.setMass(MassType.INFINITE);
        return wall;
    }

    /** Builds a rectangular arena's wall as one static body: four boxes whose inner faces are the arena's sides. */
    private static Body createRectangleWall(WorldSpec.Arena arena) {
        Body wall = new Body();
        double t = WALL_THICKNESS_M;
        double w = arena.widthM();
        double h = arena.heightM();
        double[][] sides = { // centre x, centre y, width, height; the corners are filled by the bottom and top sides
            {arena.x(), arena.minY() - t / 2, w + 2 * t, t},
            {arena.x(), arena.maxY() + t / 2, w + 2 * t, t},
            {arena.minX() - t / 2, arena.y(), t, h},
            {arena.maxX() + t / 2, arena.y(), t, h},
        };
        for (double[] side : sides) {
            Convex box = Geometry.createRectangle(side[2], side[3]);
            box.translate(side[0], side[1]);
            wall.addFixture(box, 1.0, 0.0, 0.0).setUserData(WallTag.INSTANCE);
        }
        wall.setMass(MassType.INFINITE);
        return wall;
    }

    /**
     * Builds every obstacle as a fixture of one static body: dyn4j's step walks every body, so one body
     * keeps the step's cost nearly flat in the obstacle count. Each fixture carries its obstacle.
     */
    private static Body createObstacles(List<WorldSpec.Obstacle> obstacles) {
        Body body = new Body();
        for (WorldSpec.Obstacle o : obstacles) {
            Convex shape;
            if (o.isCircle()) {
                shape = Geometry.createCircle(o.radiusM());
            } else {
                shape = Geometry.createRectangle(o.widthM(), o.heightM());
                shape.rotate(o.angleRad());
            }
            shape.translate(o.x(), o.y());
            BodyFixture fixture = body.addFixture(shape, 1.0, 0.0, 0.0);
            fixture.setUserData(o);
        }
        body.setMass(MassType.INFINITE);
        return body;
    }

    /** Marks the wall's fixtures in user data (obstacle fixtures carry their {@link WorldSpec.Obstacle}). */
    enum WallTag {
        INSTANCE
    }

    /** Advances the world by exactly one {@code timeStepMs}. */
    public void step() {
        Transform t = robotBody.getTransform();
        double x0 = t.getTranslationX();
        double y0 = t.getTranslationY();
        if (level > 0.0) {
            double left = robot.leftSpeedMps();
            double right = robot.rightSpeedMps();
            if (!noise.wheelSlip().isNone()) {
                left *= errors.slipFactor(steps, 0);
                right *= errors.slipFactor(steps, 1);
            }
            double v = (left + right) / 2.0;
            double w = (right - left) / robot.axleWidthM();
            double heading = t.getRotationAngle();
            robotBody.setLinearVelocity(v * Math.cos(heading), v * Math.sin(heading));
            robotBody.setAngularVelocity(w);
            leftTravelM += robot.leftSpeedMps() * dt;
            rightTravelM += robot.rightSpeedMps() * dt;
        } else {
            robotBody.setLinearVelocity(0.0, 0.0);
            robotBody.setAngularVelocity(0.0);
        }
        world.step(1);
        steps++;
        errors.advance(steps);
        double dx = t.getTranslationX() - x0;
        double dy = t.getTranslationY() - y0;
        afterStep(Math.sqrt(dx * dx + dy * dy));
    }

    /** Updates battery, station, checkpoints, clearance, collisions and the ground truth after a move. */
    private void afterStep(double movedM) {
        Transform t = robotBody.getTransform();
        double x = t.getTranslationX();
        double y = t.getTranslationY();
        WorldSpec.Battery b = spec.battery();
        truth.distanceM += movedM;
        level = Math.max(0.0, level - movedM * b.drainPerMeter());

        WorldSpec.RechargeStation s = spec.rechargeStation();
        double sx = x - s.x();
        double sy = y - s.y();
        atStation = sx * sx + sy * sy <= s.radiusM() * s.radiusM();
        if (charging && !atStation) {
            charging = false;
        }
        if (charging) {
            level = Math.min(b.rechargeTo(), level + b.rechargeRatePerS() * dt);
            if (level >= b.rechargeTo()) {
                charging = false;
            }
        }

        List<WorldSpec.Checkpoint> cps = spec.checkpoints();
        int k = truth.checkpointsReached;
        if (k < cps.size()) {
            WorldSpec.Checkpoint c = cps.get(k);
            double cx = x - c.x();
            double cy = y - c.y();
            double cr = spec.checkpointRadiusM();
            if (cx * cx + cy * cy <= cr * cr) {
                truth.checkpointsReached = k + 1;
            }
        }

        updateClearance(x, y);
        countCollisions(x, y);

        truth.x = x;
        truth.y = y;
        truth.headingRad = normalizeAngle(t.getRotationAngle());
        truth.batteryPct = level;
        truth.minBatteryPct = Math.min(truth.minBatteryPct, level);
    }

    /**
     * Counts a collision when the wall or an obstacle touches the robot and was not already engaged; it stays
     * engaged until the rim is {@value #RELEASE_M} m clear of it, so that the solver's touch-and-release while
     * the robot pushes, turns or slides against it is one collision, not dozens. The whole wall is one thing.
     */
    private void countCollisions(double x, double y) {
        touching.clear();
        if (steps > 0) {
            for (ContactConstraint<Body> cc : world.getContacts(robotBody)) {
                if (cc.isSensor()) {
                    continue;
                }
                Object tag = (cc.getBody1() == robotBody ? cc.getFixture2() : cc.getFixture1()).getUserData();
                if (!containsSame(touching, tag)) {
                    touching.add(tag);
                }
            }
        }
        for (Object tag : touching) {
            if (!containsSame(engaged, tag)) {
                engaged.add(tag);
                truth.collisions++;
            }
        }
        for (int i = engaged.size() - 1; i >= 0; i--) {
            Object tag = engaged.get(i);
            if (!containsSame(touching, tag) && clearanceTo(tag, x, y) > RELEASE_M) {
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

    /** @return the gap between the robot's rim and the wall or an obstacle, metres */
    private double clearanceTo(Object tag, double x, double y) {
        if (tag instanceof WorldSpec.Obstacle o) {
            return o.distanceTo(x, y) - spec.robot().radiusM();
        }
        return wallClearance(x, y);
    }

    /** The clearance at the start, against every obstacle (later steps look only nearby). */
    private double initialClearance() {
        Transform t = robotBody.getTransform();
        double x = t.getTranslationX();
        double y = t.getTranslationY();
        double c = wallClearance(x, y);
        for (WorldSpec.Obstacle o : spec.obstacles()) {
            c = Math.min(c, Math.max(0.0, o.distanceTo(x, y) - spec.robot().radiusM()));
        }
        return c;
    }

    private double wallClearance(double x, double y) {
        return Math.max(0.0, spec.arena().inside(x, y) - spec.robot().radiusM());
    }

    /** Lowers the minimum clearance; only obstacles within the current minimum can lower it, so ask the broadphase. */
    private void updateClearance(double x, double y) {
        double min = Math.min(truth.minClearanceM, wallClearance(x, y));
        double reach = spec.robot().radiusM() + min;
        if (min > 0.0 && !spec.obstacles().isEmpty()) {
            AABB query = new AABB(x - reach, y - reach, x + reach, y + reach);
            Iterator<DetectResult<Body, BodyFixture>> it = world.detectIterator(query, staticOnly);
            while (it.hasNext()) {
                Object data = it.next().getFixture().getUserData();
                if (data instanceof WorldSpec.Obstacle o) {
                    min = Math.min(min, Math.max(0.0, o.distanceTo(x, y) - spec.robot().radiusM()));
                }
            }
        }
        truth.minClearanceM = min;
    }

    /** @return the angle in (-π, π] */
    static double normalizeAngle(double a) {
        double r = Math.IEEEremainder(a, 2.0 * Math.PI);
        return r <= -Math.PI ? r + 2.0 * Math.PI : r;
    }

    // ---- device back-ends (package-private: devices call these) ----

    double[] gpsValues() {
        if (!noise.gpsFix()) {
            return new double[] {Double.NaN, Double.NaN};
        }
        Vector2 p = robotBody.getTransform().getTranslation();
        double x = p.x;
        double y = p.y;
        if (!noise.gpsBias().isNone()) {
            x += errors.gpsBiasXM();
            y += errors.gpsBiasYM();
        }
        if (noise.gpsSigmaM() > 0.0) {
            x += noise.gpsSigmaM() * SensorNoise.gaussian(spec.seed(), steps, 0);
            y += noise.gpsSigmaM() * SensorNoise.gaussian(spec.seed(), steps, 1);
        }
        return new double[] {x, y};
    }

    double yawValue() {
        double yaw = robotBody.getTransform().getRotationAngle();
        if (!noise.headingDrift().isNone()) {
            yaw += errors.headingErrorRad();
        }
        if (noise.yawSigmaRad() > 0.0) {
            yaw += noise.yawSigmaRad() * SensorNoise.gaussian(spec.seed(), steps, 2);
        }
        return normalizeAngle(yaw);
    }

    double[] wheelTravelM() {
        return new double[] {leftTravelM, rightTravelM};
    }

    double distanceValue(int index) {
        if (sampledStep != steps) {
            sampleDistances();
            sampledStep = steps;
        }
        return distanceCache[index];
    }

    /** Casts every distance sensor's ray once for this step. */
    private void sampleDistances() {
        Transform t = robotBody.getTransform();
        double heading = t.getRotationAngle();
        double radius = spec.robot().radiusM();
        ray.setStart(t.getTranslation());
        List<DistanceSensor> sensors = robot.distanceSensors();
        for (int i = 0; i < sensors.size(); i++) {
            DistanceSensor s = sensors.get(i);
            double range = s.getRangeM();
            ray.setDirection(heading + s.getAngleRad());
            // Cast from the centre so that a ray starting inside a touching obstacle still hits it.
            RaycastResult<Body, BodyFixture> hit = world.raycastClosest(ray, radius + range, staticOnly);
            double d = hit == null ? range : Math.min(range, Math.max(0.0, hit.getRaycast().getDistance() - radius));
            double sigma = noise.distanceSigmaAtM(d);
            if (sigma > 0.0) {
                d += sigma * SensorNoise.gaussian(spec.seed(), steps, 3 + i);
                d = Math.max(0.0, Math.min(range, d));
            }
            distanceCache[i] = d;
        }
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

    // ---- public accessors ----

    /** @return the world this simulation was built from */
    public WorldSpec spec() {
        return spec;
    }

    /** @return the sensor errors and wheel slip in use */
    public SensorNoise noise() {
        return noise;
    }

    /** @return the dyn4j world (for rendering and tests; changing it voids determinism) */
    public World<Body> world() {
        return world;
    }

    /** @return the robot's dyn4j body */
    public Body robotBody() {
        return robotBody;
    }

    /** @return the arena wall's dyn4j body */
    public Body wallBody() {
        return wallBody;
    }

    /** @return the robot, as its controller sees it */
    public SimRobot robot() {
        return robot;
    }

    /** @return the ground truth, updated after every step */
    public GroundTruth groundTruth() {
        return truth;
    }

    /** @return the fixed step, milliseconds */
    public int timeStepMs() {
        return spec.timeStepMs();
    }

    /** @return the number of steps taken */
    public long steps() {
        return steps;
    }

    /** @return the simulated time, milliseconds (steps × timeStepMs) */
    public long simTimeMs() {
        return steps * spec.timeStepMs();
    }

    /** @return the simulated time, seconds */
    public double simTimeS() {
        return simTimeMs() / 1000.0;
    }

    /** @return whether the world's {@code maxSimTimeS} has been reached */
    public boolean timeLimitReached() {
        return simTimeMs() >= (long) Math.ceil(spec.maxSimTimeS() * 1000.0);
    }
}
