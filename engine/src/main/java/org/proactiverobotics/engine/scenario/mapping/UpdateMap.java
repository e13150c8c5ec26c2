package org.proactiverobotics.engine.scenario.mapping;

import java.util.List;
import org.proactiverobotics.engine.Outcome;
import org.proactiverobotics.engine.Rule;
import org.proactiverobotics.engine.RuleContext;
import org.proactiverobotics.engine.belief.BeliefObserver;
import org.proactiverobotics.engine.motion.DriveProfile;
import org.proactiverobotics.engine.navigation.SharedWorld;
import org.proactiverobotics.engine.tables.DistanceScan;
import org.proactiverobotics.engine.tables.MapChunk;
import org.proactiverobotics.engine.tables.OccupancyMap;
import org.proactiverobotics.engine.tables.OccupancyMapTable;
import org.proactiverobotics.engine.tables.PoseEstimate;
import org.proactiverobotics.engine.tables.PoseEstimateTable;
import org.proactiverobotics.engine.tables.SensorReadings;

/**
 * Adds each new distance scan to the map: along every ray, the cells it crossed lose evidence of
 * a wall (unknown ones become free) and the cell where it hit (a reading shorter than
 * {@value #FREE_MARGIN} of the range below it) gains some ({@link OccupancyMap#hit}). The scan is placed at the
 * pose estimate of the same moment (within {@value #SAME_MOMENT_MS} ms); a scan
 * without them is skipped. Every chunk a scan changed is written in the same iteration (its
 * transaction), so the stored map is always the one the engine's last committed iteration knew:
 * a resumed engine reloads it and plans the same routes, step for step (writing chunks where only
 * free cells changed later made a killed and resumed engine part from the uninterrupted run).
 * Clones itself every iteration.
 */
public final class UpdateMap extends Rule {

    /**
     * A reading within this share of the range is taken as a ray that hit nothing: a free ray reads
     * a little under its range when the sensor is noisy, and marking that as a wall drew a ring of
     * walls round the robot (every checkpoint unreachable within two seconds under --noise small).
     */
    static final double FREE_MARGIN = 0.1;
    /**
     * A hit this close, as a share of the range, confirms its cell at once: the robot is next to the
     * wall (the collision reflex sees it too), and a route planned through it would never be driven.
     */
    static final double CLOSE_HIT = 0.3;
    /**
     * A hit ray does not clear the cells it enters this close before its end, metres: a reading a
     * little too long ends inside the wall, and clearing the cells it crossed there wore a wall's
     * corner away under small noise until the robot's side grazed it (corridors, seed 17, number 14).
     */
    static final double UNCLEARED_M = 0.04;
    /**
     * In a shared world, a ray that hit something clears even a wall-for-good cell it crossed at
     * least this far before its end (a ray that hit nothing, every cell it crossed), metres: an obstacle that moved away is seen through, while a ray that ends in a wall's
     * cell, or crosses the free corner of one on its way into the wall, is no proof it is empty.
     */
    static final double CLEAR_BEFORE_END_M = 0.15;
    /** Readings this close in simulated time are taken as one moment, ms. */
    static final long SAME_MOMENT_MS = 40;

    /** The simulated time of the last scan added, ms (-1: none yet). */
    private long lastScanMs = -1;
    /** In a shared world, the cells something moved into (null for a lone robot: nothing saved). */
    private MovingCells moving;
    /** The requests to look again ({@link SharedWorld#LOOK_AGAIN}) served so far. */
    private int lookedAgain;

    /** The map as stored, loaded on the first run after a start or a resume. */
    private transient OccupancyMap map;
    private transient DistanceScan scan;
    private transient PoseEstimate position;

    @Override
    public String scenario() {
        return MappingScenario.NAME;
    }

    @Override
    protected void acquireGuardData(RuleContext ctx) {
        SensorReadings readings = ctx.service(SensorReadings.class);
        scan = readings.newestScan().orElse(null);
    }

    /** Guard: a scan the map does not hold yet. */
    @Override
    protected boolean activationGuards(RuleContext ctx) {
        return scan != null && scan.simTimeMs() > lastScanMs;
    }

    @Override
    protected void acquireConditionData(RuleContext ctx) {
        position = ctx.service(PoseEstimateTable.class).newestPose().orElse(null);
    }

    /** Condition: the robot's pose at the scan's moment is known. */
    @Override
    protected boolean conditions(RuleContext ctx) {
        return position != null && position.knowsHeading() && Math.abs(position.simTimeMs() - scan.simTimeMs()) <= SAME_MOMENT_MS;
    }

    @Override
    protected void actions(RuleContext ctx) {
        OccupancyMapTable table = ctx.service(OccupancyMapTable.class);
        if (map == null) {
            map = OccupancyMap.of(table.readMap());
        }
        double radiusM = ctx.findService(DriveProfile.class).orElse(DriveProfile.DEFAULT).axleWidthM() / 2;
        if (ctx.findService(SharedWorld.class).isPresent()) {
            if (moving == null) {
                moving = new MovingCells();
            }
            int asked = SharedWorld.lookAgainAsked(ctx.memory().values());
            if (asked > lookedAgain) {
                lookedAgain = asked;
                moving.forget(map); // no way left on the map: what moved in goes, the rays draw again what is still there
            }
            addScan(map, position.xM(), position.yM(), position.yawRad(), radiusM, scan, moving);
            moving.decay(map, position.xM(), position.yM(), position.yawRad(), radiusM, scan);
        } else {
            addScan(map, position.xM(), position.yM(), position.yawRad(), radiusM, scan);
        }
        lastScanMs = scan.simTimeMs();
        List<MapChunk> changed = map.takeChanged();
        if (!changed.isEmpty()) {
            table.writeChunks(changed, scan.simTimeMs());
            ctx.findService(BeliefObserver.class).ifPresent(b -> b.mapChanged(ctx.iteration(), changed));
        }
    }

    @Override
    protected void rulesGeneration(RuleContext ctx, Outcome outcome) {
        ctx.generate(this);
    }

    /**
     * Marks one scan's rays on a map.
     *
     * @param map     the map
     * @param xM      the robot's x at the scan, metres
     * @param yM      its y, metres
     * @param yawRad  its heading, radians
     * @param radiusM its body's radius (the rays start at the rim), metres
     * @param scan    the scan
     */
    public static void addScan(OccupancyMap map, double xM, double yM, double yawRad, double radiusM, DistanceScan scan) {
        addScan(map, xM, yM, yawRad, radiusM, scan, null);
    }

    /**
     * Marks one scan's rays on a map, in a world the robot may share with others.
     *
     * @param map     the map
     * @param xM      the robot's x at the scan, metres
     * @param yM      its y, metres
     * @param yawRad  its heading, radians
     * @param radiusM its body's radius (the rays start at the rim), metres
     * @param scan    the scan
     * @param moving  in a world shared with other robots, the cells something moved into (rays clear what they
     *                see through, walls for good included, and a hit on a cell seen free is followed here);
     *                null for a lone robot
     */
    static void addScan(OccupancyMap map, double xM, double yM, double yawRad, double radiusM, DistanceScan scan,
                        MovingCells moving) {
        for (int k = 0; k < scan.anglesRad().length; k++) {
            double d = scan.distancesM()[k];
            if (!(d >= 0) || !Double.isFinite(d)) {
                continue; // a reading that is not a number marks nothing
            }
            boolean hit = d < scan.rangeM() * (1 - FREE_MARGIN);
            double a = yawRad + scan.anglesRad()[k];
            double reach = radiusM + Math.min(d, scan.rangeM());
            double ex = xM + Math.cos(a) * reach;
            double ey = yM + Math.sin(a) * reach;
            traverse(map, xM, yM, ex, ey, hit, hit && d < scan.rangeM() * CLOSE_HIT, radiusM, moving);
        }
    }

    /** Walks the cells from (x0, y0) to (x1, y1) (Amanatides-Woo): free on the way, the last occupied on a hit. */
    private static void traverse(OccupancyMap map, double x0, double y0, double x1, double y1, boolean hit, boolean close,
                                 double radiusM, MovingCells moving) {
        int i = OccupancyMap.cell(x0);
        int j = OccupancyMap.cell(y0);
        int ei = OccupancyMap.cell(x1);
        int ej = OccupancyMap.cell(y1);
        double dx = x1 - x0;
        double dy = y1 - y0;
        int si = dx > 0 ? 1 : -1;
        int sj = dy > 0 ? 1 : -1;
        double c = OccupancyMap.CELL_M;
        double tdx = dx == 0 ? Double.POSITIVE_INFINITY : Math.abs(c / dx);
        double tdy = dy == 0 ? Double.POSITIVE_INFINITY : Math.abs(c / dy);
        double nextX = dx == 0 ? Double.POSITIVE_INFINITY : ((si > 0 ? (i + 1) * c : i * c) - x0) / dx;
        double nextY = dy == 0 ? Double.POSITIVE_INFINITY : ((sj > 0 ? (j + 1) * c : j * c) - y0) / dy;
        int guard = Math.abs(ei - i) + Math.abs(ej - j) + 2;
        // a hit's last few centimetres may lie inside the wall (a reading a little long): not cleared
        double keepFrom = hit ? 1.0 - UNCLEARED_M / Math.hypot(dx, dy) : Double.POSITIVE_INFINITY;
        // in a shared world, the cells left well behind before the ray's end are seen through: cleared, walls for good too
        // (a ray that hit nothing saw through every cell it crossed, its last one too)
        double clearBefore = moving == null ? Double.NEGATIVE_INFINITY : hit ? 1.0 - CLEAR_BEFORE_END_M / Math.hypot(dx, dy) : 2.0;
        double entered = 0.0;
        double left = Math.min(nextX, nextY);
        while ((i != ei || j != ej) && guard-- > 0) {
            if (left < clearBefore) {
                map.clear(i, j);
            } else if (entered < keepFrom) {
                map.miss(i, j); // seen free; a wall drawn here by a noisy reading loses its evidence
            }
            if (nextX < nextY) {
                entered = nextX;
                nextX += tdx;
                i += si;
            } else {
                entered = nextY;
                nextY += tdy;
                j += sj;
            }
            left = Math.min(nextX, nextY);
        }
        if (moving != null && hit && map.get(ei, ej) == OccupancyMap.FREE) {
            moving.addWithNeighbours(map, ei, ej, radiusM); // seen free, now hit: something moved in
        }
        if (close) {
            map.confirm(ei, ej);
        } else if (hit) {
            map.hit(ei, ej);
        } else if (moving != null) {
            map.clear(ei, ej);
        } else {
            map.miss(ei, ej);
        }
    }
}
