package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.openqa.selenium.By;
import org.openqa.selenium.support.ui.WebDriverWait;

/**
 * {@code watch} as the compose file's watch service runs it, as the SELECT-only viewer user, on
 * MariaDB: the page says the robot is awaited, then follows a two-process mission as it runs, in
 * a real Chromium; it serves GET and refuses what would write.
 */
class WatchBrowserTest {

    private static final Pattern LISTENING = Pattern.compile("http://127\\.0\\.0\\.1:(\\d+)/");

    @TempDir
    static Path tmp;
    private static Deployment deployment;
    private static Browser browser;

    @BeforeAll
    static void deploy() throws Exception {
        Browser.assumeInstalled();
        deployment = Deployment.create();
        browser = Browser.start();
    }

    @AfterAll
    static void tearDown() throws Exception {
        if (browser != null) {
            browser.close();
        }
        if (deployment != null) {
            deployment.close();
        }
    }

    @Test
    void theLiveViewWaitsForTheMissionThenFollowsItAsItRuns() throws Exception {
        Path watchLog = tmp.resolve("watch.log");
        deployment.start("watch", Map.of("--bind", "127.0.0.1", "--port", "0"), watchLog);
        Deployment.awaitLog(watchLog, "Watching robot 1: http://127.0.0.1:", 60);
        Matcher m = LISTENING.matcher(Files.readString(watchLog));
        assertThat(m.find()).isTrue();
        String base = "http://127.0.0.1:" + m.group(1) + "/";
        browser.consoleErrors();
        browser.driver().get(base);
        WebDriverWait wait = new WebDriverWait(browser.driver(), Duration.ofSeconds(60));
        wait.until(d -> stepInfo().startsWith("waiting for the mission"));

        Path engineLog = tmp.resolve("engine.log");
        deployment.start("engine", Map.of("--heartbeat", tmp.resolve("engine.beat").toString()), engineLog);
        Deployment.awaitLog(engineLog, "waiting for the robot", 30);
        deployment.start("robot", Map.of("--out", tmp.resolve("out").toString(),
                "--heartbeat", tmp.resolve("robot.beat").toString()), tmp.resolve("robot.log"));

        wait.until(d -> stepInfo().startsWith("iteration "));
        long first = shownIteration();
        wait.until(d -> shownIteration() > first + 20);
        assertThat(stepInfo()).contains("simTimeS ").contains("winner ").contains("command ");
        assertThat(browser.consoleErrors()).as("console errors").isEmpty();

        HttpClient http = HttpClient.newHttpClient();
        HttpResponse<String> steps = http.send(HttpRequest.newBuilder(URI.create(base + "steps?from=0")).build(),
                HttpResponse.BodyHandlers.ofString());
        assertThat(steps.statusCode()).isEqualTo(200);
        assertThat(steps.body()).contains("\"iteration\":[").contains("\"winner\":[");
        HttpResponse<String> post = http.send(HttpRequest.newBuilder(URI.create(base + "steps"))
                .POST(HttpRequest.BodyPublishers.ofString("x")).build(), HttpResponse.BodyHandlers.ofString());
        assertThat(post.statusCode()).isEqualTo(405);
        assertThat(Files.readString(watchLog)).doesNotContain("denied");
    }

    private static String stepInfo() {
        return browser.driver().findElement(By.id("step-info")).getText();
    }

    private static long shownIteration() {
        String info = stepInfo();
        if (!info.startsWith("iteration ")) {
            return -1;
        }
        return Long.parseLong(info.substring("iteration ".length(), info.indexOf('\n')));
    }
}
