package org.usarsim.wss.app;

import java.io.IOException;
import java.io.PrintStream;
import java.lang.reflect.InvocationTargetException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.atomic.AtomicReference;
import java.util.logging.Level;
import javax.swing.SwingUtilities;
import org.usarsim.wss.attach.MonitorClient;
import org.usarsim.wss.gui.Attaching;
import org.usarsim.wss.gui.MainWindow;
import org.usarsim.wss.gui.WindowPreferences;

/**
 * {@code --attach URL [--token-file FILE] [--trust-cert FILE]}: a window attached to a running
 * WSS's monitor endpoint (docs/monitor.md), until it is closed (or SIGTERM). The token is the
 * file's first line, else the one remembered for that URL, else the window asks; it is never taken
 * from the command line, where {@code ps} would show it.
 */
final class AttachRun {

    private AttachRun() {
    }

    static int run(PrintStream out, Options.Attach options) throws RunFailure {
        if (java.awt.GraphicsEnvironment.isHeadless()) {
            throw RunFailure.badInput("--attach opens a window: there is no display here (DISPLAY is unset)");
        }
        LogSetup.install(out, Level.INFO);
        String cert = options.trustCert() == null ? "" : options.trustCert().toString();
        WindowPreferences preferences = new WindowPreferences();
        Attaching.Request request = options.tokenFile() != null
                ? new Attaching.Request(options.url(), token(options.tokenFile()), cert, false)
                : onEventThread(() -> Attaching.ask(null, options.url(), cert, preferences));
        if (request == null) {
            return Main.OK; // the dialog was cancelled
        }
        MonitorClient client;
        try {
            client = Attaching.connect(request);
        } catch (IOException e) {
            throw new RunFailure(Main.CANNOT_START, "cannot attach to " + request.url() + ": " + e.getMessage());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return Main.OK;
        }
        try (StopSignal stop = new StopSignal()) {
            SwingUtilities.invokeLater(() -> MainWindow.openAttached(client, preferences, stop::stop));
            stop.await();
        } finally {
            client.close();
        }
        return Main.OK;
    }

    /** The token: the file's first line, stripped. */
    private static String token(Path file) throws RunFailure {
        try {
            String token = Files.readAllLines(file).stream().map(String::strip).filter(line -> !line.isEmpty()).findFirst().orElse("");
            if (token.isEmpty()) {
                throw RunFailure.badInput("--token-file " + file + " holds no token");
            }
            return token;
        } catch (IOException e) {
            throw RunFailure.badInput("--token-file " + file + " cannot be read: " + e.getMessage());
        }
    }

    private interface Asking {
        Attaching.Request ask();
    }

    private static Attaching.Request onEventThread(Asking asking) throws RunFailure {
        AtomicReference<Attaching.Request> asked = new AtomicReference<>();
        try {
            SwingUtilities.invokeAndWait(() -> asked.set(asking.ask()));
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (InvocationTargetException e) {
            throw new RunFailure(Main.CANNOT_START, "cannot ask for the token: " + e.getCause());
        }
        return asked.get();
    }
}
