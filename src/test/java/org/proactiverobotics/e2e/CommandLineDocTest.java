package org.proactiverobotics.e2e;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * docs/command-line.md shows each command's {@code --help} verbatim: every such block must be what
 * the command prints today, and every command must have one, so the manual cannot drift.
 */
class CommandLineDocTest extends CommandLineTest {

    private static final String PROMPT = "$ java -jar app/target/proactive.jar ";

    @Test
    void everyHelpBlockIsWhatTheCommandPrints() throws IOException {
        List<String> lines = Files.readAllLines(Deployment.root().resolve("docs/command-line.md"));
        List<String> shown = new ArrayList<>();
        for (int i = 0; i < lines.size(); i++) {
            String line = lines.get(i);
            if (!line.startsWith(PROMPT) || !line.endsWith(" --help")) {
                continue; // --version differs in the jar (its manifest) from the test's classes
            }
            String[] args = line.substring(PROMPT.length()).trim().split(" ");
            StringBuilder expected = new StringBuilder();
            for (int j = i + 1; j < lines.size() && !lines.get(j).startsWith("$ ") && !lines.get(j).startsWith("```"); j++) {
                expected.append(lines.get(j).stripTrailing()).append('\n');
            }
            out.getBuffer().setLength(0);
            assertThat(run(args)).as(line).isZero();
            String printed = out.toString().lines().map(String::stripTrailing).reduce("", (a, b) -> a + b + "\n");
            assertThat(expected.toString()).as("docs/command-line.md: the output of `%s`", line.substring(2)).isEqualTo(printed);
            shown.add(String.join(" ", Arrays.copyOf(args, args.length - 1)));
        }
        out.getBuffer().setLength(0);
        run("--help");
        for (String command : out.toString().split("Commands:")[1].lines()
                .filter(l -> l.matches("  [a-z].*")).map(l -> l.strip().split(" ")[0]).toList()) { // not the wrapped lines
            if (command.equals("help")) {
                continue;
            }
            assertThat(shown).as("docs/command-line.md shows `%s --help`", command)
                    .anySatisfy(s -> assertThat(s).startsWith(command));
        }
    }
}
