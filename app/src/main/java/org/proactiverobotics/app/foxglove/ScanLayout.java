package org.proactiverobotics.app.foxglove;

import java.util.List;

/**
 * Where each distance ray goes in a foxglove.LaserScan, whose ranges lie at equally spaced bearings:
 * the bearings are spaced by the greatest common divisor of the gaps between the rays' angles (1° for
 * the default twelve rays, 181 bearings from -90° to 90°), so that each ray keeps its exact angle
 * and the bearings between rays read 0.
 */
final class ScanLayout {

    /** More bearings than this and the rays are spread evenly instead (angles approximate). */
    private static final int MAX_BEARINGS = 3601;

    final double startRad;
    final double endRad;
    /** Ranges per scan. */
    final int bearings;
    /** Each ray's bearing index. */
    final int[] slot;

    private ScanLayout(double startRad, double endRad, int bearings, int[] slot) {
        this.startRad = startRad;
        this.endRad = endRad;
        this.bearings = bearings;
        this.slot = slot;
    }

    /** @param anglesDeg the rays' angles from the heading, degrees, rightmost first */
    static ScanLayout of(List<Double> anglesDeg) {
        int n = anglesDeg.size();
        long[] tenths = new long[n];
        for (int i = 0; i < n; i++) {
            tenths[i] = Math.round(anglesDeg.get(i) * 10);
        }
        long step = 0;
        boolean increasing = true;
        for (int i = 1; i < n; i++) {
            long gap = tenths[i] - tenths[i - 1];
            increasing &= gap > 0;
            step = gcd(step, Math.abs(gap));
        }
        int[] slot = new int[n];
        if (n < 2 || !increasing || (tenths[n - 1] - tenths[0]) / step + 1 > MAX_BEARINGS) {
            for (int i = 0; i < n; i++) {
                slot[i] = i;
            }
            return new ScanLayout(Math.toRadians(anglesDeg.get(0)), Math.toRadians(anglesDeg.get(n - 1)), n, slot);
        }
        for (int i = 0; i < n; i++) {
            slot[i] = (int) ((tenths[i] - tenths[0]) / step);
        }
        return new ScanLayout(Math.toRadians(tenths[0] / 10.0), Math.toRadians(tenths[n - 1] / 10.0), slot[n - 1] + 1, slot);
    }

    private static long gcd(long a, long b) {
        return b == 0 ? a : gcd(b, a % b);
    }
}
