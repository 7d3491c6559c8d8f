package org.usarsim.wss.app;

import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.Reader;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.net.InetAddress;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Properties;
import java.util.function.Function;
import java.util.logging.Level;
import org.usarsim.wss.LogText;
import org.usarsim.wss.hub.HubConfig;
import org.usarsim.wss.model.ModelCatalog;
import org.usarsim.wss.model.PluginFolder;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.Setting;
import org.usarsim.wss.monitor.MonitorConfig;
import org.usarsim.wss.model.ModelSettings;

/**
 * A run's configuration as a properties file (--config FILE) gives it, over the built-in defaults:
 * the server's own {@code wss.*} settings, declared in {@link ConfigKeys} with the models'
 * {@link Setting} type, and the settings every model of the catalog declares
 * ({@code PropagationModel.settings()}); the hub's part is built by {@link HubConfigBuilder}.
 * The window takes its server settings from it too. Headless mode reads the defaults and one properties file,
 * nothing else, so a run is reproducible. A key is accepted when the server or a model of the
 * catalog declares it, its value when that declaration's rule accepts it; the chosen model
 * ({@code wss.model}) is handed the values of its own keys. docs/headless.md documents each key.
 */
public final class ConfigFile {

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
        ConfigKeys.SERVER.forEach(setting -> rules.put(setting.key(), setting));
        Map<String, String> values = new LinkedHashMap<>(Setting.defaults(ConfigKeys.SERVER));
        for (String key : keys) {
            if (rules.containsKey(key)) {
                values.put(key, checked(rules.get(key), properties.getProperty(key), source));
            } else if (key.startsWith(FixedPorts.ROBOT)) {
                values.put(key, properties.getProperty(key).strip());
            }
        }
        ConfigFile server = new ConfigFile(values, null, List.of());
        HubConfigBuilder hub = new HubConfigBuilder(values);
        hub.forcedPairs(source);
        hub.shaping(source);
        server.recordFile(source);
        hub.fixed(source);
        try {
            hub.checkFixedPortsFree();
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

    /** The base robots' routes are watched to ({@code wss.route.base}), null for none (docs/routes.md). */
    String routeBase() {
        String base = get(ConfigKeys.ROUTE_BASE).strip();
        return base.isEmpty() ? null : base;
    }

    /** The hub's configuration: the server's settings as {@link HubConfigBuilder} builds them. */
    HubConfig hubConfig() {
        return new HubConfigBuilder(values).build();
    }

    /** The wss.monitor.* settings (docs/monitor.md); checked against each other when the monitor opens. */
    MonitorConfig monitorConfig() {
        InetAddress bind;
        try {
            bind = InetAddress.getByName(get(MonitorConfig.BIND_ADDRESS)); // its rule checked it is an address
        } catch (java.net.UnknownHostException e) {
            throw new IllegalArgumentException(MonitorConfig.BIND_ADDRESS + ": " + e.getMessage(), e);
        }
        return new MonitorConfig(Integer.parseInt(get(MonitorConfig.PORT)), bind,
                path(get(MonitorConfig.TOKENS)), Integer.parseInt(get(MonitorConfig.MAX_CLIENTS)), path(get(MonitorConfig.KEYSTORE)),
                path(get(MonitorConfig.KEYSTORE_PASSWORD_FILE)));
    }

    private static Path path(String value) {
        return value == null || value.isBlank() ? null : Path.of(value.strip());
    }

    /**
     * Refuses a fixed port whose number something on this machine holds now (the window's Start
     * asks again as it starts a server: the number may have been taken since the file was read).
     *
     * @throws IllegalArgumentException as {@link HubConfigBuilder#checkFixedPortsFree()}
     */
    void checkFixedPortsFree() {
        new HubConfigBuilder(values).checkFixedPortsFree();
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
        for (String key : ConfigKeys.SHAPING_KEYS) {
            if (file.containsKey(key)) {
                set.put(key, get(key));
            }
        }
        return set;
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
