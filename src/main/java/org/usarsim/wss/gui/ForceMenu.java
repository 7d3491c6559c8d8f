package org.usarsim.wss.gui;

import java.awt.Window;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.function.Supplier;
import java.util.logging.Level;
import java.util.logging.Logger;
import javax.swing.JMenuItem;
import javax.swing.JPopupMenu;
import javax.swing.SwingUtilities;
import org.usarsim.wss.hub.core.Force;
import org.usarsim.wss.hub.core.RatePin;
import org.usarsim.wss.shaping.Bitrate;

/**
 * The right-click menu on a pair of robots (a row of the statistics table, a line of the map):
 * force the pair down, force it up, force it up with its rate and delay pinned ("Limit rate...",
 * asked by a {@link RateLimitDialog}), or give it back to the model. The hub is called on a thread
 * of the menu's own, never on the event thread; what changed comes back through the hub's events
 * like any other change.
 */
final class ForceMenu {

    private static final Logger LOG = Logger.getLogger(ForceMenu.class.getName());
    static final String DOWN = "Force down";
    static final String UP = "Force up";
    static final String LIMIT = "Limit rate...";
    static final String RELEASE = "Release to the model";

    private final ExecutorService worker = Executors.newSingleThreadExecutor(task -> {
        Thread thread = new Thread(task, "wss-window-force");
        thread.setDaemon(true);
        return thread;
    });
    private final Supplier<PairControls> running;
    private final boolean offered;

    /** @param running the server that runs now, or null when none does */
    ForceMenu(Supplier<PairControls> running) {
        this(running, true);
    }

    /**
     * @param running the controls of the server shown now, or null when none runs
     * @param offered whether the window offers the menu at all (an attached window: only with an operator's token)
     */
    ForceMenu(Supplier<PairControls> running, boolean offered) {
        this.running = running;
        this.offered = offered;
    }

    /** Event thread: the menu for the pair, its items disabled when no server runs; null when the window offers none. */
    JPopupMenu menuFor(String robotA, String robotB) {
        if (!offered) {
            return null;
        }
        JPopupMenu menu = new JPopupMenu(robotA + " - " + robotB);
        PairControls server = running.get();
        String pair = robotA + " - " + robotB;
        menu.add(item(DOWN + " " + pair, server, () -> server.force(robotA, robotB, Force.DOWN)));
        menu.add(item(UP + " " + pair, server, () -> server.force(robotA, robotB, Force.UP)));
        JMenuItem limit = new JMenuItem(LIMIT);
        limit.setEnabled(server != null);
        limit.addActionListener(e -> {
            Window owner = menu.getInvoker() == null ? null : SwingUtilities.getWindowAncestor(menu.getInvoker());
            RatePin pin = RateLimitDialog.ask(owner, robotA, robotB);
            if (pin != null) {
                String shape = Bitrate.format(pin.bitsPerSecond()) + (pin.pinsDelay() ? ", delay " + pin.delayMs() + " ms" : "")
                        + (pin.pinsJitter() ? ", jitter " + pin.jitterMs() + " ms" : "");
                call(LIMIT + " " + pair, () -> {
                    LOG.info("window: limit rate " + pair + " to " + shape + " (forced up)"); // who, before what it does
                    server.force(robotA, robotB, Force.UP, pin);
                });
            }
        });
        menu.add(limit);
        menu.add(item(RELEASE, server, () -> server.release(robotA, robotB)));
        return menu;
    }

    private JMenuItem item(String text, PairControls server, Runnable action) {
        JMenuItem item = new JMenuItem(text);
        item.setEnabled(server != null);
        item.addActionListener(e -> call(text, action));
        return item;
    }

    /** Calls the hub on the menu's thread; a failure is logged. */
    private void call(String what, Runnable action) {
        worker.execute(() -> {
            try {
                action.run();
            } catch (RuntimeException ex) {
                LOG.log(Level.WARNING, what + " failed: " + ex, ex);
            }
        });
    }

    void close() {
        worker.shutdownNow();
    }
}
