package org.usarsim.wss.app;

import java.awt.GraphicsEnvironment;
import java.io.IOException;
import java.io.PrintStream;
import java.net.InetAddress;
import java.net.UnknownHostException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Properties;
import java.util.concurrent.CountDownLatch;
import java.util.function.Function;
import java.util.logging.Level;
import java.util.logging.Logger;
import javax.swing.SwingUtilities;
import org.usarsim.wss.Version;
import org.usarsim.wss.gui.Launch;
import org.usarsim.wss.gui.MainWindow;
import org.usarsim.wss.gui.ModelPreferences;
import org.usarsim.wss.gui.WindowLog;
import org.usarsim.wss.gui.WindowPreferences;
import org.usarsim.wss.hub.HubConfig;
import org.usarsim.wss.model.ModelCatalog;
import org.usarsim.wss.model.ModelProvider;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.Setting;
import org.usarsim.wss.recording.Recording;
import org.usarsim.wss.recording.RecordingException;
import org.usarsim.wss.recording.RecordingReader;
import org.usarsim.wss.recording.WorldExport;
import org.usarsim.wss.world.RosbridgeServer;
import org.usarsim.wss.world.WorldFileException;
import org.usarsim.wss.world.WorldServer;
import sun.misc.Signal;
import sun.misc.SignalHandler;

/**
 * Starts the WSS. With a display, {@code [--config FILE] [--start]} opens the main window
 * (docs/gui.md); {@code --headless [--config FILE]} runs without a window, from built-in
 * defaults and the file, as does the first form when there is no display. {@code --world FILE [--port N] [--bind ADDRESS] [--rosbridge PORT [--ros-rate HZ]]} runs a USARSim-compatible
 * world server instead (docs/world.md); {@code --export-world RUN.rec [--out FILE]} writes a recording as a
 * world file (docs/replay.md). {@link #run} does it all and returns the exit code
 * ({@link #OK}, {@link #CANNOT_START}, {@link #BAD_INPUT}); {@link #main} only exits with it.
 */
public final class Main {

    /** Exit code: --help, or stopped by SIGTERM, Ctrl-C or closing the window. */
    public static final int OK = 0;
    /** Exit code: the server cannot start (port in use, model will not start). */
    public static final int CANNOT_START = 1;
    /**
     * Exit code: a bad command line, properties file or world file, found before anything listens,
     * or a model that refuses its input as it starts (a bad recording: {@code ModelInputException}).
     */
    public static final int BAD_INPUT = 2;

    /** Where the help's docs/ are: the Debian package's launcher sets {@code wss.docs=/usr/share/doc/wss/} (docs/install.md). */
    private static final String DOCS = System.getProperty("wss.docs", "docs/");

    /** What --help prints (and the package's manual page wss.1 is made of), naming the command and the docs as given. */
    static String help(String command, String docs) {
        String text = OptionsParser.help(command) + "\n" + ConfigFile.help(ConfigFile.defaults().catalog());
        return text.replace("docs/", docs);
    }

    /** Why a run ends before it serves: the exit code and the one line for standard error. */
    private static final class Failure extends Exception {
        final int code;

        Failure(int code, String message) {
            super(message);
            this.code = code;
        }
    }

    private Main() {
    }

    public static void main(String[] args) {
        System.exit(run(System.out, System.err, args));
    }

    /**
     * Runs the WSS (or the world server, or --help) as the command line asks: the log goes to
     * {@code out}, a failure's one line to {@code err}. A server runs until SIGTERM, Ctrl-C or
     * closing the window, then is closed; the exit code is returned. The root logger and the
     * signal handlers are put back as they were before it returns.
     */
    public static int run(PrintStream out, PrintStream err, String... args) {
        LogSetup.Saved logging = LogSetup.save();
        try {
            return parseAndRun(out, err, args);
        } catch (Failure e) {
            err.println("wss: " + e.getMessage());
            return e.code;
        } finally {
            logging.restore();
        }
    }

    private static int parseAndRun(PrintStream out, PrintStream err, String... args) throws Failure {
        Options options;
        try {
            options = OptionsParser.parse(args);
        } catch (OptionsParser.Mistake e) {
            throw badInput(e.getMessage());
        }
        return switch (options.action()) {
            case VERSION -> {
                out.println("wss " + Version.current());
                yield OK;
            }
            case HELP -> {
                out.print(help(OptionsParser.COMMAND, DOCS));
                yield OK;
            }
            case EXPORT_WORLD -> exportWorld(out, err, options.export(), options.out());
            case WORLD -> runWorld(out, options.world(), options.port(), options.bind(), options.rosbridge(), options.rosRate());
            case SERVE -> serve(out, options);
            case PRINT_PORTS -> printPorts(out, err, options.config());
        };
    }

    /** The WSS, in its window or headless, from the defaults and the --config file. */
    private static int serve(PrintStream out, Options options) throws Failure {
        Path config = options.config();
        Properties file = read(config);
        ConfigFile configFile = configFile(file, config, out);
        String noDisplay = options.headless() ? null : noDisplay();
        if (options.headless() || noDisplay != null) {
            if (noDisplay != null) {
                Logger.getLogger(Main.class.getName()).info(noDisplay + ": running headless");
            }
            return runHeadless(configFile, config);
        }
        return runWindow(configFile, file, config != null, options.start());
    }

    /** The --config file's properties (none without one). */
    private static Properties read(Path config) throws Failure {
        try {
            return config == null ? new Properties() : ConfigFile.read(config);
        } catch (ConfigFileException e) {
            throw badInput(e.getMessage());
        }
    }

    /** The configuration of the defaults and {@code file}, checked; the log goes to {@code log}. */
    private static ConfigFile configFile(Properties file, Path config, PrintStream log) throws Failure {
        // Logging is set up as soon as the server's keys are known, before the catalog logs its plugins.
        Function<ConfigFile, ModelCatalog> catalog = server -> {
            LogSetup.install(log, server.logLevel());
            return ConfigFile.modelsFor(server);
        };
        try {
            return ConfigFile.of(file, config == null ? "the defaults" : config.toString(), catalog);
        } catch (ConfigFileException e) {
            throw badInput(e.getMessage());
        }
    }

    /**
     * {@code --print-ports [--config FILE]}: every fixed port of the configuration, one a line, to
     * {@code out}; checked as headless mode checks it (a bad file: its one line, exit 2), nothing
     * started. The log (plugins loaded) goes to {@code err}, so {@code out} holds only the ports;
     * without a fixed port, one line on {@code err} says so.
     */
    private static int printPorts(PrintStream out, PrintStream err, Path config) throws Failure {
        ConfigFile configFile = configFile(read(config), config, err);
        knownModel(configFile.catalog(), configFile.modelName());
        HubConfig hub = configFile.hubConfig();
        List<String> lines = FixedPorts.lines(hub.fixed(), hub.bindAddress());
        if (lines.isEmpty()) {
            err.println("wss: no fixed port in " + (config == null ? "the defaults" : config) + " (wss.fixed is empty)");
        }
        lines.forEach(out::println);
        out.flush();
        return OK;
    }

    /**
     * {@code --export-world RUN.rec [--out FILE]}: the recording as a world file, to {@code out} or
     * to the file. A recording cut short, or with lines skipped, is exported all the same, with a
     * warning on standard error.
     */
    private static int exportWorld(PrintStream out, PrintStream err, Path recordingFile, Path to) throws Failure {
        Recording recording;
        try {
            recording = RecordingReader.read(recordingFile);
        } catch (RecordingException e) {
            throw badInput(e.getMessage());
        }
        if (recording.cutShort()) {
            err.println("wss: warning: " + recordingFile + " was cut short (no end line): exported up to its last whole line");
        }
        if (recording.unknownLines() + recording.unreadableLines() > 0) {
            err.println("wss: warning: " + recordingFile + ": skipped " + recording.unknownLines() + " unknown and "
                    + recording.unreadableLines() + " unreadable lines (the first: " + recording.firstProblem() + ")");
        }
        String text = WorldExport.worldFile(recording, recordingFile.getFileName().toString());
        if (to == null) {
            out.print(text);
            out.flush();
            return OK;
        }
        try {
            Files.writeString(to, text, StandardCharsets.UTF_8);
        } catch (java.nio.file.NoSuchFileException e) {
            throw badInput("cannot write the world file " + to + ": its folder " + to.toAbsolutePath().getParent() + " does not exist");
        } catch (java.nio.file.AccessDeniedException e) {
            throw badInput("cannot write the world file " + to + ": permission denied");
        } catch (IOException e) {
            throw badInput("cannot write the world file " + to + ": " + (e.getMessage() == null ? e.toString() : e.getMessage()));
        }
        return OK;
    }

    private static Failure badInput(String message) {
        return new Failure(BAD_INPUT, message);
    }

    /** Why no window can open here, or null when one can. */
    private static String noDisplay() {
        String display = System.getenv("DISPLAY");
        if (GraphicsEnvironment.isHeadless()) {
            return "no display (DISPLAY is " + (display == null ? "unset" : "'" + display + "'") + ")";
        }
        try {
            GraphicsEnvironment.getLocalGraphicsEnvironment().getScreenDevices();
            return null;
        } catch (Throwable e) { // AWTError, or an UnsatisfiedLinkError from a JDK without its X11 library
            return "the display " + display + " cannot be opened (" + e + ")";
        }
    }

    private static ModelProvider knownModel(ModelCatalog catalog, String name) throws Failure {
        ModelProvider model = catalog.provider(name);
        if (model == null) {
            throw badInput("wss.model = '" + name + "' is not a known model; known: " + String.join(", ", catalog.names()));
        }
        return model;
    }

    private static int runHeadless(ConfigFile configFile, Path config) throws Failure {
        ModelCatalog catalog = configFile.catalog();
        ModelProvider model = knownModel(catalog, configFile.modelName());
        Logger log = Logger.getLogger(Main.class.getName());
        for (String key : configFile.ignoredKeys()) {
            log.warning(config + ": " + key + " is not a setting of " + model.name() + " (it is one of "
                    + String.join(", ", declaring(catalog, key)) + "): ignored");
        }
        Server server;
        try {
            server = Server.create(configFile.hubConfig(), model, configFile.modelValues(),
                    configFile.eventLog() ? configFile.eventLogDir() : null, configFile.record().orElse(null));
        } catch (Server.StartFailure e) {
            throw new Failure(CANNOT_START, e.getMessage());
        }
        // Before anything listens: a SIGTERM right after the start line must still exit 0.
        try (StopSignal stop = new StopSignal()) {
            try {
                server.start();
            } catch (Server.StartFailure e) {
                throw new Failure(e.badInput() ? BAD_INPUT : CANNOT_START, e.getMessage());
            }
            try (StatsLog stats = StatsLog.every(configFile.statsInterval(), server.hub(), configFile.hubConfig().shaping().on())) {
                stop.await();
            } finally {
                server.close();
            }
        }
        return OK;
    }

    /**
     * The main window, starting servers as headless mode does, until it is closed (or SIGTERM,
     * which stops the server). The keys {@code file} sets (none without --config) go over the stored ones.
     */
    private static int runWindow(ConfigFile configFile, Properties file, boolean fromFile, boolean start) throws Failure {
        ModelCatalog catalog = configFile.catalog();
        Launch launch = new Launch(file.containsKey("wss.port") ? configFile.get("wss.port") : null,
                file.containsKey("wss.model") ? knownModel(catalog, configFile.modelName()).name() : null,
                file.containsKey("wss.eventLog") ? configFile.eventLog() : null,
                fromFile ? configFile.modelKeysSetBy(file) : null, fromFile ? configFile.shapingKeysSetBy(file) : null, start,
                file.containsKey("wss.record") ? configFile.record().isPresent() : null);
        WindowLog windowLog = new WindowLog();
        Logger.getLogger("").addHandler(windowLog);
        WindowServers servers = new WindowServers(configFile);
        try (StopSignal stop = new StopSignal()) {
            SwingUtilities.invokeLater(() -> MainWindow.open(servers, catalog.providers(), new WindowPreferences(), new ModelPreferences(),
                    windowLog, launch, stop::stop));
            try {
                stop.await();
            } finally {
                servers.stopCurrent();
            }
        }
        return OK;
    }

    /** The names of the models that declare this key. */
    private static List<String> declaring(ModelCatalog catalog, String key) {
        return catalog.models().stream().filter(model -> Setting.find(model.settings(), key) != null)
                .map(PropagationModel::name).toList();
    }

    /** The world server (and its rosbridge, on a port not -1): read the file, listen, serve until SIGTERM or Ctrl-C. */
    private static int runWorld(PrintStream out, Path file, int port, String bindText, int rosbridgePort, double rosRate)
            throws Failure {
        InetAddress address;
        try {
            address = InetAddress.getByName(bindText);
        } catch (UnknownHostException e) {
            throw badInput("--bind " + bindText + " is not an address of this machine: " + e.getMessage());
        }
        LogSetup.install(out, Level.INFO);
        // Before anything listens: a SIGTERM right after the start line must still exit 0.
        try (StopSignal stop = new StopSignal()) {
            WorldServer server;
            try {
                server = WorldServer.start(file, address, port);
            } catch (WorldFileException e) {
                throw badInput(e.getMessage());
            } catch (IOException e) {
                throw new Failure(CANNOT_START, "cannot listen on " + address.getHostAddress() + ":" + port + ": " + e.getMessage());
            }
            RosbridgeServer rosbridge = null;
            try {
                if (rosbridgePort >= 0) {
                    try {
                        rosbridge = RosbridgeServer.start(server, address, rosbridgePort, rosRate,
                                RosbridgeServer.DEFAULT_CONNECTION_DELAY);
                    } catch (IOException e) {
                        throw new Failure(CANNOT_START, "cannot listen for rosbridge on " + address.getHostAddress() + ":"
                                + rosbridgePort + ": " + e.getMessage());
                    }
                }
                stop.await();
            } finally {
                if (rosbridge != null) {
                    rosbridge.close();
                }
                server.close();
            }
        }
        return OK;
    }

    /**
     * What a running server waits on: SIGTERM, Ctrl-C (SIGINT) or {@link #stop()} (the window
     * closed) ends the wait. Closing puts back the signal handlers found.
     */
    private static final class StopSignal implements AutoCloseable {
        private static final Signal TERM = new Signal("TERM");
        private static final Signal INT = new Signal("INT");

        private final CountDownLatch stopped = new CountDownLatch(1);
        private final SignalHandler termBefore;
        private final SignalHandler intBefore;

        StopSignal() {
            termBefore = Signal.handle(TERM, signal -> stop());
            intBefore = Signal.handle(INT, signal -> stop());
        }

        void stop() {
            stopped.countDown();
        }

        /** Until stopped; an interrupt ends the wait too. */
        void await() {
            try {
                stopped.await();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }

        @Override
        public void close() {
            Signal.handle(TERM, termBefore);
            Signal.handle(INT, intBefore);
        }
    }
}
