package org.usarsim.wss.model;

import java.net.InetAddress;
import java.net.UnknownHostException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.Collection;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;

/**
 * One setting a model (or the server) declares: its key, a label for dialogs, its type, default,
 * allowed range, unit and a line of help. {@link #problem} is the one rule for its values, used by
 * the headless properties file, the GUI's dialogs and stored preferences alike; its words say what
 * is expected ("a whole number of milliseconds from 100 to 60000").
 *
 * <p>Declared with a factory and refinements, each returning a new, immutable setting:
 * <pre>
 * Setting.integer("usarsim.port", "Port", 7435).from(1).to(65535).noun("a port number").help("...")
 * Setting.number("distance.d0", "d0", "2").above(0).unit("m").help("...")
 * </pre>
 */
public final class Setting {

    /** What a value is. Values are always strings, stripped of surrounding whitespace. */
    public enum Type {
        /** A whole number ({@code int}); see {@link #from}, {@link #to}. */
        INTEGER,
        /** A finite decimal number ({@code double}); see {@link #from}, {@link #above}, {@link #to}, {@link #below}. */
        NUMBER,
        /** {@code true} or {@code false}, in any case; a check box in the dialogs. */
        BOOLEAN,
        /** Any text that is not empty. */
        TEXT,
        /** A host name or an IP address: not empty, no whitespace. */
        HOST,
        /** An IP address of this machine, or a name that resolves to one. */
        ADDRESS,
        /** An existing directory. */
        DIRECTORY,
        /** One of a fixed list of words. */
        CHOICE,
        /** A comma-separated list of IP addresses, written as numbers ({@link #addressList}). */
        ADDRESSES,
        /** A comma-separated list of robot pairs {@code A:B} ({@link RobotPair#listOf}). */
        PAIRS
    }

    private final String key;
    private final String label;
    private final Type type;
    private final String defaultValue;
    private final List<String> choices;
    // Set by the refinements, each on a fresh copy: a setting never changes once returned.
    private Bounds bounds = Bounds.NONE;
    private String unit;
    private String help = "";
    private String noun;
    private String note;
    private boolean emptyAllowed;
    private String alias;

    private Setting(String key, String label, Type type, String defaultValue, List<String> choices) {
        this.key = Objects.requireNonNull(key, "key");
        this.label = Objects.requireNonNull(label, "label");
        this.type = Objects.requireNonNull(type, "type");
        this.defaultValue = Objects.requireNonNull(defaultValue, "defaultValue").strip();
        this.choices = List.copyOf(choices);
    }

    private static Setting of(String key, String label, Type type, String defaultValue) {
        return new Setting(key, label, type, defaultValue, List.of());
    }

    /** A copy to refine. */
    private Setting copy() {
        Setting copy = new Setting(key, label, type, defaultValue, choices);
        copy.bounds = bounds;
        copy.unit = unit;
        copy.help = help;
        copy.noun = noun;
        copy.note = note;
        copy.emptyAllowed = emptyAllowed;
        copy.alias = alias;
        return copy;
    }

    /** A whole number. */
    public static Setting integer(String key, String label, int defaultValue) {
        return of(key, label, Type.INTEGER, String.valueOf(defaultValue));
    }

    /** A finite decimal number; the default as it is to be shown, e.g. {@code "-49.67"}. */
    public static Setting number(String key, String label, String defaultValue) {
        return of(key, label, Type.NUMBER, defaultValue);
    }

    /** True or false: a check box. */
    public static Setting bool(String key, String label, boolean defaultValue) {
        return of(key, label, Type.BOOLEAN, String.valueOf(defaultValue));
    }

    /** Text that is not empty. */
    public static Setting text(String key, String label, String defaultValue) {
        return of(key, label, Type.TEXT, defaultValue);
    }

    /** A host name or an IP address. */
    public static Setting host(String key, String label, String defaultValue) {
        return of(key, label, Type.HOST, defaultValue);
    }

    /** An IP address of this machine (or a name of one). */
    public static Setting address(String key, String label, String defaultValue) {
        return of(key, label, Type.ADDRESS, defaultValue);
    }

    /** An existing directory. */
    public static Setting directory(String key, String label, String defaultValue) {
        return of(key, label, Type.DIRECTORY, defaultValue);
    }

    /** A comma-separated list of IP addresses, written as numbers. */
    public static Setting addresses(String key, String label, String defaultValue) {
        return of(key, label, Type.ADDRESSES, defaultValue);
    }

    /** A comma-separated list of robot pairs {@code A:B}. */
    public static Setting pairs(String key, String label, String defaultValue) {
        return of(key, label, Type.PAIRS, defaultValue);
    }

    /** One of these words, exactly. */
    public static Setting choice(String key, String label, String defaultValue, List<String> choices) {
        return new Setting(key, label, Type.CHOICE, defaultValue, choices);
    }

    // ---- refinements ----

    /** The smallest value allowed, itself allowed. */
    public Setting from(double minimum) {
        return bounded(bounds.low(minimum, false));
    }

    /** Values must be above this one (NUMBER). */
    public Setting above(double minimum) {
        return bounded(bounds.low(minimum, true));
    }

    /** The largest value allowed, itself allowed. */
    public Setting to(double maximum) {
        return bounded(bounds.high(maximum, false));
    }

    /** Values must be below this one (NUMBER). */
    public Setting below(double maximum) {
        return bounded(bounds.high(maximum, true));
    }

    private Setting bounded(Bounds range) {
        Setting copy = copy();
        copy.bounds = range;
        return copy;
    }

    /** The unit, as shown beside the field: {@code ms}, {@code s}, {@code m}, {@code dB}, ... */
    public Setting unit(String symbol) {
        Setting copy = copy();
        copy.unit = symbol;
        return copy;
    }

    /** A line saying what the setting does: the dialogs' tooltip, {@code --help} and the docs. */
    public Setting help(String line) {
        Setting copy = copy();
        copy.help = line == null ? "" : line;
        return copy;
    }

    /** What a value is called in {@link #expected}, instead of the type's word: "a port number". */
    public Setting noun(String words) {
        Setting copy = copy();
        copy.noun = words;
        return copy;
    }

    /** A remark on a special value, added to {@link #expected} in parentheses: "0: any free port". */
    public Setting note(String remark) {
        Setting copy = copy();
        copy.note = remark;
        return copy;
    }

    /** An empty value is accepted too, and means this: "none". */
    public Setting orEmpty(String meaning) {
        Setting copy = note("empty: " + meaning);
        copy.emptyAllowed = true;
        return copy;
    }

    /**
     * The key this setting had before: a properties file, stored preferences and a model's
     * {@code configure} may still give the value under it ({@link #checked}, the server's file).
     */
    public Setting alias(String oldKey) {
        Setting copy = copy();
        copy.alias = Objects.requireNonNull(oldKey, "oldKey");
        return copy;
    }

    // ---- the declaration ----

    public String key() {
        return key;
    }

    public String label() {
        return label;
    }

    public Type type() {
        return type;
    }

    public String defaultValue() {
        return defaultValue;
    }

    /** The unit's symbol, or null. */
    public String unit() {
        return unit;
    }

    /** The label with its unit, as a dialog shows it: "Timeout (ms)". */
    public String labelWithUnit() {
        return unit == null ? label : label + " (" + unit + ")";
    }

    public String help() {
        return help;
    }

    /** The key this setting had before ({@link #alias(String)}), or null. */
    public String alias() {
        return alias;
    }

    // ---- the rule ----

    /**
     * Null when the value (stripped of surrounding whitespace) is accepted; else the words for
     * what is expected, e.g. "a port number from 1 to 65535", to follow "is not".
     */
    public String problem(String value) {
        return value != null && accepts(value.strip()) ? null : expected();
    }

    /** What a value must be: "a number of metres above 0", "true or false", ... */
    public String expected() {
        StringBuilder words = new StringBuilder(noun != null ? noun : switch (type) {
            case INTEGER -> "a whole number";
            case NUMBER -> "a number";
            case BOOLEAN -> "true or false";
            case TEXT -> "some text";
            case HOST -> "a host name or IP address";
            case ADDRESS -> "an IP address of this machine";
            case DIRECTORY -> "an existing directory";
            case CHOICE -> "one of " + String.join(", ", choices);
            case ADDRESSES -> "a comma-separated list of IP addresses of clients (not 0.0.0.0 or ::, which no client has)";
            case PAIRS -> RobotPair.LIST_WORDS;
        });
        boolean numeric = type == Type.INTEGER || type == Type.NUMBER;
        String range = numeric ? bounds.words() : "";
        if (numeric && unit != null) {
            words.append(range.isEmpty() ? " (" + unit + ")" : " of " + unitWords(unit));
        }
        words.append(range);
        if (note != null) {
            words.append(" (").append(note).append(')');
        }
        return words.toString();
    }

    private static String unitWords(String unit) {
        return switch (unit) {
            case "ms" -> "milliseconds";
            case "s" -> "seconds";
            case "m" -> "metres";
            default -> unit;
        };
    }

    private boolean accepts(String value) {
        if (value.isEmpty()) {
            return emptyAllowed;
        }
        return switch (type) {
            case INTEGER -> {
                try {
                    yield bounds.contains(Integer.parseInt(value));
                } catch (NumberFormatException e) {
                    yield false;
                }
            }
            case NUMBER -> {
                try {
                    double number = Double.parseDouble(value);
                    yield Double.isFinite(number) && bounds.contains(number);
                } catch (NumberFormatException e) {
                    yield false;
                }
            }
            case BOOLEAN -> value.equalsIgnoreCase("true") || value.equalsIgnoreCase("false");
            case TEXT -> true;
            case HOST -> value.chars().noneMatch(Character::isWhitespace);
            case ADDRESS -> isAddress(value);
            case DIRECTORY -> isDirectory(value);
            case CHOICE -> choices.contains(value);
            case ADDRESSES -> addressList(value) != null;
            case PAIRS -> RobotPair.listOf(value) != null;
        };
    }

    private static boolean isAddress(String value) {
        try {
            InetAddress.getByName(value);
            return true;
        } catch (UnknownHostException | SecurityException e) {
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

    /**
     * The addresses of a list such as {@code 127.0.0.1, 10.0.0.7} (whitespace around the items
     * allowed), or null when the text is not such a list. Each item is an IPv4 address in dotted
     * decimal or an IPv6 address in hex, never a name: nothing is looked up. The wildcard address
     * ({@code 0.0.0.0}, {@code ::}) is refused: no connection comes from it, so it would match nobody.
     */
    public static List<InetAddress> addressList(String text) {
        return AddressList.parse(text);
    }

    // ---- lists of settings ----

    /**
     * The given values over the declared defaults, every declared key present (other given keys
     * kept as they are), each declared one checked by its rule: what a model takes at its start. A
     * value given under a setting's {@linkplain #alias() old key} only is taken as its key's.
     *
     * @throws IllegalArgumentException for the first refused value, its message
     *                                  {@code key: 'value' is not ...}
     */
    public static Map<String, String> checked(Collection<Setting> declared, Map<String, String> given) {
        return SettingLists.checked(declared, given);
    }

    /** Every setting's default, by key, in declaration order. */
    public static Map<String, String> defaults(List<Setting> settings) {
        return SettingLists.defaults(settings);
    }

    /** The setting of this key in the list, or null. */
    public static Setting find(List<Setting> settings, String key) {
        return SettingLists.find(settings, key);
    }

    /** The setting of the list whose {@linkplain #alias() old key} this is, or null. */
    public static Setting findAlias(Collection<Setting> settings, String oldKey) {
        return SettingLists.findAlias(settings, oldKey);
    }

    /**
     * What is wrong with a model's declaration, or null: a setting that is null, a key that is
     * blank, a {@code wss.*} key (the server's), a key declared twice, a default its own rule refuses.
     */
    public static String declarationProblem(List<Setting> settings) {
        return SettingLists.declarationProblem(settings);
    }

    @Override
    public String toString() {
        return key + " = " + defaultValue + " (" + expected() + ")";
    }
}
