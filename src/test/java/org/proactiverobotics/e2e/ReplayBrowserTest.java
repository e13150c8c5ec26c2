package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.openqa.selenium.By;
import org.openqa.selenium.OutputType;
import org.openqa.selenium.support.ui.Select;
import org.openqa.selenium.support.ui.WebDriverWait;
import org.proactiverobotics.app.mission.ScenarioColours;
import org.proactiverobotics.engine.robot.RobotEngine;
import org.proactiverobotics.engine.robot.ScenarioPlugins;

/**
 * replay.html, as `run` writes it for the reference arena, in a real (headless) Chromium: it loads
 * with no console error and fetches nothing, {@code #iteration=N} shows iteration N's record as
 * trace.jsonl has it, play advances, and the robot is drawn at the trace's pose.
 */
class ReplayBrowserTest extends CommandLineTest {

    private static final Pattern SIM_TIME = Pattern.compile("\"simTimeS\":([^,]+),");

    @TempDir
    static Path dir;
    private static Browser browser;
    private static Path page;
    private static List<String> lines;

    @BeforeAll
    static void runAMissionAndOpenABrowser() throws IOException {
        Browser.assumeInstalled();
        Path out = dir.resolve("out");
        ReplayBrowserTest cli = new ReplayBrowserTest();
        assertThat(cli.run("run", "--quiet", "--out", out.toString())).as(cli.err.toString()).isZero();
        page = out.resolve("replay.html");
        lines = Files.readAllLines(out.resolve("trace.jsonl"));
        browser = Browser.start();
    }

    @AfterAll
    static void closeTheBrowser() throws IOException {
        if (browser != null) {
            browser.close();
        }
    }

    private void open(String fragment) {
        browser.driver().get("about:blank");
        browser.driver().get(page.toUri() + fragment);
    }

    private String stepInfo() {
        return browser.driver().findElement(By.id("step-info")).getText();
    }

    @Test
    void loadsWithNoConsoleErrorAndHoldsNoExternalUrl() throws IOException {
        browser.consoleErrors();
        open("");
        assertThat(stepInfo()).startsWith("iteration " + iteration(lines.get(0)));
        assertThat(browser.consoleErrors()).as("console errors").isEmpty();
        assertThat(browser.js("return performance.getEntriesByType('resource').length")).as("resources fetched")
                .isEqualTo(0L);
        String html = Files.readString(page);
        assertThat(html).doesNotContainPattern("(?i)(https?:|wss?:|ftp:)//").doesNotContain("src=\"//")
                .doesNotContain("<link");
        assertThat(html).contains("<script id=\"replay-data\" type=\"application/json\">{");
    }

    @Test
    void theIterationInTheAddressShowsItsRecordAsTheTraceHasIt() {
        List<String> chosen = new ArrayList<>(List.of(lines.get(0), lines.get(lines.size() / 3), lines.get(lines.size() - 1)));
        lines.stream().filter(l -> l.contains("\"checkpointReached\"")).findFirst().ifPresent(chosen::add);
        lines.stream().filter(l -> l.contains("\"winner\":\"ObstacleAvoidance\"")).findFirst().ifPresent(chosen::add);
        assertThat(chosen).hasSize(5);
        for (String line : chosen) {
            JsonObject o = JsonParser.parseString(line).getAsJsonObject();
            long n = o.get("iteration").getAsLong();
            open("#iteration=" + n);
            String info = stepInfo();
            assertThat(info).as("iteration %d", n).startsWith("iteration " + n + "\n")
                    .contains(simTimeText(line)).contains(o.get("winner").getAsString())
                    .contains(o.get("command").getAsString());
            o.getAsJsonObject("suggestions").entrySet()
                    .forEach(e -> assertThat(info).contains(e.getKey() + ": " + e.getValue().getAsString()));
            if (o.getAsJsonObject("seen").has("scanM") && o.getAsJsonObject("seen").get("scanM").isJsonArray()) {
                int rays = o.getAsJsonObject("seen").getAsJsonArray("scanM").size();
                String scanLine = info.lines().filter(l -> l.startsWith("scan m ")).findFirst().orElseThrow();
                assertThat(scanLine.substring("scan m ".length()).split(" ")).as("every ray's reading: %s", scanLine)
                        .hasSize(rays).allMatch(r -> r.matches("-?\\d+(\\.\\d)?°:(\\d+\\.\\d\\d|–)"), "angle°:reading");
            }
        }
        // a new address on the same page moves too
        long later = iteration(lines.get(lines.size() / 2));
        browser.js("location.hash = arguments[0]", "#iteration=" + later);
        new WebDriverWait(browser.driver(), Duration.ofSeconds(5))
                .until(d -> stepInfo().startsWith("iteration " + later + "\n"));
    }

    @Test
    void playAdvancesTheIteration() {
        open("#iteration=" + iteration(lines.get(0)));
        new Select(browser.driver().findElement(By.id("speed"))).selectByValue("5"); // the 47 s mission in 9 s
        long before = (Long) browser.js("return window.replay.step()");
        browser.driver().findElement(By.id("play")).click();
        new WebDriverWait(browser.driver(), Duration.ofSeconds(10))
                .until(d -> (Long) browser.js("return window.replay.step()") > before + 20);
        browser.driver().findElement(By.id("play")).click();
        String info = stepInfo();
        long shown = Long.parseLong(info.substring("iteration ".length(), info.indexOf('\n')));
        assertThat(shown).isGreaterThan(iteration(lines.get(0)) + 20).isLessThan(iteration(lines.get(lines.size() - 1)));
        assertThat(browser.driver().getCurrentUrl()).endsWith("#iteration=" + shown);
        assertThat(browser.consoleErrors()).isEmpty();
    }

    @Test
    void theRobotIsDrawnAtTheTracePoseInTheWinnersColour() throws IOException {
        Map<String, String> colours = ScenarioColours.of(RobotEngine.freshSlots(ScenarioPlugins.none()));
        String line = lines.get(lines.size() / 3);
        JsonObject o = JsonParser.parseString(line).getAsJsonObject();
        JsonObject pose = o.getAsJsonObject("pose");
        open("#iteration=" + o.get("iteration").getAsLong());
        @SuppressWarnings("unchecked")
        List<Number> shown = (List<Number>) browser.js("return window.replay.pose()");
        assertThat(shown.get(0).doubleValue()).isEqualTo(pose.get("xM").getAsDouble());
        assertThat(shown.get(1).doubleValue()).isEqualTo(pose.get("yM").getAsDouble());
        // pixels inside the robot's disc, off its heading line and the GPS cross, have the winner's colour
        @SuppressWarnings("unchecked")
        List<String> pixels = (List<String>) browser.js(
                "var v = window.replay.view(), x = arguments[0], y = arguments[1], h = arguments[2], r = 0.12;"
                        + "var g = document.getElementById('world').getContext('2d'), out = [];"
                        + "[0.75, 2.0, 2.35, 3.9, 4.2].forEach(function (a) {"
                        + "  var px = Math.round(v.ox + (x + 0.55 * r * Math.cos(h + a)) * v.s),"
                        + "      py = Math.round(v.oy - (y + 0.55 * r * Math.sin(h + a)) * v.s);"
                        + "  var d = g.getImageData(px, py, 1, 1).data;"
                        + "  out.push('#' + [d[0], d[1], d[2]].map(function (c) { return (c < 16 ? '0' : '') + c.toString(16); }).join(''));"
                        + "}); return out;",
                pose.get("xM").getAsDouble(), pose.get("yM").getAsDouble(), pose.get("headingRad").getAsDouble());
        String winnerColour = colours.get(o.get("winner").getAsString());
        assertThat(pixels.stream().filter(winnerColour::equals).count()).as("pixels %s, winner %s", pixels, winnerColour)
                .isGreaterThanOrEqualTo(3);
        // the README's picture, made here
        Path shot = Path.of("target", "replay-screenshot.png");
        Files.write(shot, browser.driver().getScreenshotAs(OutputType.BYTES));
    }

    private static long iteration(String line) {
        return JsonParser.parseString(line).getAsJsonObject().get("iteration").getAsLong();
    }

    /** The simulated time exactly as the line writes it. */
    private static String simTimeText(String line) {
        Matcher m = SIM_TIME.matcher(line);
        assertThat(m.find()).isTrue();
        return "simTimeS " + m.group(1);
    }
}
