package org.usarsim.wss.gui;

import java.awt.Window;
import java.io.IOException;
import java.net.URI;
import java.nio.file.Path;
import java.util.concurrent.ExecutionException;
import java.util.logging.Logger;
import javax.swing.JOptionPane;
import javax.swing.SwingWorker;
import org.usarsim.wss.attach.MonitorClient;

/**
 * How a window comes to be attached (docs/monitor.md, "Attaching the window"): File > Attach...
 * asks ({@link AttachDialog}), connects off the event thread and opens a new window attached to the
 * server; {@code wss --attach} asks only for a token it has neither from {@code --token-file} nor
 * remembered.
 */
public final class Attaching {

    private static final Logger LOG = Logger.getLogger(Attaching.class.getName());

    private Attaching() {
    }

    /** What to attach with: the URL, the token, the certificate file to trust alone (empty: the JDK's trust store), and whether the token is remembered. */
    public record Request(String url, String token, String cert, boolean remember) {
    }

    /** Whether the text is a monitor's URL: http or https, a host (no user or token in it), a port. */
    public static boolean isMonitorUrl(String url) {
        return url.matches("https?://[^/?#@\\s]+(/\\S*)?");
    }

    /**
     * The token for that URL when one is remembered, else the dialog's (the URL and certificate shown,
     * the token remembered if ticked): what to attach with, or null when cancelled. Event thread.
     */
    public static Request ask(Window owner, String url, String cert, WindowPreferences preferences) {
        String remembered = preferences.attachToken(url);
        if (remembered != null) {
            return new Request(url, remembered, cert, true);
        }
        Request asked = AttachDialog.ask(owner, url, cert);
        if (asked != null) {
            preferences.storeAttach(asked.url(), asked.cert(), asked.token(), asked.remember());
        }
        return asked;
    }

    /** Connects as asked (blocking: never on the event thread); the certificate empty: the JDK's trust store. */
    public static MonitorClient connect(Request asked) throws IOException, InterruptedException {
        return MonitorClient.connect(URI.create(asked.url()), asked.token(), asked.cert().isEmpty() ? null : Path.of(asked.cert()));
    }

    /** File > Attach...: the dialog, then a new attached window; closing it closes only it. Event thread. */
    static void fromMenu(Window owner, WindowPreferences preferences) {
        Request asked = AttachDialog.ask(owner, preferences.attachUrl(), preferences.attachCert());
        if (asked == null) {
            return;
        }
        preferences.storeAttach(asked.url(), asked.cert(), asked.token(), asked.remember());
        new SwingWorker<MonitorClient, Void>() {
            @Override
            protected MonitorClient doInBackground() throws Exception {
                return connect(asked);
            }

            @Override
            protected void done() {
                try {
                    MainWindow.openAttached(get(), preferences, () -> { });
                } catch (ExecutionException e) {
                    String why = "Cannot attach to " + asked.url() + ": " + e.getCause().getMessage();
                    LOG.warning(why);
                    JOptionPane.showMessageDialog(owner, WrappedMessage.of(why), MainWindow.TITLE, JOptionPane.ERROR_MESSAGE);
                } catch (InterruptedException e) {
                    throw new IllegalStateException("the event thread was interrupted", e);
                }
            }
        }.execute();
    }
}
