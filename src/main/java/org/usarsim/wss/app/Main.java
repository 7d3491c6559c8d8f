package org.usarsim.wss.app;

import java.awt.GraphicsEnvironment;
import java.io.PrintStream;
import java.nio.file.Path;
import java.util.List;
import java.util.Properties;
import java.util.function.Function;
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

/**
 * Starts the WSS. With a display, {@code [--config FILE] [--start]} opens the main window
 * (docs/gui.md); {@code --headless [--config FILE]} runs without a window, from built-in
 * defaults and the file, as does the first form when there is no display. {@code --world FILE [--port N] [--bind ADDRESS] [--rosbridge PORT [--ros-rate HZ]]} runs a USARSim-compatible
 * world server instead (docs/world.md); {@code --export-world RUN.rec [--out FILE]} writes a recording as a
 * world file (docs/replay.md); those two are programs of their own, {@link WorldServerRun} and
 * {@link WorldFileExport}. {@link #run} dispatches on the {@link Options} and returns the exit code
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
        String text = OptionsParser.help(command) + "\n" + ConfigKeys.help(ConfigFile.defaults().catalog());
        return text.replace("docs/", docs);
    }

    private Main() {
    }

    /**
     * The process: {@link #run}, then exit with its code. The log is not handed back to
     * java.util.logging's own two-line format when the run returns: a line written as the process
     * ends keeps the server's one format (issue 36, item 13).
     */
    public static void main(String[] args) {
        System.exit(run(System.out, System.err, false, args));
    }

    /**
     * Runs the WSS (or the world server, or --help) as the command line asks: the log goes to
     * {@code out}, a failure's one line to {@code err}. A server runs until SIGTERM, Ctrl-C or
     * closing the window, then is closed; the exit code is returned. The root logger and the
     * signal handlers are put back as they were before it returns.
     */
    public static int run(PrintStream out, PrintStream err, String... args) {
        return run(out, err, true, args);
    }

    /** As above; the root logger is put back as it was only when {@code restoreLogging}. */
    private static int run(PrintStream out, PrintStream err, boolean restoreLogging, String... args) {
        LogSetup.Saved logging = LogSetup.save();
        try {
            return parseAndRun(out, err, args);
        } catch (RunFailure e) {
            err.println("wss: " + e.getMessage());
            return e.code;
        } finally {
            if (restoreLogging) {
                logging.restore();
            }
        }
    }

    private static int parseAndRun(PrintStream out, PrintStream err, String... args) throws RunFailure {
        Options options;
        try {
            options = OptionsParser.parse(args);
        } catch (OptionsParser.Mistake e) {
            throw RunFailure.badInput(e.getMessage());
        }
        if (options instanceof Options.Version) {
            out.println("wss " + Version.current());
            return OK;
        }
        if (options instanceof Options.Help) {
            out.print(help(OptionsParser.COMMAND, DOCS));
            return OK;
        }
        if (options instanceof Options.ExportWorld export) {
            return WorldFileExport.run(out, err, export);
        }
        if (options instanceof Options.World world) {
            return WorldServerRun.run(out, world);
        }
        if (options instanceof Options.Attach attach) {
            return AttachRun.run(out, attach);
        }
        if (options instanceof Options.PrintPorts printPorts) {
            return printPorts(out, err, printPorts.config());
        }
        return serve(out, (Options.Serve) options);
    }

    /** The WSS, in its window or headless, from the defaults and the --config file. */
    private static int serve(PrintStream out, Options.Serve options) throws RunFailure {
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
    private static Properties read(Path config) throws RunFailure {
        try {
            return config == null ? new Properties() : ConfigFile.read(config);
        } catch (ConfigFileException e) {
            throw RunFailure.badInput(e.getMessage());
        }
    }

    /** The configuration of the defaults and {@code file}, checked; the log goes to {@code log}. */
    private static ConfigFile configFile(Properties file, Path config, PrintStream log) throws RunFailure {
        // Logging is set up as soon as the server's keys are known, before the catalog logs its plugins.
        Function<ConfigFile, ModelCatalog> catalog = server -> {
            LogSetup.install(log, server.logLevel());
            return ConfigFile.modelsFor(server);
        };
        try {
            return ConfigFile.of(file, config == null ? "the defaults" : config.toString(), catalog);
        } catch (ConfigFileException e) {
            throw RunFailure.badInput(e.getMessage());
        }
    }

    /**
     * {@code --print-ports [--config FILE]}: every fixed port of the configuration, one a line, to
     * {@code out}; checked as headless mode checks it (a bad file: its one line, exit 2), nothing
     * started. The log (plugins loaded) goes to {@code err}, so {@code out} holds only the ports;
     * without a fixed port, one line on {@code err} says so.
     */
    private static int printPorts(PrintStream out, PrintStream err, Path config) throws RunFailure {
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

    private static ModelProvider knownModel(ModelCatalog catalog, String name) throws RunFailure {
        ModelProvider model = catalog.provider(name);
        if (model == null) {
            throw RunFailure.badInput("wss.model = '" + name + "' is not a known model; known: " + String.join(", ", catalog.names()));
        }
        return model;
    }

    private static int runHeadless(ConfigFile configFile, Path config) throws RunFailure {
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
            server.hub().setRouteBase(configFile.routeBase());
        } catch (Server.StartFailure e) {
            throw new RunFailure(CANNOT_START, e.getMessage());
        }
        server.monitor(configFile.monitorConfig());
        // Before anything listens: a SIGTERM right after the start line must still exit 0.
        try (StopSignal stop = new StopSignal()) {
            try {
                server.start();
            } catch (Server.StartFailure e) {
                throw new RunFailure(e.badInput() ? BAD_INPUT : CANNOT_START, e.getMessage());
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
    private static int runWindow(ConfigFile configFile, Properties file, boolean fromFile, boolean start) throws RunFailure {
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
}
