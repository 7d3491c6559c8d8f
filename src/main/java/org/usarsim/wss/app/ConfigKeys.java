package org.usarsim.wss.app;

import java.util.Arrays;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.usarsim.wss.hub.FixedSetup;
import org.usarsim.wss.hub.HubConfig;
import org.usarsim.wss.hub.core.FixedPort;
import org.usarsim.wss.model.ModelCatalog;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.Setting;
import org.usarsim.wss.monitor.MonitorConfig;
import org.usarsim.wss.protocol.ControlPort;
import org.usarsim.wss.shaping.JitterConfig;
import org.usarsim.wss.shaping.JitterDistribution;
import org.usarsim.wss.shaping.LossTable;
import org.usarsim.wss.shaping.RateTable;
import org.usarsim.wss.shaping.ShapingConfig;

/**
 * The keys a properties file (--config FILE) may hold: the server's own {@code wss.*} settings,
 * declared here with the models' {@link Setting} type (docs/headless.md documents each), and the
 * list of every key for {@code --help}, the server's and those the catalog's models declare.
 */
final class ConfigKeys {

    /** The link shaping keys, read together by ShapingConfig. */
    static final List<String> SHAPING_KEYS = List.of(ShapingConfig.SHAPING, ShapingConfig.RATES, ShapingConfig.DELAY_MS,
            ShapingConfig.AIRTIME, ShapingConfig.QUEUE_MS, ShapingConfig.JITTER, ShapingConfig.JITTER_DISTRIBUTION, ShapingConfig.REORDER);
    /** What wss.shaping.loss takes, in words. */
    static final String LOSS_WORDS = "rows dBm:percent from the strongest signal to the weakest (-85:1,-87:10,-90:50)";
    /** What wss.shaping.rates takes, in words. */
    static final String RATES_WORDS = "steps dBm:rate from the strongest signal to the weakest (-72:54M,-77:36M)";

    /** The robot every other's route is watched to (docs/routes.md). */
    static final String ROUTE_BASE = "wss.route.base";

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
                            + " with links shaped, A:B:RATE:DELAY:JITTER pins the pair's rate, delay and jitter (docs/shaping.md)"),
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
            Setting.integer(ShapingConfig.JITTER, "Jitter", 0).from(0).to(ShapingConfig.MAX_JITTER_MS).unit("ms").note("0: none")
                    .help("With links shaped, each grant's or datagram's delay varies by this much, drawn from the distribution"
                            + " below (docs/shaping.md, \"Jitter\"); a TCP link's bytes keep their order"),
            Setting.choice(ShapingConfig.JITTER_DISTRIBUTION, "Jitter distribution", JitterConfig.NONE.distribution().word(),
                    Arrays.stream(JitterDistribution.values()).map(JitterDistribution::word).toList())
                    .help("The jitter's distribution, as netem names them: uniform (delay +- jitter), normal, pareto, paretonormal"),
            Setting.bool(ShapingConfig.REORDER, "Reorder datagrams", false)
                    .help("With a jitter, a fixed UDP port's datagrams may overtake each other (false: each waits for the one before)"),
            Setting.text(ShapingConfig.SEED, "Seed", String.valueOf(JitterConfig.DEFAULT_SEED)).noun("a whole number")
                    .help("The seed of every random draw of a run (the jitter): the same seed, the same draws"),
            Setting.text(FixedPorts.KEY, "Fixed ports", "").orEmpty("none").noun(FixedPort.WORDS)
                    .help("WSS ports made at Start and kept, between robots declared with wss.robot.NAME = ADDRESS"
                            + " (default address 127.0.0.1; docs/fixed-ports.md)"),
            Setting.integer(FixedPorts.UDP_IDLE, "UDP session expiry", FixedSetup.DEFAULT_UDP_IDLE_SECONDS).from(1).to(86400).unit("s")
                    .help("A fixed UDP port forgets a sender (and closes its socket toward the target) after this long without"
                            + " a datagram either way"),
            Setting.choice("wss.logLevel", "Log level", "INFO", List.of("SEVERE", "WARNING", "INFO", "FINE", "FINER", "FINEST"))
                    .help("How much the log says; FINE adds every control command and its reply"),
            Setting.integer(MonitorConfig.PORT, "Monitor port", 0).from(-1).to(65535).noun("a port number").note("0: no monitor, -1: any free port")
                    .help("The monitor endpoint (docs/monitor.md): state, events, metrics and the operator's commands over HTTP(S)"),
            Setting.address(MonitorConfig.BIND_ADDRESS, "Monitor bind address", MonitorConfig.DEFAULT_BIND_ADDRESS)
                    .help("The address the monitor listens on; one other machines reach needs wss.monitor.keystore (TLS)"),
            Setting.text(MonitorConfig.TOKENS, "Monitor tokens", "").orEmpty("none").noun("a file path")
                    .help("The monitor's token file: lines 'viewer TOKEN' / 'operator TOKEN', readable by its owner only"),
            Setting.integer(MonitorConfig.MAX_CLIENTS, "Monitor streams", MonitorConfig.DEFAULT_MAX_CLIENTS).from(1).to(1024)
                    .help("The most event streams (GET /api/events) open at once; the next is answered 503"),
            Setting.text(MonitorConfig.KEYSTORE, "Monitor keystore", "").orEmpty("none: plain HTTP, loopback only").noun("a file path")
                    .help("A PKCS12 keystore: the monitor serves HTTPS with its key"),
            Setting.text(MonitorConfig.KEYSTORE_PASSWORD_FILE, "Monitor keystore password", "").orEmpty("none").noun("a file path")
                    .help("A file, readable by its owner only, whose first line is the keystore's password"),
            Setting.text(ROUTE_BASE, "Route base", "").orEmpty("none").noun("a robot's name")
                    .help("Robots without a route to this robot are cut off: the log and the event log say so once per change"
                            + " (CUT_OFF, ROUTE; docs/routes.md)"));

    private ConfigKeys() {
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
}
