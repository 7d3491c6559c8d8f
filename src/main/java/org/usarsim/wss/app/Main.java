package org.usarsim.wss.app;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.logging.Logger;
import org.usarsim.wss.hub.CsvEventLog;
import org.usarsim.wss.hub.Hub;
import org.usarsim.wss.model.ModelCatalog;
import org.usarsim.wss.model.ModelStartException;
import org.usarsim.wss.model.PluginFolder;
import org.usarsim.wss.model.PropagationModel;
import sun.misc.Signal;

/**
 * Starts the WSS. {@code --headless [--config FILE]} runs without a window, from built-in
 * defaults and the file. Exit codes: 0 after SIGTERM or Ctrl-C, 1 when the server cannot start
 * (control port in use, model will not start), 2 for a bad command line or configuration.
 */
public final class Main {

    static final String USAGE = "usage: java -jar wss.jar [--headless] [--config FILE]";

    private Main() {
    }

    public static void main(String[] args) {
        Path config = null;
        boolean headless = false;
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
                case "--help":
                case "-h":
                    System.out.println(USAGE);
                    return;
                default:
                    fail(2, "unknown argument " + args[i] + "\n" + USAGE);
            }
        }
        runHeadless(config, headless);
    }

    private static void runHeadless(Path config, boolean asked) {
        Settings settings;
        try {
            settings = config == null ? Settings.defaults() : Settings.load(config);
        } catch (SettingsException e) {
            fail(2, e.getMessage());
            return;
        }
        LogSetup.toStandardOutput(settings.logLevel());
        if (!asked) {
            Logger.getLogger(Main.class.getName()).info("there is no window yet: running headless");
        }
        List<Path> pluginFolders = new ArrayList<>();
        PluginFolder.besideCodeOf(Main.class).ifPresent(pluginFolders::add);
        settings.pluginDir().ifPresent(pluginFolders::add);
        ModelCatalog catalog = ModelCatalog.load(Main.class.getClassLoader(), pluginFolders);
        PropagationModel model = catalog.find(settings.modelName());
        if (model == null) {
            fail(2, "wss.model = '" + settings.modelName() + "' is not a known model; known: " + String.join(", ", catalog.names()));
        }
        Hub hub = new Hub(settings.hubConfig(), model);
        CsvEventLog eventLog = settings.eventLog() ? openEventLog(settings.eventLogDir()) : null;
        if (eventLog != null) {
            hub.addListener(eventLog);
        }
        // Before anything listens: a SIGTERM right after the start line must still exit 0.
        Signal.handle(new Signal("TERM"), signal -> stop(hub, eventLog));
        Signal.handle(new Signal("INT"), signal -> stop(hub, eventLog));
        try {
            model.configure(settings.modelSettings());
            hub.start();
        } catch (IOException e) {
            fail(1, "cannot listen for robots on " + settings.get("wss.bindAddress") + ":" + settings.get("wss.port")
                    + ": " + e.getMessage());
        } catch (ModelStartException | RuntimeException e) {
            fail(1, model.name() + " did not start: " + e.getMessage());
        }
        try {
            new CountDownLatch(1).await();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
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

    private static void fail(int status, String message) {
        System.err.println("wss: " + message);
        System.exit(status);
    }
}
