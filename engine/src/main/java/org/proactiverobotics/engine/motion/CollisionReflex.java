package org.proactiverobotics.engine.motion;

import java.util.Arrays;
import java.util.Locale;
import org.proactiverobotics.engine.tables.DistanceScan;
import org.proactiverobotics.engine.tables.OccupancyMap;

/**
 * The collision reflex any scenario may hold, as a robot's collision monitor does: it vets the
 * command the robot is about to drive and speaks only when that command would bring the body
 * into something within its braking reach; otherwise it lets the command go, so the scenarios
 * that find the way (which plan on the map) drive everywhere, doorways and narrow corridors
 * included. A vetoed command is replaced by the forward arc nearest to it that keeps the body
 * clear over cells the rays have seen free (so the robot slips past a door jamb or a pillar), else
 * by a turn on the spot, which sweeps nothing new for a disc, in the direction it wanted to turn
 * (toward the freer side when it wanted none, kept until the way is clear, so the robot does not
 * dither between two sides).
 * The reach is the distance covered at the command's speed while a reading is answered, decided
 * and acted on, plus the time to stop ({@link Clearance#imminentM()}, from the robot's speed,
 * control period and sensor range), plus {@value #SIDE_MARGIN_M} m.
 *
 * <p>The command's arc is checked against the points the rays hit now and in the last
 * {@value #MEMORY_MS} ms, placed by the GPS and inertial-unit readings (a short memory, as a
 * robot's local costmap keeps): a few rays leave gaps at the flanks, and a pillar or a wall's
 * corner seen a moment ago is still there when it slips between two rays. The memory keeps one hit
 * per {@value #MEMORY_SPACING_M} m, so the newest scan's hits are checked too, each where it was
 * read: a wall the body closes on reads nearer than the hit remembered beside it. Plain fields, so
 * it is saved with the rule that holds it.
 */
public final class CollisionReflex {

    /** Hits are remembered this long, milliseconds. */
    static final long MEMORY_MS = 3000;
    /** At most this many remembered hits (the oldest go first). */
    static final int MEMORY_POINTS = 64;
    /** A hit this close to a remembered one adds nothing, metres. */
    static final double MEMORY_SPACING_M = 0.04;
    /** Room kept between the body and a hit, metres (readings jitter by about a centimetre). */
    public static final double SIDE_MARGIN_M = 0.02;
    /** The arc is checked every this many metres. */
    private static final double ARC_STEP_M = 0.01;
    /** Vetoes in a row after which the robot backs off a little. */
    static final int STUCK_VETOES = 40;
    /** Iterations it then backs off for. */
    static final int BACK_ITERATIONS = 12;
    /** Backing-off speed, as a share of the top speed. */
    static final double BACK_SPEED = 0.3;
    /** Backing off checks this far behind, metres. */
    static final double BACK_REACH_M = 0.1;
    /** A flank reading this close, metres from the rim, guards that side (a ray set with wide gaps cannot see the wall between). */
    static final double FLANK_GUARD_M = 0.06;
    /** Turning toward a guarded flank faster than this is vetoed, radians per second. */
    static final double FLANK_TURN_RAD_S = 0.2;
    /** Arcs tried on each side of a vetoed command's turn before a turn on the spot. */
    static final int AROUND_ARCS = 6;
    /** Turn-rate step between the arcs tried, radians per second. */
    static final double AROUND_STEP_RAD_S = 0.4;
    /** Top speed of an arc the command did not ask for, as a share of the robot's top speed. */
    static final double AROUND_SPEED = 0.5;
    /** Turn rate of a turn on the spot, radians per second. */
    private static final double TURN_RAD_S = 1.8;
    private static final double DEG = Math.PI / 180;

    /** The side of the last turn on the spot, +1 left, -1 right, 0 none: kept while the way is blocked. */
    private int turning;
    /** The last scan's nearest reading at each flank (left, right), metres from the rim. */
    private double[] lastFlankM = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY};
    /** Vetoes since a forward command last went through. */
    private int vetoes;
    /** Iterations of backing off still to go. */
    private int backing;
    /** Remembered hits: x, y (metres) and simulated time (ms) of each, oldest first. */
    private double[] hitX = new double[0];
    private double[] hitY = new double[0];
    private long[] hitMs = new long[0];
    /** The newest scan's hits, x and y (metres), every one as read (the memory above drops those near a remembered hit). */
    private double[] nowX = new double[0];
    private double[] nowY = new double[0];

    /** What made the last veto, for its reason in words: one of the {@code CAUSE_} constants (not saved). */
    private transient int cause;
    /** The thing that made it: a hit's or an occupied cell's point (metres), or the flank reading's distance from the rim. */
    private transient double causeX;
    private transient double causeY;
    /** The robot's pose and the reach the last veto was judged with, metres and radians. */
    private transient double vetoX;
    private transient double vetoY;
    private transient double vetoYaw;
    private transient double vetoReachM;
    private transient double vetoRadiusM;
    /** Whether the guarded flank's wall converged (else the command turned toward it). */
    private transient boolean flankClosing;
    /** The thing found by the last {@link #hitsWithin} that answered true (cause, point). */
    private transient int foundCause;
    private transient double foundX;
    private transient double foundY;

    private static final int CAUSE_NONE = 0;
    private static final int CAUSE_HIT = 1;
    private static final int CAUSE_CELL = 2;
    private static final int CAUSE_FLANK = 3;
    private static final int CAUSE_BACKING = 4;
    private static final int CAUSE_BEHIND = 5;

    /** Whether a reverse command is vetted too (set for a robot that shares its world; not saved as state that changes). */
    private boolean vetsReverse;

    /**
     * Vets reverse commands too, from now on: a command that backs the body, over its braking reach,
     * toward a hit (the rays' hits of the last {@value #MEMORY_MS} ms, placed where they were: what the
     * front rays saw before the robot turned or backed, and what rear rays, where the body has them,
     * see now) or toward a map cell that is occupied or that the rays never saw is replaced by STOP.
     * Off by default: a lone robot's runs stay as they were.
     *
     * @return this reflex
     */
    public CollisionReflex vettingReverse() {
        vetsReverse = true;
        return this;
    }

    /** @return whether the reflex vetoed the last command it vetted */
    public boolean engaged() {
        return turning != 0;
    }

    /**
     * Vets a command.
     *
     * @param intended the command the robot would drive (null: none, the robot stops; a text not in the
     *                 robot's grammar is vetted as full speed ahead)
     * @param s        the newest distance scan
     * @param xM       the robot's x at the scan, metres
     * @param yM       its y, metres
     * @param yawRad   its heading, radians
     * @param profile  the robot's drive (its body's radius is half the axle width)
     * @param c        the distances to keep
     * @return a turn on the spot when the command would bring the body into a hit within its reach, else null
     */
    public String vet(String intended, DistanceScan s, double xM, double yM, double yawRad, DriveProfile profile, Clearance c) {
        return vet(intended, s, null, xM, yM, yawRad, profile, c);
    }

    /**
     * Vets a command against the hits and the occupied cells of the map known so far: the map
     * remembers a wall's end or a corner the rays saw on the way in, wherever they point now.
     *
     * @param intended the command the robot would drive (as {@link #vet(String, DistanceScan, double, double, double, DriveProfile, Clearance)})
     * @param s        the newest distance scan
     * @param map      the map known so far (null: the hits alone)
     * @param xM       the robot's x at the scan, metres
     * @param yM       its y, metres
     * @param yawRad   its heading, radians
     * @param profile  the robot's drive
     * @param c        the distances to keep
     * @return a turn on the spot when the command would bring the body into a hit or an occupied cell within its reach, else null
     */
    public String vet(String intended, DistanceScan s, OccupancyMap map, double xM, double yM, double yawRad,
                      DriveProfile profile, Clearance c) {
        double radiusM = profile.axleWidthM() / 2;
        remember(s, xM, yM, yawRad, radiusM);
        cause = CAUSE_NONE;
        vetoX = xM;
        vetoY = yM;
        vetoYaw = yawRad;
        vetoRadiusM = radiusM;
        if (backing > 0) {
            String back = backOff(map, xM, yM, yawRad, profile);
            if (back != null) {
                cause = CAUSE_BACKING;
                return back;
            }
        }
        if (intended == null) {
            turning = 0;
            vetoes = 0;
            return null;
        }
        double[] wheels = Steering.wheelSpeeds(intended);
        if (wheels == null) {
            wheels = new double[] {profile.maxSpeedMps(), profile.maxSpeedMps()}; // unknown: assume the worst
        }
        double speed = (wheels[0] + wheels[1]) / 2;
        double turnRate = (wheels[1] - wheels[0]) / profile.axleWidthM();
        if (speed < -1e-6 && vetsReverse) {
            return vetReverse(map, xM, yM, yawRad, radiusM, speed, turnRate, profile, c);
        }
        if (speed <= 1e-6) {
            return null; // turning on the spot or backing off: the rays look ahead only
        }
        double reachM = c.imminentM() * Math.min(1.0, speed / profile.maxSpeedMps()) + SIDE_MARGIN_M;
        vetoReachM = reachM;
        double leftBefore = lastFlankM[0];
        double rightBefore = lastFlankM[1];
        int guarded = flankGuard(s, turnRate);
        if (guarded != 0) {
            turning = -guarded; // away from the flank it would close on
            cause = CAUSE_FLANK;
            causeX = guarded > 0 ? lastFlankM[0] : lastFlankM[1];
            causeY = guarded;
            flankClosing = closing(causeX, guarded > 0 ? leftBefore : rightBefore);
        }
        if (guarded == 0 && !hitsWithin(map, xM, yM, yawRad, radiusM, speed, turnRate, reachM, false)) {
            turning = 0;
            vetoes = 0;
            return null;
        }
        if (guarded == 0) {
            cause = foundCause;
            causeX = foundX;
            causeY = foundY;
        }
        String around = aroundArc(s, map, xM, yM, yawRad, radiusM, profile, c, speed, turnRate, guarded);
        if (around != null) {
            return around;
        }
        if (++vetoes >= STUCK_VETOES) {
            vetoes = 0; // the way it wants stays blocked however it turns: back off a little, then let it try again
            backing = BACK_ITERATIONS;
            String back = backOff(map, xM, yM, yawRad, profile);
            if (back != null) {
                cause = CAUSE_BACKING;
                return back;
            }
        }
        if (guarded == 0) { // else turning stays away from the guarded flank
            if (Math.abs(turnRate) > 0.05) {
                turning = turnRate > 0 ? +1 : -1; // the way the command was turning
            } else if (turning == 0) {
                turning = freerSide(s);
            }
        }
        return Steering.drive(0.0, turning * TURN_RAD_S, profile);
    }

    /**
     * The forward arc nearest the command's turn that keeps the body clear, over cells the rays
     * have seen (an arc the command did not ask for must not sweep a corner that slipped between
     * two rays): the body slips past a door jamb or between two pillars instead of turning on the
     * spot back and forth, as the route keeps asking for the way the reflex refuses. Null when none.
     */
    private String aroundArc(DistanceScan s, OccupancyMap map, double xM, double yM, double yawRad, double radiusM,
                             DriveProfile profile, Clearance c, double speed, double turnRate, int guarded) {
        if (map == null) {
            return null;
        }
        double v = Math.min(speed, AROUND_SPEED * profile.maxSpeedMps());
        double reachM = c.imminentM() * v / profile.maxSpeedMps() + SIDE_MARGIN_M;
        int first = guarded != 0 ? -guarded : freerSide(s);
        for (int k = 1; k <= AROUND_ARCS; k++) {
            for (int q = 0; q < 2; q++) {
                int side = q == 0 ? first : -first;
                double w = turnRate + side * k * AROUND_STEP_RAD_S;
                if (guarded != 0 && w * guarded > FLANK_TURN_RAD_S) {
                    continue; // not toward the flank that is guarded
                }
                if (!hitsWithin(map, xM, yM, yawRad, radiusM, v, w, reachM, true)) {
                    return Steering.drive(v, w, profile);
                }
            }
        }
        return null;
    }

    /** @return the side the scan sees more room on, +1 left, -1 right */
    private static int freerSide(DistanceScan s) {
        return s.sum(12 * DEG, 180 * DEG) >= s.sum(-180 * DEG, -12 * DEG) ? +1 : -1;
    }

    /**
     * A reverse command: STOP when its arc over the braking reach would bring the body closer than
     * the margin to a remembered hit, an occupied cell or a cell the rays never saw (backing into what
     * it cannot see is backing blind), else null (the command goes).
     */
    private String vetReverse(OccupancyMap map, double xM, double yM, double yawRad, double radiusM, double speed,
                              double turnRate, DriveProfile profile, Clearance c) {
        double reachM = c.imminentM() * Math.min(1.0, -speed / profile.maxSpeedMps()) + SIDE_MARGIN_M;
        vetoReachM = reachM;
        turning = 0;
        vetoes = 0;
        if (!hitsWithin(map, xM, yM, yawRad, radiusM, speed, turnRate, reachM, true)) {
            return null;
        }
        cause = CAUSE_BEHIND;
        causeX = foundX;
        causeY = foundY;
        return Steering.STOP;
    }

    /** One step of backing off straight, or null (and no more backing) when something is behind too. */
    private String backOff(OccupancyMap map, double xM, double yM, double yawRad, DriveProfile profile) {
        double backSpeed = -BACK_SPEED * profile.maxSpeedMps();
        backing--;
        if (!hitsWithin(map, xM, yM, yawRad, profile.axleWidthM() / 2, backSpeed, 0.0, BACK_REACH_M, false)) {
            return Steering.drive(backSpeed, 0.0, profile);
        }
        backing = 0;
        return null;
    }

    /**
     * Whether the body, driven along the command's arc for {@code reachM}, comes closer than the
     * margin to a hit or an occupied cell (with {@code unseenToo}, to a cell the rays never saw).
     */
    private boolean hitsWithin(OccupancyMap map, double xM, double yM, double yawRad, double radiusM,
                               double speed, double turnRate, double reachM, boolean unseenToo) {
        double keep = radiusM + SIDE_MARGIN_M;
        double keep2 = keep * keep;
        int steps = (int) Math.ceil(reachM / ARC_STEP_M);
        double dir = Math.signum(speed);
        double perStepRad = turnRate / Math.abs(speed) * ARC_STEP_M;
        double px = xM;
        double py = yM;
        double heading = yawRad;
        for (int q = 1; q <= steps; q++) {
            heading += perStepRad;
            px += dir * ARC_STEP_M * Math.cos(heading);
            py += dir * ARC_STEP_M * Math.sin(heading);
            if (approached(hitX, hitY, xM, yM, px, py, keep2) || approached(nowX, nowY, xM, yM, px, py, keep2)) {
                return true;
            }
            if (map != null && (map.occupiedApproached(xM, yM, px, py, keep)
                    || unseenToo && map.unknownApproached(xM, yM, px, py, keep))) {
                foundCell(map, px, py, keep);
                return true;
            }
        }
        return false;
    }

    /**
     * Whether the body, moved from (xM, yM) to (px, py), comes within {@code sqrt(keep2)} of one of
     * the points and closer to it than it was: a point it is already beside or leaving is no veto.
     */
    private boolean approached(double[] xs, double[] ys, double xM, double yM, double px, double py, double keep2) {
        for (int k = 0; k < xs.length; k++) {
            double dx = xs[k] - px;
            double dy = ys[k] - py;
            double d2 = dx * dx + dy * dy;
            if (d2 < keep2) {
                double ax = xs[k] - xM;
                double ay = ys[k] - yM;
                if (d2 < ax * ax + ay * ay - 1e-6) {
                    found(CAUSE_HIT, xs[k], ys[k]);
                    return true;
                }
            }
        }
        return false;
    }

    private void found(int kind, double x, double y) {
        foundCause = kind;
        foundX = x;
        foundY = y;
    }

    /** Notes the occupied cell nearest a point of the arc, within {@code keepM} of it (the point itself when none: an unseen cell). */
    private void foundCell(OccupancyMap map, double px, double py, double keepM) {
        double best = Double.POSITIVE_INFINITY;
        found(CAUSE_CELL, px, py);
        for (int j = OccupancyMap.cell(py - keepM); j <= OccupancyMap.cell(py + keepM); j++) {
            for (int i = OccupancyMap.cell(px - keepM); i <= OccupancyMap.cell(px + keepM); i++) {
                double d = Math.hypot(OccupancyMap.centre(i) - px, OccupancyMap.centre(j) - py);
                if (d < best && d < keepM && map.get(i, j) == OccupancyMap.OCCUPIED) {
                    best = d;
                    found(CAUSE_CELL, OccupancyMap.centre(i), OccupancyMap.centre(j));
                }
            }
        }
    }

    /**
     * Why the last vetted command was replaced, in words, saying only what the reflex knows: where
     * the hit or the map's occupied cell lies from the body (distance from its rim, bearing from its
     * heading), the braking reach it was judged with, a guarded flank, or a back-off.
     *
     * @param intended the command vetted (null: none)
     * @return the reason, or null when the last command was not replaced
     */
    public String reason(String intended) {
        String what = "vetoed " + (intended == null ? "no command" : intended) + ": ";
        switch (cause) {
            case CAUSE_HIT:
            case CAUSE_CELL:
                double d = Math.max(0.0, Math.hypot(causeX - vetoX, causeY - vetoY) - vetoRadiusM);
                double bearing = Math.toDegrees(Math.atan2(causeY - vetoY, causeX - vetoX) - vetoYaw);
                bearing = bearing - 360.0 * Math.floor((bearing + 180.0) / 360.0);
                return String.format(Locale.ROOT, "%s%s %.2f m away at %d°, within braking reach %.2f m", what,
                        cause == CAUSE_HIT ? "obstacle a ray hit" : "occupied map cell", d, Math.round(bearing), vetoReachM);
            case CAUSE_FLANK:
                return String.format(Locale.ROOT, "%sobstacle %.2f m off the %s flank (rays at 60° to 120°), %s", what, causeX,
                        causeY > 0 ? "left" : "right",
                        flankClosing ? "closing in" : "and the command turns toward it");
            case CAUSE_BEHIND:
                double behind = Math.max(0.0, Math.hypot(causeX - vetoX, causeY - vetoY) - vetoRadiusM);
                double at = Math.toDegrees(Math.atan2(causeY - vetoY, causeX - vetoX) - vetoYaw);
                at = at - 360.0 * Math.floor((at + 180.0) / 360.0);
                return String.format(Locale.ROOT, "%sbacking toward %s %.2f m away at %d°, within braking reach %.2f m: stopped",
                        what, foundCause == CAUSE_HIT ? "an obstacle a ray hit" : "an occupied or unseen map cell", behind,
                        Math.round(at), vetoReachM);
            case CAUSE_BACKING:
                return String.format(Locale.ROOT, "%sbacking off %.2f m: the way stayed blocked through %d vetoes in a row",
                        what, BACK_REACH_M, STUCK_VETOES);
            default:
                return null;
        }
    }

    /**
     * The flank (+1 left, -1 right, 0 none) that a forward command would close on: one whose nearest
     * reading (60° to 120°) is within {@value #FLANK_GUARD_M} m of the rim and either shrank since
     * the last scan (the wall there converges) or lies on the side the command turns to. Between the
     * 45° and 90° rays a wall's continuation or a box's corner is not seen, and it is what a body
     * sliding along it hits. Remembers this scan's flank readings.
     */
    private int flankGuard(DistanceScan s, double turnRate) {
        double left = s.min(60 * DEG, 120 * DEG);
        double right = s.min(-120 * DEG, -60 * DEG);
        int guarded = 0;
        if (left < FLANK_GUARD_M && (closing(left, lastFlankM[0]) || turnRate > FLANK_TURN_RAD_S)) {
            guarded = +1;
        } else if (right < FLANK_GUARD_M && (closing(right, lastFlankM[1]) || turnRate < -FLANK_TURN_RAD_S)) {
            guarded = -1;
        }
        lastFlankM[0] = left;
        lastFlankM[1] = right;
        return guarded;
    }

    /** Whether a flank reading shrank since the last scan, which saw that wall too (not one just come into the ray). */
    private static boolean closing(double nowM, double lastM) {
        return lastM < 2 * FLANK_GUARD_M && nowM < lastM - 0.002;
    }

    /** Forgets every remembered hit (the robot's position is unknown, so they cannot be placed). */
    public void forget() {
        hitX = new double[0];
        hitY = new double[0];
        hitMs = new long[0];
        nowX = new double[0];
        nowY = new double[0];
    }

    /** Keeps the scan's hits as the newest, adds them to the memory and forgets the old and the far. */
    private void remember(DistanceScan s, double xM, double yM, double yawRad, double radiusM) {
        int n = hitX.length;
        double[] xs = new double[n + s.anglesRad().length];
        double[] ys = new double[xs.length];
        long[] ms = new long[xs.length];
        int m = 0;
        int fresh = 0;
        double[] freshX = new double[s.anglesRad().length];
        double[] freshY = new double[freshX.length];
        double farM = radiusM + s.rangeM() + 0.5;
        for (int k = 0; k < n; k++) {
            if (s.simTimeMs() - hitMs[k] <= MEMORY_MS && Math.hypot(hitX[k] - xM, hitY[k] - yM) <= farM) {
                xs[m] = hitX[k];
                ys[m] = hitY[k];
                ms[m++] = hitMs[k];
            }
        }
        for (int k = 0; k < s.anglesRad().length; k++) {
            double d = s.distancesM()[k];
            if (Double.isNaN(d)) {
                d = 0.0; // a reading that is not a number counts as an obstacle at the rim, not as free space
            }
            if (!(d < s.rangeM() - 1e-6) || d < 0) {
                continue;
            }
            double a = yawRad + s.anglesRad()[k];
            double px = xM + (radiusM + d) * Math.cos(a);
            double py = yM + (radiusM + d) * Math.sin(a);
            freshX[fresh] = px;
            freshY[fresh++] = py;
            boolean known = false;
            for (int q = 0; q < m && !known; q++) {
                known = Math.hypot(xs[q] - px, ys[q] - py) < MEMORY_SPACING_M;
            }
            if (!known) {
                xs[m] = px;
                ys[m] = py;
                ms[m++] = s.simTimeMs();
            }
        }
        int from = Math.max(0, m - MEMORY_POINTS);
        hitX = Arrays.copyOfRange(xs, from, m);
        hitY = Arrays.copyOfRange(ys, from, m);
        hitMs = Arrays.copyOfRange(ms, from, m);
        nowX = Arrays.copyOf(freshX, fresh);
        nowY = Arrays.copyOf(freshY, fresh);
    }
}
