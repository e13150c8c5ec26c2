package org.proactiverobotics.app.sweep;

import java.util.Locale;

/**
 * A success rate as a paper gives it: k accomplished of n missions, with the 95 % Wilson score
 * interval of the proportion (which, unlike the normal approximation, stays within 0–1 and is not
 * empty at k = 0 or k = n). Rates and bounds are fractions (0–1); the {@code shown} methods give
 * percent, one decimal, and "—" when there is no mission.
 *
 * @param accomplished k, missions accomplished
 * @param missions     n, missions in all
 */
public record SuccessRate(int accomplished, int missions) {

    /** The standard normal quantile of 0.975: a two-sided 95 % interval. */
    public static final double Z95 = 1.959963984540054;
    /** What is shown for a figure that has no mission to stand on. */
    public static final String NONE = "—";

    /**
     * @param accomplished k, from 0 to n
     * @param missions     n, from 0
     * @throws IllegalArgumentException when k is outside 0–n
     */
    public SuccessRate {
        if (missions < 0 || accomplished < 0 || accomplished > missions) {
            throw new IllegalArgumentException("a success rate needs 0 <= k <= n, not k=" + accomplished + ", n=" + missions);
        }
    }

    /** @return k / n, a fraction; NaN when n is 0 */
    public double rate() {
        return missions == 0 ? Double.NaN : (double) accomplished / missions;
    }

    /** @return the 95 % Wilson interval's lower bound, a fraction; exactly 0 when k is 0; NaN when n is 0 */
    public double wilsonLow() {
        if (missions == 0) {
            return Double.NaN;
        }
        return accomplished == 0 ? 0 : Math.max(0, centre() - halfWidth());
    }

    /** @return the 95 % Wilson interval's upper bound, a fraction; exactly 1 when k is n; NaN when n is 0 */
    public double wilsonHigh() {
        if (missions == 0) {
            return Double.NaN;
        }
        return accomplished == missions ? 1 : Math.min(1, centre() + halfWidth());
    }

    /** @return "k/n" */
    public String shownCount() {
        return accomplished + "/" + missions;
    }

    /** @return the rate in percent with one decimal ("62.5"); "—" when n is 0 */
    public String shownPercent() {
        return missions == 0 ? NONE : percent(rate());
    }

    /** @return the 95 % interval in percent, one decimal, low–high ("35.4–84.8"); "—" when n is 0 */
    public String shownInterval() {
        return missions == 0 ? NONE : percent(wilsonLow()) + "–" + percent(wilsonHigh());
    }

    private double centre() {
        double n = missions;
        double z2 = Z95 * Z95;
        return (rate() + z2 / (2 * n)) / (1 + z2 / n);
    }

    private double halfWidth() {
        double n = missions;
        double p = rate();
        double z2 = Z95 * Z95;
        return Z95 * Math.sqrt(p * (1 - p) / n + z2 / (4 * n * n)) / (1 + z2 / n);
    }

    private static String percent(double fraction) {
        return String.format(Locale.ROOT, "%.1f", 100 * fraction);
    }
}
