package org.proactiverobotics.e2e;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.jar.JarEntry;
import java.util.jar.JarOutputStream;
import java.util.stream.Stream;
import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;

/**
 * Builds real plug-in jars for tests, as a user's build would: Java sources compiled against the
 * engine (the test class path), packed with their META-INF/services list.
 */
final class PluginJars {

    static final String SERVICES = "META-INF/services/org.proactiverobotics.engine.Scenario";

    private PluginJars() {
    }

    /**
     * @param jar      the jar to write
     * @param sources  Java sources by fully qualified class name
     * @param services the scenario classes to list (null: no services file at all)
     * @return the jar
     */
    static Path build(Path jar, Map<String, String> sources, List<String> services) throws IOException {
        Path src = Files.createTempDirectory("plugin-src");
        Path classes = Files.createTempDirectory("plugin-classes");
        List<String> files = new ArrayList<>();
        for (Map.Entry<String, String> e : sources.entrySet()) {
            Path file = src.resolve(e.getKey().replace('.', '/') + ".java");
            Files.createDirectories(file.getParent());
            Files.writeString(file, e.getValue());
            files.add(file.toString());
        }
        if (!files.isEmpty()) {
            JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
            List<String> args = new ArrayList<>(List.of("--release", "17", "-cp", System.getProperty("java.class.path"),
                    "-d", classes.toString()));
            args.addAll(files);
            if (javac.run(null, null, null, args.toArray(String[]::new)) != 0) {
                throw new IllegalStateException("plug-in sources did not compile: " + sources.keySet());
            }
        }
        try (JarOutputStream out = new JarOutputStream(Files.newOutputStream(jar))) {
            try (Stream<Path> walk = Files.walk(classes)) {
                for (Path p : walk.filter(Files::isRegularFile).sorted().toList()) {
                    out.putNextEntry(new JarEntry(classes.relativize(p).toString().replace('\\', '/')));
                    Files.copy(p, out);
                    out.closeEntry();
                }
            }
            if (services != null) {
                out.putNextEntry(new JarEntry(SERVICES));
                write(out, String.join("\n", services) + "\n");
                out.closeEntry();
            }
        }
        return jar;
    }

    private static void write(OutputStream out, String text) throws IOException {
        out.write(text.getBytes(StandardCharsets.UTF_8));
    }

    /** A scenario class with no rules of its own, for the jars a test expects refused. */
    static String bare(String pkg, String className, String name) {
        return """
                package %s;
                public final class %s implements org.proactiverobotics.engine.Scenario {
                    public String name() { return "%s"; }
                }
                """.formatted(pkg, className, name);
    }

    /** A scenario class named {@code pkg.Name} whose first rule is {@code rule} (a class of the same package). */
    static String scenario(String pkg, String className, String name, String ruleClass) {
        return """
                package %s;
                import java.util.List;
                import org.proactiverobotics.engine.Rule;
                import org.proactiverobotics.engine.Scenario;
                public final class %s implements Scenario {
                    public String name() { return "%s"; }
                    public List<Rule> firstRules() { return List.of(new %s()); }
                }
                """.formatted(pkg, className, name, ruleClass);
    }

    /**
     * Slowpoke: heads for the next checkpoint at no more than 0.25 m/s, every iteration, from
     * GPS and heading: a plug-in whose word drives the robot when the strategy ranks it first.
     */
    static Path slowpoke(Path dir) throws IOException {
        String creep = """
                package slowpoke;
                import org.proactiverobotics.engine.Outcome;
                import org.proactiverobotics.engine.Rule;
                import org.proactiverobotics.engine.RuleContext;
                import org.proactiverobotics.engine.motion.DriveProfile;
                import org.proactiverobotics.engine.motion.Steering;
                import org.proactiverobotics.engine.tables.Checkpoint;
                import org.proactiverobotics.engine.tables.GpsFix;
                import org.proactiverobotics.engine.tables.Heading;
                import org.proactiverobotics.engine.tables.MissionTables;
                import org.proactiverobotics.engine.tables.SensorReadings;
                public final class Creep extends Rule {
                    private long suggested;
                    private transient GpsFix gps;
                    private transient Heading heading;
                    private transient Checkpoint target;
                    public String scenario() { return "Slowpoke"; }
                    protected void acquireGuardData(RuleContext ctx) {
                        SensorReadings r = ctx.service(SensorReadings.class);
                        gps = r.newestGps().orElse(null);
                        heading = r.newestHeading().orElse(null);
                        target = ctx.service(MissionTables.class).checkpoints().stream().filter(c -> !c.reached())
                                .findFirst().orElse(null);
                    }
                    protected boolean activationGuards(RuleContext ctx) { return gps != null && heading != null && target != null; }
                    protected void actions(RuleContext ctx) {
                        DriveProfile slow = new DriveProfile(0.25, ctx.service(DriveProfile.class).axleWidthM());
                        ctx.suggest(Steering.goTo(gps.xM(), gps.yM(), heading.yawRad(), target.xM(), target.yM(), slow));
                        suggested++;
                    }
                    protected void rulesGeneration(RuleContext ctx, Outcome outcome) { ctx.generate(this); }
                }
                """;
        return build(dir.resolve("slowpoke.jar"), Map.of("slowpoke.SlowpokeScenario",
                scenario("slowpoke", "SlowpokeScenario", "Slowpoke", "Creep"), "slowpoke.Creep", creep),
                List.of("slowpoke.SlowpokeScenario"));
    }

    /** One scenario per part that throws, every time it runs, plus one whose metaRule() throws; all suggest STOP first. */
    static Path broken(Path dir) throws IOException {
        Map<String, String> sources = new java.util.LinkedHashMap<>();
        List<String> services = new ArrayList<>();
        String[][] parts = {
                {"GuardData", "acquireGuardData(RuleContext ctx)", "void"},
                {"Guards", "activationGuards(RuleContext ctx)", "boolean"},
                {"ConditionData", "acquireConditionData(RuleContext ctx)", "void"},
                {"Conditions", "conditions(RuleContext ctx)", "boolean"},
                {"Actions", "actions(RuleContext ctx)", "void"},
                {"Generation", "rulesGeneration(RuleContext ctx, Outcome outcome)", "void"}};
        for (String[] p : parts) {
            String rule = "Fail" + p[0];
            sources.put("broken." + rule, """
                    package broken;
                    import org.proactiverobotics.engine.Outcome;
                    import org.proactiverobotics.engine.Rule;
                    import org.proactiverobotics.engine.RuleContext;
                    public final class %s extends Rule {
                        public String scenario() { return "Fails%s"; }
                        protected %s %s { throw new IllegalStateException("%s fails, as designed"); }
                    }
                    """.formatted(rule, p[0], p[2], p[1], p[0]));
            sources.put("broken.Fails" + p[0] + "Scenario", scenario("broken", "Fails" + p[0] + "Scenario", "Fails" + p[0], rule));
            services.add("broken.Fails" + p[0] + "Scenario");
        }
        sources.put("broken.FailsToStartScenario", """
                package broken;
                import org.proactiverobotics.engine.MetaRule;
                import org.proactiverobotics.engine.Scenario;
                public final class FailsToStartScenario implements Scenario {
                    public String name() { return "FailsToStart"; }
                    public MetaRule metaRule() { throw new IllegalStateException("no meta-rule, as designed"); }
                }
                """);
        services.add("broken.FailsToStartScenario");
        return build(dir.resolve("broken.jar"), sources, services);
    }
}
