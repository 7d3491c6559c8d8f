package org.usarsim.wss.app;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;
import org.usarsim.wss.gui.Attaching;
import org.usarsim.wss.world.RosbridgeServer;

/**
 * Reads Main's command line into an {@link Options}: each option once in {@link #FLAGS} (its
 * names, its value, its --help text), then the rules on how they combine. A new option is a row
 * in {@link #FLAGS}, a component of the {@link Options} record of its action and its place in
 * {@link #options}. Every
 * mistake is a {@link Mistake} whose message is the one line (with the usage) Main prints.
 */
final class OptionsParser {

    /** The command the usage names: the Debian package's launcher sets {@code wss.command=wss} (docs/install.md). */
    static final String COMMAND = System.getProperty("wss.command", "java -jar wss.jar");

    static final String USAGE = usage(COMMAND);

    /** What the help says of the command line without options. */
    private static final String NO_OPTION = "open the WSS's window (docs/gui.md); without a display, run headless";

    /** Every option, in the order --help lists them. */
    private static final List<Flag> FLAGS = List.of(
            Flag.toggle("--start", "in the window, press Start at once"),
            Flag.toggle("--headless", "run the WSS without a window"),
            Flag.valued("--config", "FILE", "a file", "the WSS's properties file (docs/headless.md); in the window, its wss.port,\n"
                    + "wss.model and wss.eventLog override the stored ones, its wss.record ticks\n"
                    + "Record and is where Start records, its model settings the stored ones\n"
                    + "for this session"),
            Flag.valued("--world", "FILE", "a value",
                    "instead of the WSS, serve USARSim's position protocol from a world file (docs/world.md)"),
            Flag.valued("--port", "N", "a value",
                    "the world server's port, 0 to 65535, 0 = any free port (default " + Defaults.WORLD_PORT + ")"),
            Flag.valued("--bind", "ADDRESS", "a value",
                    "the address the world server listens on (default " + Defaults.ALL_INTERFACES + ": every interface)"),
            Flag.valued("--rosbridge", "PORT", "a value",
                    "the world server also serves its world over rosbridge v2 (WebSocket) on\n"
                    + "this port, 0 = any free port (docs/world.md, docs/ros-messages.md)"),
            Flag.valued("--ros-rate", "HZ", "a value",
                    "the rate of every publisher of the world server's rosbridge, above 0 and at\n"
                    + "most " + (int) RosbridgeServer.MAX_RATE_HZ + " (default " + (int) RosbridgeServer.DEFAULT_RATE_HZ + "; docs/world.md, \"Over rosbridge\")"),
            Flag.valued("--export-world", "RUN.rec", "a file",
                    "write a world file whose robots follow the recording's paths, with its walls\n"
                    + "(docs/replay.md); to standard output, or to the file of --out FILE"),
            Flag.valued("--out", "FILE", "a file", "where --export-world writes the world file"),
            Flag.toggle("--print-ports", "print every fixed port of --config FILE, one a line, and exit: its protocol,\n"
                    + "FROM->TO:PORT, the WSS's number and the robots' addresses (docs/fixed-ports.md)"),
            Flag.valued("--attach", "URL", "a URL", "open a window attached to a running WSS's monitor endpoint,\n"
                    + "https://host:port or http://host:port (docs/monitor.md)"),
            Flag.valued("--token-file", "FILE", "a file", "the monitor token --attach sends, read from this file (without it,\n"
                    + "the window asks); never a token on the command line"),
            Flag.valued("--trust-cert", "FILE", "a file", "--attach over https trusts only this certificate (PEM, as\n"
                    + "keytool -exportcert -rfc writes it), not the JDK's trust store"),
            Flag.toggle("--version", "print the version and exit"),
            Flag.toggle("--help", "print this and every property of --config FILE, and exit", "-h"));

    /** The column where the help's texts begin. */
    private static final int HELP_COLUMN = 22;

    /** A command line Main refuses: the message (with the usage where it helps) for standard error. */
    static final class Mistake extends Exception {
        Mistake(String message) {
            super(message);
        }
    }

    /**
     * One option: its names (the first is its key), the placeholder of its value (null: it takes
     * none), what the error says is missing when the value is, and its --help text.
     */
    private record Flag(List<String> names, String value, String missing, String help) {

        static Flag toggle(String name, String help, String... aliases) {
            List<String> names = new ArrayList<>(List.of(name));
            names.addAll(List.of(aliases));
            return new Flag(List.copyOf(names), null, null, help);
        }

        static Flag valued(String name, String value, String missing, String help) {
            return new Flag(List.of(name), value, missing, help);
        }

        String key() {
            return names.get(0);
        }

        /** How --help shows it: {@code --port N}, {@code --help, -h}. */
        String label() {
            return String.join(", ", names) + (value == null ? "" : " " + value);
        }
    }

    private OptionsParser() {
    }

    static String usage(String command) {
        return "usage: " + command + " [--config FILE] [--start]\n"
                + "       " + command + " --headless [--config FILE]\n"
                + "       " + command + " --world FILE [--port N] [--bind ADDRESS] [--rosbridge PORT [--ros-rate HZ]]\n"
                + "       " + command + " --export-world RUN.rec [--out FILE]\n"
                + "       " + command + " --print-ports [--config FILE]\n"
                + "       " + command + " --attach URL [--token-file FILE] [--trust-cert FILE]\n"
                + "       " + command + " --version | --help";
    }

    /** The usage naming this command, then each option on its line(s). */
    static String help(String command) {
        StringBuilder help = new StringBuilder(usage(command)).append('\n').append(helpLines("(no option)", NO_OPTION));
        for (Flag flag : FLAGS) {
            help.append('\n').append(helpLines(flag.label(), flag.help()));
        }
        return help.toString();
    }

    private static String helpLines(String label, String text) {
        String gap = " ".repeat(Math.max(2, HELP_COLUMN - 2 - label.length()));
        return "  " + label + gap + text.lines().collect(Collectors.joining("\n" + " ".repeat(HELP_COLUMN)));
    }

    /**
     * The options of this command line. Reading stops at --version or --help (what follows is not
     * looked at); otherwise every argument must be an option, and they must go together.
     */
    static Options parse(String... args) throws Mistake {
        Map<String, String> given = new HashMap<>();
        for (int i = 0; i < args.length; i++) {
            Flag flag = flag(args[i]);
            if (flag == null) {
                throw new Mistake("unknown argument " + args[i] + "\n" + USAGE);
            }
            if (flag.key().equals("--version")) {
                return new Options.Version();
            }
            if (flag.key().equals("--help")) {
                return new Options.Help();
            }
            if (flag.value() == null) {
                given.put(flag.key(), "");
            } else if (i + 1 == args.length) {
                throw new Mistake(args[i] + " needs " + flag.missing() + "\n" + USAGE);
            } else {
                given.put(flag.key(), args[++i]);
            }
        }
        return options(given);
    }

    private static Flag flag(String arg) {
        return FLAGS.stream().filter(flag -> flag.names().contains(arg)).findFirst().orElse(null);
    }

    /** The options given, checked against each other in this order. */
    private static Options options(Map<String, String> given) throws Mistake {
        boolean headless = given.containsKey("--headless");
        boolean start = given.containsKey("--start");
        Path config = path(given, "--config");
        Path world = path(given, "--world");
        String port = given.get("--port");
        String bind = given.get("--bind");
        String rosbridge = given.get("--rosbridge");
        String rosRate = given.get("--ros-rate");
        if (rosRate != null && (world == null || rosbridge == null)) {
            throw new Mistake("--ros-rate is the rate of the world server's rosbridge: it needs --world FILE and --rosbridge PORT\n"
                    + USAGE);
        }
        Path export = path(given, "--export-world");
        Path out = path(given, "--out");
        boolean printPorts = given.containsKey("--print-ports");
        if (printPorts && given.keySet().stream().anyMatch(key -> !key.equals("--print-ports") && !key.equals("--config"))) {
            throw new Mistake("--print-ports only prints the fixed ports of --config FILE: no other option\n" + USAGE);
        }
        if (printPorts) {
            return new Options.PrintPorts(config);
        }
        Options attach = attach(given);
        if (attach != null) {
            return attach;
        }
        if (export != null && (headless || config != null || start || world != null || port != null || bind != null
                || rosbridge != null)) {
            throw new Mistake("--export-world only writes a world file: no --headless, --config, --start, --world, --port, --bind"
                    + " or --rosbridge\n"
                    + USAGE);
        }
        if (out != null && export == null) {
            throw new Mistake("--out is where --export-world writes: it needs --export-world RUN.rec\n" + USAGE);
        }
        if (export != null) {
            return new Options.ExportWorld(export, out);
        }
        if (world != null && (headless || config != null)) {
            throw new Mistake("--world runs the world server alone, without --headless or --config\n" + USAGE);
        }
        if (world != null && start) {
            throw new Mistake("--start presses the window's Start; the world server starts at once\n" + USAGE);
        }
        if (headless && start) {
            throw new Mistake("--start is for the window; headless, the server starts at once\n" + USAGE);
        }
        if (world == null && (port != null || bind != null || rosbridge != null)) {
            throw new Mistake("--port, --bind and --rosbridge are for the world server: they need --world FILE\n" + USAGE);
        }
        if (world != null) {
            return new Options.World(world, port("--port", port == null ? String.valueOf(Defaults.WORLD_PORT) : port),
                    bind == null ? Defaults.ALL_INTERFACES : bind, rosbridge == null ? -1 : port("--rosbridge", rosbridge),
                    rosRate == null ? RosbridgeServer.DEFAULT_RATE_HZ : rate(rosRate));
        }
        return new Options.Serve(headless, start, config);
    }

    /** {@code --attach URL [--token-file FILE] [--trust-cert FILE]} alone, else null when not asked. */
    private static Options attach(Map<String, String> given) throws Mistake {
        String url = given.get("--attach");
        if (url == null) {
            if (given.containsKey("--token-file") || given.containsKey("--trust-cert")) {
                throw new Mistake("--token-file and --trust-cert are for the window --attach opens: they need --attach URL\n" + USAGE);
            }
            return null;
        }
        if (given.keySet().stream().anyMatch(key -> !List.of("--attach", "--token-file", "--trust-cert").contains(key))) {
            throw new Mistake("--attach only opens a window attached to a running WSS: no option but --token-file and --trust-cert\n"
                    + USAGE);
        }
        if (!Attaching.isMonitorUrl(url)) {
            throw new Mistake("--attach " + url + " is not a monitor's URL: https://host:port or http://host:port\n" + USAGE);
        }
        return new Options.Attach(url, path(given, "--token-file"), path(given, "--trust-cert"));
    }

    private static Path path(Map<String, String> given, String key) {
        String value = given.get(key);
        return value == null ? null : Path.of(value);
    }

    private static double rate(String text) throws Mistake {
        double rate = Double.NaN;
        try {
            rate = Double.parseDouble(text);
        } catch (NumberFormatException e) {
            // reported below
        }
        if (!(rate > 0 && rate <= RosbridgeServer.MAX_RATE_HZ) || !text.matches("[0-9.]+")) {
            throw new Mistake("--ros-rate " + text + " is not a rate in Hz above 0 and at most " + (int) RosbridgeServer.MAX_RATE_HZ + " (20, 5, 0.5)\n" + USAGE);
        }
        return rate;
    }

    private static int port(String option, String text) throws Mistake {
        int port = -1;
        try {
            port = Integer.parseInt(text);
        } catch (NumberFormatException e) {
            // reported below
        }
        if (port < 0 || port > 65535) {
            throw new Mistake(option + " " + text + " is not a port number from 0 to 65535 (0: any free port)\n" + USAGE);
        }
        return port;
    }
}
