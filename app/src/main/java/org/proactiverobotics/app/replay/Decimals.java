package org.proactiverobotics.app.replay;

/**
 * Writes a number held as whole units of 10^-decimals (millimetres as metres, say) exactly as
 * {@code Double.toString(units / 10^decimals)} would, at a fraction of its cost: the decimal
 * itself, trailing zeros dropped, at least one digit after the point. The trace writes about
 * twenty such numbers per iteration.
 */
final class Decimals {

    private static final long[] SCALE = {1, 10, 100, 1000, 10_000};
    /** From here on Double.toString switches to scientific notation. */
    private static final double PLAIN_LIMIT = 1e7;

    private Decimals() {
    }

    /**
     * @param units    the value in units of 10^-decimals
     * @param decimals 1 to 4
     * @return the value as Double.toString writes it
     */
    static String of(long units, int decimals) {
        long scale = SCALE[decimals];
        if (Math.abs((double) units) >= PLAIN_LIMIT * scale) {
            return Double.toString(units / (double) scale);
        }
        StringBuilder sb = new StringBuilder(12);
        long u = units;
        if (u < 0) {
            sb.append('-');
            u = -u;
        }
        sb.append(u / scale).append('.');
        long fraction = u % scale;
        if (fraction == 0) {
            return sb.append('0').toString();
        }
        int digits = decimals;
        while (fraction % 10 == 0) {
            fraction /= 10;
            digits--;
        }
        String f = Long.toString(fraction);
        for (int pad = digits - f.length(); pad > 0; pad--) {
            sb.append('0');
        }
        return sb.append(f).toString();
    }
}
