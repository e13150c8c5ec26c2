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
 * A user's clone holds only the repository: no Markdown or Java file may send the reader outside it (the
 * team's design notes, a copy of the paper), and every relative Markdown link must lead to a file or folder
 * that exists.
 */
class NoOutsideLinksTest {

    /** Text that points at the team's notes outside the repository; split so that a grep finds no such text here. */
    private static final String SHARED = "shared" + "/";
    private static final String DESIGN = "DES" + "IGN";
    private static final List<String> OUTSIDE = List.of("../" + SHARED, SHARED + DESIGN, DESIGN + ".md", DESIGN + " section");
    /** A Markdown link or image: [text](target) or ![alt](target), the target up to a space or ')'. */
    private static final Pattern LINK = Pattern.compile("!?\\[[^\\]]*]\\(([^)\\s]+)(?:\\s+\"[^\"]*\")?\\)");
    private static final Pattern FENCE = Pattern.compile("(?ms)^```.*?^```");

    private static List<Path> files(String suffix) throws IOException {
        Path root = Deployment.root();
        try (Stream<Path> walk = Files.walk(root)) {
            return walk.filter(p -> p.toString().endsWith(suffix) && Files.isRegularFile(p))
                    .filter(p -> {
                        for (Path part : root.relativize(p)) {
                            String name = part.toString();
                            // node_modules: the MCAP reference reader's installed packages, not ours
                            if (name.equals("target") || name.equals("node_modules") || name.startsWith(".")) {
                                return false;
                            }
                        }
                        return true;
                    })
                    .sorted().toList();
        }
    }

    @Test
    void noMarkdownOrJavaFilePointsOutsideTheRepository() throws IOException {
        List<Path> files = new ArrayList<>(files(".md"));
        files.addAll(files(".java"));
        assertThat(files).as("the walk finds the project's files").hasSizeGreaterThan(100);
        List<String> found = new ArrayList<>();
        for (Path file : files) {
            List<String> lines = Files.readAllLines(file);
            for (int i = 0; i < lines.size(); i++) {
                for (String outside : OUTSIDE) {
                    if (lines.get(i).contains(outside)) {
                        found.add(Deployment.root().relativize(file) + ":" + (i + 1) + ": " + lines.get(i).strip());
                    }
                }
            }
        }
        assertThat(found).as("references outside the repository (cite docs/ pages or the paper instead)").isEmpty();
    }

    @Test
    void everyRelativeMarkdownLinkLeadsToAFileOfTheRepository() throws IOException {
        Path root = Deployment.root();
        List<String> broken = new ArrayList<>();
        int checked = 0;
        for (Path file : files(".md")) {
            String text = FENCE.matcher(Files.readString(file)).replaceAll("");
            Matcher m = LINK.matcher(text);
            while (m.find()) {
                String target = m.group(1);
                if (target.matches("[a-zA-Z][a-zA-Z0-9+.-]*:.*") || target.startsWith("#")) {
                    continue; // a URL (http:, mailto:) or an anchor of the same page
                }
                String path = target.replaceAll("#.*$", "");
                Path resolved = file.getParent().resolve(path).normalize();
                checked++;
                if (!resolved.startsWith(root) || !Files.exists(resolved)) {
                    broken.add(root.relativize(file) + ": (" + target + ")");
                }
            }
        }
        assertThat(checked).as("links checked").isGreaterThan(20);
        assertThat(broken).as("Markdown links to nothing in the repository").isEmpty();
    }
}
