package org.proactiverobotics.robot;

import java.util.regex.Pattern;

/**
 * A parsed, checked command of {@code engine_comments.command}.
 *
 * <p>Grammar: a {@link Mode} name in upper case followed by exactly its arguments, separated by
 * white space (leading and trailing space ignored):
 * <pre>
 * STOP | RECHARGE | DRIVE left_mps right_mps | FORWARD mps | TURN_LEFT mps | TURN_RIGHT mps
 * </pre>
 * Numbers are plain decimals ({@code 0.4}, {@code -.25}, {@code 1e-1}); {@code NaN},
 * {@code Infinity}, hexadecimal and suffixed forms are refused, as is any speed beyond the
 * robot's maximum (see each mode for the range).
 *
 * @param mode     the mode to switch to
 * @param leftMps  the left wheel's speed, m/s
 * @param rightMps the right wheel's speed, m/s
 */
public record Command(Mode mode, double leftMps, double rightMps) {

    /** Stop both wheels. */
    public static final Command STOP = new Command(Mode.STOP, 0.0, 0.0);

    private static final Pattern NUMBER = Pattern.compile("[-+]?(\\d+(\\.\\d*)?|\\.\\d+)([eE][-+]?\\d+)?");
    private static final Pattern SPACE = Pattern.compile("\\s+");
    private static final int MAX_LENGTH = 255;

    /**
     * Parses and checks a command.
     *
     * @param text        the text the engine wrote
     * @param maxSpeedMps the robot's highest wheel speed, m/s
     * @return the command
     * @throws MalformedCommandException naming what is wrong
     */
    public static Command parse(String text, double maxSpeedMps) throws MalformedCommandException {
        if (text == null) {
            throw new MalformedCommandException("empty command (null)");
        }
        String trimmed = text.strip();
        if (trimmed.isEmpty() || trimmed.length() > MAX_LENGTH) {
            throw new MalformedCommandException("empty or over-long command: '" + abbreviate(text) + "'");
        }
        String[] words = SPACE.split(trimmed);
        Mode mode = Mode.command(words[0]).orElseThrow(
                () -> new MalformedCommandException("unknown command '" + abbreviate(words[0]) + "' in '" + abbreviate(text) + "'"));
        int given = words.length - 1;
        if (given != mode.arguments()) {
            throw new MalformedCommandException(mode + " takes " + mode.arguments() + " argument(s), got " + given
                    + ": '" + abbreviate(text) + "'");
        }
        double[] v = new double[given];
        for (int i = 0; i < given; i++) {
            v[i] = number(words[i + 1], text);
        }
        return switch (mode) {
            case STOP -> STOP;
            case RECHARGE -> new Command(Mode.RECHARGE, 0.0, 0.0);
            case DRIVE -> new Command(mode, speed(v[0], -maxSpeedMps, maxSpeedMps, text),
                    speed(v[1], -maxSpeedMps, maxSpeedMps, text));
            case FORWARD -> {
                double s = speed(v[0], -maxSpeedMps, maxSpeedMps, text);
                yield new Command(mode, s, s);
            }
            case TURN_LEFT -> {
                double s = speed(v[0], 0.0, maxSpeedMps, text);
                yield new Command(mode, -s, s);
            }
            case TURN_RIGHT -> {
                double s = speed(v[0], 0.0, maxSpeedMps, text);
                yield new Command(mode, s, -s);
            }
            case WAITING -> throw new AssertionError("WAITING is not a command");
        };
    }

    private static double number(String word, String text) throws MalformedCommandException {
        if (!NUMBER.matcher(word).matches()) {
            throw new MalformedCommandException("not a number: '" + abbreviate(word) + "' in '" + abbreviate(text) + "'");
        }
        double d = Double.parseDouble(word);
        if (!Double.isFinite(d)) {
            throw new MalformedCommandException("not a finite number: '" + abbreviate(word) + "' in '" + abbreviate(text) + "'");
        }
        return d;
    }

    private static double speed(double v, double min, double max, String text) throws MalformedCommandException {
        if (v < min || v > max) {
            throw new MalformedCommandException("speed " + v + " m/s out of [" + min + ", " + max + "] in '"
                    + abbreviate(text) + "'");
        }
        return v == 0.0 ? 0.0 : v; // no -0.0
    }

    private static String abbreviate(String s) {
        return s.length() <= 60 ? s : s.substring(0, 57) + "...";
    }
}
