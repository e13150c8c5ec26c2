package org.proactiverobotics.sim2d;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.TreeMap;

/**
 * Draws a world to SVG: arena, obstacles, numbered checkpoints, the recharge station, the start pose, a 1 m
 * scale bar, and optionally the robot (heading and sensor rays), a trajectory coloured by category (for
 * instance which scenario's command was driving; one colour per category) and labelled markers (for instance
 * recharge stops). In a world of several robots every robot's start and checkpoints are drawn in a colour of its
 * own, every station numbered, and {@link #robotPath} and {@link #robotAt} draw each robot's path and body.
 * <p>
 * World coordinates are metres with +y up; the picture flips y so that it looks as the world does.
 * Usage: {@code new SvgRenderer(spec).robot(sim).trajectory(points).render()}.
 */
public final class SvgRenderer {

    /**
     * One sample of a path.
     *
     * @param x        metres
     * @param y        metres
     * @param category what the robot was doing here (a colour per category); null for none
     */
    public record TrajectoryPoint(double x, double y, String category) {
    }

    /**
     * A labelled point of interest, such as where a recharge happened.
     *
     * @param x     metres
     * @param y     metres
     * @param label short text drawn beside the marker
     */
    public record Marker(double x, double y, String label) {
    }

    /**
     * The robot as drawn: pose and, optionally, one ray per distance sensor.
     *
     * @param x            metres
     * @param y            metres
     * @param headingRad   radians, 0 along +x, counter-clockwise positive
     * @param rayAnglesRad ray angles relative to the heading, radians (empty for no rays)
     * @param rayLengthsM  ray lengths from the rim, metres, one per angle
     * @param rangeM       the sensors' range, metres (a ray shorter than this hit something)
     */
    public record RobotPose(double x, double y, double headingRad, double[] rayAnglesRad, double[] rayLengthsM,
                            double rangeM) {
        /** Checks that every angle has a length. */
        public RobotPose {
            if (rayAnglesRad.length != rayLengthsM.length) {
                throw new IllegalArgumentException("one ray length per angle");
            }
        }
    }

    private static final String[] PALETTE = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b",
            "#e377c2", "#17becf", "#7f7f7f", "#bcbd22"};
    /** One colour per robot of a world with several (dark enough to read on white; not the trajectory's palette order). */
    private static final String[] ROBOT_PALETTE = {"#103060", "#b03060", "#207020", "#a05a00", "#6040a0", "#00707a",
            "#704020", "#505050"};
    private static final double MARGIN_M = 0.6;
    private static final int SIZE_PX = 800;

    private final WorldSpec spec;
    private final Map<String, String> colours = new LinkedHashMap<>();
    private final List<TrajectoryPoint> trajectory = new ArrayList<>();
    /** Where each {@link #trajectory(List)} call's points begin: a path of its own, not joined to the one before. */
    private final java.util.Set<Integer> pathStarts = new java.util.HashSet<>();
    private final List<Marker> markers = new ArrayList<>();
    /** Each robot's path in a world of several, by its index in {@link WorldSpec#robots()}. */
    private final Map<Integer, List<TrajectoryPoint>> robotPaths = new TreeMap<>();
    /** Each robot's body in a world of several, by its index. */
    private final Map<Integer, RobotPose> robotPoses = new TreeMap<>();
    private RobotPose robot;
    private String title;

    /** @param spec the world to draw */
    public SvgRenderer(WorldSpec spec) {
        this.spec = Objects.requireNonNull(spec);
    }

    /** Draws the robot at a pose, without rays. */
    public SvgRenderer robot(double x, double y, double headingRad) {
        this.robot = new RobotPose(x, y, headingRad, new double[0], new double[0], spec.robot().sensorRangeM());
        return this;
    }

    /** Draws the robot at a pose with its sensor rays. */
    public SvgRenderer robot(RobotPose pose) {
        this.robot = pose;
        return this;
    }

    /** Draws a simulation's robot where it truly is, with the rays its distance sensors read now. */
    public SvgRenderer robot(Simulation sim) {
        List<DistanceSensor> sensors = sim.robot().distanceSensors();
        double[] angles = new double[sensors.size()];
        double[] lengths = new double[sensors.size()];
        for (int i = 0; i < angles.length; i++) {
            angles[i] = sensors.get(i).getAngleRad();
            lengths[i] = sensors.get(i).getValue();
        }
        GroundTruth t = sim.groundTruth();
        this.robot = new RobotPose(t.x(), t.y(), t.headingRad(), angles, lengths, spec.robot().sensorRangeM());
        return this;
    }

    /**
     * Adds a path, drawn in order, coloured by each point's category; each call's path is drawn apart from the
     * others (one per robot of a world with several).
     */
    public SvgRenderer trajectory(List<TrajectoryPoint> points) {
        pathStarts.add(trajectory.size());
        trajectory.addAll(points);
        return this;
    }

    /**
     * In a world of several robots, adds one robot's path, drawn in that robot's colour (the points' categories
     * are not drawn: the colour says whose path it is).
     *
     * @param robotIndex the robot's index in {@link WorldSpec#robots()}
     * @param points     its path, in order
     */
    public SvgRenderer robotPath(int robotIndex, List<TrajectoryPoint> points) {
        Objects.checkIndex(robotIndex, spec.robots().size());
        robotPaths.computeIfAbsent(robotIndex, k -> new ArrayList<>()).addAll(points);
        return this;
    }

    /**
     * In a world of several robots, draws one robot's body (its radius) in its colour, with its rays if the pose has any.
     *
     * @param robotIndex the robot's index in {@link WorldSpec#robots()}
     * @param pose       where it is
     */
    public SvgRenderer robotAt(int robotIndex, RobotPose pose) {
        Objects.checkIndex(robotIndex, spec.robots().size());
        robotPoses.put(robotIndex, pose);
        return this;
    }

    /** Adds a labelled marker. */
    public SvgRenderer marker(double x, double y, String label) {
        markers.add(new Marker(x, y, label));
        return this;
    }

    /** Adds labelled markers. */
    public SvgRenderer markers(List<Marker> list) {
        markers.addAll(list);
        return this;
    }

    /**
     * Fixes a category's colour (any CSS colour); other categories take the first palette colour not in use.
     *
     * @throws IllegalArgumentException when another category has that colour: the legend could not tell them apart
     */
    public SvgRenderer colour(String category, String cssColour) {
        colours.forEach((other, used) -> {
            if (!other.equals(category) && used.equalsIgnoreCase(cssColour)) {
                throw new IllegalArgumentException("colour " + cssColour + " is already " + other + "'s; " + category
                        + " needs one of its own");
            }
        });
        colours.put(category, cssColour);
        return this;
    }

    /** Sets a caption drawn at the top left (default: the world's name). */
    public SvgRenderer title(String caption) {
        this.title = caption;
        return this;
    }

    /** Writes {@link #render()} to a file, UTF-8. */
    public void write(Path file) throws IOException {
        Files.writeString(file, render(), StandardCharsets.UTF_8);
    }

    /** @return the picture as an SVG document */
    public String render() {
        WorldSpec.Arena arena = spec.arena();
        double t = Simulation.WALL_THICKNESS_M;
        double r;
        View v;
        if (arena.isCircle()) {
            r = arena.radiusM();
            double half = r + t + MARGIN_M;
            v = new View(-half, -half, half, half, SIZE_PX, SIZE_PX);
        } else {
            r = Math.max(arena.widthM(), arena.heightM()) / 2; // the font and marks scale as in a circle this wide
            double m = t + MARGIN_M;
            double left = arena.minX() - m;
            double top = -(arena.maxY() + m);
            double right = arena.maxX() + m;
            double bottom = -(arena.minY() - m);
            double aspect = (bottom - top) / (right - left);
            v = aspect <= 1 ? new View(left, top, right, bottom, SIZE_PX, (int) Math.max(1, Math.round(SIZE_PX * aspect)))
                    : new View(left, top, right, bottom, (int) Math.max(1, Math.round(SIZE_PX / aspect)), SIZE_PX);
        }
        StringBuilder sb = new StringBuilder(4096);
        sb.append("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
        sb.append(f("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" viewBox=\"%s %s %s %s\">\n",
                v.widthPx(), v.heightPx(), n(v.left()), n(v.top()), n(v.right() - v.left()), n(v.bottom() - v.top())));
        double font = Math.max(0.18, r / 25);
        sb.append(f("<style>text{font-family:sans-serif;font-size:%spx}</style>\n", n(font)));
        sb.append(f("<rect x=\"%s\" y=\"%s\" width=\"%s\" height=\"%s\" fill=\"white\"/>\n",
                n(v.left()), n(v.top()), n(v.right() - v.left()), n(v.bottom() - v.top())));
        sb.append(f("<title>%s</title>\n", esc(caption())));

        if (arena.isCircle()) {
            sb.append(f("<g id=\"arena\"><circle cx=\"0\" cy=\"0\" r=\"%s\" fill=\"#fafafa\" stroke=\"#444\" stroke-width=\"%s\"/></g>\n",
                    n(r + t / 2), n(t)));
        } else {
            sb.append(f("<g id=\"arena\"><rect x=\"%s\" y=\"%s\" width=\"%s\" height=\"%s\" fill=\"#fafafa\" stroke=\"#444\" stroke-width=\"%s\"/></g>\n",
                    n(arena.minX() - t / 2), n(-(arena.maxY() + t / 2)), n(arena.widthM() + t), n(arena.heightM() + t), n(t)));
        }
        obstacles(sb);
        station(sb, font);
        checkpoints(sb);
        start(sb, font);
        trajectory(sb);
        robotPaths(sb);
        markers(sb, font);
        robot(sb);
        robotBodies(sb);
        checkpointLabels(sb, font); // after the robot, which ends on the last checkpoint
        scaleBar(sb, v, font);
        legend(sb, v, font);
        sb.append("</svg>\n");
        return sb.toString();
    }

    private String caption() {
        return title != null ? title : spec.name();
    }

    private void obstacles(StringBuilder sb) {
        sb.append("<g id=\"obstacles\" fill=\"#8a8a8a\" stroke=\"#333\" stroke-width=\"0.02\">\n");
        for (WorldSpec.Obstacle o : spec.obstacles()) {
            if (o.isCircle()) {
                sb.append(f("  <circle cx=\"%s\" cy=\"%s\" r=\"%s\"/>\n", n(o.x()), n(-o.y()), n(o.radiusM())));
            } else {
                // SVG angles turn clockwise on screen because y points down.
                sb.append(f("  <rect x=\"%s\" y=\"%s\" width=\"%s\" height=\"%s\" transform=\"translate(%s %s) rotate(%s)\"/>\n",
                        n(-o.widthM() / 2), n(-o.heightM() / 2), n(o.widthM()), n(o.heightM()), n(o.x()), n(-o.y()),
                        n(-o.angleDeg())));
            }
        }
        sb.append("</g>\n");
    }

    private void station(StringBuilder sb, double font) {
        if (spec.rechargeStations().size() == 1) {
            station(sb, font, spec.rechargeStation(), "station", "recharge");
            return;
        }
        for (int i = 0; i < spec.rechargeStations().size(); i++) {
            station(sb, font, spec.rechargeStations().get(i), "station-" + (i + 1), "recharge " + (i + 1));
        }
    }

    private void station(StringBuilder sb, double font, WorldSpec.RechargeStation s, String id, String label) {
        sb.append(f("<g id=\"%s\"><circle cx=\"%s\" cy=\"%s\" r=\"%s\" fill=\"#c8f0c8\" stroke=\"#2a8a2a\" stroke-width=\"0.03\"/>"
                        + "<text x=\"%s\" y=\"%s\" text-anchor=\"middle\" fill=\"#2a8a2a\">%s</text></g>\n",
                esc(id), n(s.x()), n(-s.y()), n(s.radiusM()), n(s.x()), n(-s.y() - s.radiusM() - font * 0.4), esc(label)));
    }

    private void checkpoints(StringBuilder sb) {
        if (spec.hasSeveralRobots()) {
            fleetCheckpoints(sb);
            return;
        }
        sb.append("<g id=\"checkpoints\">\n");
        for (WorldSpec.Checkpoint c : spec.checkpoints()) {
            sb.append(f("  <circle cx=\"%s\" cy=\"%s\" r=\"%s\" fill=\"#fff3c4\" stroke=\"#c08a00\" stroke-width=\"0.03\" stroke-dasharray=\"0.06 0.04\"/>\n",
                    n(c.x()), n(-c.y()), n(spec.checkpointRadiusM())));
        }
        sb.append("</g>\n");
    }

    /** Every robot's checkpoints, outlined in that robot's colour. */
    private void fleetCheckpoints(StringBuilder sb) {
        sb.append("<g id=\"checkpoints\">\n");
        for (int k = 0; k < spec.robots().size(); k++) {
            for (WorldSpec.Checkpoint c : spec.robots().get(k).checkpoints()) {
                sb.append(f("  <circle cx=\"%s\" cy=\"%s\" r=\"%s\" fill=\"#fff3c4\" stroke=\"%s\" stroke-width=\"0.03\" stroke-dasharray=\"0.06 0.04\"/>\n",
                        n(c.x()), n(-c.y()), n(spec.checkpointRadiusM()), robotColour(k)));
            }
        }
        sb.append("</g>\n");
    }

    /** The colour of the robot at index k of {@link WorldSpec#robots()}: its start, checkpoints and labels. */
    private static String robotColour(int k) {
        return ROBOT_PALETTE[k % ROBOT_PALETTE.length];
    }

    /** The checkpoints' numbers, above each circle by more than the robot's radius: a robot on it never hides them. */
    private void checkpointLabels(StringBuilder sb, double font) {
        if (spec.hasSeveralRobots()) {
            fleetCheckpointLabels(sb);
            return;
        }
        sb.append("<g id=\"checkpoint-labels\" fill=\"#805c00\" font-weight=\"bold\" text-anchor=\"middle\""
                + " stroke=\"white\" stroke-width=\"0.05\" paint-order=\"stroke\">\n");
        List<WorldSpec.Checkpoint> cps = spec.checkpoints();
        for (int i = 0; i < cps.size(); i++) {
            WorldSpec.Checkpoint c = cps.get(i);
            sb.append(f("  <text x=\"%s\" y=\"%s\">%d</text>\n", n(c.x()), n(-c.y() - labelOffsetM()), i + 1));
        }
        sb.append("</g>\n");
    }

    /** Each robot's checkpoints numbered from 1 in visiting order, "robot id.number", in the robot's colour. */
    private void fleetCheckpointLabels(StringBuilder sb) {
        sb.append("<g id=\"checkpoint-labels\" font-weight=\"bold\" text-anchor=\"middle\""
                + " stroke=\"white\" stroke-width=\"0.05\" paint-order=\"stroke\">\n");
        for (int k = 0; k < spec.robots().size(); k++) {
            WorldSpec.RobotEntry entry = spec.robots().get(k);
            double offset = spec.checkpointRadiusM() + entry.robot().radiusM() + 0.05;
            for (int i = 0; i < entry.checkpoints().size(); i++) {
                WorldSpec.Checkpoint c = entry.checkpoints().get(i);
                sb.append(f("  <text x=\"%s\" y=\"%s\" fill=\"%s\">%d.%d</text>\n", n(c.x()), n(-c.y() - offset),
                        robotColour(k), entry.id(), i + 1));
            }
        }
        sb.append("</g>\n");
    }

    /** From a checkpoint's centre up to its label's baseline, metres: clear of the circle and of a robot inside it. */
    private double labelOffsetM() {
        return spec.checkpointRadiusM() + spec.robot().radiusM() + 0.05;
    }

    /** Where the robot started: a hollow disc with its heading, labelled. */
    private void start(StringBuilder sb, double font) {
        if (spec.hasSeveralRobots()) {
            for (int k = 0; k < spec.robots().size(); k++) {
                WorldSpec.RobotEntry entry = spec.robots().get(k);
                startOf(sb, font, entry.robot(), "start-" + entry.id(), robotColour(k), "robot " + entry.id());
            }
            return;
        }
        WorldSpec.Robot r = spec.robot();
        double heading = Math.toRadians(r.headingDeg());
        sb.append(f("<g id=\"start\" stroke=\"#103060\" stroke-width=\"0.03\"><circle cx=\"%s\" cy=\"%s\" r=\"%s\" fill=\"white\"/>"
                        + "<line x1=\"%s\" y1=\"%s\" x2=\"%s\" y2=\"%s\"/>"
                        + "<text x=\"%s\" y=\"%s\" stroke=\"none\" fill=\"#103060\" dominant-baseline=\"central\">start</text></g>\n",
                n(r.x()), n(-r.y()), n(r.radiusM()), n(r.x()), n(-r.y()), n(r.x() + r.radiusM() * Math.cos(heading)),
                n(-(r.y() + r.radiusM() * Math.sin(heading))), n(r.x() + r.radiusM() + font * 0.4), n(-r.y())));
    }

    /** One robot's start in a world of several: a hollow disc with its heading, in its colour, labelled with its id. */
    private void startOf(StringBuilder sb, double font, WorldSpec.Robot r, String id, String colour, String label) {
        double heading = Math.toRadians(r.headingDeg());
        sb.append(f("<g id=\"%s\" stroke=\"%s\" stroke-width=\"0.03\"><circle cx=\"%s\" cy=\"%s\" r=\"%s\" fill=\"white\"/>"
                        + "<line x1=\"%s\" y1=\"%s\" x2=\"%s\" y2=\"%s\"/>"
                        + "<text x=\"%s\" y=\"%s\" stroke=\"none\" fill=\"%s\" dominant-baseline=\"central\">%s</text></g>\n",
                esc(id), colour, n(r.x()), n(-r.y()), n(r.radiusM()), n(r.x()), n(-r.y()),
                n(r.x() + r.radiusM() * Math.cos(heading)), n(-(r.y() + r.radiusM() * Math.sin(heading))),
                n(r.x() + r.radiusM() + font * 0.4), n(-r.y()), colour, esc(label)));
    }

    /** A 1 m bar at the bottom left, labelled. */
    private void scaleBar(StringBuilder sb, View v, double font) {
        double x0 = v.left() + 0.15;
        double y = v.bottom() - 0.25;
        double tick = font * 0.4;
        sb.append(f("<g id=\"scale\" stroke=\"#222\" stroke-width=\"0.03\"><line x1=\"%s\" y1=\"%s\" x2=\"%s\" y2=\"%s\"/>"
                        + "<line x1=\"%s\" y1=\"%s\" x2=\"%s\" y2=\"%s\"/><line x1=\"%s\" y1=\"%s\" x2=\"%s\" y2=\"%s\"/>"
                        + "<text x=\"%s\" y=\"%s\" stroke=\"none\" fill=\"#222\" text-anchor=\"middle\">1 m</text></g>\n",
                n(x0), n(y), n(x0 + 1.0), n(y), n(x0), n(y - tick), n(x0), n(y + tick), n(x0 + 1.0), n(y - tick),
                n(x0 + 1.0), n(y + tick), n(x0 + 0.5), n(y - tick - font * 0.2)));
    }

    private void trajectory(StringBuilder sb) {
        if (trajectory.isEmpty()) {
            return;
        }
        sb.append("<g id=\"trajectory\" fill=\"none\" stroke-width=\"0.04\" stroke-linejoin=\"round\" stroke-linecap=\"round\">\n");
        int start = 0;
        for (int i = 1; i <= trajectory.size(); i++) {
            // One polyline per run of a category; each run starts at the previous run's last point.
            if (i == trajectory.size() || pathStarts.contains(i)
                    || !Objects.equals(trajectory.get(i).category(), trajectory.get(start).category())) {
                String category = trajectory.get(start).category();
                sb.append(f("  <polyline stroke=\"%s\" points=\"", esc(colourOf(category))));
                for (int k = pathStarts.contains(start) ? start : start - 1; k < i; k++) {
                    TrajectoryPoint p = trajectory.get(k);
                    sb.append(n(p.x())).append(',').append(n(-p.y())).append(' ');
                }
                sb.append("\"/>\n");
                start = i;
            }
        }
        sb.append("</g>\n");
    }

    private void robotPaths(StringBuilder sb) {
        for (Map.Entry<Integer, List<TrajectoryPoint>> e : robotPaths.entrySet()) {
            if (e.getValue().isEmpty()) {
                continue;
            }
            sb.append(f("<polyline id=\"path-%d\" fill=\"none\" stroke=\"%s\" stroke-width=\"0.04\" stroke-linejoin=\"round\""
                    + " stroke-linecap=\"round\" points=\"", spec.robots().get(e.getKey()).id(), robotColour(e.getKey())));
            for (TrajectoryPoint p : e.getValue()) {
                sb.append(n(p.x())).append(',').append(n(-p.y())).append(' ');
            }
            sb.append("\"/>\n");
        }
    }

    private void robotBodies(StringBuilder sb) {
        for (Map.Entry<Integer, RobotPose> e : robotPoses.entrySet()) {
            RobotPose pose = e.getValue();
            double rr = spec.robots().get(e.getKey()).robot().radiusM();
            sb.append(f("<g id=\"robot-%d\">\n", spec.robots().get(e.getKey()).id()));
            rays(sb, pose, rr);
            sb.append(f("  <circle cx=\"%s\" cy=\"%s\" r=\"%s\" fill=\"%s\" stroke=\"#103060\" stroke-width=\"0.02\"/>\n",
                    n(pose.x()), n(-pose.y()), n(rr), robotColour(e.getKey())));
            sb.append(f("  <line x1=\"%s\" y1=\"%s\" x2=\"%s\" y2=\"%s\" stroke=\"white\" stroke-width=\"0.03\"/>\n",
                    n(pose.x()), n(-pose.y()), n(pose.x() + rr * Math.cos(pose.headingRad())),
                    n(-(pose.y() + rr * Math.sin(pose.headingRad())))));
            sb.append("</g>\n");
        }
    }

    private String colourOf(String category) {
        String key = category == null ? "" : category;
        return colours.computeIfAbsent(key, k -> {
            for (String candidate : PALETTE) {
                if (colours.values().stream().noneMatch(candidate::equalsIgnoreCase)) {
                    return candidate;
                }
            }
            return PALETTE[colours.size() % PALETTE.length]; // more categories than colours
        });
    }

    private void markers(StringBuilder sb, double font) {
        if (markers.isEmpty()) {
            return;
        }
        sb.append("<g id=\"markers\">\n");
        for (Marker m : markers) {
            sb.append(f("  <path d=\"M %s %s l 0.09 0.09 l -0.09 0.09 l -0.09 -0.09 z\" transform=\"translate(0 -0.09)\" fill=\"#e6007e\"/>"
                            + "<text x=\"%s\" y=\"%s\" fill=\"#e6007e\">%s</text>\n",
                    n(m.x()), n(-m.y()), n(m.x() + 0.12), n(-m.y() - 0.1), esc(m.label())));
        }
        sb.append("</g>\n");
    }

    private void robot(StringBuilder sb) {
        if (robot == null) {
            return;
        }
        double rr = spec.robot().radiusM();
        double x = robot.x();
        double y = robot.y();
        sb.append("<g id=\"robot\">\n");
        rays(sb, robot, rr);
        sb.append(f("  <circle cx=\"%s\" cy=\"%s\" r=\"%s\" fill=\"#3070d0\" stroke=\"#103060\" stroke-width=\"0.02\"/>\n",
                n(x), n(-y), n(rr)));
        sb.append(f("  <line x1=\"%s\" y1=\"%s\" x2=\"%s\" y2=\"%s\" stroke=\"white\" stroke-width=\"0.03\"/>\n",
                n(x), n(-y), n(x + rr * Math.cos(robot.headingRad())), n(-(y + rr * Math.sin(robot.headingRad())))));
        sb.append("</g>\n");
    }

    /** One line per distance sensor from the rim, red where it hit something. */
    private void rays(StringBuilder sb, RobotPose pose, double rr) {
        for (int i = 0; i < pose.rayAnglesRad().length; i++) {
            double a = pose.headingRad() + pose.rayAnglesRad()[i];
            double len = pose.rayLengthsM()[i];
            double x0 = pose.x() + rr * Math.cos(a);
            double y0 = pose.y() + rr * Math.sin(a);
            boolean hit = len < pose.rangeM();
            sb.append(f("  <line x1=\"%s\" y1=\"%s\" x2=\"%s\" y2=\"%s\" stroke=\"%s\" stroke-width=\"0.015\"/>\n",
                    n(x0), n(-y0), n(x0 + len * Math.cos(a)), n(-(y0 + len * Math.sin(a))), hit ? "#e03030" : "#9ab"));
        }
    }

    private void legend(StringBuilder sb, View v, double font) {
        sb.append(f("<text x=\"%s\" y=\"%s\" font-weight=\"bold\">%s</text>\n", n(v.left() + 0.15), n(v.top() + font * 1.4),
                esc(caption())));
        if (trajectory.isEmpty()) {
            return;
        }
        double y = v.top() + font * 2.8;
        for (Map.Entry<String, String> e : colours.entrySet()) {
            if (trajectory.stream().noneMatch(p -> Objects.equals(p.category() == null ? "" : p.category(), e.getKey()))) {
                continue;
            }
            sb.append(f("<line x1=\"%s\" y1=\"%s\" x2=\"%s\" y2=\"%s\" stroke=\"%s\" stroke-width=\"0.06\"/>"
                            + "<text x=\"%s\" y=\"%s\" dominant-baseline=\"central\">%s</text>\n",
                    n(v.left() + 0.15), n(y), n(v.left() + 0.55), n(y), esc(e.getValue()), n(v.left() + 0.65), n(y),
                    esc(e.getKey().isEmpty() ? "(none)" : e.getKey())));
            y += font * 1.3;
        }
    }

    /** What the picture shows, in SVG coordinates (metres, y down), and its size in pixels. */
    private record View(double left, double top, double right, double bottom, int widthPx, int heightPx) {
    }

    private static String f(String format, Object... args) {
        return String.format(Locale.ROOT, format, args);
    }

    /** Millimetre precision keeps files small and output stable. */
    private static String n(double v) {
        String s = String.format(Locale.ROOT, "%.3f", v);
        return "-0.000".equals(s) ? "0.000" : s;
    }

    private static String esc(String s) {
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;");
    }
}
