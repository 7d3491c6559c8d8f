package org.usarsim.wss.app;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.InetAddress;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Properties;
import java.util.Set;
import java.util.TreeMap;
import java.util.logging.Level;
import java.util.prefs.Preferences;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.usarsim.wss.gui.TestPreferences;
import org.usarsim.wss.gui.WindowPreferences;
import org.usarsim.wss.hub.core.Force;
import org.usarsim.wss.hub.FixedSetup;
import org.usarsim.wss.hub.HubConfig;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.model.Setting;
import org.usarsim.wss.model.obstacle.ObstaclePropagationModel;
import org.usarsim.wss.replay.ReplayPropagationModel;
import org.usarsim.wss.shaping.ShapingConfig;

class ConfigFileTest {

    /** Every key and its documented default. */
    private static final Map<String, String> DEFAULTS = Map.ofEntries(
            Map.entry("wss.port", "50000"),
            Map.entry("wss.bindAddress", "0.0.0.0"),
            Map.entry("wss.model", "NoopPropagationModel"),
            Map.entry("wss.eventLog", "false"),
            Map.entry("wss.eventLogDir", "."),
            Map.entry("wss.record", ""),
            Map.entry("wss.matchSourceAddress", "true"),
            Map.entry("wss.chunkSize", "65536"),
            Map.entry("wss.socketBuffer", "4194304"),
            Map.entry("wss.pluginDir", ""),
            Map.entry("wss.portMemory", "600"),
            Map.entry("wss.maxPortsPerRobot", "1000"),
            Map.entry("wss.maxPortsPerAddress", "10000"),
            Map.entry("wss.deadPeerSeconds", "30"),
            Map.entry("wss.statsInterval", "0"),
            Map.entry("wss.operators", "127.0.0.1"),
            Map.entry("wss.force.down", ""),
            Map.entry("wss.force.up", ""),
            Map.entry("wss.shaping", "off"),
            Map.entry("wss.shaping.rates", "-72:54M,-73:48M,-77:36M,-81:24M,-83:18M,-85:12M,-86:9M,-87:6M"),
            Map.entry("wss.shaping.delayMs", "2"),
            Map.entry("wss.shaping.airtime", "true"),
            Map.entry("wss.shaping.queueMs", "20"),
            Map.entry("wss.shaping.loss", "-85:1,-87:10,-90:50"),
            Map.entry("wss.shaping.jitter", "0"),
            Map.entry("wss.shaping.jitterDistribution", "uniform"),
            Map.entry("wss.shaping.reorder", "false"),
            Map.entry("wss.seed", "0"),
            Map.entry("wss.fixed", ""),
            Map.entry("wss.udpIdleSeconds", "60"),
            Map.entry("wss.logLevel", "INFO"),
            Map.entry("wss.monitor.port", "0"),
            Map.entry("wss.monitor.bindAddress", "127.0.0.1"),
            Map.entry("wss.monitor.tokens", ""),
            Map.entry("wss.monitor.maxClients", "16"),
            Map.entry("wss.monitor.keystore", ""),
            Map.entry("wss.monitor.keystorePasswordFile", ""),
            Map.entry("wss.route.base", ""),
            Map.entry("positions", "usarsim"),
            Map.entry("positions.interval", "1000"),
            Map.entry("usarsim.host", "127.0.0.1"),
            Map.entry("usarsim.port", "7435"),
            Map.entry("usarsim.timeout", "2000"),
            Map.entry("rosbridge.url", "ws://127.0.0.1:9090"),
            Map.entry("rosbridge.topic", "/gazebo/model_states"),
            Map.entry("rosbridge.type", ""),
            Map.entry("rosbridge.frame", "world"),
            Map.entry("rosbridge.names", ""),
            Map.entry("rosbridge.stale", "0"),
            Map.entry("rosbridge.grace", "10000"),
            Map.entry("rosbridge.maxMessage", "16"),
            Map.entry("distance.cutoff", "-93"),
            Map.entry("distance.pd0", "-49.67"),
            Map.entry("distance.n", "1"),
            Map.entry("distance.d0", "2"),
            Map.entry("distance.margin", "0"),
            Map.entry("distance.holdTime", "0"),
            Map.entry("shadowing.sigma", "0"),
            Map.entry("shadowing.distance", "5"),
            Map.entry("obstacle.attenuation", "6.325"),
            Map.entry("obstacle.cacheDistance", "1.0"),
            Map.entry("obstacle.walls", ""),
            Map.entry("rosbridge.map", "/map"),
            Map.entry("obstacle.materials", "Hard_wall*=concrete, Medium_wall*=brick, Soft_wall*=drywall, *glass*=glass, *=concrete"),
            Map.entry("obstacle.loss", "concrete:15, brick:10, drywall:4, wood:4, glass:2, metal:30"),
            Map.entry("obstacle.heightBand", "0.1..2.0"),
            Map.entry("replay.file", ""),
            Map.entry("replay.speed", "1"),
            Map.entry("replay.start", "0"),
            Map.entry("replay.loop", "false"),
            Map.entry("rfcomms.preset", "gz-sim"),
            Map.entry("rfcomms.txPower", ""),
            Map.entry("rfcomms.noiseFloor", ""),
            Map.entry("rfcomms.l0", ""),
            Map.entry("rfcomms.fadingExponent", ""),
            Map.entry("rfcomms.sigma", ""),
            Map.entry("rfcomms.maxRange", ""),
            Map.entry("rfcomms.capacity", ""));

    @TempDir
    Path dir;

    private Path write(String content) throws IOException {
        Path file = dir.resolve("wss.properties");
        Files.writeString(file, content, StandardCharsets.UTF_8);
        return file;
    }

    private static Properties props(String key, String value) {
        Properties properties = new Properties();
        properties.setProperty(key, value);
        return properties;
    }

    // ---- defaults ----

    @Test
    void defaultsHaveEveryKey() {
        ConfigFile settings = ConfigFile.defaults();
        assertAll(DEFAULTS.entrySet().stream().map(e -> () -> assertEquals(e.getValue(), settings.get(e.getKey()), e.getKey())));
    }

    @Test
    void defaultsHaveNoOtherKey() throws Exception {
        ConfigFile settings = ConfigFile.defaults();
        assertEquals(null, settings.get("wss.nonsense"));
        assertEquals(Map.of(), settings.modelValues().asMap(), "NoopPropagationModel declares no setting");
        // the obstacle model declares every non-wss key but the replay's: exactly the documented ones.
        Map<String, String> expected = new TreeMap<>(DEFAULTS);
        expected.keySet().removeIf(key -> key.startsWith("wss.") || key.startsWith("replay.") || key.startsWith("rfcomms."));
        assertEquals(expected, ConfigFile.of(props("wss.model", "ObstaclePropagationModel"), "t").modelValues().asMap());
        Map<String, String> replay = new TreeMap<>(DEFAULTS);
        replay.keySet().removeIf(key -> !key.startsWith("replay."));
        assertEquals(replay, ConfigFile.of(props("wss.model", "ReplayPropagationModel"), "t").modelValues().asMap());
    }

    @Test
    void theIssuesNamesOfTheWallKeysAreTakenAsTheObstacleModels() throws Exception {
        Properties file = props("wss.model", "ObstaclePropagationModel");
        file.setProperty("wss.walls.materials", "Hard_wall*=metal");
        file.setProperty("wss.walls.loss", "metal:25");
        ConfigFile settings = ConfigFile.of(file, "t");
        assertEquals("Hard_wall*=metal", settings.modelValues().asMap().get("obstacle.materials"));
        assertEquals("metal:25", settings.modelValues().asMap().get("obstacle.loss"));
    }

    @Test
    void theOldNameOfTheIntervalIsTakenAsTheNewOne() throws Exception {
        Properties file = props("wss.model", "DistanceOnlyPropagationModel");
        file.setProperty("usarsim.interval", " 250 ");
        ConfigFile settings = ConfigFile.of(file, "t");
        assertEquals("250", settings.get("positions.interval"));
        assertEquals("250", settings.modelValues().asMap().get("positions.interval"));
        assertFalse(settings.modelValues().asMap().containsKey("usarsim.interval"));
        assertEquals(Map.of("positions.interval", "250"), settings.modelKeysSetBy(file).asMap(), "what the window is handed");
        file.setProperty("positions.interval", "300");
        ConfigFileException both = assertThrows(ConfigFileException.class, () -> ConfigFile.of(file, "my.properties"));
        assertEquals("my.properties: usarsim.interval is the old name of positions.interval; set only positions.interval",
                both.getMessage());
        ConfigFileException bad = rejected("usarsim.interval", "99");
        assertTrue(bad.getMessage().endsWith("usarsim.interval = '99' is not a whole number of milliseconds from 100 to 60000"
                + " (usarsim.interval is the old name of positions.interval)"), bad.getMessage());
        assertTrue(ConfigKeys.help(ConfigFile.defaults().catalog()).contains("(formerly usarsim.interval)"));
    }

    @Test
    void theWindowIsHandedOnlyTheModelKeysTheFileSets() throws Exception {
        Properties file = props("wss.model", "DistanceOnlyPropagationModel");
        file.setProperty("wss.port", "0");
        file.setProperty("distance.n", " 3 ");
        file.setProperty("usarsim.port", "7436");
        assertEquals(Map.of("distance.n", "3", "usarsim.port", "7436"), ConfigFile.of(file, "t").modelKeysSetBy(file).asMap());
    }

    @Test
    void defaultTypedValues() {
        ConfigFile settings = ConfigFile.defaults();
        assertEquals("NoopPropagationModel", settings.modelName());
        assertFalse(settings.eventLog());
        assertEquals(Level.INFO, settings.logLevel());
        assertTrue(settings.pluginDir().isEmpty(), "no plugin folder unless one is named");
    }

    @Test
    void defaultHubConfig() throws Exception {
        HubConfig config = ConfigFile.defaults().hubConfig();
        assertEquals(InetAddress.getByName("0.0.0.0"), config.bindAddress());
        assertTrue(config.bindAddress().isAnyLocalAddress());
        assertEquals(50000, config.controlPort());
        assertEquals(65536, config.chunkSize());
        assertEquals(4194304, config.socketBuffer());
        assertEquals(600, config.portMemorySeconds());
        assertEquals(1000, config.maxPortsPerRobot());
        assertEquals(30, config.deadPeerSeconds());
        assertEquals(Set.of(InetAddress.getByName("127.0.0.1")), config.operators());
        assertEquals(Map.of(), config.forced());
        assertTrue(config.matchSourceAddress());
    }

    @Test
    void emptyPropertiesGiveTheDefaults() throws Exception {
        ConfigFile settings = ConfigFile.of(new Properties(), "nothing");
        DEFAULTS.forEach((key, value) -> assertEquals(value, settings.get(key), key));
    }

    @Test
    void emptyFileGivesTheDefaults() throws Exception {
        ConfigFile settings = ConfigFile.load(write("# nothing but a comment\n\n"));
        DEFAULTS.forEach((key, value) -> assertEquals(value, settings.get(key), key));
    }

    // ---- a file overriding values ----

    @Test
    void fileOverridesValuesAndKeepsTheOtherDefaults() throws Exception {
        Path file = write(String.join("\n",
                "# a test configuration",
                "wss.port = 0",
                "wss.bindAddress=127.0.0.1",
                "wss.eventLog=TRUE",
                "wss.matchSourceAddress: false",
                "wss.chunkSize=1",
                "wss.logLevel=FINEST",
                "usarsim.host=sim.example.org",
                "usarsim.port=65535",
                "distance.cutoff=-120.5",
                "distance.n=2.5   ",
                "obstacle.attenuation=0",
                ""));
        ConfigFile settings = ConfigFile.load(file);
        assertEquals("0", settings.get("wss.port"));
        assertEquals("127.0.0.1", settings.get("wss.bindAddress"));
        assertTrue(settings.eventLog());
        assertEquals("false", settings.get("wss.matchSourceAddress"));
        assertEquals("1", settings.get("wss.chunkSize"));
        assertEquals(Level.FINEST, settings.logLevel());
        assertEquals("sim.example.org", settings.get("usarsim.host"));
        assertEquals("65535", settings.get("usarsim.port"));
        assertEquals("-120.5", settings.get("distance.cutoff"));
        assertEquals("2.5", settings.get("distance.n"), "trailing whitespace is stripped");
        assertEquals("0", settings.get("obstacle.attenuation"));
        // untouched keys keep their defaults
        assertEquals("NoopPropagationModel", settings.modelName());
        assertEquals("-49.67", settings.get("distance.pd0"));
        assertEquals("2", settings.get("distance.d0"));
        assertEquals("1.0", settings.get("obstacle.cacheDistance"));

        HubConfig config = settings.hubConfig();
        assertEquals(InetAddress.getByName("127.0.0.1"), config.bindAddress());
        assertEquals(0, config.controlPort());
        assertEquals(1, config.chunkSize());
        assertFalse(config.matchSourceAddress());
    }

    @Test
    void loadingDoesNotChangeTheDefaults() throws Exception {
        ConfigFile.of(props("wss.port", "1234"), "test");
        assertEquals("50000", ConfigFile.defaults().get("wss.port"));
    }

    @Test
    void theWindowsFirstRunHasTheDefaultsOfAPropertiesFile() throws Exception {
        Preferences node = TestPreferences.create();
        try {
            WindowPreferences nothingStored = new WindowPreferences(node);
            ConfigFile defaults = ConfigFile.defaults();
            assertEquals(defaults.get("wss.port"), nothingStored.port());
            assertEquals(defaults.modelName(), nothingStored.model());
            assertEquals("50000", nothingStored.port(), "docs/protocol.md");
            assertEquals("NoopPropagationModel", nothingStored.model(), "docs/headless.md");
        } finally {
            TestPreferences.remove(node);
        }
    }

    @Test
    void modelNameMayBeAnyNonEmptyName() throws Exception {
        assertEquals("org.example.SomeModel", ConfigFile.of(props("wss.model", "org.example.SomeModel"), "t").modelName());
    }

    @ParameterizedTest
    @CsvSource({
        "wss.port, 0", "wss.port, 65535",
        "wss.chunkSize, 1048576",
        "usarsim.port, 1",
        "positions.interval, 100", "positions.interval, 60000", "usarsim.timeout, 100", "usarsim.timeout, 60000",
        "distance.margin, 0", "distance.margin, 3.5", "distance.holdTime, 0", "distance.holdTime, 2.5",
        "distance.n, 0.001", "distance.d0, 1e-3",
        "obstacle.attenuation, 0", "obstacle.cacheDistance, 0",
        "distance.cutoff, -1e3", "distance.pd0, 10",
        "wss.eventLog, False", "wss.matchSourceAddress, TRUE",
        "wss.logLevel, SEVERE", "wss.logLevel, WARNING", "wss.logLevel, FINE", "wss.logLevel, FINER",
        "wss.bindAddress, 127.0.0.1", "wss.bindAddress, ::1",
    })
    void acceptsBoundaryValues(String key, String value) throws Exception {
        assertEquals(value, ConfigFile.of(props(key, value), "t").get(key));
    }

    @Test
    void pluginDirNamesAnExistingFolder() throws Exception {
        Path plugins = Files.createDirectories(dir.resolve("my plugins"));
        ConfigFile settings = ConfigFile.of(props("wss.pluginDir", " " + plugins + " "), "t");
        assertEquals(plugins, settings.pluginDir().orElseThrow());
        assertTrue(ConfigFile.of(props("wss.pluginDir", ""), "t").pluginDir().isEmpty(), "empty: none");
    }

    @Test
    void pluginDirThatIsNoFolder() throws Exception {
        ConfigFileException absent = rejected("wss.pluginDir", dir.resolve("absent").toString());
        assertTrue(absent.getMessage().contains("directory"), absent.getMessage());
        rejected("wss.pluginDir", write("wss.port=1\n").toString());
        rejected("wss.pluginDir", "nul\u0000char");
    }

    // ---- the checks the GUI reuses ----

    @Test
    void problemIsNullForAnAcceptedValue() {
        assertEquals(null, problem("usarsim.port", "7435"));
        assertEquals(null, problem("distance.holdTime", " 1.5 "), "stripped like a file's value");
        assertEquals(null, problem("positions.interval", "100"));
    }

    @Test
    void problemSaysWhatTheKeyExpects() {
        assertEquals("a port number from 1 to 65535", problem("usarsim.port", "0"));
        assertEquals("a number above 0", problem("distance.n", "0"));
        assertEquals("a whole number of milliseconds from 100 to 60000", problem("usarsim.timeout", "99"));
        assertEquals("a number of dB, 0 or more", problem("distance.margin", "-1"));
        assertEquals("a number of seconds, 0 or more", problem("distance.holdTime", "x"));
    }

    @Test
    void problemAgreesWithTheFileCheck() throws Exception {
        // the same rule: what problem() accepts, a file accepts, and what it refuses, a file refuses
        for (String key : modelDefaults().keySet()) {
            for (String value : new String[] {"", "0", "-1", "1", "99", "100", "70000", "abc", "1.5", "NaN"}) {
                boolean accepted = problem(key, value) == null;
                try {
                    ConfigFile.of(props(key, value), "t");
                    assertTrue(accepted, key + " = '" + value + "': the file accepts it, problem() does not");
                } catch (ConfigFileException e) {
                    assertFalse(accepted, key + " = '" + value + "': problem() accepts it, the file does not");
                    assertTrue(e.getMessage().endsWith(problem(key, value)), e.getMessage());
                }
            }
        }
    }

    @Test
    void modelDefaultsAreTheModelKeysOfTheDefaults() {
        Map<String, String> expected = new TreeMap<>(DEFAULTS);
        expected.keySet().removeIf(key -> key.startsWith("wss."));
        assertEquals(expected, modelDefaults());
    }

    /** The rule of a key: the server's, or the built-in models' (the obstacle model declares every one). */
    private static Setting rule(String key) {
        Setting server = Setting.find(ConfigKeys.SERVER, key);
        return server != null ? server : Setting.find(allDeclared(), key);
    }

    private static String problem(String key, String value) {
        return rule(key).problem(value);
    }

    /** The defaults of the built-in models' keys. */
    private static Map<String, String> modelDefaults() {
        Map<String, String> defaults = new TreeMap<>(Setting.defaults(new ObstaclePropagationModel().settings()));
        defaults.putAll(Setting.defaults(new ReplayPropagationModel().settings()));
        defaults.putAll(Setting.defaults(new org.usarsim.wss.model.rfcomms.RfCommsPropagationModel().settings()));
        return defaults;
    }

    // ---- modelValues() and hubConfig() ----

    @Test
    void modelSettingsHoldTheModelKeysAndNoWssKey() throws Exception {
        Properties properties = new Properties();
        properties.setProperty("wss.port", "0");
        properties.setProperty("wss.model", "ObstaclePropagationModel");
        properties.setProperty("usarsim.host", "10.0.0.7");
        properties.setProperty("distance.d0", "3.5");
        properties.setProperty("obstacle.cacheDistance", "0.25");
        Map<String, String> model = ConfigFile.of(properties, "t").modelValues().asMap();

        assertTrue(model.keySet().stream().noneMatch(key -> key.startsWith("wss.")), model.toString());
        assertTrue(model.keySet().stream().allMatch(key -> key.startsWith("positions") || key.startsWith("usarsim.")
                || key.startsWith("rosbridge.") || key.startsWith("distance.") || key.startsWith("obstacle.")
                || key.startsWith("shadowing.")), model.toString());
        assertEquals(Map.ofEntries(
                Map.entry("positions", "usarsim"),
                Map.entry("positions.interval", "1000"),
                Map.entry("usarsim.host", "10.0.0.7"),
                Map.entry("usarsim.port", "7435"),
                Map.entry("usarsim.timeout", "2000"),
                Map.entry("rosbridge.url", "ws://127.0.0.1:9090"),
                Map.entry("rosbridge.topic", "/gazebo/model_states"),
                Map.entry("rosbridge.type", ""),
                Map.entry("rosbridge.frame", "world"),
                Map.entry("rosbridge.names", ""),
                Map.entry("rosbridge.stale", "0"),
                Map.entry("rosbridge.grace", "10000"),
                Map.entry("rosbridge.maxMessage", "16"),
                Map.entry("obstacle.walls", ""),
                Map.entry("rosbridge.map", "/map"),
                Map.entry("distance.cutoff", "-93"),
                Map.entry("distance.pd0", "-49.67"),
                Map.entry("distance.n", "1"),
                Map.entry("distance.d0", "3.5"),
                Map.entry("distance.margin", "0"),
                Map.entry("distance.holdTime", "0"),
                Map.entry("obstacle.attenuation", "6.325"),
                Map.entry("obstacle.cacheDistance", "0.25"),
                Map.entry("obstacle.materials", "Hard_wall*=concrete, Medium_wall*=brick, Soft_wall*=drywall, *glass*=glass, *=concrete"),
                Map.entry("obstacle.loss", "concrete:15, brick:10, drywall:4, wood:4, glass:2, metal:30"),
                Map.entry("obstacle.heightBand", "0.1..2.0"),
                Map.entry("shadowing.sigma", "0"),
                Map.entry("shadowing.distance", "5")), model);
        assertEquals(3.5, ConfigFile.of(properties, "t").modelValues().getDouble("distance.d0", -1), 0);
    }

    @Test
    void hubConfigFromProperties() throws Exception {
        Properties properties = new Properties();
        properties.setProperty("wss.bindAddress", "127.0.0.1");
        properties.setProperty("wss.port", "4321");
        properties.setProperty("wss.chunkSize", "512");
        properties.setProperty("wss.matchSourceAddress", "False");
        properties.setProperty("wss.socketBuffer", "0");
        InetAddress local = InetAddress.getByName("127.0.0.1");
        assertEquals(new HubConfig(local, 4321, 512, 0, false, 600, 1000, HubConfig.MAX_PORTS_PER_ADDRESS, 30, Set.of(local), Map.of(),
                Map.of(), ShapingConfig.OFF, FixedSetup.NONE),
                ConfigFile.of(properties, "t").hubConfig());
    }

    @Test
    void operatorsAndForcedPairsFromProperties() throws Exception {
        Properties properties = new Properties();
        properties.setProperty("wss.operators", " 127.0.0.1 , 10.0.0.7,::1");
        properties.setProperty("wss.force.down", "R1:R2, Zed:Alpha");
        properties.setProperty("wss.force.up", " R2:R3 ,R3:R2");
        HubConfig config = ConfigFile.of(properties, "t").hubConfig();
        assertEquals(Set.of(InetAddress.getByName("127.0.0.1"), InetAddress.getByName("10.0.0.7"), InetAddress.getByName("::1")),
                config.operators());
        assertEquals(Map.of(RobotPair.of("R1", "R2"), Force.DOWN, RobotPair.of("Alpha", "Zed"), Force.DOWN,
                RobotPair.of("R2", "R3"), Force.UP), config.forced());
        properties.setProperty("wss.operators", "");
        assertEquals(Set.of(), ConfigFile.of(properties, "t").hubConfig().operators(), "empty: nobody");
    }

    @Test
    void theWildcardAddressAsAnOperatorIsRefusedClearly() {
        Properties properties = new Properties();
        properties.setProperty("wss.operators", "0.0.0.0");
        ConfigFileException e = assertThrows(ConfigFileException.class, () -> ConfigFile.of(properties, "my.properties"));
        assertEquals("my.properties: wss.operators = '0.0.0.0' is not a comma-separated list of IP addresses of clients"
                + " (not 0.0.0.0 or ::, which no client has) (empty: nobody)", e.getMessage());
    }

    @Test
    void aPairForcedBothWaysIsRefused() {
        Properties properties = new Properties();
        properties.setProperty("wss.force.down", "A:B,C:D");
        properties.setProperty("wss.force.up", "D:C");
        ConfigFileException e = assertThrows(ConfigFileException.class, () -> ConfigFile.of(properties, "my.properties"));
        assertEquals("my.properties: the pair C:D is in both wss.force.down and wss.force.up; force it one way", e.getMessage());
    }

    // ---- the chosen model's keys and the others' ----

    @Test
    void theChosenModelIsHandedItsOwnKeysOnlyAndTheOthersAreNoted() throws Exception {
        Properties properties = new Properties();
        properties.setProperty("wss.model", "DistanceOnlyPropagationModel");
        properties.setProperty("distance.n", "2");
        properties.setProperty("obstacle.attenuation", "3");
        ConfigFile settings = ConfigFile.of(properties, "t");
        Map<String, String> model = settings.modelValues().asMap();
        assertEquals("2", model.get("distance.n"));
        assertEquals(21, model.size(), "positions.*, usarsim.*, rosbridge.*, distance.* and shadowing.*: " + model);
        assertFalse(model.containsKey("obstacle.attenuation"), "not a setting of DistanceOnlyPropagationModel");
        assertEquals(List.of("obstacle.attenuation"), settings.ignoredKeys());
        assertEquals("3", settings.get("obstacle.attenuation"), "checked all the same");
        rejected("obstacle.attenuation", "-3");
    }

    @Test
    void aModelNotInTheCatalogIsReportedLaterAndItsKeysAreIgnored() throws Exception {
        Properties properties = new Properties();
        properties.setProperty("wss.model", "Nowhere");
        properties.setProperty("usarsim.port", "7000");
        ConfigFile settings = ConfigFile.of(properties, "t");
        assertEquals(Map.of(), settings.modelValues().asMap());
        assertEquals(List.of("usarsim.port"), settings.ignoredKeys());
    }

    @Test
    void theUnknownKeyErrorListsTheServersAndEveryModelsKeys() {
        ConfigFileException e = rejected("distance.nonsense", "1");
        assertTrue(e.getMessage().endsWith("known keys: " + String.join(", ", DEFAULTS.keySet().stream()
                .sorted(java.util.Comparator.comparingInt(ConfigFileTest::order)).toList())), e.getMessage());
    }

    /** The order the keys are declared in: the server's, then the models' in catalog order. */
    private static int order(String key) {
        return allDeclared().stream().map(Setting::key).toList().indexOf(key);
    }

    @Test
    void helpListsEveryKeyWithItsDefaultAndRule() {
        String help = ConfigKeys.help(ConfigFile.defaults().catalog());
        for (Setting setting : allDeclared()) {
            assertTrue(help.contains("  " + setting.key() + " = " + setting.defaultValue() + "\n      " + setting.expected()),
                    setting.key() + " in:\n" + help);
        }
        assertTrue(help.contains("model NoopPropagationModel: no settings"), help);
    }

    @Test
    void docsHeadlessListEveryDeclaredKeyWithItsDefault() throws IOException {
        String docs = Files.readString(Path.of("docs/headless.md"), StandardCharsets.UTF_8);
        for (Setting setting : allDeclared()) {
            String row = "| `" + setting.key() + "` | ";
            assertTrue(docs.contains(row), setting.key() + " has a row in docs/headless.md");
            String defaultCell = docs.substring(docs.indexOf(row) + row.length()).split(" \\| ")[0];
            assertTrue(defaultCell.contains(setting.defaultValue().isEmpty() ? "empty" : "`" + setting.defaultValue() + "`"),
                    setting.key() + ": docs say " + defaultCell + ", the code " + setting.defaultValue());
        }
    }

    /** The server's settings and every built-in model's. */
    private static List<Setting> allDeclared() {
        List<Setting> all = new java.util.ArrayList<>(ConfigKeys.SERVER);
        all.addAll(new ObstaclePropagationModel().settings());
        all.addAll(new ReplayPropagationModel().settings());
        all.addAll(new org.usarsim.wss.model.rfcomms.RfCommsPropagationModel().settings());
        return all;
    }

    // ---- bad values ----

    /** The message names the key and the value. */
    private static ConfigFileException rejected(String key, String value) {
        ConfigFileException e = assertThrows(ConfigFileException.class, () -> ConfigFile.of(props(key, value), "my.properties"),
                key + " = '" + value + "' should be rejected");
        String message = e.getMessage();
        assertTrue(message.contains(key), "names the key: " + message);
        assertTrue(message.contains("'" + value.strip() + "'"), "names the value: " + message);
        assertTrue(message.contains("my.properties"), "names the source: " + message);
        assertFalse(message.contains("\n"), "one line: " + message);
        return e;
    }

    @Test
    void unknownKey() {
        ConfigFileException e = rejected("wss.prot", "50001");
        assertTrue(e.getMessage().contains("unknown key"), e.getMessage());
        assertTrue(e.getMessage().contains("wss.port"), "lists the known keys: " + e.getMessage());
    }

    @Test
    void keysAreCaseSensitive() {
        rejected("WSS.PORT", "1");
    }

    @ParameterizedTest
    @CsvSource({
        "wss.port, abc", "wss.port, 5e4", "wss.port, 50000.0", "wss.port, 0x10",
        "usarsim.port, seven", "wss.chunkSize, lots",
        "distance.cutoff, low", "distance.pd0, '-49,67'", "distance.n, two",
        "distance.d0, 2m", "obstacle.attenuation, six", "obstacle.cacheDistance, one",
        "distance.cutoff, NaN", "distance.n, Infinity", "distance.pd0, -Infinity",
        "usarsim.interval, often", "usarsim.interval, 1000.5", "positions.interval, often", "usarsim.timeout, 2s",
        "distance.margin, some", "distance.holdTime, 1s", "distance.holdTime, NaN",
    })
    void notANumber(String key, String value) {
        rejected(key, value);
    }

    @ParameterizedTest
    @CsvSource({
        "wss.port, 70000", "wss.port, 65536", "wss.port, -1",
        "usarsim.port, 0", "usarsim.port, 65536",
        "wss.chunkSize, 0", "wss.chunkSize, 1048577", "wss.socketBuffer, -1", "wss.socketBuffer, 268435457",
        "distance.n, 0", "distance.n, -1",
        "distance.d0, -1", "distance.d0, 0",
        "obstacle.attenuation, -1", "obstacle.cacheDistance, -0.5",
        "usarsim.interval, 99", "usarsim.interval, 60001", "positions.interval, 99", "usarsim.timeout, 0", "usarsim.timeout, 60001",
        "distance.margin, -0.1", "distance.holdTime, -1",
    })
    void outOfRange(String key, String value) {
        rejected(key, value);
    }

    @ParameterizedTest
    @CsvSource({"wss.eventLog, yes", "wss.eventLog, 1", "wss.matchSourceAddress, on", "wss.matchSourceAddress, nope"})
    void badBoolean(String key, String value) {
        rejected(key, value);
    }

    @ParameterizedTest
    @CsvSource({"wss.logLevel, info", "wss.logLevel, DEBUG", "wss.logLevel, ALL", "wss.logLevel, 800"})
    void badLogLevel(String key, String value) {
        rejected(key, value);
    }

    @ParameterizedTest
    @CsvSource({
        "wss.portMemory, -2", "wss.portMemory, 31536001", "wss.portMemory, 10m", "wss.portMemory, 1.5",
        "wss.maxPortsPerRobot, 0", "wss.maxPortsPerRobot, 1000001", "wss.maxPortsPerRobot, many",
        "wss.deadPeerSeconds, -1", "wss.deadPeerSeconds, 86401", "wss.deadPeerSeconds, 30s",
        "wss.statsInterval, -1", "wss.statsInterval, 86401", "wss.statsInterval, 1.5",
    })
    void badRobotLimits(String key, String value) {
        rejected(key, value);
    }

    @Test
    void robotLimitsAtTheirEdges() throws Exception {
        Properties properties = new Properties();
        properties.setProperty("wss.portMemory", "-1");
        properties.setProperty("wss.maxPortsPerRobot", "1");
        properties.setProperty("wss.deadPeerSeconds", "0");
        HubConfig config = ConfigFile.of(properties, "t").hubConfig();
        assertEquals(List.of(-1, 1, 0), List.of(config.portMemorySeconds(), config.maxPortsPerRobot(), config.deadPeerSeconds()));
        properties.setProperty("wss.portMemory", "0");
        properties.setProperty("wss.deadPeerSeconds", "2");
        config = ConfigFile.of(properties, "t").hubConfig();
        assertEquals(List.of(0, 2), List.of(config.portMemorySeconds(), config.deadPeerSeconds()));
        assertEquals(0, ConfigFile.defaults().statsInterval(), "no statistics table unless asked for");
        properties.setProperty("wss.statsInterval", "86400");
        assertEquals(86400, ConfigFile.of(properties, "t").statsInterval());
    }

    @Test
    void emptyUsarsimHost() {
        rejected("usarsim.host", "");
        rejected("usarsim.host", "   ");
        rejected("usarsim.host", "my host");
    }

    @Test
    void emptyValues() {
        rejected("wss.model", "");
        rejected("wss.bindAddress", "");
        rejected("wss.port", "");
        rejected("distance.n", "");
    }

    @Test
    void badValueInAFile() throws Exception {
        Path file = write("wss.port=0\nwss.port=70000\n");
        ConfigFileException e = assertThrows(ConfigFileException.class, () -> ConfigFile.load(file));
        assertTrue(e.getMessage().contains("wss.port"), e.getMessage());
        assertTrue(e.getMessage().contains("70000"), e.getMessage());
        assertTrue(e.getMessage().contains(file.toString()), "names the file: " + e.getMessage());
    }

    @Test
    void distanceNZeroInAFile() throws Exception {
        Path file = write("distance.n=0\n");
        ConfigFileException e = assertThrows(ConfigFileException.class, () -> ConfigFile.load(file));
        assertTrue(e.getMessage().contains("distance.n = '0'"), e.getMessage());
    }

    @Test
    void missingFile() {
        Path file = dir.resolve("absent.properties");
        ConfigFileException e = assertThrows(ConfigFileException.class, () -> ConfigFile.load(file));
        assertTrue(e.getMessage().contains(file.toString()), e.getMessage());
    }

    @Test
    void malformedEscapeInAFile() throws Exception {
        Path file = write("usarsim.host=\\uZZZZ\n");
        ConfigFileException e = assertThrows(ConfigFileException.class, () -> ConfigFile.load(file));
        assertTrue(e.getMessage().contains(file.toString()), e.getMessage());
    }
}
