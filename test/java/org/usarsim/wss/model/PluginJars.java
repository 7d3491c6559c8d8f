package org.usarsim.wss.model;

import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.OutputStream;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.jar.Attributes;
import java.util.jar.JarEntry;
import java.util.jar.JarOutputStream;
import java.util.jar.Manifest;
import java.util.stream.Stream;
import javax.tools.DiagnosticCollector;
import javax.tools.JavaCompiler;
import javax.tools.JavaFileObject;
import javax.tools.StandardJavaFileManager;
import javax.tools.ToolProvider;

/**
 * Model plugins built at test time, as a plugin author builds one: Java sources compiled against
 * the server's classes, packed in a jar with its services file. Also packs the server itself as
 * a runnable jar.
 */
public final class PluginJars {

    public static final String PACKAGE = "org.example.wssplugin";

    /** Answers -42.5 dBm for every pair; its name() is "FixedStrength". */
    public static final String FIXED = PACKAGE + ".FixedStrengthModel";

    /**
     * Declares two settings, tuned.level (a whole number from 1 to 10, default 3) and tuned.gain (a
     * number of dB, 0 or more, default 2.5); answers -10 * level - gain dBm for every pair, and logs
     * what it was configured with; its name() is "Tuned".
     */
    public static final String TUNED = PACKAGE + ".TunedModel";

    /** The test plugins by simple class name. Each one but Base and Helper is a model, good or bad. */
    private static final Map<String, String> SOURCES = new LinkedHashMap<>();

    static {
        source("Base", """
                public abstract class Base implements PropagationModel {
                    private volatile boolean active;
                    public void setRobotLinkModel(RobotLinkModel links) {}
                    public void setEventListener(WssEventListener listener) {}
                    public void start() { active = true; }
                    public void shutdown() { active = false; }
                    public boolean isActive() { return active; }
                    public double getSignalStrengthForPair(String from, String to) { return -42.5; }
                    public boolean connectionIsPossibleForPair(String from, String to) { return true; }
                }""");
        source("FixedStrengthModel", """
                public final class FixedStrengthModel extends Base {
                    public String name() { return "FixedStrength"; }
                }""");
        source("TunedModel", """
                public final class TunedModel extends Base {
                    private volatile int level = 3;
                    private volatile double gain = 2.5;
                    public String name() { return "Tuned"; }
                    public java.util.List<Setting> settings() {
                        return java.util.List.of(
                                Setting.integer("tuned.level", "Level", 3).from(1).to(10)
                                        .help("How many steps of 10 dB the strength is below 0 dBm"),
                                Setting.number("tuned.gain", "Gain", "2.5").from(0).unit("dB")
                                        .help("Taken off the level's strength"));
                    }
                    public void configure(ModelSettings settings) {
                        level = settings.getInt("tuned.level", level);
                        gain = settings.getDouble("tuned.gain", gain);
                        java.util.logging.Logger.getLogger(TunedModel.class.getName())
                                .info("Tuned configured with tuned.level " + level + ", tuned.gain " + gain);
                    }
                    public double getSignalStrengthForPair(String from, String to) { return -10.0 * level - gain; }
                }""");
        source("BadDefault", """
                public final class BadDefault extends Base {
                    public java.util.List<Setting> settings() {
                        return java.util.List.of(Setting.integer("bad.level", "Level", 0).from(1).to(10));
                    }
                }""");
        source("DeclarationThrows", """
                public final class DeclarationThrows extends Base {
                    public java.util.List<Setting> settings() { throw new IllegalStateException("settings() fails"); }
                }""");
        source("ServerKey", """
                public final class ServerKey extends Base {
                    public java.util.List<Setting> settings() {
                        return java.util.List.of(Setting.integer("wss.port", "Port", 1));
                    }
                }""");
        source("OtherModel", """
                public final class OtherModel extends Base {
                    public double getSignalStrengthForPair(String from, String to) { return -60; }
                }""");
        source("ConstructorThrows", """
                public final class ConstructorThrows extends Base {
                    public ConstructorThrows() { throw new IllegalStateException("the constructor fails"); }
                }""");
        source("StaticInitThrows", """
                public final class StaticInitThrows extends Base {
                    static final int VALUE = fail();
                    static int fail() { throw new IllegalStateException("the static initialiser fails"); }
                }""");
        source("NameThrows", """
                public final class NameThrows extends Base {
                    public String name() { throw new UnsupportedOperationException("name() fails"); }
                }""");
        source("NullName", """
                public final class NullName extends Base {
                    public String name() { return null; }
                }""");
        source("CalledNoop", """
                public final class CalledNoop extends Base {
                    public String name() { return "NoopPropagationModel"; }
                }""");
        source("NotAModel", """
                public final class NotAModel {
                }""");
        source("NoPublicConstructor", """
                public final class NoPublicConstructor extends Base {
                    private NoPublicConstructor() {}
                }""");
        source("Helper", """
                public abstract class Helper extends Base {
                }""");
        source("NeedsHelper", """
                public final class NeedsHelper extends Helper {
                }""");
    }

    private static void source(String name, String body) {
        SOURCES.put(name, "package " + PACKAGE + ";\n\nimport org.usarsim.wss.model.*;\n\n" + body + "\n");
    }

    /** The test plugins' classes, compiled once in this JVM (see {@link #compile}). */
    private static Path compiled;

    private PluginJars() {
    }

    /** Where the server's classes are: target/classes, or the jar they came from. */
    public static Path serverClasses() {
        try {
            return Path.of(PropagationModel.class.getProtectionDomain().getCodeSource().getLocation().toURI());
        } catch (URISyntaxException e) {
            throw new IllegalStateException(e);
        }
    }

    /**
     * Every test plugin's classes in {@code dir}/classes, compiled against the server's classes;
     * returns that folder. The compiler runs once in a test JVM (the first call); later calls copy its classes.
     */
    public static Path compile(Path dir) throws IOException {
        Path classes = Files.createDirectories(dir.resolve("classes"));
        Path once = compiledOnce();
        try (var files = Files.walk(once)) {
            for (Path file : files.filter(Files::isRegularFile).toList()) {
                Path copy = classes.resolve(once.relativize(file).toString());
                Files.createDirectories(copy.getParent());
                Files.copy(file, copy);
            }
        }
        return classes;
    }

    /**
     * The classes the compiler wrote on the first call, into a temporary folder of this JVM's own,
     * removed as the JVM exits.
     */
    private static synchronized Path compiledOnce() throws IOException {
        if (compiled == null) {
            Path dir = Files.createTempDirectory("wss-test-plugins");
            Runtime.getRuntime().addShutdownHook(new Thread(() -> removeTree(dir)));
            compiled = javac(dir);
        }
        return compiled;
    }

    private static void removeTree(Path dir) {
        try (var files = Files.walk(dir)) {
            for (Path file : files.sorted(Comparator.reverseOrder()).toList()) {
                Files.deleteIfExists(file);
            }
        } catch (IOException e) {
            // the JVM is exiting: what is left stays in the temporary folder
        }
    }

    private static Path javac(Path dir) throws IOException {
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        assertNotNull(javac, "the tests run on a JDK");
        Path sources = Files.createDirectories(dir.resolve("src"));
        Path classes = Files.createDirectories(dir.resolve("classes"));
        List<Path> files = new ArrayList<>();
        for (Map.Entry<String, String> source : SOURCES.entrySet()) {
            Path file = sources.resolve(source.getKey() + ".java");
            Files.writeString(file, source.getValue(), StandardCharsets.UTF_8);
            files.add(file);
        }
        DiagnosticCollector<JavaFileObject> diagnostics = new DiagnosticCollector<>();
        try (StandardJavaFileManager fileManager = javac.getStandardFileManager(diagnostics, null, StandardCharsets.UTF_8)) {
            boolean compiled = javac.getTask(null, fileManager, diagnostics,
                    List.of("--release", "17", "-classpath", serverClasses().toString(), "-d", classes.toString()),
                    null, fileManager.getJavaFileObjectsFromPaths(files)).call();
            assertTrue(compiled, "the test plugins compile: " + diagnostics.getDiagnostics());
        }
        return classes;
    }

    /**
     * Writes a plugin jar holding these classes (simple names, from {@code classes}) and a services
     * file listing these models (simple names; a name without a class is fine); none: no services file.
     */
    public static Path jar(Path jar, Path classes, List<String> classNames, List<String> services) throws IOException {
        return jar(jar, classes, classNames, services, null);
    }

    /** The same, with a manifest whose Class-Path names these jars (relative to this one); null: none. */
    public static Path jar(Path jar, Path classes, List<String> classNames, List<String> services, String classPath)
            throws IOException {
        Files.createDirectories(jar.getParent());
        Manifest manifest = manifest(null);
        if (classPath != null) {
            manifest.getMainAttributes().put(Attributes.Name.CLASS_PATH, classPath);
        }
        try (JarOutputStream out = new JarOutputStream(Files.newOutputStream(jar), manifest)) {
            for (String name : classNames) {
                String entry = PACKAGE.replace('.', '/') + "/" + name + ".class";
                put(out, entry, Files.readAllBytes(classes.resolve(entry)));
            }
            if (!services.isEmpty()) {
                StringBuilder list = new StringBuilder("# test plugin models\n");
                services.forEach(name -> list.append(PACKAGE).append('.').append(name).append('\n'));
                put(out, PluginFolder.SERVICES, list.toString().getBytes(StandardCharsets.UTF_8));
            }
        }
        return jar;
    }

    /** A plugin jar with the one working model, FixedStrengthModel. */
    public static Path fixedStrengthJar(Path jar, Path classes) throws IOException {
        return jar(jar, classes, List.of("Base", "FixedStrengthModel"), List.of("FixedStrengthModel"));
    }

    /** A plugin jar with the model that declares two settings, TunedModel. */
    public static Path tunedJar(Path jar, Path classes) throws IOException {
        return jar(jar, classes, List.of("Base", "TunedModel"), List.of("TunedModel"));
    }

    /** The server as a runnable jar, made from its classes: what {@code mvn package} makes. */
    public static Path serverJar(Path jar) throws IOException {
        Path classes = serverClasses();
        assertTrue(Files.isDirectory(classes), "the server's classes are a folder: " + classes);
        Files.createDirectories(jar.getParent());
        List<Path> files;
        try (Stream<Path> walk = Files.walk(classes)) {
            files = walk.filter(Files::isRegularFile).sorted().toList();
        }
        try (JarOutputStream out = new JarOutputStream(Files.newOutputStream(jar), manifest("org.usarsim.wss.app.Main"))) {
            for (Path file : files) {
                put(out, classes.relativize(file).toString().replace('\\', '/'), Files.readAllBytes(file));
            }
        }
        return jar;
    }

    private static Manifest manifest(String mainClass) {
        Manifest manifest = new Manifest();
        manifest.getMainAttributes().put(Attributes.Name.MANIFEST_VERSION, "1.0");
        if (mainClass != null) {
            manifest.getMainAttributes().put(Attributes.Name.MAIN_CLASS, mainClass);
        }
        return manifest;
    }

    private static void put(JarOutputStream out, String name, byte[] content) throws IOException {
        out.putNextEntry(new JarEntry(name));
        out.write(content);
        out.closeEntry();
    }

    /** A file that is not a jar at all, named like one. */
    public static Path corruptJar(Path jar) throws IOException {
        Files.createDirectories(jar.getParent());
        try (OutputStream out = Files.newOutputStream(jar)) {
            out.write("this is not a zip file, only named like one\n".getBytes(StandardCharsets.US_ASCII));
        }
        return jar;
    }
}
