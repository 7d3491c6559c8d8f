package org.usarsim.wss.app;

import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.Reader;
import java.net.InetAddress;
import java.net.UnknownHostException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Optional;
import java.util.Properties;
import java.util.function.Predicate;
import java.util.logging.Level;
import org.usarsim.wss.hub.HubConfig;
import org.usarsim.wss.model.ModelSettings;

/**
 * Every property the server takes, its default and what values it accepts: the one place for
 * these rules. Headless mode reads the defaults and one properties file, nothing else, so a run
 * is reproducible. docs/headless.md documents each key.
 */
public final class Settings {

    /** A property's rule: its default and a check of a value (stripped of surrounding whitespace). */
    private record Key(String defaultValue, String expected, Predicate<String> check) {
    }

    private static final Map<String, Key> KEYS = new LinkedHashMap<>();

    static {
        KEYS.put("wss.port", new Key("50000", "a port number from 0 to 65535 (0: any free port)", v -> isInt(v, 0, 65535)));
        KEYS.put("wss.bindAddress", new Key("0.0.0.0", "an IP address of this machine (0.0.0.0: all)", Settings::isAddress));
        KEYS.put("wss.model", new Key("NoopPropagationModel", "the name of a propagation model", v -> !v.isEmpty()));
        KEYS.put("wss.eventLog", new Key("false", "true or false", Settings::isBoolean));
        KEYS.put("wss.eventLogDir", new Key(".", "a directory", v -> !v.isEmpty()));
        KEYS.put("wss.matchSourceAddress", new Key("true", "true or false", Settings::isBoolean));
        KEYS.put("wss.chunkSize", new Key("65536", "a whole number of bytes from 1 to 1048576", v -> isInt(v, 1, 1024 * 1024)));
        KEYS.put("wss.socketBuffer", new Key("4194304", "a whole number of bytes from 0 to 268435456 (0: the OS decides)", v -> isInt(v, 0, 256 * 1024 * 1024)));
        KEYS.put("wss.pluginDir", new Key("", "an existing directory (empty: none)", v -> v.isEmpty() || isDirectory(v)));
        KEYS.put("wss.portMemory", new Key("600", "a whole number of seconds from -1 to 31536000 (0: forget at once, -1: never)", v -> isInt(v, -1, 31_536_000)));
        KEYS.put("wss.maxPortsPerRobot", new Key("1000", "a whole number from 1 to 1000000", v -> isInt(v, 1, 1_000_000)));
        KEYS.put("wss.deadPeerSeconds", new Key("30", "a whole number of seconds from 2 to 86400, or 0 (the OS's keepalive)", v -> v.equals("0") || isInt(v, 2, 86400)));
        KEYS.put("wss.logLevel", new Key("INFO", "one of SEVERE, WARNING, INFO, FINE, FINER, FINEST", Settings::isLevel));
        KEYS.put("usarsim.host", new Key("127.0.0.1", "a host name or IP address", v -> !v.isEmpty() && v.chars().noneMatch(Character::isWhitespace)));
        KEYS.put("usarsim.port", new Key("7435", "a port number from 1 to 65535", v -> isInt(v, 1, 65535)));
        KEYS.put("usarsim.interval", new Key("1000", "a whole number of milliseconds from 100 to 60000", v -> isInt(v, 100, 60000)));
        KEYS.put("usarsim.timeout", new Key("2000", "a whole number of milliseconds from 100 to 60000", v -> isInt(v, 100, 60000)));
        KEYS.put("distance.cutoff", new Key("-93", "a number (dBm)", v -> isNumber(v, Double.NEGATIVE_INFINITY, false)));
        KEYS.put("distance.pd0", new Key("-49.67", "a number (dBm)", v -> isNumber(v, Double.NEGATIVE_INFINITY, false)));
        KEYS.put("distance.n", new Key("1", "a number above 0", v -> isNumber(v, 0, true)));
        KEYS.put("distance.d0", new Key("2", "a number of metres above 0", v -> isNumber(v, 0, true)));
        KEYS.put("distance.margin", new Key("0", "a number of dB, 0 or more", v -> isNumber(v, 0, false)));
        KEYS.put("distance.holdTime", new Key("0", "a number of seconds, 0 or more", v -> isNumber(v, 0, false)));
        KEYS.put("obstacle.attenuation", new Key("6.325", "a number of dB, 0 or more", v -> isNumber(v, 0, false)));
        KEYS.put("obstacle.cacheDistance", new Key("1.0", "a number of metres, 0 or more", v -> isNumber(v, 0, false)));
    }

    private final Map<String, String> values;

    private Settings(Map<String, String> values) {
        this.values = values;
    }

    /** The built-in defaults. */
    static Settings defaults() {
        Map<String, String> values = new LinkedHashMap<>();
        KEYS.forEach((key, rule) -> values.put(key, rule.defaultValue()));
        return new Settings(values);
    }

    /** The defaults overridden by a properties file. */
    static Settings load(Path file) throws SettingsException {
        Properties properties = new Properties();
        try (InputStream in = Files.newInputStream(file); Reader reader = new InputStreamReader(in, StandardCharsets.UTF_8)) {
            properties.load(reader);
        } catch (IOException | IllegalArgumentException e) {
            throw new SettingsException("cannot read " + file + ": " + e.getMessage());
        }
        return of(properties, file.toString());
    }

    /** The defaults overridden by these properties; {@code source} names them in errors. */
    static Settings of(Properties properties, String source) throws SettingsException {
        Settings settings = defaults();
        for (String key : properties.stringPropertyNames().stream().sorted().toList()) {
            String value = properties.getProperty(key).strip();
            Key rule = KEYS.get(key);
            if (rule == null) {
                throw new SettingsException(source + ": unknown key " + key + " (value '" + value + "'); known keys: "
                        + String.join(", ", KEYS.keySet()));
            }
            if (!rule.check().test(value)) {
                throw new SettingsException(source + ": " + key + " = '" + value + "' is not " + rule.expected());
            }
            settings.values.put(key, value);
        }
        return settings;
    }

    /**
     * What is wrong with a value for a key, for the GUI's dialogs: null when the value (stripped of
     * surrounding whitespace) is accepted, else the words for what the key expects, e.g.
     * "a port number from 1 to 65535".
     *
     * @throws IllegalArgumentException for a key that is not a property
     */
    public static String problem(String key, String value) {
        Key rule = KEYS.get(key);
        if (rule == null) {
            throw new IllegalArgumentException("unknown key " + key);
        }
        return rule.check().test(value.strip()) ? null : rule.expected();
    }

    /** The default of every key a model reads (usarsim.*, distance.*, obstacle.*), sorted by key. */
    public static Map<String, String> modelDefaults() {
        return Collections.unmodifiableMap(defaults().modelSettings().asMap());
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
                    Integer.parseInt(get("wss.maxPortsPerRobot")), Integer.parseInt(get("wss.deadPeerSeconds")));
        } catch (UnknownHostException e) {
            throw new IllegalStateException("wss.bindAddress was checked", e);
        }
    }

    /** What the models read: every usarsim.*, distance.* and obstacle.* value. */
    ModelSettings modelSettings() {
        Map<String, String> model = new LinkedHashMap<>(values);
        model.keySet().removeIf(key -> key.startsWith("wss."));
        return new ModelSettings(model);
    }

    private static boolean isInt(String value, int min, int max) {
        try {
            int number = Integer.parseInt(value);
            return number >= min && number <= max;
        } catch (NumberFormatException e) {
            return false;
        }
    }

    private static boolean isNumber(String value, double min, boolean exclusive) {
        try {
            double number = Double.parseDouble(value);
            return Double.isFinite(number) && (exclusive ? number > min : number >= min);
        } catch (NumberFormatException e) {
            return false;
        }
    }

    private static boolean isDirectory(String value) {
        try {
            return Files.isDirectory(Path.of(value));
        } catch (InvalidPathException e) {
            return false;
        }
    }

    private static boolean isBoolean(String value) {
        return value.equalsIgnoreCase("true") || value.equalsIgnoreCase("false");
    }

    private static boolean isLevel(String value) {
        return switch (value) {
            case "SEVERE", "WARNING", "INFO", "FINE", "FINER", "FINEST" -> true;
            default -> false;
        };
    }

    private static boolean isAddress(String value) {
        if (value.isEmpty()) {
            return false;
        }
        try {
            InetAddress.getByName(value);
            return true;
        } catch (UnknownHostException e) {
            return false;
        }
    }
}
