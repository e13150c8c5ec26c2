package org.proactiverobotics.engine.motion;

import java.math.BigDecimal;
import java.math.RoundingMode;
import org.proactiverobotics.protocol.CommandWord;

/**
 * Steering laws and the text of the robot's commands ({@code DRIVE <left_mps> <right_mps>},
 * {@code STOP}, {@code RECHARGE}).
 */
public final class Steering {

    /** The command that stops both wheels. */
    public static final String STOP = CommandWord.STOP.name();
    /** The command that stops and charges at the station. */
    public static final String RECHARGE = CommandWord.RECHARGE.name();

    /** Turn rate per radian of heading error, 1/s. */
    private static final double TURN_GAIN = 3.0;
    /** Highest turn rate the go-to law asks for, rad/s. */
    private static final double MAX_TURN_RAD_S = 2.5;
    /** Beyond this heading error the robot turns on the spot instead of driving on. */
    private static final double TURN_ON_SPOT_RAD = Math.toRadians(60);
    /** A target this close to straight behind is turned to on the side last turned to, degrees. */
    private static final double BEHIND_DEG = 20;
    /** Speed per metre left to the target, 1/s: slows down on arrival. */
    private static final double ARRIVAL_GAIN = 0.8;
    /** Lowest forward speed while arriving, m/s, so the robot never stalls short of the target. */
    private static final double MIN_ARRIVAL_SPEED = 0.08;

    private Steering() {
    }

    /**
     * The go-to-point law: turn toward the target in proportion to the heading error, drive on
     * at a speed that falls with the error and near the target.
     *
     * @param xM      robot x, metres
     * @param yM      robot y, metres
     * @param yawRad  robot heading, radians
     * @param targetX target x, metres
     * @param targetY target y, metres
     * @param profile the robot's drive
     * @return a DRIVE command
     */
    public static String goTo(double xM, double yM, double yawRad, double targetX, double targetY, DriveProfile profile) {
        return goTo(xM, yM, yawRad, targetX, targetY, profile, 0);
    }

    /**
     * As {@link #goTo(double, double, double, double, double, DriveProfile)}, for a caller that keeps
     * the side it last turned to: a target within {@value #BEHIND_DEG}° of straight behind is turned
     * to on that side. A command acts a step after the heading it was worked out from, so with a
     * target at ±180° the side flipped every step and the robot rocked on the spot for good (rooms,
     * seed 17, radius 0.2 m, number 12).
     *
     * @param behindSide the side of the last turn, +1 left, -1 right, 0 none ({@link #turnSide})
     * @return a DRIVE command
     */
    public static String goTo(double xM, double yM, double yawRad, double targetX, double targetY, DriveProfile profile,
                              int behindSide) {
        double error = error(xM, yM, yawRad, targetX, targetY, behindSide);
        double turn = clamp(TURN_GAIN * error, MAX_TURN_RAD_S);
        double speed = Math.abs(error) > TURN_ON_SPOT_RAD ? 0.0 : profile.maxSpeedMps() * Math.cos(error);
        speed = Math.min(speed, Math.max(MIN_ARRIVAL_SPEED, ARRIVAL_GAIN * Math.hypot(targetX - xM, targetY - yM)));
        return drive(speed, turn, profile);
    }

    /** @return the side {@link #goTo(double, double, double, double, double, DriveProfile, int)} turns to, +1 left, -1 right */
    public static int turnSide(double xM, double yM, double yawRad, double targetX, double targetY, int behindSide) {
        return error(xM, yM, yawRad, targetX, targetY, behindSide) >= 0 ? +1 : -1;
    }

    /** The heading error to a target, radians; near ±π on the side given (when not 0). */
    private static double error(double xM, double yM, double yawRad, double targetX, double targetY, int behindSide) {
        double error = wrap(Math.atan2(targetY - yM, targetX - xM) - yawRad);
        if (behindSide != 0 && Math.abs(error) > Math.PI - Math.toRadians(BEHIND_DEG)) {
            error = behindSide * Math.abs(error);
        }
        return error;
    }

    /**
     * A DRIVE command for a forward speed and a turn rate, scaled down together so that no wheel
     * exceeds the profile's highest speed (the turn keeps its share).
     *
     * @param speedMps forward speed, metres per second
     * @param turnRadS turn rate, radians per second, counter-clockwise positive
     * @param profile  the robot's drive
     * @return the command text; STOP when an input is not a finite number (a corrupt target, say):
     *         the engine never sends a command the robot would refuse
     */
    public static String drive(double speedMps, double turnRadS, DriveProfile profile) {
        if (!Double.isFinite(speedMps) || !Double.isFinite(turnRadS)) {
            return STOP;
        }
        double half = turnRadS * profile.axleWidthM() / 2.0;
        double left = speedMps - half;
        double right = speedMps + half;
        double fastest = Math.max(Math.abs(left), Math.abs(right));
        if (fastest > profile.maxSpeedMps()) {
            double scale = profile.maxSpeedMps() / fastest;
            left *= scale;
            right *= scale;
        }
        StringBuilder command = new StringBuilder(24).append(CommandWord.DRIVE.name()).append(' ');
        return appendFixed4(appendFixed4(command, left).append(' '), right).toString();
    }

    /**
     * Appends a number with four decimals, exactly as {@code String.format(Locale.ROOT, "%.4f", v)}
     * writes it (half-up on the shortest decimal form, the sign of a negative that rounds to zero
     * kept), at a fifth of its cost: the engine formats two per iteration (the profile's top frame).
     */
    static StringBuilder appendFixed4(StringBuilder sb, double v) {
        BigDecimal rounded = BigDecimal.valueOf(v).setScale(4, RoundingMode.HALF_UP);
        if (rounded.signum() == 0 && (v < 0 || 1 / v < 0)) {
            sb.append('-');
        }
        return sb.append(rounded.toPlainString());
    }

    /**
     * @param command a command text, in the robot's grammar
     * @return the left and right wheel speeds it asks for, metres per second (DRIVE, FORWARD,
     *         TURN_LEFT, TURN_RIGHT; zero for STOP and RECHARGE), or null for a text that is none of these
     */
    public static double[] wheelSpeeds(String command) {
        if (command == null) {
            return null;
        }
        if (command.equals(STOP) || command.equals(RECHARGE)) {
            return new double[] {0.0, 0.0};
        }
        int first = command.indexOf(' ');
        if (first < 0) {
            return null;
        }
        int second = command.indexOf(' ', first + 1);
        String word = command.substring(0, first);
        try {
            if (word.equals(CommandWord.DRIVE.name())) {
                return second < 0 ? null : new double[] {Double.parseDouble(command.substring(first + 1, second)),
                        Double.parseDouble(command.substring(second + 1))};
            }
            if (second >= 0) {
                return null;
            }
            double v = Double.parseDouble(command.substring(first + 1));
            return switch (word) {
                case "FORWARD" -> new double[] {v, v};
                case "TURN_LEFT" -> new double[] {-v, v};
                case "TURN_RIGHT" -> new double[] {v, -v};
                default -> null;
            };
        } catch (NumberFormatException e) {
            return null;
        }
    }

    /**
     * @param angleRad an angle, radians
     * @return the same angle in (-π, π]
     */
    public static double wrap(double angleRad) {
        double a = Math.IEEEremainder(angleRad, 2 * Math.PI);
        return a <= -Math.PI ? a + 2 * Math.PI : a;
    }

    private static double clamp(double value, double limit) {
        return Math.max(-limit, Math.min(limit, value));
    }
}
