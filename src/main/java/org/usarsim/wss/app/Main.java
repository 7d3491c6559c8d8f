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
import org.usarsim.wss.model.ModelCatalog;
import org.usarsim.wss.model.ModelProvider;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.Setting;
import org.usarsim.wss.recording.Recording;
import org.usarsim.wss.recording.RecordingException;
import org.usarsim.wss.recording.RecordingReader;
import org.usarsim.wss.recording.WorldExport;
import org.usarsim.wss.world.WorldFileException;
import org.usarsim.wss.world.WorldServer;
import sun.misc.Signal;
import sun.misc.SignalHandler;

/**
 * Starts the WSS. With a display, {@code [--config FILE] [--start]} opens the main window
 * (docs/gui.md); {@code --headless [--config FILE]} runs without a window, from built-in
 * defaults and the file, as does the first form when there is no display. {@code --world FILE [--port N] [--bind ADDRESS]} runs a USARSim-compatible
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

    static final String USAGE = "usage: java -jar wss.jar [--config FILE] [--start]\n"
            + "       java -jar wss.jar --headless [--config FILE]\n"
            + "       java -jar wss.jar --world FILE [--port N] [--bind ADDRESS]\n"
            + "       java -jar wss.jar --export-world RUN.rec [--out FILE]\n"
            + "       java -jar wss.jar --version | --help";

    private static final String HELP = USAGE + "\n"
            + "  (no option)         open the WSS's window (docs/gui.md); without a display, run headless\n"
            + "  --start             in the window, press Start at once\n"
            + "  --headless          run the WSS without a window\n"
            + "  --config FILE       the WSS's properties file (docs/headless.md); in the window, its wss.port,\n"
            + "                      wss.model and wss.eventLog override the stored ones, its wss.record ticks\n"
            + "                      Record and is where Start records, its model settings the stored ones\n"
            + "                      for this session\n"
            + "  --world FILE        instead of the WSS, serve USARSim's position protocol from a world file (docs/world.md)\n"
            + "  --port N            the world server's port, 0 to 65535, 0 = any free port (default " + Defaults.WORLD_PORT + ")\n"
            + "  --bind ADDRESS      the address the world server listens on (default " + Defaults.ALL_INTERFACES
            + ": every interface)\n"
            + "  --export-world RUN.rec  write a world file whose robots follow the recording's paths, with its walls\n"
            + "                      (docs/replay.md); to standard output, or to the file of --out FILE\n"
            + "  --out FILE          where --export-world writes the world file\n"
            + "  --version           print the version and exit\n"
            + "  --help, -h          print this and every property of --config FILE, and exit";

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
        Path config = null;
        boolean headless = false;
        boolean start = false;
        Path world = null;
        String port = null;
        String bind = null;
        Path export = null;
        Path exportTo = null;
        for (int i = 0; i < args.length; i++) {
            switch (args[i]) {
                case "--headless":
                    headless = true;
                    break;
                case "--start":
                    start = true;
                    break;
                case "--config":
                    if (i + 1 == args.length) {
                        throw badInput("--config needs a file\n" + USAGE);
                    }
                    config = Path.of(args[++i]);
                    break;
                case "--world":
                case "--port":
                case "--bind": {
                    String option = args[i];
                    if (i + 1 == args.length) {
                        throw badInput(option + " needs a value\n" + USAGE);
                    }
                    String value = args[++i];
                    if (option.equals("--world")) {
                        world = Path.of(value);
                    } else if (option.equals("--port")) {
                        port = value;
                    } else {
                        bind = value;
                    }
                    break;
                }
                case "--export-world":
                case "--out": {
                    String option = args[i];
                    if (i + 1 == args.length) {
                        throw badInput(option + " needs a file\n" + USAGE);
                    }
                    if (option.equals("--export-world")) {
                        export = Path.of(args[++i]);
                    } else {
                        exportTo = Path.of(args[++i]);
                    }
                    break;
                }
                case "--version":
                    out.println("wss " + Version.current());
                    return OK;
                case "--help":
                case "-h":
                    out.println(HELP);
                    out.print(ConfigFile.help(ConfigFile.defaults().catalog()));
                    return OK;
                default:
                    throw badInput("unknown argument " + args[i] + "\n" + USAGE);
            }
        }
        if (export != null && (headless || config != null || start || world != null || port != null || bind != null)) {
            throw badInput("--export-world only writes a world file: no --headless, --config, --start, --world, --port or --bind\n"
                    + USAGE);
        }
        if (exportTo != null && export == null) {
            throw badInput("--out is where --export-world writes: it needs --export-world RUN.rec\n" + USAGE);
        }
        if (export != null) {
            return exportWorld(out, err, export, exportTo);
        }
        if (world != null && (headless || config != null)) {
            throw badInput("--world runs the world server alone, without --headless or --config\n" + USAGE);
        }
        if (world != null && start) {
            throw badInput("--start presses the window's Start; the world server starts at once\n" + USAGE);
        }
        if (headless && start) {
            throw badInput("--start is for the window; headless, the server starts at once\n" + USAGE);
        }
        if (world == null && (port != null || bind != null)) {
            throw badInput("--port and --bind are for the world server: they need --world FILE\n" + USAGE);
        }
        if (world != null) {
            return runWorld(out, world, port == null ? String.valueOf(Defaults.WORLD_PORT) : port,
                    bind == null ? Defaults.ALL_INTERFACES : bind);
        }
        Properties file = new Properties();
        ConfigFile configFile;
        try {
            if (config != null) {
                file = ConfigFile.read(config);
            }
            // Logging is set up as soon as the server's keys are known, before the catalog logs its plugins.
            Function<ConfigFile, ModelCatalog> catalog = server -> {
                LogSetup.install(out, server.logLevel());
                return ConfigFile.modelsFor(server);
            };
            configFile = ConfigFile.of(file, config == null ? "the defaults" : config.toString(), catalog);
        } catch (ConfigFileException e) {
            throw badInput(e.getMessage());
        }
        String noDisplay = headless ? null : noDisplay();
        if (headless || noDisplay != null) {
            if (noDisplay != null) {
                Logger.getLogger(Main.class.getName()).info(noDisplay + ": running headless");
            }
            return runHeadless(configFile, config);
        }
        return runWindow(configFile, file, config != null, start);
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

    /** The world server: read the file, listen, serve until SIGTERM or Ctrl-C. */
    private static int runWorld(PrintStream out, Path file, String portText, String bindText) throws Failure {
        int port = -1;
        try {
            port = Integer.parseInt(portText);
        } catch (NumberFormatException e) {
            // reported below
        }
        if (port < 0 || port > 65535) {
            throw badInput("--port " + portText + " is not a port number from 0 to 65535 (0: any free port)\n" + USAGE);
        }
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
            try {
                stop.await();
            } finally {
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
