package org.proactiverobotics.engine.navigation;

import java.util.Arrays;
import java.util.Locale;

/**
 * The places a route follower has closed on its own map: discs (centre and radius, metres) round
 * a narrow place where the robot made no progress, each with the side the robot came from and the
 * reason in words. A planner keeps a route out of them, except that a robot standing inside one
 * may leave it toward the side it came from ({@link #allows}): it is never walled in by its own
 * mark, and never let through. Plain fields, so they are saved with the rule that holds the
 * follower and a resumed engine plans round the same places.
 */
public final class ClosedPlaces {

    /** At most this many places are closed (then the oldest is reopened): a bounded saved state. */
    static final int MAX_PLACES = 16;

    private double[] xs = new double[0];
    private double[] ys = new double[0];
    private double[] rs = new double[0];
    /** The unit vector from each centre toward the side the robot came from. */
    private double[] us = new double[0];
    private double[] vs = new double[0];
    private String[] reasons = new String[0];

    /** No place closed. */
    public ClosedPlaces() {
    }

    /** @return how many places are closed */
    public int size() {
        return xs.length;
    }

    /** @return whether no place is closed */
    public boolean isEmpty() {
        return xs.length == 0;
    }

    /**
     * Closes a disc.
     *
     * @param xM      its centre's x, metres
     * @param yM      its centre's y, metres
     * @param radiusM its radius, metres
     * @param backX   the x of the direction the robot came from (not zero with backY)
     * @param backY   its y
     * @param reason  why, in words
     */
    void close(double xM, double yM, double radiusM, double backX, double backY, String reason) {
        int from = xs.length >= MAX_PLACES ? 1 : 0;
        double len = Math.hypot(backX, backY);
        xs = append(Arrays.copyOfRange(xs, from, xs.length), xM);
        ys = append(Arrays.copyOfRange(ys, from, ys.length), yM);
        rs = append(Arrays.copyOfRange(rs, from, rs.length), radiusM);
        us = append(Arrays.copyOfRange(us, from, us.length), backX / len);
        vs = append(Arrays.copyOfRange(vs, from, vs.length), backY / len);
        String[] r = Arrays.copyOfRange(reasons, from, reasons.length + 1);
        r[r.length - 1] = reason;
        reasons = r;
    }

    /** @return whether a point lies inside a closed place */
    boolean inside(double xM, double yM) {
        for (int k = 0; k < xs.length; k++) {
            if (in(k, xM, yM)) {
                return true;
            }
        }
        return false;
    }

    private boolean in(int k, double xM, double yM) {
        double dx = xM - xs[k];
        double dy = yM - ys[k];
        return dx * dx + dy * dy < rs[k] * rs[k];
    }

    /**
     * Whether a move between two points keeps out of the closed places: a point inside one may be
     * reached only from inside it, moving toward the side the robot came from.
     */
    boolean allows(double fromX, double fromY, double toX, double toY) {
        for (int k = 0; k < xs.length; k++) {
            if (in(k, toX, toY) && (!in(k, fromX, fromY) || (toX - fromX) * us[k] + (toY - fromY) * vs[k] <= 0)) {
                return false;
            }
        }
        return true;
    }

    /** @return whether a straight drive between two points enters a closed place, or goes through one other than back the way the robot came */
    boolean crossed(double x0, double y0, double x1, double y1) {
        if (xs.length == 0) {
            return false;
        }
        double len = Math.hypot(x1 - x0, y1 - y0);
        int n = Math.max(1, (int) Math.ceil(len / 0.025));
        double px = x0;
        double py = y0;
        for (int k = 1; k <= n; k++) {
            double t = (double) k / n;
            double qx = x0 + t * (x1 - x0);
            double qy = y0 + t * (y1 - y0);
            if (!allows(px, py, qx, qy)) {
                return true;
            }
            px = qx;
            py = qy;
        }
        return false;
    }

    /** @return the newest place's reason (null when none is closed) */
    public String newestReason() {
        return reasons.length == 0 ? null : reasons[reasons.length - 1];
    }

    /** @return the closed places in words: "(x, y) r m" each, for an unreachable checkpoint's reason */
    public String describe() {
        StringBuilder sb = new StringBuilder();
        for (int k = 0; k < xs.length; k++) {
            sb.append(k == 0 ? "" : ", ").append(String.format(Locale.ROOT, "(%.2f, %.2f)", xs[k], ys[k]));
        }
        return sb.toString();
    }

    double x(int k) {
        return xs[k];
    }

    double y(int k) {
        return ys[k];
    }

    double radius(int k) {
        return rs[k];
    }

    private static double[] append(double[] a, double v) {
        double[] b = Arrays.copyOf(a, a.length + 1);
        b[a.length] = v;
        return b;
    }
}
