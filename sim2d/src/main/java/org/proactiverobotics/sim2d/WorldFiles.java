package org.proactiverobotics.sim2d;

import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.UncheckedIOException;
import java.net.JarURLConnection;
import java.net.URISyntaxException;
import java.net.URL;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Enumeration;
import java.util.List;
import java.util.Properties;
import java.util.TreeSet;
import java.util.jar.JarEntry;
import java.util.jar.JarFile;
import java.util.stream.Stream;

/**
 * Loads and validates world files (docs/world-file.md): from disk, from a string, or bundled in the jar
 * (the project's {@code worlds/*.json}, packaged as resources under {@code worlds/}).
 * Every invalid input ends in a {@link WorldValidationException} listing all its problems.
 */
public final class WorldFiles {

    /** The world {@code run} uses when given none. */
    public static final String DEFAULT_WORLD = "reference-arena";

    private static final String RESOURCE_DIR = "worlds/";
    private static final String DESCRIPTIONS = "descriptions.properties";

    private WorldFiles() {
    }

    /**
     * @param file a world file
     * @return the validated world
     * @throws WorldValidationException when the file cannot be read or is invalid
     */
    public static WorldSpec load(Path file) {
        String json;
        try {
            json = Files.readString(file, StandardCharsets.UTF_8);
        } catch (IOException | UncheckedIOException e) {
            throw new WorldValidationException(file.toString(),
                    List.of("(file): cannot read " + file + ": " + describe(e)));
        }
        Path dir = file.toAbsolutePath().getParent();
        return new WorldParser(dir).parse(json, file.toString());
    }

    /**
     * @param json a world file's text
     * @return the validated world
     * @throws WorldValidationException when the text is invalid
     */
    public static WorldSpec parse(String json) {
        return parse(json, "<string>");
    }

    /**
     * @param json   a world file's text
     * @param source what the text came from, for messages (a {@code map} file name is relative to the working directory)
     * @return the validated world
     * @throws WorldValidationException when the text is invalid
     */
    public static WorldSpec parse(String json, String source) {
        return new WorldParser(null).parse(json, source);
    }

    /**
     * @param json    a world file's text
     * @param source  what the text came from, for messages
     * @param baseDir the folder a {@code map} file name is relative to (the world file's)
     * @return the validated world, a named map's walls among its obstacles
     * @throws WorldValidationException when the text is invalid
     */
    public static WorldSpec parse(String json, String source, Path baseDir) {
        return new WorldParser(baseDir).parse(json, source);
    }

    /**
     * @param name a bundled world's name, such as {@code reference-arena} ({@code .json} optional)
     * @return the validated world
     * @throws IllegalArgumentException when no such world is bundled
     */
    public static WorldSpec bundled(String name) {
        String base = name.endsWith(".json") ? name.substring(0, name.length() - 5) : name;
        String resource = RESOURCE_DIR + base + ".json";
        try (InputStream in = WorldFiles.class.getClassLoader().getResourceAsStream(resource)) {
            if (in == null) {
                throw new IllegalArgumentException("no bundled world \"" + base + "\"; bundled: " + bundledNames());
            }
            return parse(new String(in.readAllBytes(), StandardCharsets.UTF_8), "bundled:" + resource);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read bundled world " + resource, e);
        }
    }

    /**
     * @param name a bundled world's name
     * @return one line of what the world is for (from {@code worlds/descriptions.properties}), or "" when it has none
     */
    public static String description(String name) {
        Properties descriptions = new Properties();
        try (InputStream in = WorldFiles.class.getClassLoader().getResourceAsStream(RESOURCE_DIR + DESCRIPTIONS)) {
            if (in != null) {
                descriptions.load(new InputStreamReader(in, StandardCharsets.UTF_8));
            }
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read " + RESOURCE_DIR + DESCRIPTIONS, e);
        }
        return descriptions.getProperty(name, "");
    }

    /** @return the default world, {@value #DEFAULT_WORLD} */
    public static WorldSpec defaultWorld() {
        return bundled(DEFAULT_WORLD);
    }

    /** @return the names of the bundled worlds, sorted */
    public static List<String> bundledNames() {
        URL anchor = WorldFiles.class.getClassLoader().getResource(RESOURCE_DIR + DEFAULT_WORLD + ".json");
        if (anchor == null) {
            return List.of();
        }
        TreeSet<String> names = new TreeSet<>();
        try {
            if ("jar".equals(anchor.getProtocol())) {
                JarURLConnection connection = (JarURLConnection) anchor.openConnection();
                connection.setUseCaches(false);
                try (JarFile jar = connection.getJarFile()) {
                    Enumeration<JarEntry> entries = jar.entries();
                    while (entries.hasMoreElements()) {
                        String entry = entries.nextElement().getName();
                        if (entry.startsWith(RESOURCE_DIR) && entry.endsWith(".json") && entry.indexOf('/', RESOURCE_DIR.length()) < 0) {
                            names.add(entry.substring(RESOURCE_DIR.length(), entry.length() - 5));
                        }
                    }
                }
            } else {
                try (Stream<Path> files = Files.list(Path.of(anchor.toURI()).getParent())) {
                    files.map(p -> p.getFileName().toString()).filter(f -> f.endsWith(".json"))
                            .forEach(f -> names.add(f.substring(0, f.length() - 5)));
                }
            }
        } catch (IOException | URISyntaxException e) {
            throw new IllegalStateException("cannot list bundled worlds at " + anchor, e);
        }
        return new ArrayList<>(names);
    }

    private static String describe(Exception e) {
        Throwable t = e instanceof UncheckedIOException u ? u.getCause() : e;
        String type = t.getClass().getSimpleName();
        if (t instanceof java.nio.file.NoSuchFileException) {
            return "no such file";
        }
        return t.getMessage() == null ? type : type + ": " + t.getMessage();
    }
}
