package org.usarsim.wss.app;

import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.Reader;
import java.net.InetAddress;
import java.net.UnknownHostException;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collection;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Properties;
import java.util.Set;
import java.util.function.Function;
import java.util.logging.Level;
import org.usarsim.wss.LogText;
import org.usarsim.wss.hub.FixedSetup;
import org.usarsim.wss.hub.core.FixedPort;
import org.usarsim.wss.hub.core.Force;
import org.usarsim.wss.hub.HubConfig;
import org.usarsim.wss.model.ModelCatalog;
import org.usarsim.wss.model.PluginFolder;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.model.Setting;
import org.usarsim.wss.shaping.LossTable;
import org.usarsim.wss.shaping.RateTable;
import org.usarsim.wss.shaping.ShapingConfig;
import org.usarsim.wss.model.ModelSettings;
import org.usarsim.wss.protocol.ControlPort;

/**
 * A run's configuration as a properties file (--config FILE) gives it, over the built-in defaults:
 * the server's own {@code wss.*} settings, declared here with the models' {@link Setting} type,
 * and the settings every model of the catalog declares ({@code PropagationModel.settings()}).
 * The window takes its server settings from it too. Headless mode reads the defaults and one properties file,
 * nothing else, so a run is reproducible. A key is accepted when the server or a model of the
 * catalog declares it, its value when that declaration's rule accepts it; the chosen model
 * ({@code wss.model}) is handed the values of its own keys. docs/headless.md documents each key.
 */
public final class ConfigFile {

    /** The link shaping keys, read together by ShapingConfig. */
    private static final List<String> SHAPING_KEYS = List.of(ShapingConfig.SHAPING, ShapingConfig.RATES, ShapingConfig.DELAY_MS,
            ShapingConfig.AIRTIME, ShapingConfig.QUEUE_MS);
    /** What wss.shaping.loss takes, in words. */
    private static final String LOSS_WORDS = "rows dBm:percent from the strongest signal to the weakest (-85:1,-87:10,-90:50)";
    /** What wss.shaping.rates takes, in words. */
    private static final String RATES_WORDS = "steps dBm:rate from the strongest signal to the weakest (-72:54M,-77:36M)";

    /** The server's own settings. */
    static final List<Setting> SERVER = List.of(
            Setting.integer("wss.port", "Control port", ControlPort.DEFAULT).from(0).to(65535).noun("a port number").note("0: any free port")
                    .help("The control port robots connect to; 0 lets the OS choose one, which the start line names"),
            Setting.address("wss.bindAddress", "Bind address", Defaults.ALL_INTERFACES).note(Defaults.ALL_INTERFACES + ": all")
                    .help("The address the control port and every WSS port listen on"),
            Setting.text("wss.model", "Model", ModelCatalog.DEFAULT_MODEL).noun("the name of a propagation model")
                    .help("The propagation model: its name, or its simple or fully qualified class name"),
            Setting.bool("wss.eventLog", "Event log", false).help("Write the CSV event log, a new file per run"),
            Setting.text("wss.eventLogDir", "Event log folder", ".").noun("a directory")
                    .help("Where the event log file goes (created if missing)"),
            Setting.text("wss.record", "Record to", "").orEmpty("none").noun("a file path")
                    .help("Record the run to this file (docs/replay.md; .gz: compressed); an existing file is kept and"
                            + " the start time added to the new one's name"),
            Setting.bool("wss.matchSourceAddress", "Match source address", true)
                    .help("Accept a connection on a WSS port only from the source robot's IP address"),
            Setting.integer("wss.chunkSize", "Chunk size", 65536).from(1).to(1024 * 1024).unit("bytes")
                    .help("The most bytes a link reads, and then writes, at a time in each direction"),
            Setting.integer("wss.socketBuffer", "Socket buffer", 4194304).from(0).to(256 * 1024 * 1024).unit("bytes")
                    .note("0: the OS decides").help("The send and receive buffer size of both sockets of every link"),
            Setting.directory("wss.pluginDir", "Plugin folder", "").orEmpty("none")
                    .help("A folder of model plugin jars, loaded after those of the plugins/ folder beside wss.jar"),
            Setting.integer("wss.portMemory", "Port memory", 600).from(-1).to(31_536_000).unit("s")
                    .note("0: forget at once, -1: never")
                    .help("How long the WSS ports of a robot that left keep their numbers"),
            Setting.integer("wss.maxPortsPerRobot", "WSS ports per robot", 1000).from(1).to(1_000_000)
                    .help("The most WSS ports one robot may hold as source"),
            Setting.integer("wss.maxPortsPerAddress", "WSS ports per address", HubConfig.MAX_PORTS_PER_ADDRESS).from(1).to(10_000_000)
                    .help("The most WSS ports the robots registered from one IP address may hold as source, together"),
            Setting.integer("wss.deadPeerSeconds", "Dead peer detection", 30).from(0).to(86400).unit("s")
                    .note("0: the OS's keepalive")
                    .help("Within how long keepalive finds a robot whose machine vanished"),
            Setting.integer("wss.statsInterval", "Statistics interval", Defaults.STATS_INTERVAL).from(0).to(86400).unit("s")
                    .note("0: never").help("Every so many seconds the headless log shows the statistics of every pair of robots"),
            Setting.addresses("wss.operators", "Operators", "127.0.0.1").orEmpty("nobody")
                    .help("The addresses whose control connections may force pairs (FORCE, docs/protocol.md section 7)"),
            Setting.pairs("wss.force.down", "Forced down", "").orEmpty("none")
                    .help("Pairs of robots forced down from the start, even in range, until an operator releases them"),
            Setting.text("wss.force.up", "Forced up", "").orEmpty("none")
                    .noun(ForcedUp.WORDS)
                    .help("Pairs of robots forced up from the start, whatever the model says, until an operator releases them;"
                            + " with links shaped, A:B:RATE:DELAY pins the pair's rate and delay (docs/shaping.md)"),
            Setting.choice(ShapingConfig.SHAPING, "Link shaping", "off", List.of("off", "on"))
                    .help("Shape every link like radio: rate and delay from the signal, a robot's airtime shared (docs/shaping.md)"),
            Setting.text(ShapingConfig.RATES, "Rates by strength", RateTable.DEFAULT.toString())
                    .noun(RATES_WORDS)
                    .help("A pair whose strength is at or above a step's dBm gets its rate; below the last, the last"),
            Setting.integer(ShapingConfig.DELAY_MS, "Delay", ShapingConfig.DEFAULT_DELAY_MS)
                    .from(ShapingConfig.MIN_DELAY_MS).to(ShapingConfig.MAX_DELAY_MS).unit("ms")
                    .help("Bytes reach the target no sooner than this after the WSS read them, plus their time on the air"),
            Setting.bool(ShapingConfig.AIRTIME, "Shared airtime", true)
                    .help("A robot's radio is one channel all its links share, by time"),
            Setting.integer(ShapingConfig.QUEUE_MS, "Queue", ShapingConfig.DEFAULT_QUEUE_MS)
                    .from(ShapingConfig.MIN_QUEUE_MS).to(ShapingConfig.MAX_QUEUE_MS).unit("ms")
                    .help("The most a shaped link holds each way beyond its delay, in time at its rate (a radio's queue)"),
            Setting.text(ShapingConfig.LOSS, "Loss by strength", LossTable.DEFAULT.toString()).orEmpty("no loss")
                    .noun(LOSS_WORDS)
                    .help("With links shaped, a UDP datagram of a pair whose strength is at or below a row's dBm is lost with"
                            + " that row's percent, the last such row counting (docs/shaping.md); TCP is never dropped"),
            Setting.text(FixedPorts.KEY, "Fixed ports", "").orEmpty("none").noun(FixedPort.WORDS)
                    .help("WSS ports made at Start and kept, between robots declared with wss.robot.NAME = ADDRESS"
                            + " (default address 127.0.0.1; docs/fixed-ports.md)"),
            Setting.integer(FixedPorts.UDP_IDLE, "UDP session expiry", FixedSetup.DEFAULT_UDP_IDLE_SECONDS).from(1).to(86400).unit("s")
                    .help("A fixed UDP port forgets a sender (and closes its socket toward the target) after this long without"
                            + " a datagram either way"),
            Setting.choice("wss.logLevel", "Log level", "INFO", List.of("SEVERE", "WARNING", "INFO", "FINE", "FINER", "FINEST"))
                    .help("How much the log says; FINE adds every control command and its reply"));

    private final Map<String, String> values;
    private final ModelCatalog catalog;
    private final List<String> ignored;

    private ConfigFile(Map<String, String> values, ModelCatalog catalog, List<String> ignored) {
        this.values = values;
        this.catalog = catalog;
        this.ignored = ignored;
    }

    /** The built-in defaults, with the built-in models and those of the plugins folder beside the code. */
    static ConfigFile defaults() {
        try {
            return of(new Properties(), "the defaults");
        } catch (ConfigFileException e) {
            throw new IllegalStateException("a default breaks its own rule: " + e.getMessage(), e);
        }
    }

    /** The defaults overridden by a properties file, with the catalog {@link #modelsFor} gives. */
    static ConfigFile load(Path file) throws ConfigFileException {
        return of(read(file), file.toString());
    }

    /** The properties of a file. */
    static Properties read(Path file) throws ConfigFileException {
        Properties properties = new Properties();
        try (InputStream in = Files.newInputStream(file); Reader reader = new InputStreamReader(in, StandardCharsets.UTF_8.newDecoder())) {
            properties.load(reader);
        } catch (CharacterCodingException e) {
            throw new ConfigFileException("cannot read " + file + ": it is not UTF-8 text (write it in UTF-8, or use \\uXXXX escapes)");
        } catch (IOException | IllegalArgumentException e) {
            throw new ConfigFileException("cannot read " + file + ": " + e.getMessage());
        }
        return properties;
    }

    /** The defaults overridden by these properties, with the catalog {@link #modelsFor} gives. */
    static ConfigFile of(Properties properties, String source) throws ConfigFileException {
        return of(properties, source, ConfigFile::modelsFor);
    }

    /**
     * The defaults overridden by these properties; {@code source} names them in errors. The
     * {@code wss.*} values are checked first; then {@code catalogFor} is asked for the models,
     * given those server values (the plugin folder, the log level), and every other key is checked
     * with the rule of the model that declares it: the chosen model's own declaration first, then
     * the first model's of the catalog that declares the key.
     */
    static ConfigFile of(Properties properties, String source, Function<ConfigFile, ModelCatalog> catalogFor)
            throws ConfigFileException {
        List<String> keys = properties.stringPropertyNames().stream().sorted().toList();
        Map<String, Setting> rules = new LinkedHashMap<>();
        SERVER.forEach(setting -> rules.put(setting.key(), setting));
        Map<String, String> values = new LinkedHashMap<>(Setting.defaults(SERVER));
        for (String key : keys) {
            if (rules.containsKey(key)) {
                values.put(key, checked(rules.get(key), properties.getProperty(key), source));
            } else if (key.startsWith(FixedPorts.ROBOT)) {
                values.put(key, properties.getProperty(key).strip());
            }
        }
        ConfigFile server = new ConfigFile(values, null, List.of());
        server.forcedPairs(source);
        server.shaping(source);
        server.recordFile(source);
        server.fixed(source);
        try {
            server.checkFixedPortsFree();
        } catch (IllegalArgumentException e) {
            throw new ConfigFileException(source + ": " + e.getMessage());
        }
        ModelCatalog catalog = catalogFor.apply(server);
        PropagationModel chosen = catalog.find(values.get("wss.model"));
        List<Setting> own = chosen == null ? List.of() : chosen.settings();
        own.forEach(setting -> rules.putIfAbsent(setting.key(), setting));
        for (PropagationModel model : catalog.models()) {
            model.settings().forEach(setting -> rules.putIfAbsent(setting.key(), setting));
        }
        rules.forEach((key, rule) -> values.putIfAbsent(key, rule.defaultValue()));
        List<String> ignored = new ArrayList<>();
        for (String fileKey : keys) {
            String value = properties.getProperty(fileKey).strip();
            String key = renamed(fileKey, rules.values());
            if (!key.equals(fileKey) && properties.containsKey(key)) {
                throw new ConfigFileException(source + ": " + fileKey + " is the old name of " + key + "; set only " + key);
            }
            Setting rule = rules.get(key);
            if (rule == null && key.startsWith(FixedPorts.ROBOT)) {
                continue;
            }
            if (rule == null) {
                throw new ConfigFileException(source + ": unknown key " + key + " (value '" + value + "'); known keys: "
                        + String.join(", ", rules.keySet()));
            }
            if (!key.startsWith("wss.")) {
                values.put(key, checked(rule, fileKey, value, source));
                if (Setting.find(own, key) == null) {
                    ignored.add(key);
                }
            }
        }
        return new ConfigFile(values, catalog, List.copyOf(ignored));
    }

    /** The key a file's key stands for: itself, or the setting's whose old name it is ({@link Setting#alias()}). */
    private static String renamed(String fileKey, Collection<Setting> rules) {
        if (rules.stream().anyMatch(rule -> rule.key().equals(fileKey))) {
            return fileKey;
        }
        Setting renamed = Setting.findAlias(rules, fileKey);
        return renamed == null ? fileKey : renamed.key();
    }

    private static String checked(Setting rule, String value, String source) throws ConfigFileException {
        return checked(rule, rule.key(), value, source);
    }

    /** As {@link #checked(Setting, String, String)}, the value given under {@code fileKey}, the rule's key or its old name. */
    private static String checked(Setting rule, String fileKey, String value, String source) throws ConfigFileException {
        String stripped = value.strip();
        String problem = rule.problem(stripped);
        if (problem != null) {
            throw new ConfigFileException(source + ": " + fileKey + " = '" + stripped + "' is not " + problem
                    + (fileKey.equals(rule.key()) ? "" : " (" + fileKey + " is the old name of " + rule.key() + ")"));
        }
        return stripped;
    }

    /**
     * The models a headless run chooses from: the built-in ones, then the plugins of the folder
     * beside the code (plugins/ beside wss.jar), then those of wss.pluginDir.
     */
    static ModelCatalog modelsFor(ConfigFile server) {
        List<Path> pluginFolders = new ArrayList<>();
        PluginFolder.besideCodeOf(Main.class).ifPresent(pluginFolders::add);
        server.pluginDir().ifPresent(pluginFolders::add);
        return ModelCatalog.load(Main.class.getClassLoader(), pluginFolders);
    }

    /**
     * Every key a properties file may hold, for {@code --help}: the server's, then each model's
     * of the catalog (a key shared with a model above is named, not repeated), each with its
     * default, what it accepts and its help.
     */
    static String help(ModelCatalog catalog) {
        StringBuilder text = new StringBuilder("properties of --config FILE (docs/headless.md):\n");
        SERVER.forEach(setting -> describe(text, setting));
        Set<String> listed = new HashSet<>();
        for (PropagationModel model : catalog.models()) {
            List<Setting> settings = model.settings();
            text.append("model ").append(model.name()).append(settings.isEmpty() ? ": no settings" : ":").append('\n');
            List<String> shared = settings.stream().map(Setting::key).filter(listed::contains).toList();
            if (!shared.isEmpty()) {
                text.append("  ").append(String.join(", ", shared)).append(": as above\n");
            }
            settings.stream().filter(setting -> listed.add(setting.key())).forEach(setting -> describe(text, setting));
        }
        return text.toString();
    }

    private static void describe(StringBuilder text, Setting setting) {
        text.append("  ").append(setting.key()).append(" = ").append(setting.defaultValue()).append('\n')
                .append("      ").append(setting.expected()).append(setting.help().isEmpty() ? "" : ". " + setting.help()).append('\n');
    }

    /** The models this configuration was checked against. */
    ModelCatalog catalog() {
        return catalog;
    }

    /**
     * The keys the file set that the chosen model does not declare (another model of the catalog
     * does): checked, then not handed to the model. Headless warns of each.
     */
    List<String> ignoredKeys() {
        return ignored;
    }

    String get(String key) {
        return values.get(key);
    }

    String modelName() {
        return get("wss.model");
    }

    boolean eventLog() {
        return Boolean.parseBoolean(get("wss.eventLog"));
    }

    Path eventLogDir() {
        return Path.of(get("wss.eventLogDir"));
    }

    /** Refuses a wss.record the OS cannot take as a file name, or that names a folder. */
    private void recordFile(String source) throws ConfigFileException {
        String value = get("wss.record");
        if (value.isEmpty()) {
            return;
        }
        try {
            if (Files.isDirectory(Path.of(value))) {
                throw new ConfigFileException(source + ": wss.record = '" + value + "' is not a file to record to: it is a folder");
            }
        } catch (InvalidPathException e) {
            throw new ConfigFileException(source + ": wss.record = '" + LogText.escape(value) + "' is not a file path: " + e.getReason());
        }
    }

    /** The file wss.record names, to record each run to; empty when none is named. */
    Optional<Path> record() {
        String value = get("wss.record");
        return value.isEmpty() ? Optional.empty() : Optional.of(Path.of(value));
    }

    /** Seconds between two statistics tables in the headless log; 0: never. */
    int statsInterval() {
        return Integer.parseInt(get("wss.statsInterval"));
    }

    /** The folder named by wss.pluginDir, whose jars are loaded as model plugins; empty when none is named. */
    Optional<Path> pluginDir() {
        String value = get("wss.pluginDir");
        return value.isEmpty() ? Optional.empty() : Optional.of(Path.of(value));
    }

    Level logLevel() {
        return Level.parse(get("wss.logLevel"));
    }

    HubConfig hubConfig() {
        try {
            return new HubConfig(InetAddress.getByName(get("wss.bindAddress")), Integer.parseInt(get("wss.port")),
                    Integer.parseInt(get("wss.chunkSize")), Integer.parseInt(get("wss.socketBuffer")),
                    Boolean.parseBoolean(get("wss.matchSourceAddress")), Integer.parseInt(get("wss.portMemory")),
                    Integer.parseInt(get("wss.maxPortsPerRobot")), Integer.parseInt(get("wss.maxPortsPerAddress")),
                    Integer.parseInt(get("wss.deadPeerSeconds")), Set.copyOf(listed(get("wss.operators"), Setting::addressList)),
                    forcedPairs(null), ForcedUp.parse(get("wss.force.up")).pins(), shaping(null), fixed(null));
        } catch (UnknownHostException | ConfigFileException e) {
            throw new IllegalStateException("wss.bindAddress, wss.operators, wss.force.*, wss.shaping.*, wss.robot.* and wss.fixed were checked", e);
        }
    }

    /** The shaping settings, checked together (docs/shaping.md). */
    private ShapingConfig shaping(String source) throws ConfigFileException {
        Map<String, String> shapingValues = new LinkedHashMap<>();
        for (String key : SHAPING_KEYS) {
            shapingValues.put(key, get(key));
        }
        try {
            RateTable.parse(get(ShapingConfig.RATES));
        } catch (IllegalArgumentException e) {
            throw new ConfigFileException(source + ": " + ShapingConfig.RATES + " = '" + get(ShapingConfig.RATES) + "' is not "
                    + RATES_WORDS + ": " + e.getMessage());
        }
        shapingValues.put(ShapingConfig.LOSS, get(ShapingConfig.LOSS));
        try {
            LossTable.parse(get(ShapingConfig.LOSS));
        } catch (IllegalArgumentException e) {
            throw new ConfigFileException(source + ": " + ShapingConfig.LOSS + " = '" + get(ShapingConfig.LOSS) + "' is not "
                    + LOSS_WORDS + ": " + e.getMessage());
        }
        try {
            return ShapingConfig.from(shapingValues);
        } catch (IllegalArgumentException e) {
            throw new ConfigFileException(source + ": " + e.getMessage());
        }
    }

    /**
     * The model keys (not {@code wss.*}) that {@code file}, the properties this configuration was
     * read from, sets, with their checked values: what the window puts over the stored model settings.
     */
    ModelSettings modelKeysSetBy(Properties file) {
        List<Setting> rules = new ArrayList<>();
        catalog.models().forEach(model -> rules.addAll(model.settings()));
        Map<String, String> set = new LinkedHashMap<>();
        file.stringPropertyNames().stream().filter(key -> !key.startsWith("wss.")).sorted()
                .map(key -> renamed(key, rules)).forEach(key -> set.put(key, get(key)));
        return new ModelSettings(set);
    }

    /**
     * The link shaping keys ({@code wss.shaping*}) that {@code file}, the properties this
     * configuration was read from, sets, with their checked values: what the window puts over its
     * stored link shaping.
     */
    Map<String, String> shapingKeysSetBy(Properties file) {
        Map<String, String> set = new LinkedHashMap<>();
        for (String key : SHAPING_KEYS) {
            if (file.containsKey(key)) {
                set.put(key, get(key));
            }
        }
        return set;
    }

    /**
     * Refuses a fixed port whose number something on this machine holds now: checked as the file
     * is read, and again as the window's Start starts a server (the number may have been taken since).
     *
     * @throws IllegalArgumentException {@code wss.fixed = '...' is not ...: tcp A->B:1883@11883: tcp port 11883 is in use (why)}
     */
    void checkFixedPortsFree() {
        HubConfig hub = hubConfig();
        FixedPorts.checkFree(hub.fixed(), get(FixedPorts.KEY), hub.bindAddress());
    }

    /** The declared robots and the fixed ports, checked together (docs/fixed-ports.md). */
    private FixedSetup fixed(String source) throws ConfigFileException {
        Map<String, String> robots = new LinkedHashMap<>();
        values.keySet().stream().filter(key -> key.startsWith(FixedPorts.ROBOT)).sorted().forEach(key -> robots.put(key, get(key)));
        try {
            return FixedPorts.setup(robots, get(FixedPorts.KEY), Integer.parseInt(get(FixedPorts.UDP_IDLE)),
                    Integer.parseInt(get("wss.port")), InetAddress.getByName(get("wss.bindAddress")));
        } catch (IllegalArgumentException e) {
            throw new ConfigFileException(source + ": " + e.getMessage());
        } catch (UnknownHostException e) {
            throw new IllegalStateException("wss.bindAddress was checked", e);
        }
    }

    /**
     * The pairs of wss.force.down and wss.force.up, each checked by its rule before.
     *
     * @throws ConfigFileException when a pair is in both (a bad configuration of {@code source})
     */
    private Map<RobotPair, Force> forcedPairs(String source) throws ConfigFileException {
        Map<RobotPair, Force> forced = new LinkedHashMap<>();
        listed(get("wss.force.down"), RobotPair::listOf).forEach(pair -> forced.put(pair, Force.DOWN));
        ForcedUp up;
        try {
            up = ForcedUp.parse(get("wss.force.up"));
        } catch (IllegalArgumentException e) {
            throw new ConfigFileException(source + ": wss.force.up = '" + get("wss.force.up") + "' is not " + e.getMessage());
        }
        for (RobotPair pair : up.pairs()) {
            if (forced.put(pair, Force.UP) == Force.DOWN) {
                throw new ConfigFileException(source + ": the pair " + pair.first() + ":" + pair.second()
                        + " is in both wss.force.down and wss.force.up; force it one way");
            }
        }
        return forced;
    }

    /** The items of a list setting's value, checked by its rule before: none when it is empty. */
    private static <T> List<T> listed(String value, Function<String, List<T>> parse) {
        return value.isEmpty() ? List.of() : parse.apply(value);
    }

    /** What the chosen model is handed: the value of each key it declares; none when there is no such model. */
    ModelSettings modelValues() {
        PropagationModel model = catalog.find(modelName());
        Map<String, String> own = new LinkedHashMap<>();
        if (model != null) {
            model.settings().forEach(setting -> own.put(setting.key(), values.get(setting.key())));
        }
        return new ModelSettings(own);
    }
}
