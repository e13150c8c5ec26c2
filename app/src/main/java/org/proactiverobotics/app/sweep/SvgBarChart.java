package org.proactiverobotics.app.sweep;

import java.math.BigDecimal;
import java.math.MathContext;
import java.util.List;
import java.util.Locale;

/**
 * A horizontal bar chart as one standalone SVG document: its own xmlns, size and white background,
 * every style an attribute (no stylesheet), so that the same text is both drawn inline in
 * summary.html and saved alone as a figure. Bars come in groups (a heading each, e.g. the
 * strategy) and are coloured by series (e.g. the noise level, a colour-blind-safe palette); a bar
 * may carry an interval drawn as a whisker. Lengths are SVG user units (pixels at 100 %).
 */
final class SvgBarChart {

    /**
     * One bar.
     *
     * @param group     the heading it is drawn under; empty for none
     * @param series    its label, which also picks its colour
     * @param value     its length in the axis's unit; NaN draws no bar
     * @param low       its interval's low end; NaN for no whisker
     * @param high      its interval's high end; NaN for no whisker
     * @param valueText what is written to its right (the figure as the tables show it)
     * @param tooltip   its hover text
     */
    record Bar(String group, String series, double value, double low, double high, String valueText, String tooltip) {
    }

    static final String SVG_NS = "http://www.w3.org/2000/svg";

    /** Okabe and Ito's palette, told apart by colour-blind readers too. */
    private static final List<String> PALETTE = List.of("#0072B2", "#E69F00", "#009E73", "#CC79A7", "#56B4E9", "#D55E00",
            "#F0E442", "#000000");
    private static final int WIDTH = 640;
    private static final double CHAR_W = 6.8; // a 12 px sans-serif character, on average, wide enough not to overlap
    private static final int TITLE_H = 30;
    private static final int HEADING_H = 18;
    private static final int ROW_H = 20;
    private static final int BAR_H = 13;
    private static final int MAX_LABEL_W = 230;

    private SvgBarChart() {
    }

    /**
     * @param title     drawn at the top (and the document's title)
     * @param axisLabel under the axis, with its unit
     * @param bars      top to bottom
     * @param axisMax   the axis's end; NaN to fit the longest bar or whisker
     * @param series    every series' label, in colour order
     * @return the chart as a standalone SVG document (no XML declaration)
     */
    static String render(String title, String axisLabel, List<Bar> bars, double axisMax, List<String> series) {
        int labelW = 0;
        int valueW = 60;
        double longest = 0;
        for (Bar b : bars) {
            labelW = Math.max(labelW, (int) Math.ceil((b.group().isEmpty() ? 14 : 24) + b.series().length() * CHAR_W));
            labelW = Math.max(labelW, (int) Math.ceil(12 + b.group().length() * (CHAR_W + 0.6)));
            valueW = Math.max(valueW, (int) Math.ceil(12 + b.valueText().length() * CHAR_W));
            for (double v : new double[] {b.value(), b.high()}) {
                if (!Double.isNaN(v)) {
                    longest = Math.max(longest, v);
                }
            }
        }
        labelW = Math.min(Math.max(labelW, 80), MAX_LABEL_W);
        double[] ticks = ticks(Double.isNaN(axisMax) ? longest : axisMax);
        double max = ticks[ticks.length - 1];
        int x0 = labelW;
        int x1 = WIDTH - valueW;
        StringBuilder body = new StringBuilder();
        int y = TITLE_H;
        String group = null;
        for (Bar b : bars) {
            if (!b.group().isEmpty() && !b.group().equals(group)) {
                body.append(text(8, y + 13, fit(b.group(), labelW - 12, CHAR_W + 0.6), "start", " font-weight=\"bold\""));
                y += HEADING_H;
            }
            group = b.group();
            int mid = y + ROW_H / 2;
            body.append(text(x0 - 8, mid + 4, fit(b.series(), labelW - (b.group().isEmpty() ? 14 : 24), CHAR_W), "end", ""));
            String colour = PALETTE.get(Math.max(0, series.indexOf(b.series())) % PALETTE.size());
            if (!Double.isNaN(b.value())) {
                double w = Math.max(1, (x1 - x0) * b.value() / max);
                body.append(String.format(Locale.ROOT,
                        "<rect x=\"%d\" y=\"%d\" width=\"%.1f\" height=\"%d\" fill=\"%s\"><title>%s</title></rect>",
                        x0, mid - BAR_H / 2, w, BAR_H, colour, escape(b.tooltip())));
            }
            if (!Double.isNaN(b.low()) && !Double.isNaN(b.high())) {
                double lo = x0 + (x1 - x0) * Math.max(0, b.low()) / max;
                double hi = x0 + (x1 - x0) * Math.min(max, b.high()) / max;
                body.append(String.format(Locale.ROOT, "<path d=\"M%.1f %dH%.1fM%.1f %dv10M%.1f %dv10\" stroke=\"#222\""
                        + " stroke-width=\"1.3\" fill=\"none\"/>", lo, mid, hi, lo, mid - 5, hi, mid - 5));
            }
            body.append(text(x1 + 8, mid + 4, b.valueText(), "start", ""));
            y += ROW_H;
        }
        int axisY = y + 4;
        StringBuilder grid = new StringBuilder();
        for (double t : ticks) {
            double x = x0 + (x1 - x0) * t / max;
            grid.append(String.format(Locale.ROOT, "<line x1=\"%.1f\" y1=\"%d\" x2=\"%.1f\" y2=\"%d\" stroke=\"%s\"/>", x,
                    TITLE_H, x, axisY, t == 0 ? "#888" : "#e3e3e3"));
            grid.append(text(x, axisY + 14, number(t), "middle", " fill=\"#555\""));
        }
        grid.append(String.format(Locale.ROOT, "<line x1=\"%d\" y1=\"%d\" x2=\"%d\" y2=\"%d\" stroke=\"#888\"/>", x0, axisY,
                x1, axisY));
        grid.append(text((x0 + x1) / 2.0, axisY + 30, axisLabel, "middle", " fill=\"#333\""));
        int height = axisY + 40;
        return "<svg xmlns=\"" + SVG_NS + "\" width=\"" + WIDTH + "\" height=\"" + height + "\" viewBox=\"0 0 " + WIDTH + " "
                + height + "\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\" font-size=\"12\" fill=\"#222\">"
                + "<title>" + escape(title) + "</title>"
                + "<rect width=\"" + WIDTH + "\" height=\"" + height + "\" fill=\"#fff\"/>"
                + text(8, 18, title, "start", " font-size=\"13\" font-weight=\"bold\"")
                + grid + body + "</svg>";
    }

    /** @return ticks from 0 to a round end at or past {@code longest}: steps of 1, 2, 2.5 or 5 times a power of ten */
    static double[] ticks(double longest) {
        if (!(longest > 0)) {
            return new double[] {0, 1};
        }
        double raw = longest / 5;
        double power = Math.pow(10, Math.floor(Math.log10(raw)));
        double step = power * 10;
        for (double m : new double[] {1, 2, 2.5, 5, 10}) {
            if (m * power >= raw) {
                step = m * power;
                break;
            }
        }
        int count = (int) Math.ceil(longest / step - 1e-9);
        double[] ticks = new double[count + 1];
        for (int i = 0; i <= count; i++) {
            ticks[i] = i * step;
        }
        return ticks;
    }

    private static String number(double v) {
        return BigDecimal.valueOf(v).round(new MathContext(6)).stripTrailingZeros().toPlainString();
    }

    private static String text(double x, double y, String s, String anchor, String more) {
        return String.format(Locale.ROOT, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"%s\"%s>%s</text>", x, y, anchor, more,
                escape(s));
    }

    /** @return s, cut with an ellipsis where it would be wider than {@code widthPx} */
    private static String fit(String s, int widthPx, double charW) {
        int room = (int) (widthPx / charW);
        return s.length() <= room ? s : s.substring(0, Math.max(1, room - 1)) + "…";
    }

    /** @return s with XML's special characters escaped, for text and attribute values alike */
    static String escape(String s) {
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;");
    }
}
