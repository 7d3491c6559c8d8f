package org.usarsim.wss.app;

import java.awt.GraphicsEnvironment;
import java.io.IOException;
import java.net.InetAddress;
import java.net.UnknownHostException;
import java.nio.file.Path;
import java.util.List;
import java.util.Properties;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Function;
import java.util.logging.Level;
import java.util.logging.Logger;
import javax.swing.SwingUtilities;
import org.usarsim.wss.gui.Launch;
import org.usarsim.wss.gui.MainWindow;
import org.usarsim.wss.gui.ModelPreferences;
import org.usarsim.wss.gui.WindowLog;
import org.usarsim.wss.gui.WindowSettings;
import org.usarsim.wss.model.ModelCatalog;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.Setting;
import org.usarsim.wss.sim.WorldFileException;
import org.usarsim.wss.sim.WorldServer;
import sun.misc.Signal;

/**
 * Starts the WSS. With a display, {@code [--config FILE] [--start]} opens the main window
 * (docs/gui.md); {@code --headless [--config FILE]} runs without a window, from built-in
 * defaults and the file, as does the first form when there is no display. {@code --world FILE [--port N] [--bind ADDRESS]} runs a USARSim-compatible
 * world server instead (docs/world.md). Exit codes: 0 after SIGTERM or Ctrl-C, 1 when the server
 * cannot start (port in use, model will not start), 2 for a bad command line, configuration or world file.
 */
public final class Main {

    static final String USAGE = "usage: java -jar wss.jar [--config FILE] [--start]\n"
            + "       java -jar wss.jar --headless [--config FILE]\n"
            + "       java -jar wss.jar --world FILE [--port N] [--bind ADDRESS]";

    private static final String HELP = USAGE + "\n"
            + "  (no option)         open the WSS's window (docs/gui.md); without a display, run headless\n"
            + "  --start             in the window, press Start at once\n"
            + "  --headless          run the WSS without a window\n"
            + "  --config FILE       the WSS's properties file (docs/headless.md); in the window, its wss.port,\n"
            + "                      wss.model and wss.eventLog override the stored ones, its model settings\n"
            + "                      the stored ones for this session\n"
            + "  --world FILE        instead of the WSS, serve USARSim's position protocol from a world file (docs/world.md)\n"
            + "  --port N            the world server's port, 0 to 65535, 0 = any free port (default 7435)\n"
            + "  --bind ADDRESS      the address the world server listens on (default 0.0.0.0: every interface)";

    private Main() {
    }

    public static void main(String[] args) {
        Path config = null;
        boolean headless = false;
        boolean start = false;
        Path world = null;
        String port = null;
        String bind = null;
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
                        fail(2, "--config needs a file\n" + USAGE);
                    }
                    config = Path.of(args[++i]);
                    break;
                case "--world":
                case "--port":
                case "--bind": {
                    String option = args[i];
                    if (i + 1 == args.length) {
                        fail(2, option + " needs a value\n" + USAGE);
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
                case "--help":
                case "-h":
                    System.out.println(HELP);
                    System.out.print(Settings.help(Settings.defaults().catalog()));
                    return;
                default:
                    fail(2, "unknown argument " + args[i] + "\n" + USAGE);
            }
        }
        if (world != null && (headless || config != null)) {
            fail(2, "--world runs the world server alone, without --headless or --config\n" + USAGE);
        }
        if (world != null && start) {
            fail(2, "--start presses the window's Start; the world server starts at once\n" + USAGE);
        }
        if (headless && start) {
            fail(2, "--start is for the window; headless, the server starts at once\n" + USAGE);
        }
        if (world == null && (port != null || bind != null)) {
            fail(2, "--port and --bind are for the world server: they need --world FILE\n" + USAGE);
        }
        if (world != null) {
            runWorld(world, port == null ? "7435" : port, bind == null ? "0.0.0.0" : bind);
            return;
        }
        Properties file = new Properties();
        Settings settings = null;
        try {
            if (config != null) {
                file = Settings.read(config);
            }
            // Logging is set up as soon as the server's keys are known, before the catalog logs its plugins.
            Function<Settings, ModelCatalog> catalog = server -> {
                LogSetup.toStandardOutput(server.logLevel());
                return Settings.modelsFor(server);
            };
            settings = Settings.of(file, config == null ? "the defaults" : config.toString(), catalog);
        } catch (SettingsException e) {
            fail(2, e.getMessage());
        }
        String noDisplay = headless ? null : noDisplay();
        if (headless || noDisplay != null) {
            if (noDisplay != null) {
                Logger.getLogger(Main.class.getName()).info(noDisplay + ": running headless");
            }
            runHeadless(settings, config);
        } else {
            runWindow(settings, file, config != null, start);
        }
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

    private static PropagationModel knownModel(ModelCatalog catalog, String name) {
        PropagationModel model = catalog.find(name);
        if (model == null) {
            fail(2, "wss.model = '" + name + "' is not a known model; known: " + String.join(", ", catalog.names()));
        }
        return model;
    }

    private static void runHeadless(Settings settings, Path config) {
        ModelCatalog catalog = settings.catalog();
        PropagationModel model = knownModel(catalog, settings.modelName());
        Logger log = Logger.getLogger(Main.class.getName());
        for (String key : settings.ignoredKeys()) {
            log.warning(config + ": " + key + " is not a setting of " + model.name() + " (it is one of "
                    + String.join(", ", declaring(catalog, key)) + "): ignored");
        }
        Server server = null;
        try {
            server = Server.create(settings.hubConfig(), model, settings.eventLog() ? settings.eventLogDir() : null);
        } catch (Server.StartFailure e) {
            fail(1, e.getMessage());
        }
        Server running = server;
        // Before anything listens: a SIGTERM right after the start line must still exit 0.
        onStopSignal(() -> {
            try {
                running.close();
            } finally {
                System.exit(0);
            }
        });
        try {
            model.configure(settings.modelSettings());
            running.start();
        } catch (Server.StartFailure e) {
            fail(1, e.getMessage());
        } catch (RuntimeException e) {
            fail(1, model.name() + " did not start: " + e.getMessage());
        }
        waitForStopSignal();
    }

    /**
     * The main window, starting servers as headless mode does; closing it (or SIGTERM) stops the
     * server and exits 0. The keys {@code file} sets (none without --config) go over the stored ones.
     */
    private static void runWindow(Settings settings, Properties file, boolean fromFile, boolean start) {
        WindowLog windowLog = new WindowLog();
        Logger.getLogger("").addHandler(windowLog);
        ModelCatalog catalog = settings.catalog();
        Launch launch = new Launch(file.containsKey("wss.port") ? settings.get("wss.port") : null,
                file.containsKey("wss.model") ? knownModel(catalog, settings.modelName()).name() : null,
                file.containsKey("wss.eventLog") ? settings.eventLog() : null,
                fromFile ? settings.modelSettings() : null, start);
        List<PropagationModel> models = catalog.names().stream().map(catalog::find).toList();
        WindowServers servers = new WindowServers(settings);
        onStopSignal(() -> {
            try {
                servers.stopCurrent();
            } finally {
                System.exit(0);
            }
        });
        SwingUtilities.invokeLater(() -> MainWindow.open(servers, models, new WindowSettings(), new ModelPreferences(),
                windowLog, launch, () -> System.exit(0)));
    }

    /** The names of the models that declare this key. */
    private static List<String> declaring(ModelCatalog catalog, String key) {
        return catalog.models().stream().filter(model -> Setting.find(model.settings(), key) != null)
                .map(PropagationModel::name).toList();
    }

    /** The world server: read the file, listen, serve until SIGTERM or Ctrl-C. */
    private static void runWorld(Path file, String portText, String bindText) {
        int port = -1;
        try {
            port = Integer.parseInt(portText);
        } catch (NumberFormatException e) {
            // reported below
        }
        if (port < 0 || port > 65535) {
            fail(2, "--port " + portText + " is not a port number from 0 to 65535 (0: any free port)\n" + USAGE);
        }
        InetAddress address = null;
        try {
            address = InetAddress.getByName(bindText);
        } catch (UnknownHostException e) {
            fail(2, "--bind " + bindText + " is not an address of this machine: " + e.getMessage());
        }
        LogSetup.toStandardOutput(Level.INFO);
        AtomicReference<WorldServer> running = new AtomicReference<>();
        Runnable stop = () -> {
            try {
                WorldServer server = running.get();
                if (server != null) {
                    server.close();
                }
            } finally {
                System.exit(0);
            }
        };
        // Before anything listens: a SIGTERM right after the start line must still exit 0.
        onStopSignal(stop);
        try {
            running.set(WorldServer.start(file, address, port));
        } catch (WorldFileException e) {
            fail(2, e.getMessage());
        } catch (IOException e) {
            fail(1, "cannot listen on " + address.getHostAddress() + ":" + port + ": " + e.getMessage());
        }
        waitForStopSignal();
    }

    /** What SIGTERM and Ctrl-C (SIGINT) do; it ends with System.exit. */
    private static void onStopSignal(Runnable stop) {
        Signal.handle(new Signal("TERM"), signal -> stop.run());
        Signal.handle(new Signal("INT"), signal -> stop.run());
    }

    /** Keeps the main thread until a stop signal's handler exits the JVM. */
    private static void waitForStopSignal() {
        try {
            new CountDownLatch(1).await();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private static void fail(int status, String message) {
        System.err.println("wss: " + message);
        System.exit(status);
    }
}
