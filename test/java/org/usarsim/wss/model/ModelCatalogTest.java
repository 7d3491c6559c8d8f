package org.usarsim.wss.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.usarsim.wss.LogCapture;
import org.usarsim.wss.model.noop.NoopPropagationModel;

/** Built-in models and plugin jars, good and bad, as the catalog finds them. */
class ModelCatalogTest {

    private static final ClassLoader APPLICATION = ModelCatalogTest.class.getClassLoader();

    @TempDir
    static Path compiled;

    private static Path classes;

    @TempDir
    Path dir;

    /** What the model package logs during a test. */
    private LogCapture log;
    private List<LogRecord> records;

    @BeforeAll
    static void compilePlugins() throws IOException {
        classes = PluginJars.compile(compiled);
    }

    @BeforeEach
    void collectTheLog() {
        log = LogCapture.of("org.usarsim.wss.model", Level.ALL);
        records = log.records;
    }

    @AfterEach
    void stopCollecting() {
        log.close();
    }

    private List<String> messages(Level level) {
        return log.messages(level);
    }

    /** The one warning that mentions all of these; fails unless there is exactly one. */
    private String warning(String... parts) {
        List<String> matching = messages(Level.WARNING).stream()
                .filter(message -> List.of(parts).stream().allMatch(message::contains)).toList();
        assertEquals(1, matching.size(), "one WARNING with " + List.of(parts) + "; all: " + messages(Level.WARNING));
        assertFalse(matching.get(0).contains("\n"), "one line: " + matching.get(0));
        return matching.get(0);
    }

    // ---- declared settings ----

    @Test
    void aPluginWhoseSettingsAreBrokenIsSkippedAndTheOthersLoad() throws IOException {
        Path folder = dir.resolve("plugins");
        Path jar = PluginJars.jar(folder.resolve("settings.jar"), classes,
                List.of("Base", "BadDefault", "DeclarationThrows", "ServerKey", "TunedModel"),
                List.of("BadDefault", "DeclarationThrows", "ServerKey", "TunedModel"));
        ModelCatalog catalog = ModelCatalog.load(APPLICATION, List.of(folder));
        assertEquals(List.of("NoopPropagationModel", "DistanceOnlyPropagationModel", "ObstaclePropagationModel", "ReplayPropagationModel", "RFComms",
                "Tuned"),
                catalog.names());
        warning("skipping the propagation model BadDefault in " + jar, "bad.level: the default '0' is not a whole number from 1 to 10");
        warning("skipping the propagation model DeclarationThrows in " + jar, "settings() failed", "settings() fails");
        warning("skipping the propagation model ServerKey in " + jar, "wss.port: the wss.* keys are the server's");
        assertEquals(List.of("tuned.level", "tuned.gain"), catalog.find("Tuned").settings().stream().map(Setting::key).toList());
    }

    // ---- built-ins ----

    @Test
    void builtInsAloneAreNoopFirst() {
        ModelCatalog catalog = ModelCatalog.load(APPLICATION);
        assertEquals("NoopPropagationModel", catalog.names().get(0));
        assertInstanceOf(NoopPropagationModel.class, catalog.find("NoopPropagationModel"));
        assertSame(catalog.find("NoopPropagationModel"), catalog.find(NoopPropagationModel.class.getName()));
        assertNull(catalog.find("FixedStrength"));
        assertTrue(messages(Level.WARNING).isEmpty(), messages(Level.WARNING).toString());
    }

    @Test
    void aMissingFolderIsSilent() {
        ModelCatalog catalog = ModelCatalog.load(APPLICATION, List.of(dir.resolve("plugins")));
        assertEquals(ModelCatalog.load(APPLICATION).names(), catalog.names());
        assertTrue(records.stream().allMatch(r -> r.getLevel().intValue() <= Level.FINE.intValue()),
                "nothing above FINE: " + messages(Level.WARNING) + messages(Level.INFO));
        assertTrue(messages(Level.FINE).stream().anyMatch(m -> m.contains(dir.resolve("plugins").toString())),
                "FINE names the folder: " + messages(Level.FINE));
    }

    // ---- a working plugin ----

    @Test
    void aPluginIsListedAndFoundByItsNameAndItsClassNames() throws Exception {
        Path jar = PluginJars.fixedStrengthJar(dir.resolve("fixed.jar"), classes);
        ModelCatalog catalog = ModelCatalog.load(APPLICATION, List.of(dir));

        assertEquals("NoopPropagationModel", catalog.names().get(0));
        assertEquals("FixedStrength", catalog.names().get(catalog.names().size() - 1), "plugins after the built-ins");
        PropagationModel model = catalog.find("FixedStrength");
        assertEquals(PluginJars.FIXED, model.getClass().getName());
        assertSame(model, catalog.find("FixedStrengthModel"));
        assertSame(model, catalog.find(PluginJars.FIXED));
        assertEquals(-42.5, model.getSignalStrengthForPair("A", "B"));

        ClassLoader loader = model.getClass().getClassLoader();
        assertInstanceOf(URLClassLoader.class, loader, "a class loader of its own");
        assertSame(APPLICATION, loader.getParent(), "whose parent is the application's");
        assertSame(PropagationModel.class, loader.loadClass(PropagationModel.class.getName()), "the SPI is the server's");
        assertEquals(List.of("loaded propagation model FixedStrength from " + jar), messages(Level.INFO));
        assertTrue(messages(Level.WARNING).isEmpty(), messages(Level.WARNING).toString());
    }

    @Test
    void eachJarHasItsOwnLoaderAndJarsLoadInNameOrder() throws Exception {
        PluginJars.jar(dir.resolve("b.jar"), classes, List.of("Base", "FixedStrengthModel"), List.of("FixedStrengthModel"));
        PluginJars.jar(dir.resolve("a.jar"), classes, List.of("Base", "OtherModel"), List.of("OtherModel"));
        ModelCatalog catalog = ModelCatalog.load(APPLICATION, List.of(dir));
        List<String> names = catalog.names();
        assertEquals(List.of("OtherModel", "FixedStrength"), names.subList(names.size() - 2, names.size()));
        assertNotSame(catalog.find("OtherModel").getClass().getClassLoader(), catalog.find("FixedStrength").getClass().getClassLoader());
        assertNotSame(catalog.find("OtherModel").getClass().getSuperclass(), catalog.find("FixedStrength").getClass().getSuperclass(),
                "each jar's Base is its own");
    }

    @Test
    void aFolderNamedTwiceIsSearchedOnce() throws Exception {
        PluginJars.fixedStrengthJar(dir.resolve("fixed.jar"), classes);
        ModelCatalog catalog = ModelCatalog.load(APPLICATION, List.of(dir, dir.resolve(".").resolve("x").resolve("..")));
        assertEquals(1, catalog.names().stream().filter("FixedStrength"::equals).count());
        assertTrue(messages(Level.WARNING).isEmpty(), messages(Level.WARNING).toString());
        assertEquals(1, messages(Level.INFO).size(), messages(Level.INFO).toString());
    }

    @Test
    void aJarFindsItsDependenciesThroughItsManifestButOnlyItsOwnModels() throws Exception {
        // The dependency lists a model of its own: it is not a plugin, so that model is not loaded.
        PluginJars.jar(dir.resolve("lib/helper.jar"), classes, List.of("Base", "Helper", "OtherModel"), List.of("OtherModel"));
        Path jar = PluginJars.jar(dir.resolve("needs-helper.jar"), classes, List.of("NeedsHelper"), List.of("NeedsHelper"),
                "lib/helper.jar");
        ModelCatalog catalog = ModelCatalog.load(APPLICATION, List.of(dir));
        List<String> names = catalog.names();
        assertEquals("NeedsHelper", names.get(names.size() - 1));
        assertNull(catalog.find("OtherModel"), "neither a plugin of its own (lib/ is not searched) nor one of needs-helper.jar");
        assertEquals(List.of("loaded propagation model NeedsHelper from " + jar), messages(Level.INFO));
        assertTrue(messages(Level.WARNING).isEmpty(), messages(Level.WARNING).toString());
    }

    @Test
    void foldersAreSearchedInOrderAndTheFirstOfTwoNamesWins() throws Exception {
        Path first = PluginJars.jar(dir.resolve("one/z.jar"), classes, List.of("Base", "FixedStrengthModel"), List.of("FixedStrengthModel"));
        Path second = PluginJars.jar(dir.resolve("two/a.jar"), classes, List.of("Base", "FixedStrengthModel"), List.of("FixedStrengthModel"));
        ModelCatalog catalog = ModelCatalog.load(APPLICATION, List.of(dir.resolve("one"), dir.resolve("two")));
        assertEquals(1, catalog.names().stream().filter("FixedStrength"::equals).count());
        assertTrue(((URLClassLoader) catalog.find("FixedStrength").getClass().getClassLoader()).getURLs()[0].toString().endsWith("one/z.jar"));
        assertEquals(List.of("loaded propagation model FixedStrength from " + first), messages(Level.INFO));
        warning(second.toString(), "FixedStrength", first.toString());
    }

    // ---- bad plugins next to a good one ----

    @Test
    void badPluginsAreReportedAndSkippedAndTheGoodOnesStillLoad() throws Exception {
        Path constructor = PluginJars.jar(dir.resolve("a-constructor.jar"), classes, List.of("Base", "ConstructorThrows"),
                List.of("ConstructorThrows"));
        Path staticInit = PluginJars.jar(dir.resolve("b-static.jar"), classes, List.of("Base", "StaticInitThrows"),
                List.of("StaticInitThrows"));
        Path corrupt = PluginJars.corruptJar(dir.resolve("c-corrupt.jar"));
        Path good = PluginJars.fixedStrengthJar(dir.resolve("d-good.jar"), classes);
        Path missing = PluginJars.jar(dir.resolve("e-missing.jar"), classes, List.of("Base"), List.of("MissingModel"));
        // One jar, many faults, and a working model listed after them all.
        Path mixed = PluginJars.jar(dir.resolve("f-mixed.jar"), classes,
                List.of("Base", "NameThrows", "NullName", "CalledNoop", "NotAModel", "NoPublicConstructor", "NeedsHelper", "OtherModel"),
                List.of("NameThrows", "NullName", "CalledNoop", "NotAModel", "NoPublicConstructor", "NeedsHelper", "OtherModel"));
        Path none = PluginJars.jar(dir.resolve("g-no-services.jar"), classes, List.of("Base", "OtherModel"), List.of());
        Files.writeString(dir.resolve("readme.txt"), "not a jar: ignored");
        Files.createDirectories(dir.resolve("folder.jar"));

        ModelCatalog catalog = ModelCatalog.load(APPLICATION, List.of(dir));

        List<String> builtIn = ModelCatalog.load(APPLICATION).names();
        List<String> names = catalog.names();
        assertEquals(builtIn, names.subList(0, builtIn.size()), "built-ins first");
        assertEquals(List.of("FixedStrength", "OtherModel"), names.subList(builtIn.size(), names.size()));
        assertEquals(-42.5, catalog.find("FixedStrength").getSignalStrengthForPair("A", "B"));
        assertEquals(-60.0, catalog.find("OtherModel").getSignalStrengthForPair("A", "B"));
        assertInstanceOf(NoopPropagationModel.class, catalog.find("NoopPropagationModel"), "the built-in keeps its name");
        assertEquals(List.of("loaded propagation model FixedStrength from " + good, "loaded propagation model OtherModel from " + mixed),
                messages(Level.INFO));

        warning(constructor.toString(), "ConstructorThrows", "the constructor fails");
        warning(staticInit.toString(), "StaticInitThrows", "the static initialiser fails");
        warning(corrupt.toString(), "cannot read it as a jar");
        warning(missing.toString(), PluginJars.PACKAGE + ".MissingModel", "not found");
        warning(mixed.toString(), "NameThrows", "name() fails");
        warning(mixed.toString(), "NullName", "returned null");
        warning(mixed.toString(), "CalledNoop", "NoopPropagationModel", "the class path");
        warning(mixed.toString(), "NotAModel", "not a subtype");
        warning(mixed.toString(), "NoPublicConstructor");
        warning(mixed.toString(), "NoClassDefFoundError", "Helper"); // the JDK does not say which model needed it
        warning(none.toString(), PluginFolder.SERVICES);
        assertEquals(11, messages(Level.WARNING).size(), "one WARNING each: " + String.join("\n", messages(Level.WARNING)));
        assertTrue(messages(Level.WARNING).stream().noneMatch(m -> m.contains("readme.txt") || m.contains("folder.jar")),
                messages(Level.WARNING).toString());
    }

    @Test
    void theReasonNamesTheModelsOwnCodeWhereItThrew() throws Exception {
        Path jar = PluginJars.jar(dir.resolve("constructor.jar"), classes, List.of("Base", "ConstructorThrows"),
                List.of("ConstructorThrows"));
        ModelCatalog.load(APPLICATION, List.of(dir));
        String warning = warning(jar.toString());
        assertEquals("skipping a propagation model in " + jar + ": Provider " + PluginJars.PACKAGE + ".ConstructorThrows"
                + " could not be instantiated: java.lang.IllegalStateException: the constructor fails"
                + " (at " + PluginJars.PACKAGE + ".ConstructorThrows.<init>(ConstructorThrows.java:6))", warning);
    }

    @Test
    void aFileNamedAsAFolderHasNoPlugins() throws Exception {
        Path file = Files.writeString(dir.resolve("a-file"), "not a folder");
        ModelCatalog catalog = ModelCatalog.load(APPLICATION, List.of(file));
        assertEquals(ModelCatalog.load(APPLICATION).names(), catalog.names());
    }

    @Test
    void besideCodeIsThePluginsFolderNextToTheClassesOrJar() {
        Path classesFolder = PluginJars.serverClasses();
        assertEquals(classesFolder.toAbsolutePath().getParent().resolve("plugins"),
                PluginFolder.besideCodeOf(ModelCatalog.class).orElseThrow());
    }
}
