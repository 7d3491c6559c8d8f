package org.usarsim.wss.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.usarsim.wss.gui.Gui.cells;
import static org.usarsim.wss.gui.Gui.find;
import static org.usarsim.wss.gui.Gui.onEdt;
import static org.usarsim.wss.gui.Gui.run;
import static org.usarsim.wss.gui.Gui.until;

import java.awt.Rectangle;
import java.awt.Window;
import java.awt.event.InputEvent;
import java.awt.event.MouseEvent;
import java.awt.event.WindowEvent;
import java.net.InetAddress;
import java.net.URI;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.prefs.Preferences;
import javax.swing.JButton;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JPopupMenu;
import javax.swing.JTable;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.usarsim.wss.attach.MonitorClient;
import org.usarsim.wss.hub.Hub;
import org.usarsim.wss.hub.TestHub;
import org.usarsim.wss.hub.TestRobot;
import org.usarsim.wss.hub.core.Force;
import org.usarsim.wss.model.noop.NoopPropagationModel;
import org.usarsim.wss.monitor.MonitorConfig;
import org.usarsim.wss.monitor.MonitorServer;
import org.usarsim.wss.monitor.Watched;
import org.usarsim.wss.shaping.ShapingConfig;

/**
 * A window attached to a real hub's monitor endpoint over real sockets (docs/monitor.md,
 * "Attaching the window"): its tables (the Routes tab too) follow the hub, its title names the server, the bar is the
 * server's, a viewer gets no force menu, and a lost connection shows the banner until it is back.
 */
@Timeout(60)
@Tag("slow")
class AttachedWindowTest {

    static final String OPERATOR = "operator-token-0123456789";
    static final String VIEWER = "viewer-token-0123456789";

    @TempDir
    Path dir;
    private Hub hub;
    private NoopPropagationModel model;
    private MonitorServer monitor;
    private Path tokens;
    private Preferences preferences;
    private JFrame frame;
    private final CountDownLatch closed = new CountDownLatch(1);

    @BeforeAll
    static void display() {
        Gui.requireDisplay();
    }

    @BeforeEach
    void startHub() throws Exception {
        model = new NoopPropagationModel();
        hub = new Hub(TestHub.config(true, 65536, 600, 1000, 30), model);
        hub.start();
        tokens = tokenFile(dir);
        monitor = startMonitor(hub, model, tokens);
        preferences = TestPreferences.create();
    }

    /** The token file of the tests: an operator's and a viewer's token, readable by its owner only. */
    static Path tokenFile(Path dir) throws Exception {
        Path file = dir.resolve("tokens");
        Files.writeString(file, "operator " + OPERATOR + "\nviewer " + VIEWER + "\n");
        Files.setPosixFilePermissions(file, PosixFilePermissions.fromString("rw-------"));
        return file;
    }

    /** The hub's monitor endpoint on 127.0.0.1, on a port the OS chooses. */
    static MonitorServer startMonitor(Hub hub, NoopPropagationModel model, Path tokens) throws Exception {
        MonitorConfig config = new MonitorConfig(-1, InetAddress.getLoopbackAddress(), tokens, MonitorConfig.DEFAULT_MAX_CLIENTS, null, null);
        MonitorServer server = MonitorServer.open(config, new Watched(hub, model, Map.of(), ShapingConfig.OFF, "127.0.0.1"));
        server.start();
        return server;
    }

    @AfterEach
    void close() throws Exception {
        if (frame != null) {
            run(() -> frame.dispatchEvent(new WindowEvent(frame, WindowEvent.WINDOW_CLOSING)));
            assertTrue(closed.await(10, TimeUnit.SECONDS), "the window closed");
        }
        if (monitor != null) {
            monitor.close();
        }
        hub.close();
        TestPreferences.remove(preferences);
    }

    private void attach(int port, String token) throws Exception {
        MonitorClient client = MonitorClient.connect(URI.create("http://127.0.0.1:" + port), token, null);
        frame = onEdt(() -> MainWindow.openAttached(client, new WindowPreferences(preferences.node("window")), closed::countDown).frame());
    }

    /** The table of that name. Event thread. */
    private JTable table(String name) {
        return find(frame.getContentPane(), JTable.class, name);
    }

    /** The state column of the statistics row of that pair, "" while there is none. Event thread. */
    private String stateOf(String first, String second) {
        return cells(table("stats")).stream().filter(row -> row.get(0).equals(first) && row.get(1).equals(second))
                .map(row -> row.get(2)).findFirst().orElse("");
    }

    @Test
    void theTablesFollowTheHubAndTheBarIsTheServers() throws Exception {
        attach(monitor.port(), OPERATOR);
        assertEquals("WSS - attached to 127.0.0.1:" + monitor.port(), onEdt(frame::getTitle));
        try (TestRobot r1 = new TestRobot(hub.controlPort(), "127.0.0.2"); TestRobot r2 = new TestRobot(hub.controlPort(), "127.0.0.3")) {
            registerPair(r1, r2);
            until("the attached window shows both robots", () -> cells(table("robots")).stream().map(row -> row.get(0)).toList()
                    .equals(List.of("r1", "r2")));
            until("the pair is up", () -> stateOf("r1", "r2").equals("up"));
            until("the Routes tab shows the server's route r1 - r2 (its monitor's routes)", () -> cells(table("routes")).stream()
                    .anyMatch(row -> row.subList(0, 3).equals(List.of("r1", "r2", "1"))));
            hub.force("r1", "r2", Force.DOWN);
            until("the pair is forced down", () -> stateOf("r1", "r2").equals("forced down"));
            hub.release("r1", "r2");
            until("the pair is up again", () -> stateOf("r1", "r2").equals("up"));
        }
        JButton start = onEdt(() -> find(frame.getContentPane(), JButton.class, "start"));
        assertFalse(onEdt(start::isEnabled), "Start / Stop is the server's");
        String tip = onEdt(start::getToolTipText);
        assertTrue(tip.startsWith("The server's own"), tip);
        assertEquals(String.valueOf(hub.controlPort()), onEdt(() -> find(frame.getContentPane(), javax.swing.JTextField.class, "port").getText()));
    }

    @Test
    void anOperatorsRightClickOffersTheForceMenuAndAViewersNothing() throws Exception {
        try (TestRobot r1 = new TestRobot(hub.controlPort(), "127.0.0.2"); TestRobot r2 = new TestRobot(hub.controlPort(), "127.0.0.3")) {
            registerPair(r1, r2);
            until("the hub saw the pair", () -> !hub.snapshot().pairs().isEmpty());
            attach(monitor.port(), VIEWER);
            until("the pair is shown", () -> stateOf("r1", "r2").equals("up"));
            rightClickFirstStatisticsRow();
            assertFalse(onEdt(AttachedWindowTest::popupShowing), "a viewer's window offers no force menu");
            assertTrue(onEdt(() -> table("stats").getRowCount() == 1), "the row was there to click");
        }
    }

    @Test
    void anOperatorsForceMenuForcesThePairOnTheServer() throws Exception {
        try (TestRobot r1 = new TestRobot(hub.controlPort(), "127.0.0.2"); TestRobot r2 = new TestRobot(hub.controlPort(), "127.0.0.3")) {
            registerPair(r1, r2);
            attach(monitor.port(), OPERATOR);
            until("the pair is shown", () -> stateOf("r1", "r2").equals("up"));
            rightClickFirstStatisticsRow();
            until("the force menu shows", AttachedWindowTest::popupShowing);
            run(() -> shownItem(ForceMenu.DOWN).doClick());
            until("the hub forced the pair down, and the window shows it", () -> stateOf("r1", "r2").equals("forced down"));
        }
    }

    @Test
    void aLostConnectionShowsTheBannerUntilTheServerIsBack() throws Exception {
        try (CuttableProxy network = new CuttableProxy(monitor.port())) {
            attach(network.port(), OPERATOR);
            JLabel banner = onEdt(() -> find(frame.getContentPane(), JLabel.class, "banner"));
            assertFalse(onEdt(banner::isVisible));
            network.cut(); // the network drops, and the server stops
            monitor.close();
            until("the banner says the connection is lost", () -> banner.isVisible()
                    && banner.getText().startsWith("Connection to 127.0.0.1:" + network.port() + " lost, reconnecting in "));
            monitor = startMonitor(hub, model, tokens); // back, elsewhere behind the same address
            network.restore(monitor.port());
            try (TestRobot r1 = new TestRobot(hub.controlPort(), "127.0.0.2")) {
                r1.initAccepting("r1");
                until("the banner goes and the tables follow the new stream", () -> !banner.isVisible()
                        && cells(table("robots")).stream().anyMatch(row -> row.get(0).equals("r1")));
            }
        }
    }

    /** File > Attach...: the dialog's URL and token, OK, and a new window attached to the server; the token not remembered unless ticked. */
    @Test
    void fileAttachAsksAndOpensAnAttachedWindow() throws Exception {
        WindowPreferences stored = new WindowPreferences(preferences.node("window"));
        javax.swing.SwingUtilities.invokeLater(() -> Attaching.fromMenu(null, stored)); // the dialog is modal
        until("the dialog shows", () -> Gui.showing("Attach to a WSS").size() == 1);
        String url = "http://127.0.0.1:" + monitor.port();
        run(() -> {
            Window dialog = Gui.showing("Attach to a WSS").get(0);
            find(dialog, javax.swing.JTextField.class, AttachDialog.URL).setText(url);
            find(dialog, javax.swing.JPasswordField.class, AttachDialog.TOKEN).setText(VIEWER);
            find(dialog, JButton.class, DialogParts.OK).doClick();
        });
        String title = "WSS - attached to 127.0.0.1:" + monitor.port();
        until("the attached window opens", () -> attachedFrame(title) != null);
        assertEquals(url, stored.attachUrl());
        assertEquals(null, stored.attachToken(url), "not ticked: the token is not stored");
        run(() -> attachedFrame(title).dispatchEvent(new WindowEvent(attachedFrame(title), WindowEvent.WINDOW_CLOSING)));
        until("the attached window closed", () -> attachedFrame(title) == null);
    }

    private static JFrame attachedFrame(String title) {
        for (Window window : Window.getWindows()) {
            if (window.isShowing() && window instanceof JFrame shown && title.equals(shown.getTitle())) {
                return shown;
            }
        }
        return null;
    }

    /** r1 and r2 register, and r1 asks a port to r2: the hub sees the pair. */
    private static void registerPair(TestRobot r1, TestRobot r2) throws Exception {
        r1.initAccepting("r1");
        r2.initAccepting("r2");
        r1.dns("r2", 0);
    }

    /** Shows the Link statistics tab and right-clicks its first row, as a user does. */
    private void rightClickFirstStatisticsRow() {
        run(() -> find(frame.getContentPane(), javax.swing.JTabbedPane.class, "tabs").setSelectedIndex(2));
        JTable stats = onEdt(() -> table("stats"));
        until("the statistics show", stats::isShowing);
        run(() -> {
            Rectangle row = stats.getCellRect(0, 0, true);
            for (int id : new int[] {MouseEvent.MOUSE_PRESSED, MouseEvent.MOUSE_RELEASED}) {
                stats.dispatchEvent(new MouseEvent(stats, id, System.currentTimeMillis(), InputEvent.BUTTON3_DOWN_MASK,
                        row.x + 5, row.y + 5, 1, true, MouseEvent.BUTTON3));
            }
        });
    }

    private static boolean popupShowing() {
        for (Window window : Window.getWindows()) {
            if (Gui.all(window, JPopupMenu.class).stream().anyMatch(JPopupMenu::isShowing)) {
                return true;
            }
        }
        return false;
    }

    private static javax.swing.JMenuItem shownItem(String text) {
        for (Window window : Window.getWindows()) {
            for (JPopupMenu menu : Gui.all(window, JPopupMenu.class)) {
                if (menu.isShowing()) {
                    return Gui.all(menu, javax.swing.JMenuItem.class).stream().filter(item -> item.getText().startsWith(text))
                            .findFirst().orElseThrow();
                }
            }
        }
        throw new AssertionError("no force menu showing");
    }
}
