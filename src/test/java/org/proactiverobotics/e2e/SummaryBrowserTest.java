package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import org.apache.commons.csv.CSVFormat;
import org.apache.commons.csv.CSVRecord;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.openqa.selenium.By;
import org.openqa.selenium.WebElement;
import org.proactiverobotics.app.sweep.WorldJson;
import org.proactiverobotics.sim2d.WorldFiles;
import org.proactiverobotics.sim2d.WorldSpec;

/**
 * summary.html, as `sweep` writes it, in a real (headless) Chromium: it loads with no console
 * error, draws a chart per metric and grouping with the sweep's own figures, sorts its table by a
 * clicked column, filters the missions not accomplished, and a failed mission's outcome opens its
 * replay.
 */
class SummaryBrowserTest extends CommandLineTest {

    @TempDir
    static Path dir;
    private static Browser browser;
    private static Path out;
    private static List<CSVRecord> results;

    @BeforeAll
    static void sweepAndOpenABrowser() throws IOException {
        Browser.assumeInstalled();
        WorldSpec ref = WorldFiles.bundled("reference-arena");
        WorldSpec limited = new WorldSpec("short-limit", ref.timeStepMs(), 3.0, 7, ref.arena(), ref.robot(), ref.obstacles(),
                ref.checkpoints(), ref.checkpointRadiusM(), ref.rechargeStation(), ref.battery());
        Path worlds = Files.createDirectories(dir.resolve("worlds"));
        Files.writeString(worlds.resolve("short-limit.json"), WorldJson.of(limited));
        out = dir.resolve("sweep");
        SummaryBrowserTest cli = new SummaryBrowserTest();
        assertThat(cli.run("sweep", "--worlds", "reference-arena", worlds.toString(), "--noise", "none,small",
                "--strategies", "safety-first,destination-first", "--link", "direct", "--out", out.toString()))
                .as(cli.err.toString()).isEqualTo(1);
        try (Reader in = Files.newBufferedReader(out.resolve("results.csv"), StandardCharsets.UTF_8)) {
            results = CSVFormat.DEFAULT.builder().setHeader().setSkipHeaderRecord(true).get().parse(in).getRecords();
        }
        browser = Browser.start();
    }

    @BeforeEach
    void openTheSummaryAfresh() {
        browser.driver().get("about:blank");
        browser.driver().get(out.resolve("summary.html").toUri().toString());
    }

    @AfterAll
    static void closeTheBrowser() throws IOException {
        if (browser != null) {
            browser.close();
        }
    }

    @Test
    void drawsEveryMetricByEveryGroupingWithTheSweepsFigures() {
        List<WebElement> plots = browser.driver().findElements(By.cssSelector("#plots .plot"));
        assertThat(plots).hasSize(5 * 3);
        WebElement successByStrategy = plots.get(0);
        assertThat(successByStrategy.findElement(By.tagName("h3")).getText()).isEqualTo("success rate % by strategy");
        List<String> bars = successByStrategy.findElements(By.cssSelector("rect > title")).stream()
                .map(t -> t.getAttribute("textContent")).toList();
        List<String> expected = new ArrayList<>();
        for (String strategy : List.of("destination-first", "safety-first")) {
            List<CSVRecord> rows = results.stream().filter(r -> r.get("strategy").equals(strategy)).toList();
            long ok = rows.stream().filter(r -> r.get("success").equals("true")).count();
            double rate = 100.0 * ok / rows.size();
            expected.add(strategy + ": " + fmt(rate) + " (" + rows.size() + " missions)");
        }
        assertThat(bars).containsExactlyElementsOf(expected);
        assertThat(browser.consoleErrors()).isEmpty();
    }

    @Test
    void aClickedColumnSortsTheTableAndASecondClickReversesIt() {
        WebElement header = browser.driver().findElements(By.cssSelector("#missions th")).stream()
                .filter(th -> th.getText().equals("sim s")).findFirst().orElseThrow();
        header.click();
        assertThat(column("sim s")).hasSize(results.size()).isSorted();
        header = browser.driver().findElements(By.cssSelector("#missions th")).stream()
                .filter(th -> th.getText().equals("sim s")).findFirst().orElseThrow();
        header.click();
        assertThat(column("sim s")).hasSize(results.size()).isSortedAccordingTo(Comparator.reverseOrder());
    }

    @Test
    void onlyFailedShowsTheMissionsNotAccomplishedEachLinkedToItsReplay() {
        WebElement onlyFailed = browser.driver().findElement(By.id("onlyFailed"));
        assertThat(onlyFailed.isSelected()).isFalse();
        assertThat(browser.driver().findElements(By.cssSelector("#missions tbody tr"))).hasSize(results.size());
        onlyFailed.click();
        long failed = results.stream().filter(r -> r.get("success").equals("false")).count();
        assertThat(failed).isPositive();
        List<WebElement> rows = browser.driver().findElements(By.cssSelector("#missions tbody tr"));
        assertThat(rows).hasSize((int) failed).allSatisfy(r -> assertThat(r.getAttribute("class")).isEqualTo("failed"));
        WebElement link = rows.get(0).findElement(By.tagName("a"));
        assertThat(link.getText()).isNotEqualTo("MISSION_ACCOMPLISHED");
        String href = link.getAttribute("href");
        assertThat(href).endsWith("/replay.html");
        link.click();
        assertThat(browser.driver().getCurrentUrl()).isEqualTo(href);
        assertThat(browser.driver().findElement(By.id("step-info")).getText()).isNotBlank();
        assertThat(browser.consoleErrors()).isEmpty();
    }

    /** A number as the page shows it: whole numbers bare, else 2 decimals below 10 and 1 from there. */
    private static String fmt(double v) {
        return v == Math.rint(v) ? String.valueOf((long) v) : String.format(java.util.Locale.ROOT, v < 10 ? "%.2f" : "%.1f", v);
    }

    /** A column's numbers as the table shows them, top to bottom. */
    private static List<Double> column(String label) {
        List<WebElement> headers = browser.driver().findElements(By.cssSelector("#missions th"));
        int index = 0;
        while (!headers.get(index).getText().equals(label)) {
            index++;
        }
        List<Double> values = new ArrayList<>();
        for (WebElement row : browser.driver().findElements(By.cssSelector("#missions tbody tr"))) {
            values.add(Double.parseDouble(row.findElements(By.tagName("td")).get(index).getText()));
        }
        return values;
    }
}
