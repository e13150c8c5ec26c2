package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.function.UnaryOperator;
import java.util.stream.Collectors;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.openqa.selenium.By;
import org.openqa.selenium.support.ui.Select;
import org.openqa.selenium.support.ui.WebDriverWait;
import org.proactiverobotics.app.mission.Mission;
import org.proactiverobotics.app.mission.MissionOptions;
import org.proactiverobotics.app.mission.NoiseLevel;

/**
 * replay.html of a world with several robots (docs/replay.md, "Several robots") in a real headless Chromium: {@code
 * #robot=2&iteration=M} shows robot 2's record as its trace lines have it, every robot is drawn where the trace
 * says it was at that time, the picker switches the record, and {@code #iteration=M} alone shows the first robot.
 */
class FleetReplayBrowserTest {

    @TempDir
    static Path dir;
    private static Browser browser;
    private static Path page;
    /** Trace lines by robot id, in order. */
    private static Map<Integer, List<JsonObject>> lines;

    @BeforeAll
    static void runAFleetAndOpenABrowser() throws Exception {
        Browser.assumeInstalled();
        Path out = Files.createDirectories(dir.resolve("out"));
        MissionOptions options = new MissionOptions(FleetMissionTest.crossing(), null, null, null, "safety-first", 1)
                .withLink(MissionOptions.Link.DIRECT).withNoise(NoiseLevel.SMALL);
        new Mission(options).engineTables(UnaryOperator.identity()).run(out);
        page = out.resolve("replay.html");
        lines = Files.readAllLines(out.resolve("trace.jsonl")).stream().map(l -> JsonParser.parseString(l).getAsJsonObject())
                .collect(Collectors.groupingBy(o -> o.get("robot").getAsInt()));
        browser = Browser.start();
    }

    @AfterAll
    static void closeTheBrowser() throws IOException {
        if (browser != null) {
            browser.close();
        }
    }

    private static void open(String fragment) {
        browser.driver().get("about:blank");
        browser.driver().get(page.toUri() + fragment);
    }

    private static String stepInfo() {
        return browser.driver().findElement(By.id("step-info")).getText();
    }

    /** The trace line of a robot at a simulated time (its last line when it was done by then). */
    private static JsonObject lineAt(int robot, double simTimeS) {
        JsonObject found = lines.get(robot).get(0);
        for (JsonObject o : lines.get(robot)) {
            if (o.get("simTimeS").getAsDouble() <= simTimeS) {
                found = o;
            }
        }
        return found;
    }

    @Test
    void robotTwosIterationShowsItsRecordAndEveryRobotIsDrawn() {
        List<JsonObject> second = lines.get(2);
        JsonObject line = second.get(second.size() / 2);
        long iteration = line.get("iteration").getAsLong();
        browser.consoleErrors();
        open("#robot=2&iteration=" + iteration);
        String info = stepInfo();
        assertThat(info).startsWith("iteration " + iteration + "\nrobot 2 (2 of 3 robots)\n")
                .contains("simTimeS " + line.get("simTimeS").getAsString())
                .contains("winner " + line.get("winner").getAsString())
                .contains("command " + line.get("command").getAsString());
        line.getAsJsonObject("suggestions").entrySet()
                .forEach(e -> assertThat(info).contains(e.getKey() + ": " + e.getValue().getAsString()));
        assertThat(browser.js("return window.replay.robot()")).isEqualTo(2L);
        assertThat(new Select(browser.driver().findElement(By.id("robot"))).getFirstSelectedOption().getText()).startsWith("2");
        // every robot drawn at its pose at that simulated time, and its disc is on the canvas
        @SuppressWarnings("unchecked")
        List<List<Number>> drawn = (List<List<Number>>) browser.js("return window.replay.drawn()");
        assertThat(drawn).extracting(d -> d.get(0).intValue()).containsExactly(2, 1, 5);
        double t = line.get("simTimeS").getAsDouble();
        for (List<Number> d : drawn) {
            JsonObject pose = lineAt(d.get(0).intValue(), t).getAsJsonObject("pose");
            assertThat(d.get(1).doubleValue()).as("robot %s x", d.get(0)).isEqualTo(pose.get("xM").getAsDouble());
            assertThat(d.get(2).doubleValue()).as("robot %s y", d.get(0)).isEqualTo(pose.get("yM").getAsDouble());
            assertThat(discPixels(d.get(1).doubleValue(), d.get(2).doubleValue(), d.get(3).doubleValue()))
                    .as("robot %s drawn", d.get(0)).isGreaterThanOrEqualTo(3);
        }
        assertThat(browser.driver().getCurrentUrl()).endsWith("#robot=2&iteration=" + iteration);
        assertThat(browser.consoleErrors()).as("console errors").isEmpty();
    }

    @Test
    void theIterationAloneShowsTheFirstRobotAndThePickerSwitchesAtTheSameTime() {
        JsonObject first = lines.get(1).get(lines.get(1).size() / 3);
        open("#iteration=" + first.get("iteration").getAsLong());
        assertThat(stepInfo()).startsWith("iteration " + first.get("iteration").getAsLong() + "\nrobot 1 (1 of 3 robots)\n");
        new Select(browser.driver().findElement(By.id("robot"))).selectByValue("2"); // robot 5, the third
        JsonObject fifth = lineAt(5, first.get("simTimeS").getAsDouble());
        new WebDriverWait(browser.driver(), Duration.ofSeconds(5)).until(d -> stepInfo().startsWith(
                "iteration " + fifth.get("iteration").getAsLong() + "\nrobot 5 (3 of 3 robots)\n"));
        assertThat(stepInfo()).contains("simTimeS " + fifth.get("simTimeS").getAsString());
        assertThat(browser.driver().getCurrentUrl()).endsWith("#robot=5&iteration=" + fifth.get("iteration").getAsLong());
        // a new address on the same page switches back
        JsonObject again = lines.get(1).get(lines.get(1).size() / 2);
        browser.js("location.hash = arguments[0]", "#robot=1&iteration=" + again.get("iteration").getAsLong());
        new WebDriverWait(browser.driver(), Duration.ofSeconds(5)).until(d -> stepInfo().startsWith(
                "iteration " + again.get("iteration").getAsLong() + "\nrobot 1 (1 of 3 robots)\n"));
    }

    /** Of five points inside a robot's disc (off its heading line), how many are not the arena's background. */
    private static long discPixels(double x, double y, double heading) {
        @SuppressWarnings("unchecked")
        List<String> pixels = (List<String>) browser.js(
                "var v = window.replay.view(), x = arguments[0], y = arguments[1], h = arguments[2], r = 0.10;"
                        + "var g = document.getElementById('world').getContext('2d'), out = [];"
                        + "[0.75, 2.0, 2.35, 3.9, 4.2].forEach(function (a) {"
                        + "  var px = Math.round(v.ox + (x + 0.55 * r * Math.cos(h + a)) * v.s),"
                        + "      py = Math.round(v.oy - (y + 0.55 * r * Math.sin(h + a)) * v.s);"
                        + "  var d = g.getImageData(px, py, 1, 1).data;"
                        + "  out.push([d[0], d[1], d[2]].join(','));"
                        + "}); return out;", x, y, heading);
        return pixels.stream().filter(p -> !p.equals("250,250,250") && !p.equals("255,255,255") && !p.equals("0,0,0")).count();
    }
}
