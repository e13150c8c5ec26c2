package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.openqa.selenium.By;
import org.openqa.selenium.support.ui.Select;
import org.openqa.selenium.support.ui.WebDriverWait;
import org.proactiverobotics.app.replay.ReplayPage;

/**
 * Issue 31: what the engine believed, in trace.jsonl and drawn by replay.html in a real (headless)
 * Chromium: the map toggle draws occupied cells where the trace's map deltas put them (and, scrubbed
 * back, not those that came later), a vetoed iteration's {@code #step-info} holds the veto's reason,
 * the jump to {@code checkpointUnreachable} lands on the iteration that declared it, every event kind
 * has a jump, and a page of an older trace (no belief) still replays.
 */
class ReplayBeliefBrowserTest extends CommandLineTest {

    /** OccupancyMap.CELL_M. */
    private static final double CELL_M = 0.05;
    /** The page's colour of an occupied cell (opaque). */
    private static final String OCCUPIED = "#1428a0";

    @TempDir
    static Path dir;
    private static Browser browser;
    private static Path walledInPage;
    private static List<JsonObject> walledIn;
    private static Path referencePage;
    private static List<JsonObject> reference;

    @BeforeAll
    static void runTwoMissionsAndOpenABrowser() throws IOException {
        Browser.assumeInstalled();
        Path world = dir.resolve("walled-in.json");
        Files.writeString(world, NavigationTest.WALLED_IN);
        ReplayBeliefBrowserTest cli = new ReplayBeliefBrowserTest();
        Path out = dir.resolve("walled-in");
        assertThat(cli.run("run", "--world", world.toString(), "--link", "direct", "--quiet", "--out", out.toString()))
                .as("a mission not accomplished: %s", cli.err).isEqualTo(1);
        walledInPage = out.resolve("replay.html");
        walledIn = lines(out.resolve("trace.jsonl"));
        Path ref = dir.resolve("reference");
        assertThat(cli.run("run", "--link", "direct", "--quiet", "--out", ref.toString())).as(cli.err.toString()).isZero();
        referencePage = ref.resolve("replay.html");
        reference = lines(ref.resolve("trace.jsonl"));
        browser = Browser.start();
    }

    @AfterAll
    static void closeTheBrowser() throws IOException {
        if (browser != null) {
            browser.close();
        }
    }

    private static List<JsonObject> lines(Path trace) throws IOException {
        return Files.readAllLines(trace).stream().map(l -> JsonParser.parseString(l).getAsJsonObject()).toList();
    }

    private void open(Path page, String fragment) {
        browser.driver().get("about:blank");
        browser.driver().get(page.toUri() + fragment);
    }

    /** Moves the open page to an iteration through its address, and waits until it shows it. */
    private void goTo(long iteration) {
        browser.js("location.hash = arguments[0]", "#iteration=" + iteration);
        new WebDriverWait(browser.driver(), Duration.ofSeconds(5))
                .until(d -> stepInfo().startsWith("iteration " + iteration + "\n"));
    }

    private String stepInfo() {
        return browser.driver().findElement(By.id("step-info")).getText();
    }

    /** The map's states after the trace's deltas up to and including an iteration: (ix, iy) → state. */
    private static Map<List<Integer>, Integer> mapAt(List<JsonObject> trace, long iteration) {
        Map<List<Integer>, Integer> cells = new HashMap<>();
        for (JsonObject line : trace) {
            if (line.get("iteration").getAsLong() > iteration) {
                break;
            }
            if (line.has("mapDelta")) {
                for (JsonElement c : line.getAsJsonArray("mapDelta")) {
                    JsonArray a = c.getAsJsonArray();
                    cells.put(List.of(a.get(0).getAsInt(), a.get(1).getAsInt()), a.get(2).getAsInt());
                }
            }
        }
        return cells;
    }

    /** The colours of the cells' centres on the canvas, as "#rrggbb". */
    @SuppressWarnings("unchecked")
    private List<String> pixels(List<List<Integer>> cells) {
        List<List<Double>> points = new ArrayList<>();
        for (List<Integer> c : cells) {
            points.add(List.of((c.get(0) + 0.5) * CELL_M, (c.get(1) + 0.5) * CELL_M));
        }
        return (List<String>) browser.js(
                "var v = window.replay.view(), g = document.getElementById('world').getContext('2d');"
                        + "return arguments[0].map(function (p) {"
                        + "  var d = g.getImageData(Math.floor(v.ox + p[0] * v.s), Math.floor(v.oy - p[1] * v.s), 1, 1).data;"
                        + "  return '#' + [d[0], d[1], d[2]].map(function (c) { return (c < 16 ? '0' : '') + c.toString(16); }).join('');"
                        + "});", points);
    }

    /** Occupied cells of a map, a few, away from the robot (its disc, rays and the route are drawn over the map). */
    private static List<List<Integer>> occupiedAwayFrom(Map<List<Integer>, Integer> map, JsonObject line, int most) {
        double x = line.getAsJsonObject("pose").get("xM").getAsDouble();
        double y = line.getAsJsonObject("pose").get("yM").getAsDouble();
        return map.entrySet().stream().filter(e -> e.getValue() == 2)
                .map(Map.Entry::getKey)
                .filter(c -> Math.hypot((c.get(0) + 0.5) * CELL_M - x, (c.get(1) + 0.5) * CELL_M - y) > 1.3)
                .sorted((a, b) -> a.get(1).equals(b.get(1)) ? a.get(0) - b.get(0) : a.get(1) - b.get(1))
                .limit(most).toList();
    }

    @Test
    void theMapToggleDrawsOccupiedCellsWhereTheTracesMapDeltasPutThem() {
        JsonObject last = walledIn.get(walledIn.size() - 1);
        long end = last.get("iteration").getAsLong();
        Map<List<Integer>, Integer> map = mapAt(walledIn, end);
        List<List<Integer>> occupied = occupiedAwayFrom(map, last, 60);
        assertThat(occupied).as("occupied cells away from the robot at the end").hasSizeGreaterThan(20);

        open(walledInPage, "#iteration=" + end);
        assertThat(pixels(occupied)).as("map toggle off (the default)").filteredOn(OCCUPIED::equals).isEmpty();
        browser.driver().findElement(By.id("show-map")).click();
        List<String> shown = pixels(occupied);
        assertThat(shown.stream().filter(OCCUPIED::equals).count()).as("occupied cells drawn: %s", shown)
                .isGreaterThanOrEqualTo(occupied.size() * 9L / 10);

        // scrubbed back to a third of the mission: cells that became occupied only later are not drawn so
        JsonObject early = walledIn.get(walledIn.size() / 3);
        Map<List<Integer>, Integer> before = mapAt(walledIn, early.get("iteration").getAsLong());
        List<List<Integer>> later = occupied.stream().filter(c -> before.getOrDefault(c, 0) != 2).toList();
        List<List<Integer>> already = occupiedAwayFrom(before, early, 40);
        goTo(early.get("iteration").getAsLong());
        assertThat(later).as("cells occupied later than iteration %s", early.get("iteration")).isNotEmpty();
        assertThat(pixels(later)).filteredOn(OCCUPIED::equals).hasSizeLessThanOrEqualTo(later.size() / 10);
        if (!already.isEmpty()) {
            assertThat(pixels(already).stream().filter(OCCUPIED::equals).count())
                    .isGreaterThanOrEqualTo(already.size() * 9L / 10);
        }
        assertThat(browser.consoleErrors()).isEmpty();
    }

    @Test
    void atAVetoedIterationTheStepInfoHoldsTheReason() {
        JsonObject vetoed = reference.stream()
                .filter(l -> l.has("reason") && "ObstacleAvoidance".equals(l.get("winner").getAsString()))
                .findFirst().orElseThrow(() -> new AssertionError("the reference mission has a veto"));
        String reason = vetoed.get("reason").getAsString();
        assertThat(reason).startsWith("vetoed ").contains(" m");
        long n = vetoed.get("iteration").getAsLong();
        open(referencePage, "#iteration=" + n);
        assertThat(stepInfo()).startsWith("iteration " + n + "\n").contains("reason " + reason)
                .contains("command " + vetoed.get("command").getAsString());
        assertThat(browser.driver().findElement(By.id("reason")).getText()).isEqualTo(reason);
        // one iteration on, no veto: no reason
        goTo(n + 1);
        assertThat(stepInfo()).doesNotContain("reason ");
    }

    @Test
    void theUnreachableJumpLandsOnTheIterationThatDeclaredIt() {
        JsonObject declared = walledIn.stream().filter(l -> l.getAsJsonArray("events").toString().contains("\"checkpointUnreachable\""))
                .findFirst().orElseThrow(() -> new AssertionError("the walled-in mission declares a checkpoint unreachable"));
        assertThat(declared.getAsJsonArray("events").toString()).contains("{\"type\":\"checkpointUnreachable\",\"index\":1}");
        assertThat(declared.get("reason").getAsString()).startsWith("no route to checkpoint 2 (index 1) at (0.00, 0.75)");
        open(walledInPage, "#iteration=" + walledIn.get(0).get("iteration").getAsLong());
        Select kind = new Select(browser.driver().findElement(By.id("event-kind")));
        // every kind of event in the trace has a jump
        List<String> offered = kind.getOptions().stream().map(o -> o.getAttribute("value")).toList();
        walledIn.stream().flatMap(l -> l.getAsJsonArray("events").asList().stream())
                .map(e -> e.getAsJsonObject().get("type").getAsString()).distinct()
                .forEach(type -> assertThat(offered).contains(type));
        kind.selectByValue("checkpointUnreachable");
        browser.driver().findElement(By.id("next-event")).click();
        long n = declared.get("iteration").getAsLong();
        assertThat(stepInfo()).startsWith("iteration " + n + "\n").contains("reason " + declared.get("reason").getAsString())
                .contains("checkpoint 2 declared unreachable");
        assertThat(browser.driver().getCurrentUrl()).endsWith("#iteration=" + n);
    }

    @Test
    void theBelievedPoseAndTheRouteAreThoseOfTheTrace() {
        JsonObject line = walledIn.get(walledIn.size() / 4);
        long n = line.get("iteration").getAsLong();
        JsonObject belief = null;
        for (JsonObject l : walledIn) {
            if (l.get("iteration").getAsLong() > n) {
                break;
            }
            if (l.has("belief")) {
                belief = l.getAsJsonObject("belief"); // carried forward
            }
        }
        assertThat(belief).isNotNull();
        open(walledInPage, "#iteration=" + n);
        @SuppressWarnings("unchecked")
        List<Number> shown = (List<Number>) browser.js("return window.replay.belief()");
        assertThat(shown.get(0).doubleValue()).isEqualTo(belief.get("xM").getAsDouble());
        assertThat(shown.get(1).doubleValue()).isEqualTo(belief.get("yM").getAsDouble());
        assertThat(shown.get(2).doubleValue()).isEqualTo(belief.get("headingRad").getAsDouble());
        assertThat(stepInfo()).contains("believed x " + String.format(java.util.Locale.ROOT, "%.3f", belief.get("xM").getAsDouble()));
    }

    @Test
    void aPageOfAnOlderTraceWithoutTheBeliefStillReplays() throws IOException {
        String html = Files.readString(referencePage);
        String mark = "<script id=\"replay-data\" type=\"application/json\">";
        int from = html.indexOf(mark) + mark.length();
        JsonObject data = JsonParser.parseString(html.substring(from, html.indexOf("</script>", from))).getAsJsonObject();
        JsonObject steps = data.getAsJsonObject("steps");
        for (String field : List.of("beliefX", "beliefY", "beliefHeading", "routes", "mapDeltas", "reasons")) {
            assertThat(steps.remove(field)).as(field).isNotNull();
        }
        Path old = dir.resolve("old-replay.html");
        Files.writeString(old, ReplayPage.html(data));
        browser.consoleErrors();
        long n = reference.get(reference.size() / 2).get("iteration").getAsLong();
        open(old, "#iteration=" + n);
        assertThat(stepInfo()).startsWith("iteration " + n + "\n").contains("scan m ").doesNotContain("believed");
        for (String toggle : List.of("show-map", "show-route", "show-belief")) {
            browser.driver().findElement(By.id(toggle)).click();
            assertThat(browser.driver().findElement(By.id(toggle)).findElement(By.xpath("..")).getAttribute("class"))
                    .isEqualTo("absent");
        }
        browser.driver().findElement(By.id("next-event")).click();
        browser.driver().findElement(By.id("play")).click();
        browser.driver().findElement(By.id("play")).click();
        assertThat(browser.consoleErrors()).as("console errors").isEmpty();
    }
}
