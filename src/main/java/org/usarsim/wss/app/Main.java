package org.usarsim.wss.app;

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
import org.usarsim.wss.hub.CsvEventLog;
import org.usarsim.wss.hub.Hub;
import org.usarsim.wss.model.ModelCatalog;
import org.usarsim.wss.model.ModelStartException;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.Setting;
import org.usarsim.wss.sim.WorldFileException;
import org.usarsim.wss.sim.WorldServer;
import sun.misc.Signal;

/**
 * Starts the WSS. {@code --headless [--config FILE]} runs without a window, from built-in
 * defaults and the file. {@code --world FILE [--port N] [--bind ADDRESS]} runs a USARSim-compatible
 * world server instead (docs/world.md). Exit codes: 0 after SIGTERM or Ctrl-C, 1 when the server
 * cannot start (port in use, model will not start), 2 for a bad command line, configuration or world file.
 */
public final class Main {

    static final String USAGE = "usage: java -jar wss.jar [--headless] [--config FILE]\n"
            + "       java -jar wss.jar --world FILE [--port N] [--bind ADDRESS]";

    private static final String HELP = USAGE + "\n"
            + "  --headless          run the WSS without a window\n"
            + "  --config FILE       the WSS's properties file (docs/headless.md)\n"
            + "  --world FILE        instead of the WSS, serve USARSim's position protocol from a world file (docs/world.md)\n"
            + "  --port N            the world server's port, 0 to 65535, 0 = any free port (default 7435)\n"
            + "  --bind ADDRESS      the address the world server listens on (default 0.0.0.0: every interface)";

    private Main() {
    }

    public static void main(String[] args) {
        Path config = null;
        boolean headless = false;
        Path world = null;
        String port = null;
        String bind = null;
        for (int i = 0; i < args.length; i++) {
            switch (args[i]) {
                case "--headless":
                    headless = true;
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
        if (world == null && (port != null || bind != null)) {
            fail(2, "--port and --bind are for the world server: they need --world FILE\n" + USAGE);
        }
        if (world != null) {
            runWorld(world, port == null ? "7435" : port, bind == null ? "0.0.0.0" : bind);
            return;
        }
        runHeadless(config, headless);
    }

    private static void runHeadless(Path config, boolean asked) {
        Settings settings;
        try {
            // Logging is set up as soon as the server's keys are known, before the catalog logs its plugins.
            Function<Settings, ModelCatalog> catalog = server -> {
                LogSetup.toStandardOutput(server.logLevel());
                return Settings.modelsFor(server);
            };
            settings = config == null ? Settings.of(new Properties(), "the defaults", catalog)
                    : Settings.of(Settings.read(config), config.toString(), catalog);
        } catch (SettingsException e) {
            fail(2, e.getMessage());
            return;
        }
        Logger log = Logger.getLogger(Main.class.getName());
        if (!asked) {
            log.info("there is no window yet: running headless");
        }
        ModelCatalog catalog = settings.catalog();
        PropagationModel model = catalog.find(settings.modelName());
        if (model == null) {
            fail(2, "wss.model = '" + settings.modelName() + "' is not a known model; known: " + String.join(", ", catalog.names()));
        }
        for (String key : settings.ignoredKeys()) {
            log.warning(config + ": " + key + " is not a setting of " + model.name() + " (it is one of "
                    + String.join(", ", declaring(catalog, key)) + "): ignored");
        }
        Hub hub = new Hub(settings.hubConfig(), model);
        CsvEventLog eventLog = settings.eventLog() ? openEventLog(settings.eventLogDir()) : null;
        if (eventLog != null) {
            hub.addListener(eventLog);
        }
        // Before anything listens: a SIGTERM right after the start line must still exit 0.
        onStopSignal(() -> stop(hub, eventLog));
        try {
            model.configure(settings.modelSettings());
            hub.start();
        } catch (IOException e) {
            fail(1, "cannot listen for robots on " + settings.get("wss.bindAddress") + ":" + settings.get("wss.port")
                    + ": " + e.getMessage());
        } catch (ModelStartException | RuntimeException e) {
            fail(1, model.name() + " did not start: " + e.getMessage());
        }
        waitForStopSignal();
    }

    /** The names of the models that declare this key. */
    private static List<String> declaring(ModelCatalog catalog, String key) {
        return catalog.models().stream().filter(model -> Setting.find(model.settings(), key) != null)
                .map(PropagationModel::name).toList();
    }

    private static CsvEventLog openEventLog(Path directory) {
        try {
            return CsvEventLog.create(directory);
        } catch (IOException e) {
            fail(1, "cannot write the event log in " + directory + ": " + e);
            return null;
        }
    }

    private static void stop(Hub hub, CsvEventLog eventLog) {
        try {
            hub.close();
            if (eventLog != null) {
                eventLog.close();
            }
        } finally {
            System.exit(0);
        }
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
