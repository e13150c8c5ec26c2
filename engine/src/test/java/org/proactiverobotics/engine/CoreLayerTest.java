package org.proactiverobotics.engine;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.DataInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.net.URISyntaxException;
import java.net.URL;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.proactiverobotics.engine.persistence.JdbcStateStore;

/**
 * The core ({@code org.proactiverobotics.engine}) is the engine's bottom layer: its compiled
 * classes refer to no other package of the project (persistence, tables, robot, scenarios, the db
 * module) and to no JDBC or JSON code. Read from the class files' constant pools, where every type
 * a class uses is named, imports, signatures and fully qualified names in code alike.
 */
class CoreLayerTest {

    /** A type name as the class file spells it: slashes, '$' for nested classes. */
    private static final Pattern PROJECT_TYPE = Pattern.compile("org/proactiverobotics/[\\w/$]+");
    private static final Pattern CORE_TYPE = Pattern.compile("org/proactiverobotics/engine/[\\w$]+");
    private static final List<String> FORBIDDEN_LIBRARIES = List.of("java/sql/", "javax/sql/", "com/google/gson/");

    @Test
    void theCoreRefersToNoOtherPackageOfTheProjectNorToDatabaseOrJsonCode() throws Exception {
        Path core = folderOf(ProactiveEngine.class);
        List<Path> classes;
        try (Stream<Path> files = Files.list(core)) {
            classes = files.filter(p -> p.toString().endsWith(".class")).sorted().toList();
        }
        assertThat(classes).as("the core's class files, in " + core)
                .extracting(p -> p.getFileName().toString())
                .contains("ProactiveEngine.class", "Rule.class", "StateStore.class", "SharedMemory.class");
        List<String> wrong = new ArrayList<>();
        for (Path c : classes) {
            for (String type : forbiddenReferences(c)) {
                wrong.add(c.getFileName() + " -> " + type);
            }
        }
        assertThat(wrong).as("the core must not depend on the layers above it: invert the dependency "
                + "through an interface of the core instead").isEmpty();
    }

    @Test
    void theCheckSeesADependencyWhereThereIsOne() throws Exception {
        Path store = folderOf(JdbcStateStore.class).resolve("JdbcStateStore.class");
        assertThat(forbiddenReferences(store)).as("persistence uses the db module and JDBC")
                .contains("org/proactiverobotics/db/MultiRow", "java/sql/Connection");
    }

    private static Path folderOf(Class<?> type) throws URISyntaxException {
        URL url = type.getResource(type.getSimpleName() + ".class");
        assertThat(url).as(type + "'s class file").isNotNull();
        assertThat(url.getProtocol()).as("compiled classes in a folder, as Maven's test phase has them").isEqualTo("file");
        return Path.of(url.toURI()).getParent();
    }

    /** @return the types outside the core that the class file names, sorted */
    private static TreeSet<String> forbiddenReferences(Path classFile) throws IOException {
        TreeSet<String> found = new TreeSet<>();
        for (String text : constantPoolTexts(classFile)) {
            Matcher m = PROJECT_TYPE.matcher(text);
            while (m.find()) {
                if (!CORE_TYPE.matcher(m.group()).matches()) {
                    found.add(m.group());
                }
            }
            for (String library : FORBIDDEN_LIBRARIES) {
                int at = text.indexOf(library);
                if (at >= 0) {
                    Matcher t = Pattern.compile("[\\w/$]+").matcher(text);
                    found.add(t.find(at) ? t.group() : library);
                }
            }
        }
        return found;
    }

    /**
     * @return the UTF-8 entries of a class file's constant pool (JVMS 4.4): class names,
     *         descriptors, signatures and strings
     */
    private static List<String> constantPoolTexts(Path classFile) throws IOException {
        List<String> texts = new ArrayList<>();
        try (InputStream raw = Files.newInputStream(classFile); DataInputStream in = new DataInputStream(raw)) {
            assertThat(in.readInt()).as(classFile + " is a class file").isEqualTo(0xCAFEBABE);
            in.readUnsignedShort(); // minor version
            in.readUnsignedShort(); // major version
            int count = in.readUnsignedShort();
            for (int i = 1; i < count; i++) {
                int tag = in.readUnsignedByte();
                switch (tag) {
                    case 1 -> texts.add(in.readUTF()); // the class file's modified UTF-8 is readUTF's
                    case 7, 8, 16, 19, 20 -> in.skipNBytes(2);
                    case 15 -> in.skipNBytes(3);
                    case 3, 4, 9, 10, 11, 12, 17, 18 -> in.skipNBytes(4);
                    case 5, 6 -> {
                        in.skipNBytes(8);
                        i++; // a long or a double takes two entries
                    }
                    default -> throw new IOException(classFile + ": unknown constant pool tag " + tag + " at entry " + i);
                }
            }
        }
        return texts;
    }
}
