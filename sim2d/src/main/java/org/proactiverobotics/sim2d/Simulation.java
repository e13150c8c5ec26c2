package org.proactiverobotics.sim2d;

import java.util.ArrayList;
import java.util.List;

import org.dyn4j.collision.broadphase.CollisionItemBroadphaseDetectorAdapter;
import org.dyn4j.dynamics.Body;
import org.dyn4j.dynamics.BodyFixture;
import org.dyn4j.dynamics.ContinuousDetectionMode;
import org.dyn4j.dynamics.Settings;
import org.dyn4j.geometry.Convex;
import org.dyn4j.geometry.Geometry;
import org.dyn4j.geometry.MassType;
import org.dyn4j.world.PhysicsWorld;
import org.dyn4j.world.World;

/**
 * A headless, deterministic dyn4j world built from a {@link WorldSpec}: the arena wall (a ring of boxes round a
 * circle, or four round a rectangle), static obstacles, and every robot of {@link WorldSpec#robots()} (a
 * differential-drive disc each, with its sensors, battery, checkpoints and ground truth), indexed 0.. in the
 * spec's order. The no-argument accessors ({@link #robot()}, {@link #groundTruth()}, {@link #robotBody()}) are
 * robot 0's, the only robot of a one-robot world.
 * <p>
 * Each {@link #step()} advances exactly {@code timeStepMs}: every robot's wheel speeds become its body's linear
 * and angular velocity, dyn4j integrates and resolves contacts once for all, then each robot's battery,
 * checkpoints, clearance and collisions are updated. Robots' bodies collide with each other and each robot's
 * rays see the others. Same spec, same noise, same commands: same trajectories, bit for bit.
 * Checkpoints and the recharge stations are markers only (a robot charges at any station); nothing collides
 * with them. Not thread-safe.
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
    private final World<Body> world;
    private final Body wallBody;
    private final StaticRayIndex staticRays;
    private final WorldRobot[] robots;
    private long steps;

    /** A simulation with perfect sensors. */
    public Simulation(WorldSpec spec) {
        this(spec, SensorNoise.NONE);
    }

    /**
     * @param spec  the world, with every robot of {@link WorldSpec#robots()}
     * @param noise the sensors' errors and the wheels' slip, drawn from the world's seed (each robot its own streams)
     */
    public Simulation(WorldSpec spec, SensorNoise noise) {
        this.spec = spec;
        this.noise = noise;
        double dt = spec.timeStepS();
        // Sized for the bodies it will hold (wall, obstacles, robots): dyn4j sizes by this the hash sets its
        // constraint graph clears every step, 512 slots by default for a world of three bodies.
        this.world = new World<>(spec.robots().size() + 2, PhysicsWorld.DEFAULT_INITIAL_JOINT_CAPACITY);
        Settings settings = world.getSettings();
        // dyn4j names it a frequency but takes the step period in seconds.
        settings.setStepFrequency(dt);
        settings.setAtRestDetectionEnabled(false);
        world.setGravity(0.0, 0.0);
        // Static bodies never move: refresh only the robots' AABBs each step (see MovingOnlyBroadphase).
        world.setBroadphaseDetector(new CollisionItemBroadphaseDetectorAdapter<>(
                new MovingOnlyBroadphase(world.getBroadphaseDetector().getDecoratedBroadphaseDetector())));
        // Continuous collision detection sweeps every body each step; it is needed only when one step can
        // carry a robot farther than half its radius (a fast robot or a long time step): the fastest decides.
        boolean fast = false;
        for (WorldSpec.RobotEntry e : spec.robots()) {
            fast |= e.robot().maxSpeedMps() * dt > e.robot().radiusM() / 2.0;
        }
        settings.setContinuousDetectionMode(fast ? ContinuousDetectionMode.ALL : ContinuousDetectionMode.NONE);

        this.wallBody = spec.arena().isCircle() ? createWall(spec.arena().radiusM()) : createRectangleWall(spec.arena());
        world.addBody(wallBody);
        List<Body> statics = new ArrayList<>(List.of(wallBody));
        if (!spec.obstacles().isEmpty()) {
            Body obstacles = createObstacles(spec.obstacles());
            world.addBody(obstacles);
            statics.add(obstacles);
        }
        this.staticRays = new StaticRayIndex(statics, world.getRaycastDetector());
        this.robots = new WorldRobot[spec.robots().size()];
        for (int i = 0; i < robots.length; i++) {
            robots[i] = new WorldRobot(this, world, i);
        }
        for (WorldRobot r : robots) {
            r.start();
        }
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

    /**
     * Advances the world by exactly one {@code timeStepMs}: every robot's wheels are applied, dyn4j steps once,
     * then each robot's errors, battery, checkpoints, clearance and collisions are updated, in the robots' order.
     */
    public void step() {
        for (WorldRobot r : robots) {
            r.applyWheels(steps);
        }
        world.step(1);
        steps++;
        for (WorldRobot r : robots) {
            r.afterWorldStep(steps);
        }
    }

    /** @return the angle in (-π, π] */
    static double normalizeAngle(double a) {
        double r = Math.IEEEremainder(a, 2.0 * Math.PI);
        return r <= -Math.PI ? r + 2.0 * Math.PI : r;
    }

    /** @return the static bodies' fixtures in a grid, for the robots' distance sensors */
    StaticRayIndex staticRays() {
        return staticRays;
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

    /** @return the first robot's dyn4j body (the robot of a one-robot world) */
    public Body robotBody() {
        return robots[0].body();
    }

    /**
     * @param index the robot's position in {@link WorldSpec#robots()} (0-based)
     * @return that robot's dyn4j body
     */
    public Body robotBody(int index) {
        return robots[index].body();
    }

    /** @return the arena wall's dyn4j body */
    public Body wallBody() {
        return wallBody;
    }

    /** @return how many robots the world has (at least one) */
    public int robotCount() {
        return robots.length;
    }

    /** @return the first robot, as its controller sees it (the robot of a one-robot world) */
    public SimRobot robot() {
        return robots[0].robot();
    }

    /**
     * @param index the robot's position in {@link WorldSpec#robots()} (0-based)
     * @return that robot, as its controller sees it
     */
    public SimRobot robot(int index) {
        return robots[index].robot();
    }

    /** @return the first robot's ground truth, updated after every step */
    public GroundTruth groundTruth() {
        return robots[0].truth();
    }

    /**
     * @param index the robot's position in {@link WorldSpec#robots()} (0-based)
     * @return that robot's ground truth, updated after every step
     */
    public GroundTruth groundTruth(int index) {
        return robots[index].truth();
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
