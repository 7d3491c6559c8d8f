package org.usarsim.wss.gui;

import static org.junit.jupiter.api.Assertions.fail;

import java.awt.Component;
import java.awt.Container;
import java.awt.GraphicsEnvironment;
import java.awt.Window;
import java.lang.reflect.InvocationTargetException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.function.BooleanSupplier;
import javax.swing.SwingUtilities;

/** Driving real Swing windows from a test: everything on the event thread, waits with a deadline. */
public final class Gui {

    private static final long DEADLINE_NS = 5_000_000_000L;

    private Gui() {
    }

    /** Fails, not skips, without a display: the GUI tests must run (CI runs them under xvfb-run). */
    public static void requireDisplay() {
        if (GraphicsEnvironment.isHeadless()) {
            fail("the GUI tests open real windows and need a display; there is none (DISPLAY is "
                    + (System.getenv("DISPLAY") == null ? "unset" : "'" + System.getenv("DISPLAY") + "'")
                    + "). Run the tests under a virtual one: xvfb-run -a mvn -B test (apt-get install xvfb)");
        }
        try {
            GraphicsEnvironment.getLocalGraphicsEnvironment().getScreenDevices();
        } catch (Throwable e) { // AWTError, or an UnsatisfiedLinkError from a JDK without its X11 library
            fail("the GUI tests cannot open the display " + System.getenv("DISPLAY") + ": " + e
                    + ". A running X server (xvfb-run -a mvn -B test) and a JDK with its X11 library"
                    + " (Debian: openjdk-17-jre, not only -headless) are needed");
        }
    }

    /** Runs on the event thread and returns its result; an exception there fails the test here. */
    public static <T> T onEdt(Callable<T> action) {
        if (SwingUtilities.isEventDispatchThread()) {
            throw new IllegalStateException("call from the test's thread");
        }
        List<T> result = new ArrayList<>(1);
        try {
            SwingUtilities.invokeAndWait(() -> {
                try {
                    result.add(action.call());
                } catch (Exception e) {
                    throw new IllegalStateException(e);
                }
            });
        } catch (InvocationTargetException e) {
            Throwable cause = e.getCause();
            if (cause instanceof RuntimeException runtime) {
                throw runtime;
            }
            if (cause instanceof Error error) {
                throw error;
            }
            throw new IllegalStateException(cause);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException(e);
        }
        return result.get(0);
    }

    /** Runs on the event thread and waits for it. */
    public static void run(Runnable action) {
        onEdt(() -> {
            action.run();
            return null;
        });
    }

    /** Polls the condition on the event thread until it holds; fails after five seconds. */
    public static void until(String what, BooleanSupplier condition) {
        long deadline = System.nanoTime() + DEADLINE_NS;
        while (!onEdt(condition::getAsBoolean)) {
            if (System.nanoTime() > deadline) {
                fail("timed out waiting until " + what);
            }
            try {
                Thread.sleep(5);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                fail("interrupted waiting until " + what);
            }
        }
    }

    /** The one component of that type and name in the window; fails when there is none. Event thread. */
    public static <T extends Component> T find(Container root, Class<T> type, String name) {
        List<T> found = new ArrayList<>();
        collect(root, type, name, found);
        if (found.size() != 1) {
            fail(found.size() + " components " + type.getSimpleName() + " named " + name + " in " + root.getName());
        }
        return found.get(0);
    }

    /** Every component of that type in the window, in order. Event thread. */
    public static <T extends Component> List<T> all(Container root, Class<T> type) {
        List<T> found = new ArrayList<>();
        collect(root, type, null, found);
        return found;
    }

    private static <T extends Component> void collect(Container container, Class<T> type, String name, List<T> found) {
        for (Component child : container.getComponents()) {
            if (type.isInstance(child) && (name == null || name.equals(child.getName()))) {
                found.add(type.cast(child));
            }
            if (child instanceof Container inner) {
                collect(inner, type, name, found);
            }
        }
    }

    /** The showing windows with that title. Event thread. */
    public static List<Window> showing(String title) {
        List<Window> windows = new ArrayList<>();
        for (Window window : Window.getWindows()) {
            if (window.isShowing() && window instanceof java.awt.Dialog dialog && title.equals(dialog.getTitle())) {
                windows.add(window);
            }
        }
        return windows;
    }

    /** What a table shows, row by row as sorted and filtered, each cell as its text (null: empty). Event thread. */
    public static List<List<String>> cells(javax.swing.JTable table) {
        List<List<String>> rows = new ArrayList<>();
        for (int row = 0; row < table.getRowCount(); row++) {
            List<String> cells = new ArrayList<>();
            for (int column = 0; column < table.getColumnCount(); column++) {
                Object value = table.getValueAt(row, column);
                cells.add(value == null ? "" : String.valueOf(value)); // null shows as an empty cell
            }
            rows.add(cells);
        }
        return rows;
    }

    /**
     * Waits for the one showing message dialog with that title, closes it with its button and
     * returns its message.
     */
    public static String closeMessage(String title) {
        until("a message dialog '" + title + "' shows", () -> showing(title).size() == 1);
        return onEdt(() -> {
            Window dialog = showing(title).get(0);
            javax.swing.JOptionPane pane = all(dialog, javax.swing.JOptionPane.class).get(0);
            // A text (the About box) or a wrapped message's area (an error).
            String message = pane.getMessage() instanceof javax.swing.text.JTextComponent text ? text.getText()
                    : String.valueOf(pane.getMessage());
            all(pane, javax.swing.JButton.class).get(0).doClick();
            return message;
        });
    }
}
