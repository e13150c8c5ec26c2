package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.io.Reader;
import java.io.StringReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Base64;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.Predicate;
import javax.xml.parsers.DocumentBuilderFactory;
import org.apache.commons.csv.CSVFormat;
import org.apache.commons.csv.CSVRecord;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.openqa.selenium.By;
import org.openqa.selenium.Dimension;
import org.openqa.selenium.WebElement;
import org.proactiverobotics.app.generate.WorldGenerator;
import org.proactiverobotics.app.sweep.SummaryHtml;
import org.proactiverobotics.app.sweep.WorldJson;
import org.proactiverobotics.sim2d.WorldSpec;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.NodeList;
import org.xml.sax.InputSource;

/**
 * summary.html, as `sweep` writes it, in a real (headless) Chromium, checked against the sweep's
 * own results.csv: its success rates are k/n with the Wilson interval of the CSV's counts, its
 * times and distances are over the accomplished missions, a chart's link saves it as a standalone
 * SVG, the page fits a 1 280 px window with its reason column in view (a long reason too), the
 * missions' table sorts and filters, and a failed mission's outcome opens its replay.
 */
class SummaryBrowserTest extends CommandLineTest {

    private static final String SVG_NS = "http://www.w3.org/2000/svg";
    /** The standard normal quantile of 0.975, as any table gives it. */
    private static final double Z = 1.959963984540054;

    @TempDir
    static Path dir;
    private static Browser browser;
    private static Path out;
    private static List<CSVRecord> results;

    @BeforeAll
    static void sweepAndOpenABrowser() throws IOException {
        Browser.assumeInstalled();
        // a world generate draws (so of a known kind, battery), its time limit cut to 3 s so that every mission on it fails
        WorldSpec drawn = new WorldGenerator(WorldGenerator.Kind.BATTERY).world(1, 1);
        WorldSpec cut = new WorldSpec(drawn.name(), drawn.timeStepMs(), 3.0, drawn.seed(), drawn.arena(), drawn.robot(),
                drawn.obstacles(), drawn.checkpoints(), drawn.checkpointRadiusM(), drawn.rechargeStation(), drawn.battery());
        Path worlds = Files.createDirectories(dir.resolve("worlds"));
        Files.writeString(worlds.resolve(cut.name() + ".json"), WorldJson.of(cut));
        out = dir.resolve("sweep");
        SummaryBrowserTest cli = new SummaryBrowserTest();
        assertThat(cli.run("sweep", "--worlds", "reference-arena", worlds.toString(), "--noise", "none,small",
                "--strategies", "safety-first,destination-first", "--link", "direct", "--out", out.toString()))
                .as(cli.err.toString()).isEqualTo(1);
        try (Reader in = Files.newBufferedReader(out.resolve("results.csv"), StandardCharsets.UTF_8)) {
            results = CSVFormat.DEFAULT.builder().setHeader().setSkipHeaderRecord(true).get().parse(in).getRecords();
        }
        assertThat(results).hasSize(8).anyMatch(r -> r.get("success").equals("true")).anyMatch(r -> r.get("success").equals("false"));
        browser = Browser.start();
    }

    @BeforeEach
    void openTheSummaryAfresh() {
        browser.driver().manage().window().setSize(new Dimension(1280, 900));
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
    void theSummarysIntervalsAreTheWilsonIntervalOfTheCsvsCounts() {
        List<WebElement> rows = browser.driver().findElements(By.cssSelector("#strategy-noise tbody tr"));
        assertThat(rows).hasSize(2 * 2);
        for (WebElement row : rows) {
            List<String> factors = texts(row, "td.factor");
            List<CSVRecord> group = csv(r -> r.get("strategy").equals(factors.get(0)) && r.get("noise").equals(factors.get(1)));
            assertShowsWilson(row, group);
        }
        // and cut by world kind too: battery-001 is generate's (kind battery), reference-arena has none
        rows = browser.driver().findElements(By.cssSelector("#strategy-noise-kind tbody tr"));
        assertThat(rows).hasSize(2 * 2 * 2);
        for (WebElement row : rows) {
            List<String> factors = texts(row, "td.factor");
            List<CSVRecord> group = csv(r -> r.get("strategy").equals(factors.get(0)) && r.get("noise").equals(factors.get(1))
                    && kindOf(r).equals(factors.get(2)));
            assertThat(group).as(factors.toString()).hasSize(1);
            assertShowsWilson(row, group);
        }
        List<String> kinds = browser.driver().findElements(By.cssSelector("#by-factor tbody tr")).stream()
                .map(r -> texts(r, "td.factor")).filter(f -> f.get(0).equals("world kind")).map(f -> f.get(1)).toList();
        assertThat(kinds).containsExactly("—", "battery");
        assertThat(browser.consoleErrors()).isEmpty();
    }

    @Test
    void timesAndDistancesAreMeansOverTheAccomplishedMissionsOnly() {
        assertThat(browser.driver().findElement(By.cssSelector("#strategy-noise thead")).getText())
                .contains("accomplished missions only");
        for (WebElement row : browser.driver().findElements(By.cssSelector("#strategy-noise tbody tr"))) {
            List<String> factors = texts(row, "td.factor");
            List<CSVRecord> accomplished = csv(r -> r.get("strategy").equals(factors.get(0))
                    && r.get("noise").equals(factors.get(1)) && r.get("success").equals("true"));
            List<CSVRecord> all = csv(r -> r.get("strategy").equals(factors.get(0)) && r.get("noise").equals(factors.get(1)));
            double time = mean(accomplished, "simTimeS");
            assertThat(time).as("the failed missions' times would change it").isNotEqualTo(mean(all, "simTimeS"));
            assertThat(row.findElement(By.cssSelector("td.time")).getText()).startsWith(String.format(Locale.ROOT, "%.1f", time));
            assertThat(row.findElement(By.cssSelector("td.distance")).getText())
                    .startsWith(String.format(Locale.ROOT, "%.1f", mean(accomplished, "distanceM")));
        }
    }

    @Test
    void aChartsLinkSavesItAsAStandaloneSvgWithTheChartsContent() throws Exception {
        List<WebElement> figures = browser.driver().findElements(By.cssSelector("#plots figure.plot"));
        assertThat(figures).hasSize(2 * 3); // success, time, distance; by strategy and noise, by world kind and strategy
        WebElement figure = browser.driver().findElement(By.id("success-by-strategy-noise"));
        @SuppressWarnings("unchecked")
        List<String> shown = (List<String>) browser.js(
                "return Array.from(arguments[0].querySelectorAll('svg text')).map(t => t.textContent)", figure);
        WebElement save = figure.findElement(By.cssSelector("a.save"));
        assertThat(save.getAttribute("href")).startsWith("data:image/svg+xml;base64,");
        assertThat(save.getAttribute("download")).isEqualTo("success-by-strategy-noise.svg");

        Path downloads = Files.createDirectories(dir.resolve("downloads"));
        browser.driver().executeCdpCommand("Browser.setDownloadBehavior",
                Map.of("behavior", "allow", "downloadPath", downloads.toString()));
        save.click();
        Path file = downloads.resolve("success-by-strategy-noise.svg");
        for (int i = 0; i < 200 && !Files.exists(file); i++) {
            Thread.sleep(50); // the download is written by the browser's own process
        }
        assertThat(file).exists();
        String saved = Files.readString(file, StandardCharsets.UTF_8);
        String linked = new String(Base64.getDecoder().decode(save.getAttribute("href").substring("data:image/svg+xml;base64,".length())),
                StandardCharsets.UTF_8);
        assertThat(saved).isEqualTo(linked);

        DocumentBuilderFactory factory = DocumentBuilderFactory.newInstance();
        factory.setNamespaceAware(true);
        Document svg = factory.newDocumentBuilder().parse(new InputSource(new StringReader(saved)));
        Element root = svg.getDocumentElement();
        assertThat(root.getNamespaceURI()).isEqualTo(SVG_NS);
        assertThat(root.getLocalName()).isEqualTo("svg");
        assertThat(root.getAttribute("width")).isNotEmpty();
        assertThat(root.getAttribute("viewBox")).isNotEmpty();
        assertThat(svg.getElementsByTagNameNS("*", "style").getLength()).as("no stylesheet to lose").isZero();
        assertThat(saved).doesNotContain("class=", "href=", "url(");
        NodeList texts = svg.getElementsByTagNameNS(SVG_NS, "text");
        List<String> savedTexts = new ArrayList<>();
        for (int i = 0; i < texts.getLength(); i++) {
            savedTexts.add(texts.item(i).getTextContent());
        }
        assertThat(savedTexts).isEqualTo(shown).contains("Success rate by strategy and noise", "safety-first",
                "destination-first", "none", "small");
        assertThat(svg.getElementsByTagNameNS(SVG_NS, "rect").getLength()).as("background and 4 bars").isEqualTo(5);
        for (String strategy : List.of("safety-first", "destination-first")) {
            for (String noise : List.of("none", "small")) {
                List<CSVRecord> group = csv(r -> r.get("strategy").equals(strategy) && r.get("noise").equals(noise));
                long k = group.stream().filter(r -> r.get("success").equals("true")).count();
                assertThat(savedTexts).anyMatch(t -> t.startsWith(k + "/" + group.size() + " "));
            }
        }
        assertThat(browser.consoleErrors()).isEmpty();
    }

    @Test
    void fitsA1280PxWindowWithTheReasonColumnInView() {
        assertFitsWithReasonsInView();
    }

    @Test
    void aLongReasonWrapsInsteadOfWideningThePage() throws IOException {
        String reason = "UncheckedIOException: /srv/experiments/2026/a-very-long-folder-name-without-any-space/"
                + "mission-0001-with-a-name-that-goes-on/and-on/".repeat(4) + "report.json (No space left on device)";
        List<SummaryHtml.Row> rows = new ArrayList<>();
        for (CSVRecord r : results) {
            String folder = r.get("mission");
            rows.add(new SummaryHtml.Row(Integer.parseInt(folder.substring(0, folder.indexOf('-'))), r.get("world"),
                    r.get("strategy"), r.get("noise"), Long.parseLong(r.get("seed")), r.get("success").equals("true") ? r.get("outcome") : "ERROR",
                    r.get("success").equals("true"), r.get("checkpointsReached") + "/" + r.get("checkpointsTotal"),
                    Double.parseDouble(r.get("simTimeS")), Double.parseDouble(r.get("wallTimeS")), Double.parseDouble(r.get("distanceM")),
                    Integer.parseInt(r.get("collisions")), Double.parseDouble(r.get("minBattery")), Integer.parseInt(r.get("recharges")),
                    r.get("success").equals("true") ? "" : reason, null));
        }
        Path page = Files.createDirectories(dir.resolve("long")).resolve("summary.html");
        SummaryHtml.writeRows(rows, "8 missions, their failures given a long reason", page);
        browser.driver().get(page.toUri().toString());
        assertFitsWithReasonsInView();
        WebElement cell = browser.driver().findElements(By.cssSelector("#missions td.reason")).stream()
                .filter(td -> !td.getText().isEmpty()).findFirst().orElseThrow();
        assertThat(cell.getText().replaceAll("\\s", "")).isEqualTo(reason.replaceAll("\\s", ""));
        assertThat(cell.getSize().getHeight()).as("wrapped over several lines").isGreaterThan(3 * 12);
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

    /** The page has no horizontal overflow, and every reason cell (and its heading) lies within the window, not squeezed away. */
    private static void assertFitsWithReasonsInView() {
        @SuppressWarnings("unchecked")
        Map<String, Object> sizes = (Map<String, Object>) browser.js("const d = document.documentElement;"
                + " return {scroll: d.scrollWidth, client: d.clientWidth, inner: window.innerWidth};");
        assertThat(((Number) sizes.get("inner")).intValue()).as("the window").isEqualTo(1280);
        assertThat(((Number) sizes.get("scroll")).intValue()).as("no horizontal scroll: %s", sizes)
                .isLessThanOrEqualTo(((Number) sizes.get("client")).intValue());
        @SuppressWarnings("unchecked")
        List<Map<String, Object>> cells = (List<Map<String, Object>>) browser.js("const heads = Array.from(document.querySelectorAll('#missions th'));"
                + " const i = heads.findIndex(th => th.textContent === 'reason');"
                + " return [heads[i], ...document.querySelectorAll('#missions td.reason')].map(e => { const r = e.getBoundingClientRect();"
                + " return {left: r.left, right: r.right, width: r.width, overflow: e.scrollWidth - e.clientWidth}; });");
        int client = ((Number) sizes.get("client")).intValue();
        assertThat(cells).hasSize(results.size() + 1).allSatisfy(c -> {
            assertThat(((Number) c.get("left")).doubleValue()).isGreaterThanOrEqualTo(0);
            assertThat(((Number) c.get("right")).doubleValue()).isLessThanOrEqualTo(client);
            assertThat(((Number) c.get("width")).doubleValue()).as("room for words").isGreaterThan(100);
            assertThat(((Number) c.get("overflow")).intValue()).as("nothing cut off within the cell").isLessThanOrEqualTo(0);
        });
    }

    /** Checks a group's row shows k/n, the rate and the Wilson interval of the CSV rows given. */
    private static void assertShowsWilson(WebElement row, List<CSVRecord> group) {
        int n = group.size();
        long k = group.stream().filter(r -> r.get("success").equals("true")).count();
        // Wilson's score interval in its textbook form: (k + z²/2 ± z √(k(n-k)/n + z²/4)) / (n + z²)
        double centre = k + Z * Z / 2;
        double half = Z * Math.sqrt(k * (double) (n - k) / n + Z * Z / 4);
        double low = k == 0 ? 0 : (centre - half) / (n + Z * Z);
        double high = k == n ? 1 : (centre + half) / (n + Z * Z);
        assertThat(row.findElement(By.cssSelector("td.count")).getText()).isEqualTo(k + "/" + n);
        assertThat(row.findElement(By.cssSelector("td.percent")).getText()).isEqualTo(pct((double) k / n));
        assertThat(row.findElement(By.cssSelector("td.interval")).getText()).isEqualTo(pct(low) + "–" + pct(high));
    }

    private static String pct(double fraction) {
        return String.format(Locale.ROOT, "%.1f", 100 * fraction);
    }

    /** A world's kind as the test knows it: the battery world is generate's, the bundled reference arena has none. */
    private static String kindOf(CSVRecord r) {
        return r.get("world").equals("battery-001") ? "battery" : "—";
    }

    private static List<CSVRecord> csv(Predicate<CSVRecord> which) {
        return results.stream().filter(which).toList();
    }

    private static double mean(List<CSVRecord> rows, String column) {
        return rows.stream().mapToDouble(r -> Double.parseDouble(r.get(column))).average().orElseThrow();
    }

    private static List<String> texts(WebElement row, String css) {
        return row.findElements(By.cssSelector(css)).stream().map(WebElement::getText).toList();
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
