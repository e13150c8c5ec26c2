package org.proactiverobotics.engine.robot;

import java.io.IOException;
import java.net.MalformedURLException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.CodeSource;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.ServiceConfigurationError;
import java.util.ServiceLoader;
import java.util.Set;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import java.util.zip.ZipFile;
import org.proactiverobotics.engine.Scenario;

/**
 * Scenarios from outside the project: jars built against the engine alone, each listing its
 * {@link Scenario} classes in {@code META-INF/services/org.proactiverobotics.engine.Scenario}.
 * They load in a class loader of their own (the engine's is its parent), in the order the jars
 * are given, and are checked at once, so that a bad plug-in is refused before anything runs.
 */
public final class ScenarioPlugins {

    private static final String SERVICE_FILE = "META-INF/services/" + Scenario.class.getName();
    private static final Pattern NAME = Pattern.compile("[A-Za-z][A-Za-z0-9_-]{0,63}");
    private static final ScenarioPlugins NONE = new ScenarioPlugins(List.of(), Map.of(), ScenarioPlugins.class.getClassLoader());

    private final List<Path> jars;
    private final Map<String, Scenario> scenarios;
    private final ClassLoader classLoader;

    private ScenarioPlugins(List<Path> jars, Map<String, Scenario> scenarios, ClassLoader classLoader) {
        this.jars = List.copyOf(jars);
        this.scenarios = Collections.unmodifiableMap(scenarios);
        this.classLoader = classLoader;
    }

    /** @return no plug-ins */
    public static ScenarioPlugins none() {
        return NONE;
    }

    /**
     * Scenarios given as objects, as plug-ins: a test of a scenario, or an application that
     * embeds the engine.
     *
     * @param scenarios the scenarios, in start order
     * @return them as plug-ins (their classes load with their own class loader)
     * @throws PluginException for a bad name, a built-in name or two scenarios of one name
     */
    public static ScenarioPlugins of(Scenario... scenarios) {
        Map<String, Scenario> byName = new LinkedHashMap<>();
        Set<String> builtIn = RobotEngine.builtInScenarios();
        Path none = Path.of("(given)");
        for (Scenario s : scenarios) {
            String name = nameOf(s, none);
            if (builtIn.contains(name) || byName.put(name, s) != null) {
                throw new PluginException("scenario '" + name + "' (" + s.getClass().getName()
                        + ") has the name of a built-in scenario or of another one given");
            }
        }
        ClassLoader loader = scenarios.length == 0 ? ScenarioPlugins.class.getClassLoader()
                : scenarios[0].getClass().getClassLoader();
        return new ScenarioPlugins(List.of(), byName, loader);
    }

    /**
     * Loads the scenarios of jars and folders of jars.
     *
     * @param paths   jars, or folders whose {@code *.jar} files are taken in name order
     * @param builtIn the names of the built-in scenarios, which no plug-in may take
     * @return the plug-ins, their scenarios in the order given
     * @throws PluginException naming the path, the class or the scenario: a path that is missing or
     *                         not a jar, a folder without jars, a jar that lists no scenario, a class
     *                         that cannot be loaded or built, a bad or duplicate scenario name
     */
    public static ScenarioPlugins load(List<Path> paths, Set<String> builtIn) {
        if (paths.isEmpty()) {
            return NONE;
        }
        List<Path> jars = jars(paths);
        URL[] urls = new URL[jars.size()];
        for (int i = 0; i < urls.length; i++) {
            try {
                urls[i] = jars.get(i).toUri().toURL();
            } catch (MalformedURLException e) {
                throw new PluginException(jars.get(i) + ": not a usable path: " + e.getMessage());
            }
        }
        URLClassLoader loader = new URLClassLoader("scenario-plugins", urls, ScenarioPlugins.class.getClassLoader());
        Map<Path, List<Scenario>> byJar = new LinkedHashMap<>();
        jars.forEach(jar -> byJar.put(jar, new ArrayList<>()));
        try {
            for (ServiceLoader.Provider<Scenario> provider : ServiceLoader.load(Scenario.class, loader).stream().toList()) {
                Class<? extends Scenario> type = provider.type();
                if (type.getClassLoader() != loader) {
                    continue; // a built-in scenario, seen through the parent
                }
                Path jar = jarOf(type, jars);
                Scenario scenario;
                try {
                    scenario = provider.get();
                } catch (ServiceConfigurationError | RuntimeException | LinkageError e) {
                    throw new PluginException(jar + ": scenario class " + type.getName() + " cannot be built: " + cause(e));
                }
                byJar.get(jar).add(scenario);
            }
        } catch (ServiceConfigurationError | LinkageError e) {
            throw new PluginException("a scenario listed in " + SERVICE_FILE + " of " + jars + " cannot be loaded: " + cause(e));
        }
        Map<String, Scenario> scenarios = new LinkedHashMap<>();
        Map<String, Path> from = new LinkedHashMap<>();
        for (Map.Entry<Path, List<Scenario>> e : byJar.entrySet()) {
            if (e.getValue().isEmpty()) {
                throw new PluginException(e.getKey() + ": " + whyEmpty(e.getKey(), byJar));
            }
            for (Scenario s : e.getValue()) {
                String name = nameOf(s, e.getKey());
                if (builtIn.contains(name)) {
                    throw new PluginException(e.getKey() + ": scenario '" + name + "' (" + s.getClass().getName()
                            + ") has the name of a built-in scenario; choose another name");
                }
                if (scenarios.containsKey(name)) {
                    throw new PluginException("two scenarios are named '" + name + "': " + scenarios.get(name).getClass().getName()
                            + " in " + from.get(name) + " and " + s.getClass().getName() + " in " + e.getKey());
                }
                scenarios.put(name, s);
                from.put(name, e.getKey());
            }
        }
        return new ScenarioPlugins(jars, scenarios, loader);
    }

    /** @return the jars loaded, in order */
    public List<Path> jars() {
        return jars;
    }

    /** @return the plug-in scenarios by name, in the order they start */
    public Map<String, Scenario> scenarios() {
        return scenarios;
    }

    /** @return the class loader of the plug-ins' classes (their rules are loaded back with it on a resume) */
    public ClassLoader classLoader() {
        return classLoader;
    }

    private static List<Path> jars(List<Path> paths) {
        List<Path> jars = new ArrayList<>();
        for (Path path : paths) {
            if (Files.isDirectory(path)) {
                List<Path> inFolder;
                try (Stream<Path> files = Files.list(path)) {
                    inFolder = files.filter(p -> p.getFileName().toString().endsWith(".jar") && Files.isRegularFile(p))
                            .sorted().toList();
                } catch (IOException e) {
                    throw new PluginException(path + ": folder cannot be read: " + e.getMessage());
                }
                if (inFolder.isEmpty()) {
                    throw new PluginException(path + ": folder holds no .jar file");
                }
                inFolder.forEach(jar -> jars.add(checkedJar(jar)));
            } else if (!Files.exists(path)) {
                throw new PluginException(path + ": no such file or folder");
            } else {
                jars.add(checkedJar(path));
            }
        }
        return jars;
    }

    private static Path checkedJar(Path path) {
        Path absolute = path.toAbsolutePath().normalize();
        try (ZipFile zip = new ZipFile(absolute.toFile())) {
            if (zip.getEntry(SERVICE_FILE) == null) {
                throw new PluginException(path + ": holds no scenario (no " + SERVICE_FILE + " in the jar)");
            }
        } catch (IOException e) {
            throw new PluginException(path + ": not a jar (" + e.getMessage() + ")");
        }
        return absolute;
    }

    /**
     * Why a jar yielded no scenario: most often its classes were already loaded from an earlier jar
     * (the same plug-in given twice, under two names), since a class is loaded once.
     */
    private static String whyEmpty(Path jar, Map<Path, List<Scenario>> byJar) {
        List<String> listed = new ArrayList<>();
        try (ZipFile zip = new ZipFile(jar.toFile())) {
            String text = new String(zip.getInputStream(zip.getEntry(SERVICE_FILE)).readAllBytes(), StandardCharsets.UTF_8);
            for (String line : text.split("\\R")) {
                String name = line.replaceFirst("#.*", "").strip();
                if (!name.isEmpty()) {
                    listed.add(name);
                }
            }
        } catch (IOException | RuntimeException e) {
            listed = List.of();
        }
        for (Map.Entry<Path, List<Scenario>> other : byJar.entrySet()) {
            for (Scenario s : other.getValue()) {
                if (listed.contains(s.getClass().getName())) {
                    return "its scenario class " + s.getClass().getName() + " is already loaded from " + other.getKey()
                            + " (a class is loaded once: give each plug-in jar once)";
                }
            }
        }
        return "holds no scenario (list its classes, which implement " + Scenario.class.getName() + ", in " + SERVICE_FILE + ")";
    }

    private static Path jarOf(Class<?> type, List<Path> jars) {
        CodeSource source = type.getProtectionDomain().getCodeSource();
        if (source != null) {
            try {
                Path location = Path.of(source.getLocation().toURI()).toAbsolutePath().normalize();
                if (jars.contains(location)) {
                    return location;
                }
            } catch (Exception e) {
                // fall through: attributed to the first jar below
            }
        }
        return jars.get(0);
    }

    private static String nameOf(Scenario s, Path jar) {
        String name;
        try {
            name = s.name();
        } catch (RuntimeException | LinkageError e) {
            throw new PluginException(jar + ": scenario class " + s.getClass().getName() + ": name() threw " + cause(e));
        }
        if (name == null || !NAME.matcher(name).matches()) {
            throw new PluginException(jar + ": scenario class " + s.getClass().getName() + " is named '" + name
                    + "': a scenario's name is a letter then up to 63 letters, digits, '-' or '_'");
        }
        return name;
    }

    /** The innermost cause, as "Type: message": what the plug-in's author needs, without the ServiceLoader wrapping. */
    private static String cause(Throwable e) {
        Throwable root = e;
        while (root.getCause() != null) {
            root = root.getCause();
        }
        String text = root.getClass().getSimpleName() + (root.getMessage() == null ? "" : ": " + root.getMessage());
        return root == e ? text : e.getMessage() + " (" + text + ")";
    }
}
