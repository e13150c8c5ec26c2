package org.proactiverobotics.robot;

import com.zaxxer.hikari.HikariDataSource;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashSet;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;
import java.util.function.Consumer;
import org.proactiverobotics.robot.link.BatteryReading;
import org.proactiverobotics.robot.link.CommandRecord;
import org.proactiverobotics.robot.link.DistanceReading;
import org.proactiverobotics.robot.link.GpsReading;
import org.proactiverobotics.robot.link.IuReading;
import org.proactiverobotics.robot.link.JdbcRobotLink;
import org.proactiverobotics.robot.link.OdometryReading;
import org.proactiverobotics.robot.link.RobotLink;
import org.proactiverobotics.robot.link.RobotPool;
import org.proactiverobotics.robot.link.SensorAnswer;
import org.proactiverobotics.protocol.Sensor;
import org.proactiverobotics.robot.link.SensorRequest;
import org.proactiverobotics.sim2d.DistanceSensor;
import org.proactiverobotics.sim2d.Simulation;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The paper's {@code ProactiveController}: the robot executes, the engine decides. At start it
 * seeds the mission rows from the world (once), writes its battery level and waits for
 * instructions; each control step it answers the engine's pending sensor requests
 * ({@link #sense()}), then reads the newest command and switches on its {@link Mode} to set the
 * wheel speeds ({@link #act()}).
 *
 * <p>Commands are checked ({@link Command#parse}): a malformed one, or one older than a command
 * already seen (of an earlier engine iteration), is logged once and ignored, and the robot keeps
 * its mode. The robot stops at the step a database call fails (it can no longer hear the engine,
 * so it does not drive on a command decided from readings it cannot refresh), and a
 * {@link Watchdog} in simulated time stops it when no new valid command arrived for
 * {@link RobotConfig#watchdogTimeoutMs()} (engine gone); either way it goes again only on a new
 * command.
 */
public class ProactiveController extends RobotSuperclass {

    private static final Logger LOG = LoggerFactory.getLogger(ProactiveController.class);

    /** A RECHARGE refused away from the station is said at most once per this much simulated time, ms. */
    static final long REFUSAL_WARN_INTERVAL_MS = 10_000;
    private static final long NEVER = Long.MIN_VALUE;
    private static final String KNOWN_SENSORS = String.join(", ", Arrays.stream(Sensor.values()).map(Enum::name).toList());

    private final int robotId;
    private final Watchdog watchdog;
    private final Set<String> unknownSensorsLogged = new HashSet<>();
    private Mode mode = Mode.WAITING;
    private Command current = Command.STOP;
    private long lastSeenCommandId = -1;
    private long lastSeenIteration = Long.MIN_VALUE;
    private long lastExecutedCommandId = -1;
    private long lastStaleCommandLogged = -1;
    private long lastUnknownRequestCounted = -1;
    /** Stopped by a failed database call or the watchdog; a new command lets the robot go again. */
    private boolean heldUntilNewCommand;
    private long lastRefusalWarnMs = NEVER;
    private long refusalsSinceWarn;
    private boolean seeded;
    private boolean startBatteryWritten;
    /** Read the checkpoints' unreachable marks every this many steps, simulated. */
    static final int UNREACHABLE_EVERY = 16;
    private long senseCalls;
    /** Steps sensed, for the checkpoints' poll. */
    private long sensedSteps;
    /** The engine marked a checkpoint unreachable: the mission is over. */
    private boolean checkpointUnreachable;
    private boolean noFixLogged;
    private Consumer<CommandRecord> commandListener = record -> { };
    /** Each wheel's travel since the start as of the last odometry reading written, metres: where the next one counts from. */
    private double reportedLeftM;
    private double reportedRightM;

    /**
     * A controller over a link someone else owns (the app's pool, an in-process link...).
     *
     * @param simulation the simulation whose robot this controls
     * @param link       the channel to the engine (closed with this controller)
     * @param config     the configuration
     */
    public ProactiveController(Simulation simulation, RobotLink link, RobotConfig config) {
        this(simulation, 0, link, config, null);
    }

    /**
     * A controller of one robot of a world with several, over a link someone else owns. Its mission rows are
     * seeded from that robot's own mission ({@link org.proactiverobotics.sim2d.WorldSpec#forRobot(int)}), under
     * {@link RobotConfig#robotId()} (the robot's id in the world file).
     *
     * @param simulation the simulation one of whose robots this controls
     * @param robotIndex that robot's position in the world's robots (0-based)
     * @param link       the channel to the engine (closed with this controller)
     * @param config     the configuration
     */
    public ProactiveController(Simulation simulation, int robotIndex, RobotLink link, RobotConfig config) {
        this(simulation, robotIndex, link, config, null);
    }

    private ProactiveController(Simulation simulation, int robotIndex, RobotLink link, RobotConfig config,
                                AutoCloseable owned) {
        super(simulation, robotIndex, link, config, owned);
        this.robotId = config.robotId();
        this.watchdog = new Watchdog(config.watchdogTimeoutMs());
    }

    /**
     * A controller with a pool of its own ({@link RobotPool}: short connection time-out) over a
     * JDBC database; the pool is closed with the controller. Nothing is connected yet: the
     * database may come up later.
     *
     * @param simulation the simulation whose robot this controls
     * @param jdbcUrl    the database's JDBC URL
     * @param user       the user, or null to take it from the URL
     * @param password   the password, or null
     * @param config     the configuration
     * @return the controller; close it when done
     */
    public static ProactiveController connect(Simulation simulation, String jdbcUrl, String user, String password,
                                              RobotConfig config) {
        HikariDataSource pool = RobotPool.open(jdbcUrl, user, password);
        return new ProactiveController(simulation, 0, new JdbcRobotLink(pool), config, pool);
    }

    /**
     * Tells a listener of every new valid command the robot executes (a report counting the
     * winning scenarios, say).
     *
     * @param listener called on the controller's thread
     * @return this controller
     */
    public ProactiveController onCommand(Consumer<CommandRecord> listener) {
        this.commandListener = Objects.requireNonNull(listener, "listener");
        return this;
    }

    /** @return the current mode */
    public Mode mode() {
        return mode;
    }

    /** @return the command being executed ({@link Command#STOP} while waiting, or stopped by a failed call or the watchdog) */
    public Command currentCommand() {
        return current;
    }

    /** @return the id of the last command executed, or -1 */
    public long lastExecutedCommandId() {
        return lastExecutedCommandId;
    }

    /** @return whether a failed database call or the watchdog has stopped the robot and no new command came since */
    public boolean stoppedUntilNewCommand() {
        return heldUntilNewCommand;
    }

    /** @return whether the start-up writes (mission rows, first battery level) are done */
    public boolean started() {
        return seeded && startBatteryWritten;
    }

    /** @return whether the engine has marked a checkpoint unreachable (read every {@value #UNREACHABLE_EVERY} steps) */
    public boolean checkpointUnreachable() {
        return checkpointUnreachable;
    }

    /** The mission is also over when the engine found a checkpoint unreachable. */
    @Override
    public boolean missionOver() {
        return checkpointUnreachable || super.missionOver();
    }

    @Override
    public void sense() {
        long now = simTimeMs();
        startIfNeeded(now);
        int every = config.retention().everySteps();
        if (config.retention().prunes() && ++senseCalls % every == 0) {
            Integer pruned = call("pruning history", 0, l -> l.prune(robotId, config.retention()));
            if (pruned != null) {
                stats.rowsPruned += pruned;
            }
        }
        if (++sensedSteps % UNREACHABLE_EVERY == 0 && !checkpointUnreachable) {
            Boolean unreachable = call("reading checkpoints", 0, l -> l.checkpointUnreachable(robotId));
            checkpointUnreachable = unreachable != null && unreachable;
        }
        List<SensorRequest> pending = call("reading sensor_requests", 0, l -> l.pendingRequests(robotId));
        if (pending == null || pending.isEmpty()) {
            return;
        }
        boolean gps = false;
        boolean iu = false;
        boolean ds = false;
        boolean battery = false;
        boolean odometry = false;
        long[] ids = new long[pending.size()];
        int answered = 0;
        for (SensorRequest r : pending) {
            Optional<Sensor> sensor = Sensor.byName(r.sensor());
            if (sensor.isEmpty()) {
                unknownRequest(r);
                continue;
            }
            switch (sensor.get()) {
                case GPS -> gps = true;
                case IU -> iu = true;
                case DS -> ds = true;
                case BATTERY -> battery = true;
                case ODOMETRY -> odometry = true;
                default -> throw new AssertionError(sensor.get());
            }
            ids[answered++] = r.id();
        }
        if (answered == 0) {
            return;
        }
        double[] travel = odometry ? robot.odometer().getTravelM() : null;
        SensorAnswer answer = new SensorAnswer(now, gps ? readGps() : null, iu ? readIu() : null,
                ds ? readDistances() : List.of(), battery ? readBattery() : null,
                odometry ? new OdometryReading(travel[0] - reportedLeftM, travel[1] - reportedRightM) : null,
                answered == ids.length ? ids : Arrays.copyOf(ids, answered));
        int readings = answer.readingCount();
        Boolean ok = call("writing " + readings + " reading(s)", readings, l -> {
            l.answer(robotId, answer);
            return Boolean.TRUE;
        });
        if (ok != null) {
            stats.requestsAnswered += answered;
            stats.readingsWritten += readings;
            if (travel != null) { // a failed write leaves its travel to the next reading
                reportedLeftM = travel[0];
                reportedRightM = travel[1];
            }
        }
    }

    @Override
    public void act() {
        long now = simTimeMs();
        Optional<CommandRecord> newest = call("reading engine_comments", 0, l -> l.newestCommand(robotId));
        if (newest != null && newest.isPresent()) {
            consider(newest.get(), now);
        }
        if (!heldUntilNewCommand && watchdog.armed() && databaseFailing()) {
            stats.linkStops++;
            hold("robot {}: the database failed {} ms of simulated time after the last new command: stopping until a"
                    + " new command comes", watchdog.sinceLastFeedMs(now));
        } else if (!heldUntilNewCommand && watchdog.expired(now)) {
            stats.watchdogStops++;
            hold("robot {}: no new command for {} ms of simulated time (engine gone or too slow): stopping",
                    watchdog.sinceLastFeedMs(now));
        }
        applyMode();
    }

    private void hold(String warning, long sinceLastCommandMs) {
        heldUntilNewCommand = true;
        LOG.warn(warning, robotId, sinceLastCommandMs);
        switchTo(Command.STOP);
    }

    /** Sets the wheels from the mode: the paper's switch. */
    private void applyMode() {
        switch (mode) {
            case WAITING, STOP, RECHARGE -> robot.setWheelSpeeds(0.0, 0.0);
            case DRIVE, FORWARD, TURN_LEFT, TURN_RIGHT -> robot.setWheelSpeeds(current.leftMps(), current.rightMps());
            default -> throw new AssertionError(mode);
        }
    }

    private void consider(CommandRecord record, long now) {
        if (record.id() == lastSeenCommandId) {
            return; // nothing new
        }
        // Older by the engine's iteration, then by id: ids from different Galera nodes interleave.
        if (record.iteration() < lastSeenIteration || record.iteration() == lastSeenIteration && record.id() < lastSeenCommandId) {
            if (record.id() != lastStaleCommandLogged) {
                lastStaleCommandLogged = record.id();
                stats.commandsIgnored++;
                LOG.warn("robot {}: ignoring command id {} ('{}', iteration {}): older than command id {} (iteration {})"
                        + " already seen", robotId, record.id(), record.command(), record.iteration(), lastSeenCommandId,
                        lastSeenIteration);
            }
            return;
        }
        lastSeenCommandId = record.id();
        lastSeenIteration = record.iteration();
        Command command;
        try {
            command = Command.parse(record.command(), robot.maxSpeedMps());
        } catch (MalformedCommandException e) {
            stats.commandsIgnored++;
            LOG.warn("robot {}: ignoring command id {} from {}: {}; keeping mode {}", robotId, record.id(),
                    record.scenario(), e.getMessage(), mode);
            return;
        }
        watchdog.feed(now);
        if (heldUntilNewCommand) {
            heldUntilNewCommand = false;
            LOG.info("robot {}: commands are back (id {}, '{}'): resuming", robotId, record.id(), record.command());
        }
        lastExecutedCommandId = record.id();
        stats.commandsExecuted++;
        switchTo(command);
        commandListener.accept(record);
    }

    private void switchTo(Command command) {
        Mode previous = mode;
        if (previous == Mode.RECHARGE && command.mode() != Mode.RECHARGE) {
            robot.battery().stopCharging();
        }
        mode = command.mode();
        current = command;
        if (mode == Mode.RECHARGE) {
            recharge();
        }
        if (previous != mode) {
            LOG.debug("robot {}: mode {} -> {}", robotId, previous, mode);
        }
    }

    /**
     * Starts charging when at the station and not charging yet. At the station and already charged is normal:
     * the engine reads the battery level only every few steps, so a RECHARGE or two still come once it is full.
     * Away from the station the command is refused: a WARN, at most once per {@link #REFUSAL_WARN_INTERVAL_MS}.
     */
    private void recharge() {
        var battery = robot.battery();
        if (battery.isCharging()) {
            return;
        }
        if (battery.startCharging()) {
            LOG.info("robot {}: charging from {}%", robotId, String.format("%.1f", battery.getLevelPct()));
        } else if (battery.isAtStation()) {
            LOG.debug("robot {}: RECHARGE at {}%, already at the recharge level", robotId,
                    String.format("%.1f", battery.getLevelPct()));
        } else {
            refusalsSinceWarn++;
            long now = simTimeMs();
            if (lastRefusalWarnMs == NEVER || now - lastRefusalWarnMs >= REFUSAL_WARN_INTERVAL_MS) {
                LOG.warn("robot {}: RECHARGE refused: not at the recharge station; standing still"
                        + " ({} refused RECHARGE command(s) since the last warning)", robotId, refusalsSinceWarn);
                lastRefusalWarnMs = now;
                refusalsSinceWarn = 0;
            }
        }
    }

    private void startIfNeeded(long now) {
        if (!seeded) {
            if (!config.seedMission()) {
                seeded = true;
            } else {
                Boolean wrote = call("seeding the mission", 0, l -> l.seedMission(robotId, Missions.of(ownMission())));
                if (wrote != null) {
                    seeded = true;
                    LOG.info("robot {}: mission rows {}", robotId, wrote ? "seeded from world '" + simulation.spec().name() + "'"
                            : "already in the database; left as they are");
                }
            }
        }
        if (!startBatteryWritten) {
            BatteryReading reading = readBattery();
            if (call("writing the start battery level", 0, l -> {
                l.writeBattery(robotId, now, reading);
                return Boolean.TRUE;
            }) != null) {
                startBatteryWritten = true;
                stats.readingsWritten++;
                LOG.info("robot {}: battery {}% written; waiting for instructions", robotId,
                        String.format("%.1f", reading.levelPct()));
            }
        }
    }

    /** @return the world as this robot's mission sees it: the world itself when it has one robot */
    private org.proactiverobotics.sim2d.WorldSpec ownMission() {
        var spec = simulation.spec();
        return spec.hasSeveralRobots() ? spec.forRobot(robotIndex) : spec;
    }

    private void unknownRequest(SensorRequest r) {
        if (r.id() > lastUnknownRequestCounted) {
            lastUnknownRequestCounted = r.id();
            stats.unknownRequests++;
        }
        if (unknownSensorsLogged.add(String.valueOf(r.sensor()))) {
            LOG.warn("robot {}: request id {} asks for unknown sensor '{}'; left unanswered (known: {})",
                    robotId, r.id(), r.sensor(), KNOWN_SENSORS);
        }
    }

    /** @return the GPS reading, or null without a fix: the request is answered, and no reading written ("no fix") */
    private GpsReading readGps() {
        double[] v = robot.gps().getValues();
        if (Double.isNaN(v[0]) || Double.isNaN(v[1])) {
            if (!noFixLogged) {
                noFixLogged = true;
                LOG.warn("robot {}: the GPS has no fix; GPS requests are answered with no reading", robotId);
            }
            return null;
        }
        return new GpsReading(v[0], v[1]);
    }

    private IuReading readIu() {
        double[] v = robot.inertialUnit().getRollPitchYaw();
        return new IuReading(v[0], v[1], v[2]);
    }

    private List<DistanceReading> readDistances() {
        List<DistanceSensor> sensors = robot.distanceSensors();
        List<DistanceReading> out = new ArrayList<>(sensors.size());
        for (DistanceSensor s : sensors) {
            out.add(new DistanceReading(s.getIndex(), s.getAngleRad(), s.getValue(), s.getRangeM()));
        }
        return out;
    }

    private BatteryReading readBattery() {
        var battery = robot.battery();
        return new BatteryReading(battery.getLevelPct(), battery.isCharging());
    }
}
