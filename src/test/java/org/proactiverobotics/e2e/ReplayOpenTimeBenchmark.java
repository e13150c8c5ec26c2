package org.proactiverobotics.e2e;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.condition.EnabledIfSystemProperty;

/**
 * A benchmark, not a test (it asserts nothing and runs only when asked): how long a replay.html
 * takes to open in headless Chromium, from the navigation's start to the end of its load event (its
 * script has drawn the first picture by then), and what
 * the engine's map costs when turned on at the last iteration and when scrubbed back to the middle.
 * Prints the median of five openings of each page (comma-separated). Run it on a long mission's page
 * (docs/replay.md):
 * {@code ./mvnw -q -o -pl e2e -am verify -Dtest=ReplayOpenTimeBenchmark -Dsurefire.failIfNoSpecifiedTests=false
 * -Dreplay.open=/tmp/long/replay.html}
 */
class ReplayOpenTimeBenchmark {

    @Test
    @EnabledIfSystemProperty(named = "replay.open", matches = ".+")
    void openEachReplayFiveTimes() throws IOException {
        for (String file : System.getProperty("replay.open").split(",")) {
            openFiveTimes(Path.of(file));
        }
    }

    private static void openFiveTimes(Path page) throws IOException {
        List<Double> open = new ArrayList<>();
        List<Double> map = new ArrayList<>();
        List<Double> scrub = new ArrayList<>();
        try (Browser browser = Browser.start()) {
            for (int k = 0; k < 5; k++) {
                browser.driver().get("about:blank");
                browser.driver().get(page.toUri().toString());
                // the page's script draws the first picture before the load event ends
                open.add(((Number) browser.js("return performance.getEntriesByType('navigation')[0].loadEventEnd"))
                        .doubleValue());
                browser.js("var t = document.getElementById('timeline'); t.value = t.max;"
                        + "t.dispatchEvent(new Event('input'));");
                map.add(((Number) browser.js("var box = document.getElementById('show-map'); if (!box) { return -1; }"
                        + "var t0 = performance.now(); box.click(); return performance.now() - t0;")).doubleValue());
                scrub.add(((Number) browser.js("var t = document.getElementById('timeline'), t0 = performance.now();"
                        + "t.value = Math.floor(t.max / 2); t.dispatchEvent(new Event('input'));"
                        + "return performance.now() - t0;")).doubleValue());
            }
        }
        System.out.printf(Locale.ROOT, "replay %s (%.1f MB): opens in %.0f ms; map on at the end %.0f ms (-1: no map);"
                        + " scrub to the middle %.0f ms (medians of 5)%n", page, Files.size(page) / 1e6, median(open), median(map), median(scrub));
    }

    private static double median(List<Double> values) {
        List<Double> sorted = values.stream().sorted().toList();
        return sorted.get(sorted.size() / 2);
    }
}
