package org.proactiverobotics.app.mission;

import java.io.PrintStream;
import java.util.Locale;

/** A live one-line status on a terminal, rewritten in place at most five times a second. */
public final class Progress {

    private static final long EVERY_NS = 200_000_000L;

    private final PrintStream out;
    private long lastNs;
    private boolean shown;

    public Progress(PrintStream out) {
        this.out = out;
    }

    public void update(double simTimeS, int reached, int total, double batteryPct, double realTimeFactor) {
        long now = System.nanoTime();
        if (shown && now - lastNs < EVERY_NS) {
            return;
        }
        lastNs = now;
        shown = true;
        out.printf(Locale.ROOT, "\r  sim %7.1f s   checkpoint %d/%d   battery %5.1f %%   %6.1fx real time ",
                simTimeS, reached, total, batteryPct, realTimeFactor);
        out.flush();
    }

    public void finish() {
        if (shown) {
            out.print("\r" + " ".repeat(78) + "\r");
            out.flush();
        }
    }
}
