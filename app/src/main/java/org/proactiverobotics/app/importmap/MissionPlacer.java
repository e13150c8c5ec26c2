package org.proactiverobotics.app.importmap;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.SplittableRandom;
import java.util.concurrent.CompletableFuture;
import java.util.function.Consumer;
import java.util.stream.IntStream;
import org.proactiverobotics.app.generate.GridPlanner;

/**
 * Places a mission on a floor from a seed: the start, K checkpoints far apart, each in another room
 * where the floor has rooms, and the recharge station near the start. Works on the {@link GridPlanner}'s
 * cells (where the robot's centre fits with its clearance), so that every point it places is one the
 * planner can reach from the start.
 * <p>
 * Rooms: the floor's largest connected part, narrowed by {@value #ROOM_ERODE_M} m more on every side, falls
 * apart at the doors (any opening under about 0.7 m plus the robot's inflated diameter); each part of at
 * least {@value #MIN_ROOM_M2} m² counts as a room (a corridor is a room too). Each checkpoint goes to the
 * unused room farthest along the floor from the points already placed (one of those within 70 % of the
 * farthest, drawn from the seed), on one of its cells farthest from them. Where rooms run out, or the
 * floor has none, the checkpoints are drawn the same way from the whole floor.
 */
final class MissionPlacer {

    /** How far inside a room's inflated free floor points are placed, and how much narrowing closes a door, metres. */
    static final double ROOM_ERODE_M = 0.35;
    /** The smallest room, square metres. */
    static final double MIN_ROOM_M2 = 1.0;
    /** The station's distance along the floor from the start, metres. */
    private static final double STATION_MIN_M = 0.8;
    private static final double STATION_MAX_M = 2.0;

    /**
     * A mission's points, metres; checkpoints in the order to visit.
     *
     * @param startX      the robot's start x
     * @param startY      the robot's start y
     * @param headingDeg  the robot's start heading, degrees
     * @param checkpoints each checkpoint's {x, y}
     * @param stationX    the station's x
     * @param stationY    the station's y
     * @param rooms       how many rooms the floor fell apart into
     */
    record Placement(double startX, double startY, double headingDeg, List<double[]> checkpoints, double stationX,
                     double stationY, int rooms) {
    }

    private final GridPlanner grid;
    private final int w;
    private final int h;
    private final boolean[] free;
    /** The breadth-first searches' queue on the calling thread, shared: one search at a time (another thread brings its own). */
    private final int[] queue;

    /** @param grid the floor's cells, on the robot's inflated footprint */
    MissionPlacer(GridPlanner grid) {
        this.grid = grid;
        this.w = grid.columns();
        this.h = grid.rows();
        this.free = grid.freeCells();
        this.queue = new int[w * h];
    }

    /**
     * @param checkpoints how many checkpoints, at least 1
     * @param seed        the seed: the same floor, count and seed give the same placement
     * @param legPlaced   told each leg {fromX, fromY, toX, toY} as soon as both its ends are placed (metres, as in
     *                    the placement): from the start or the checkpoint before to each checkpoint, and from each
     *                    checkpoint but the last to the station, so that its search may begin while the rest is placed
     * @return the placement
     * @throws IllegalStateException naming why there is none (no free cell; too little floor)
     */
    Placement place(int checkpoints, long seed, Consumer<double[]> legPlaced) {
        SplittableRandom random = new SplittableRandom(seed);
        // the steps to the nearest blocked cell, on another core meanwhile: from a cell of the floor, the nearest cell
        // off the floor is a blocked one (a free cell next to the floor is floor), so they are its steps off the floor
        CompletableFuture<int[]> clearanceOfFree = CompletableFuture.supplyAsync(() -> clearanceSteps(free));
        int minRoomCells = (int) Math.ceil(MIN_ROOM_M2 / (GridPlanner.CELL_M * GridPlanner.CELL_M));
        int fullDepth = steps(ROOM_ERODE_M);
        // and the deep parts of the free cells there too: those of the floor are its rooms (a part lies in one free part)
        CompletableFuture<List<int[]>> deepParts = clearanceOfFree.thenApplyAsync(
                clearance -> deepParts(clearance, fullDepth, minRoomCells, new int[w * h]));
        int[] component = new int[w * h];
        int floor = largestComponent(free, component);
        if (floor < 0) {
            throw new IllegalStateException("no free cell the robot fits in");
        }
        boolean[] onFloor = new boolean[w * h];
        for (int c = 0; c < onFloor.length; c++) {
            onFloor[c] = component[c] == floor;
        }
        int[] clearance = clearanceOfFree.join();
        List<int[]> rooms = List.of();
        // a floor too narrow for rooms at full depth is tried shallower, down to any free cell
        for (int depth : new int[] {fullDepth, fullDepth / 2, 0}) {
            List<int[]> parts = depth == fullDepth ? deepParts.join()
                    : deepParts(clearance, depth, depth == 0 ? 1 : minRoomCells, queue);
            rooms = parts.stream().filter(part -> onFloor[part[0]]).toList();
            if (!rooms.isEmpty()) {
                break;
            }
        }
        int[] startRoom = rooms.get(random.nextInt(rooms.size()));
        int start = startRoom[random.nextInt(startRoom.length)];
        double heading = 90.0 * random.nextInt(4);

        int[] fromStart = geodesic(onFloor, new int[] {start}, steps(STATION_MAX_M)); // only as far as the station may be
        int station = station(startRoom, fromStart, onFloor, random);
        List<Integer> placed = new ArrayList<>(List.of(start, station));
        boolean[] used = new boolean[rooms.size()];
        used[rooms.indexOf(startRoom)] = true;
        List<double[]> points = new ArrayList<>();
        int[] geo = null;
        int[] everyCell = null;
        for (int k = 0; k < checkpoints; k++) {
            if (geo == null) {
                geo = geodesic(onFloor, placed.stream().mapToInt(Integer::intValue).toArray(), Integer.MAX_VALUE);
            } else { // the distances from one more source: only where it is nearer than the others (a floor-wide search saved)
                lower(geo, onFloor, placed.get(placed.size() - 1));
            }
            int pick = farRoom(rooms, used, geo, random);
            int[] cells;
            if (pick >= 0) {
                used[pick] = true;
                cells = rooms.get(pick);
            } else { // no room left: the whole floor, away from walls as the rooms' cells are (sorted once)
                if (everyCell == null) {
                    everyCell = allCells(rooms);
                }
                cells = everyCell;
            }
            int cell = farCell(cells, geo, random);
            if (cell < 0 || geo[cell] <= 0) {
                throw new IllegalStateException("too little free floor for " + checkpoints + " checkpoints");
            }
            placed.add(cell);
            double[] point = {round(grid.x(cell % w)), round(grid.y(cell / w))};
            double[] before = k == 0 ? new double[] {round(grid.x(start % w)), round(grid.y(start / w))} : points.get(k - 1);
            points.add(point);
            legPlaced.accept(new double[] {before[0], before[1], point[0], point[1]});
            if (k < checkpoints - 1) {
                legPlaced.accept(new double[] {point[0], point[1], round(grid.x(station % w)), round(grid.y(station / w))});
            }
        }
        return new Placement(round(grid.x(start % w)), round(grid.y(start / w)), heading, points,
                round(grid.x(station % w)), round(grid.y(station / w)), rooms.size());
    }

    /** @return the label of the largest 4-connected set of free cells (labels in {@code component}, -1 elsewhere), or -1 */
    private int largestComponent(boolean[] cells, int[] component) {
        Arrays.fill(component, -1);
        int best = -1;
        int bestSize = 0;
        int label = 0;
        for (int c = 0; c < cells.length; c++) {
            if (!cells[c] || component[c] >= 0) {
                continue;
            }
            int size = flood(cells, component, c, label, queue);
            if (size > bestSize) {
                best = label;
                bestSize = size;
            }
            label++;
        }
        return best;
    }

    /** Labels the 4-connected set of {@code cells} holding {@code seed}, in {@code queue} in its order; @return its size */
    private int flood(boolean[] cells, int[] labels, int seed, int label, int[] queue) {
        int head = 0;
        int tail = 0;
        int last = w * h;
        queue[tail++] = seed;
        labels[seed] = label;
        while (head < tail) {
            int c = queue[head++];
            int i = c % w;
            // the four neighbours in this order (left, right, below, above): the rooms' cells come out in it
            int n = c - 1;
            if (i > 0 && cells[n] && labels[n] < 0) {
                labels[n] = label;
                queue[tail++] = n;
            }
            n = c + 1;
            if (i < w - 1 && cells[n] && labels[n] < 0) {
                labels[n] = label;
                queue[tail++] = n;
            }
            n = c - w;
            if (n >= 0 && cells[n] && labels[n] < 0) {
                labels[n] = label;
                queue[tail++] = n;
            }
            n = c + w;
            if (n < last && cells[n] && labels[n] < 0) {
                labels[n] = label;
                queue[tail++] = n;
            }
        }
        return tail;
    }

    /**
     * @return each cell's distance in steps (8 neighbours, the chessboard distance) to the nearest cell not among
     *         {@code cells} or off the grid (0 for those): two raster passes, forward then back, each cell taking
     *         its visited neighbours' best
     */
    private int[] clearanceSteps(boolean[] cells) {
        int[] d = new int[w * h]; // 0 off the floor
        for (int j = 0; j < h; j++) {
            for (int i = 0; i < w; i++) {
                int c = j * w + i;
                if (!cells[c]) {
                    continue;
                }
                if (i == 0 || j == 0 || i == w - 1 || j == h - 1) {
                    d[c] = 1; // a cell on the grid's edge: the outside is next to it
                } else { // the neighbours before it (left, and the row below) are done and finite
                    d[c] = Math.min(Math.min(d[c - 1], d[c - w - 1]), Math.min(d[c - w], d[c - w + 1])) + 1;
                }
            }
        }
        // back from the far corner; a cell at 0 or 1 cannot come nearer, nor can the edge's
        for (int j = h - 2; j >= 1; j--) {
            for (int i = w - 2; i >= 1; i--) {
                int c = j * w + i;
                if (d[c] > 1) {
                    d[c] = Math.min(d[c], Math.min(Math.min(d[c + 1], d[c + w - 1]), Math.min(d[c + w], d[c + w + 1])) + 1);
                }
            }
        }
        return d;
    }

    /**
     * @param clearance each cell's steps to the nearest blocked cell, 0 on blocked cells
     * @param queue     the floods' queue, a cell long each
     * @return the 4-connected sets of cells deeper than {@code depth} steps of at least {@code minCells}, each in
     *         its flood's order, in the order of their first cells
     */
    private List<int[]> deepParts(int[] clearance, int depth, int minCells, int[] queue) {
        boolean[] deep = new boolean[w * h];
        for (int c = 0; c < deep.length; c++) {
            deep[c] = clearance[c] > depth;
        }
        int[] labels = new int[w * h];
        Arrays.fill(labels, -1);
        List<int[]> parts = new ArrayList<>();
        int label = 0;
        for (int c = 0; c < deep.length; c++) {
            if (!deep[c] || labels[c] >= 0) {
                continue;
            }
            int size = flood(deep, labels, c, label++, queue);
            if (size >= minCells) {
                parts.add(Arrays.copyOf(queue, size)); // in the flood's order, the same for the same floor
            }
        }
        return parts;
    }

    /**
     * @return each cell's distance along the floor (4 neighbours, steps) from the nearest source, up to {@code limit}
     *         steps; -1 where unreachable or farther
     */
    private int[] geodesic(boolean[] onFloor, int[] sources, int limit) {
        int[] d = new int[w * h];
        Arrays.fill(d, -1);
        int head = 0;
        int tail = 0;
        for (int s : sources) {
            if (d[s] < 0) {
                d[s] = 0;
                queue[tail++] = s;
            }
        }
        int last = w * h;
        while (head < tail) {
            int c = queue[head++];
            if (d[c] >= limit) {
                continue;
            }
            int next = d[c] + 1;
            int i = c % w;
            int n = c - 1;
            if (i > 0 && onFloor[n] && d[n] < 0) {
                d[n] = next;
                queue[tail++] = n;
            }
            n = c + 1;
            if (i < w - 1 && onFloor[n] && d[n] < 0) {
                d[n] = next;
                queue[tail++] = n;
            }
            n = c - w;
            if (n >= 0 && onFloor[n] && d[n] < 0) {
                d[n] = next;
                queue[tail++] = n;
            }
            n = c + w;
            if (n < last && onFloor[n] && d[n] < 0) {
                d[n] = next;
                queue[tail++] = n;
            }
        }
        return d;
    }

    /**
     * Lowers the distances of {@link #geodesic} (no limit) to those from one more source: a search from
     * it that goes on only where it comes nearer than the distances had it, so that the result is the
     * search from every source at once, cell for cell.
     */
    private void lower(int[] d, boolean[] onFloor, int source) {
        if (d[source] == 0) {
            return;
        }
        int head = 0;
        int tail = 0;
        d[source] = 0;
        queue[tail++] = source;
        int last = w * h;
        while (head < tail) {
            int c = queue[head++];
            int next = d[c] + 1;
            int i = c % w;
            int n = c - 1;
            if (i > 0 && onFloor[n] && (d[n] < 0 || next < d[n])) {
                d[n] = next;
                queue[tail++] = n;
            }
            n = c + 1;
            if (i < w - 1 && onFloor[n] && (d[n] < 0 || next < d[n])) {
                d[n] = next;
                queue[tail++] = n;
            }
            n = c - w;
            if (n >= 0 && onFloor[n] && (d[n] < 0 || next < d[n])) {
                d[n] = next;
                queue[tail++] = n;
            }
            n = c + w;
            if (n < last && onFloor[n] && (d[n] < 0 || next < d[n])) {
                d[n] = next;
                queue[tail++] = n;
            }
        }
    }

    /** A cell of the start's room 0.8 to 2 m from the start along the floor; failing that, the farthest within 2 m. */
    private int station(int[] room, int[] fromStart, boolean[] onFloor, SplittableRandom random) {
        int lo = steps(STATION_MIN_M);
        int hi = steps(STATION_MAX_M);
        int[] near = Arrays.stream(room).filter(c -> fromStart[c] >= lo && fromStart[c] <= hi).toArray();
        if (near.length > 0) {
            return near[random.nextInt(near.length)];
        }
        int best = -1;
        for (int c = 0; c < onFloor.length; c++) {
            if (onFloor[c] && fromStart[c] >= 0 && fromStart[c] <= hi && (best < 0 || fromStart[c] > fromStart[best])) {
                best = c;
            }
        }
        return best;
    }

    /** @return an unused room among those reaching within 70 % of the farthest, drawn; -1 when every room is used */
    private int farRoom(List<int[]> rooms, boolean[] used, int[] geo, SplittableRandom random) {
        int[] reach = new int[rooms.size()];
        IntStream.range(0, rooms.size()).parallel().filter(r -> !used[r]).forEach(r -> { // each room on its own
            int most = 0;
            for (int c : rooms.get(r)) {
                most = Math.max(most, geo[c]);
            }
            reach[r] = most;
        });
        int best = 0;
        for (int r = 0; r < rooms.size(); r++) {
            if (!used[r]) {
                best = Math.max(best, reach[r]);
            }
        }
        List<Integer> far = new ArrayList<>();
        for (int r = 0; r < rooms.size(); r++) {
            if (!used[r] && reach[r] > 0 && reach[r] >= 0.7 * best) {
                far.add(r);
            }
        }
        return far.isEmpty() ? -1 : far.get(random.nextInt(far.size()));
    }

    /** @return a cell among the given ones within 80 % of the farthest from the placed points, drawn; -1 when none is reachable */
    private static int farCell(int[] cells, int[] geo, SplittableRandom random) {
        int best = 0;
        for (int c : cells) {
            best = Math.max(best, geo[c]);
        }
        int floor = best;
        int[] far = Arrays.stream(cells).filter(c -> geo[c] > 0 && geo[c] >= 0.8 * floor).toArray();
        return far.length == 0 ? -1 : far[random.nextInt(far.length)];
    }

    private static int[] allCells(List<int[]> rooms) {
        return rooms.stream().flatMapToInt(Arrays::stream).sorted().toArray();
    }

    private static int steps(double metres) {
        return (int) Math.ceil(metres / GridPlanner.CELL_M);
    }

    /** Centimetres, as {@code generate} writes its points; a cell is 5 cm, so the point stays in its cell. */
    private static double round(double v) {
        return Math.round(v * 100) / 100.0;
    }
}
