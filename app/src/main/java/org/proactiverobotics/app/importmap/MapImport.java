package org.proactiverobotics.app.importmap;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.SplittableRandom;
import java.util.concurrent.CompletableFuture;
import org.proactiverobotics.app.generate.GridPlanner;
import org.proactiverobotics.app.generate.Solvability;
import org.proactiverobotics.app.generate.WorldGenerator;
import org.proactiverobotics.app.sweep.WorldJson;
import org.proactiverobotics.sim2d.WorldFiles;
import org.proactiverobotics.sim2d.WorldSpec;
import org.proactiverobotics.sim2d.WorldValidationException;
import org.proactiverobotics.sim2d.map.BoxCover;
import org.proactiverobotics.sim2d.map.MapException;
import org.proactiverobotics.sim2d.map.MapFiles;
import org.proactiverobotics.sim2d.map.MapReading;
import org.proactiverobotics.sim2d.map.OccupancyGrid;

/**
 * A map made into a world with a seeded mission: the map's blocked cells as merged boxes, the arena
 * the map's extent, a start, checkpoints and a station placed by {@link MissionPlacer}, checked solvable
 * by {@link Solvability} on the robot's inflated footprint as {@code generate} checks its worlds; and
 * what the user should hear about the map (its size, free floor, warnings).
 *
 * @param world    the world, valid and solvable
 * @param json     its world file's text, boxes inline
 * @param grid     the map's cells as read
 * @param plan     the solvability check's plan
 * @param rooms    how many rooms the floor fell apart into for placing checkpoints
 * @param warnings one sentence each, possibly none
 */
public record MapImport(WorldSpec world, String json, OccupancyGrid grid, Solvability plan, int rooms, List<String> warnings) {

    /** A floor whose side is below this is small for a building, metres. */
    static final double SMALL_SIDE_M = 3.0;
    /** A floor whose side is above this is large for a building, metres. */
    static final double LARGE_SIDE_M = 300.0;
    /**
     * How many times the planned tour one charge must last: the robot does not know the floor and drives up to
     * about three times the planned path (what the time limit allows, at a third of top speed); with the
     * default battery, a 46 m tour on the office of docs/maps.md ran 137 m, stopped to recharge and ran out of time.
     */
    private static final double EXPLORATION = 3.0;

    /** Keeps an unmodifiable copy of the warnings. */
    public MapImport {
        warnings = List.copyOf(warnings);
    }

    /**
     * @param mapFile      a map_server YAML or a Moving AI map
     * @param cellM        metres a cell of a Moving AI map
     * @param robotRadiusM the robot's radius, metres
     * @param checkpoints  how many checkpoints
     * @param seed         the seed of the mission's draws
     * @param name         the world's name (letters, digits, {@code -}, {@code _}), or null for the map file's
     * @return the world and what to say about it
     * @throws MapException when the map cannot be read or holds no mission (naming the file)
     */
    public static MapImport of(Path mapFile, double cellM, double robotRadiusM, int checkpoints, long seed, String name) {
        MapReading reading = MapFiles.read(mapFile, cellM);
        OccupancyGrid grid = reading.grid();
        List<WorldSpec.Obstacle> boxes = BoxCover.boxes(grid);
        WorldSpec.Arena arena = WorldSpec.Arena.rectangle(grid.widthM(), grid.heightM(), grid.centreX(), grid.centreY());
        WorldSpec.Robot robot = new WorldSpec.Robot(grid.centreX(), grid.centreY(), 0.0, robotRadiusM,
                WorldSpec.Robot.DEFAULT_MAX_SPEED_MPS, WorldSpec.Robot.DEFAULT_SENSOR_RANGE_M,
                WorldGenerator.sensorAnglesDeg(robotRadiusM));
        String worldName = name != null ? name : nameOf(mapFile);
        WorldSpec floor = new WorldSpec(worldName, WorldSpec.DEFAULT_TIME_STEP_MS, WorldSpec.DEFAULT_MAX_SIM_TIME_S, 0, arena,
                robot, boxes, List.of(), WorldSpec.DEFAULT_CHECKPOINT_RADIUS_M, new WorldSpec.RechargeStation(0, 0, 0.35),
                WorldSpec.Battery.DEFAULT);
        GridPlanner planner = new GridPlanner(floor, Solvability.CLEARANCE_M);
        MissionPlacer.Placement p;
        // every leg and every way back to the station the check will ask for, searched on another core as soon as
        // both its ends are placed, while the placer goes on
        List<CompletableFuture<Void>> searches = new ArrayList<>();
        try {
            p = new MissionPlacer(planner).place(checkpoints, seed,
                    leg -> searches.add(CompletableFuture.runAsync(() -> planner.prefetch(List.of(leg)))));
        } catch (IllegalStateException e) {
            throw new MapException(mapFile, String.format(Locale.ROOT, "%s for a robot of radius %s m (its centre keeps"
                    + " %s m from every wall)", e.getMessage(), robotRadiusM, Math.round((robotRadiusM + Solvability.CLEARANCE_M) * 1000) / 1000.0));
        }
        List<WorldSpec.Checkpoint> cps = p.checkpoints().stream().map(c -> new WorldSpec.Checkpoint(c[0], c[1])).toList();
        WorldSpec.Robot start = new WorldSpec.Robot(p.startX(), p.startY(), p.headingDeg(), robot.radiusM(), robot.maxSpeedMps(),
                robot.sensorRangeM(), robot.sensorAnglesDeg());
        long noiseSeed = new SplittableRandom(seed).split().nextLong(1, 1_000_000);
        WorldSpec draft = new WorldSpec(worldName, floor.timeStepMs(), floor.maxSimTimeS(), noiseSeed, arena, start, boxes, cps,
                floor.checkpointRadiusM(), new WorldSpec.RechargeStation(p.stationX(), p.stationY(), 0.35), WorldSpec.Battery.DEFAULT);
        CompletableFuture.allOf(searches.toArray(CompletableFuture[]::new)).join();
        // the tour's length on the planner, then a battery one charge of which lasts it three times over
        double tour = tourM(planner, draft);
        double drive = EXPLORATION * tour;
        WorldSpec.Battery battery = drive <= 100.0 ? WorldSpec.Battery.DEFAULT
                : new WorldSpec.Battery(100.0, Math.floor(100.0 / drive * 1000) / 1000, 100.0, 10.0);
        WorldSpec charged = draft.withBattery(battery);
        Solvability plan = Solvability.of(charged, planner); // the same floor and footprint: its legs are known
        if (!plan.solvable()) {
            throw new MapException(mapFile, "no solvable mission for a robot of radius " + robotRadiusM + " m: " + plan.reason()
                    + "; try another --seed");
        }
        double chargeS = plan.recharges() * battery.rechargeTo() / battery.rechargeRatePerS();
        double limit = Math.ceil((plan.lengthM() / (robot.maxSpeedMps() / 3) + chargeS + 60) / 10) * 10;
        WorldSpec world = new WorldSpec(worldName, charged.timeStepMs(), limit, charged.seed(), arena, start, boxes, cps,
                charged.checkpointRadiusM(), charged.rechargeStation(), battery);
        String json = WorldJson.of(world);
        try {
            world = WorldFiles.parse(json, worldName); // the world file's own checks, as generate does
        } catch (WorldValidationException e) {
            throw new IllegalStateException("an imported world failed its own checks: " + e.problems(), e);
        }
        List<String> warnings = new ArrayList<>(reading.notes());
        warnings.addAll(warnings(grid));
        return new MapImport(world, json, grid, plan, p.rooms(), warnings);
    }

    /** @return the free floor, square metres */
    public double freeAreaM2() {
        return grid.freeCells() * grid.cellM() * grid.cellM();
    }

    /** Where the map's own shape looks wrong for a building: floor off its edge, a size out of scale. */
    static List<String> warnings(OccupancyGrid grid) {
        List<String> out = new ArrayList<>();
        int edge = grid.freeCellsOnEdge();
        if (edge > 0) {
            out.add(String.format(Locale.ROOT, "%d free cells lie on the map's edge: the floor runs off the picture, and the"
                    + " arena's wall stands there instead (was the outside read as free? check free_thresh and negate)", edge));
        }
        double w = grid.widthM();
        double h = grid.heightM();
        if (Math.min(w, h) < SMALL_SIDE_M || Math.max(w, h) > LARGE_SIDE_M) {
            out.add(String.format(Locale.ROOT, "the map is %.1f x %.1f m, an unlikely size for a building floor"
                    + " (from %.0f to %.0f m a side expected): is the resolution (or --cell-m) right?", w, h, SMALL_SIDE_M,
                    LARGE_SIDE_M));
        }
        return out;
    }

    /** The planned tour without recharges, metres: start, then each checkpoint in order. */
    private static double tourM(GridPlanner planner, WorldSpec world) {
        double x = world.robot().x();
        double y = world.robot().y();
        double sum = 0;
        for (WorldSpec.Checkpoint c : world.checkpoints()) {
            sum += planner.distance(x, y, c.x(), c.y());
            x = c.x();
            y = c.y();
        }
        return sum;
    }

    /** The map file's name without its extension, in the letters a world's name may have. */
    static String nameOf(Path mapFile) {
        String base = mapFile.getFileName().toString();
        int dot = base.lastIndexOf('.');
        if (dot > 0) {
            base = base.substring(0, dot);
        }
        String name = base.replaceAll("[^A-Za-z0-9_-]", "-");
        return name.isEmpty() ? "map" : name;
    }
}
