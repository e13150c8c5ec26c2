package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * The tutorial (docs/writing-a-scenario.md) shows the example project's code, which .ci/run builds,
 * tests and runs in a mission as a user would: every Java block of the tutorial is one of the
 * example's files, word for word, and its pom names the same dependencies.
 */
class TutorialTest {

    private static final Path ROOT = Deployment.root();
    private static final Pattern BLOCK = Pattern.compile("(?m)^```(java|xml)\\n(.*?)^```", Pattern.DOTALL);

    @Test
    void everyJavaBlockOfTheTutorialIsAFileOfTheExampleProject() throws IOException {
        String tutorial = Files.readString(ROOT.resolve("docs/writing-a-scenario.md"));
        List<String> files = new ArrayList<>();
        try (Stream<Path> walk = Files.walk(ROOT.resolve("examples/scenario-example/src"))) {
            for (Path p : walk.filter(f -> f.toString().endsWith(".java")).toList()) {
                files.add(Files.readString(p).strip());
            }
        }
        Matcher m = BLOCK.matcher(tutorial);
        int java = 0;
        while (m.find()) {
            if (m.group(1).equals("java")) {
                String block = m.group(2).strip();
                assertThat(files).as("a Java block of the tutorial that is no file of examples/scenario-example:\n" + block)
                        .contains(block);
                java++;
            } else {
                for (String dependency : List.of("<artifactId>engine</artifactId>", "<artifactId>scenario-testkit</artifactId>",
                        "<scope>provided</scope>", "<artifactId>junit-jupiter</artifactId>")) {
                    assertThat(m.group(2)).contains(dependency);
                    assertThat(Files.readString(ROOT.resolve("examples/scenario-example/pom.xml"))).contains(dependency);
                }
            }
        }
        assertThat(java).as("the scenario, its rule and its test").isGreaterThanOrEqualTo(3);
        assertThat(Files.readString(ROOT.resolve("examples/scenario-example/src/main/resources/" + PluginJars.SERVICES)))
                .contains("com.example.governor.SpeedGovernorScenario");
    }
}
