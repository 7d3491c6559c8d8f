package org.usarsim.wss.gui;

import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.function.Consumer;
import java.util.function.Supplier;
import java.util.logging.Level;
import java.util.logging.Logger;
import javax.swing.JMenuItem;
import javax.swing.JPopupMenu;
import org.usarsim.wss.hub.core.Force;

/**
 * The right-click menu on a pair of robots (a row of the statistics table, a line of the map):
 * force the pair down, force it up, or give it back to the model. The hub is called on a thread
 * of the menu's own, never on the event thread; what changed comes back through the hub's events
 * like any other change.
 */
final class ForceMenu {

    private static final Logger LOG = Logger.getLogger(ForceMenu.class.getName());
    static final String DOWN = "Force down";
    static final String UP = "Force up";
    static final String RELEASE = "Release to the model";

    private final ExecutorService worker = Executors.newSingleThreadExecutor(task -> {
        Thread thread = new Thread(task, "wss-window-force");
        thread.setDaemon(true);
        return thread;
    });
    private final Supplier<Servers.Running> running;

    /** @param running the server that runs now, or null when none does */
    ForceMenu(Supplier<Servers.Running> running) {
        this.running = running;
    }

    /** Event thread: the menu for the pair; its items are disabled when no server runs. */
    JPopupMenu menuFor(String robotA, String robotB) {
        JPopupMenu menu = new JPopupMenu(robotA + " - " + robotB);
        menu.add(item(DOWN + " " + robotA + " - " + robotB, server -> server.force(robotA, robotB, Force.DOWN)));
        menu.add(item(UP + " " + robotA + " - " + robotB, server -> server.force(robotA, robotB, Force.UP)));
        menu.add(item(RELEASE, server -> server.release(robotA, robotB)));
        return menu;
    }

    private JMenuItem item(String text, Consumer<Servers.Running> action) {
        JMenuItem item = new JMenuItem(text);
        Servers.Running server = running.get();
        item.setEnabled(server != null);
        item.addActionListener(e -> worker.execute(() -> {
            try {
                action.accept(server);
            } catch (RuntimeException ex) {
                LOG.log(Level.WARNING, text + " failed: " + ex, ex);
            }
        }));
        return item;
    }

    void close() {
        worker.shutdownNow();
    }
}
