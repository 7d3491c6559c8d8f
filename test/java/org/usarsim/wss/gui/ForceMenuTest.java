package org.usarsim.wss.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.usarsim.wss.gui.Gui.cells;
import static org.usarsim.wss.gui.Gui.find;
import static org.usarsim.wss.gui.Gui.onEdt;
import static org.usarsim.wss.gui.Gui.run;
import static org.usarsim.wss.gui.Gui.until;
import static org.usarsim.wss.hub.Sockets.assertClosedByPeer;

import java.awt.Color;
import java.awt.Window;
import java.net.ConnectException;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.List;
import java.util.Map;
import javax.swing.JButton;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JMenuItem;
import javax.swing.JPopupMenu;
import javax.swing.JTable;
import javax.swing.JTextField;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.usarsim.wss.hub.Hub;
import org.usarsim.wss.hub.HubConfig;
import org.usarsim.wss.hub.HubSnapshot;
import org.usarsim.wss.hub.TestHub;
import org.usarsim.wss.hub.TestRobot;
import org.usarsim.wss.hub.Wait;
import org.usarsim.wss.hub.core.PairState;
import org.usarsim.wss.model.ModelProvider;
import org.usarsim.wss.model.noop.NoopPropagationModel;
import org.usarsim.wss.shaping.RateTable;
import org.usarsim.wss.shaping.ShapingConfig;

/**
 * The right-click menu on a pair, for real: the main window runs a server, robots register over
 * real sockets, and the items of a real {@link ForceMenu} force the pair down, up and back to the
 * model; the window's Ports table shows the pair's ports stop and start listening. With links
 * shaped, "Limit rate..." asks a rate and a delay in a {@link RateLimitDialog} and pins them.
 */
@Timeout(60)
@Tag("slow")
class ForceMenuTest {

    private OpenWindow window;
    private HubServers servers;
    private WindowLog windowLog;
    private JFrame frame;
    private ForceMenu menu;


    @BeforeAll
    static void display() {
        Gui.requireDisplay();
    }

    @BeforeEach
    void open() throws Exception {
        open(TestHub.config(true, 65536, 600, 1000, 30));
    }

    /** The main window, its servers hubs of this configuration, and a menu on them. */
    private void open(HubConfig config) throws Exception {
        window = new OpenWindow(config, List.of(ModelProvider.of(NoopPropagationModel::new)), "NoopPropagationModel");
        servers = window.servers;
        windowLog = window.windowLog;
        frame = window.frame;
        menu = onEdt(() -> new ForceMenu(servers::running));
    }

    @AfterEach
    void close() throws Exception {
        run(menu::close);
        window.close();
    }

    /** Clicks the menu's item whose text starts so, as a user's click does. */
    private void click(String robotA, String robotB, String item) {
        run(() -> {
            JPopupMenu popup = menu.menuFor(robotA, robotB);
            JMenuItem found = Gui.all(popup, JMenuItem.class).stream().filter(i -> i.getText().startsWith(item))
                    .findFirst().orElseThrow(() -> new AssertionError("no item '" + item + "'"));
            assertTrue(found.isEnabled(), item + " is enabled while a server runs");
            found.doClick();
        });
    }

    /** Presses Start and waits for the server; returns its control port. */
    private int start() {
        JButton start = onEdt(() -> find(frame.getContentPane(), JButton.class, "start"));
        run(start::doClick);
        until("the server runs", () -> start.getText().equals("Stop"));
        return servers.running().port();
    }

    private void waitForPorts(List<List<String>> expected) {
        JTable ports = onEdt(() -> find(frame.getContentPane(), JTable.class, "ports"));
        until("ports shows " + expected, () -> cells(ports).equals(expected));
    }

    @Test
    void forceDownUpAndReleaseThroughTheMenuChangeWhatThePortsTableShows() throws Exception {
        run(() -> {
            JPopupMenu idle = menu.menuFor("r1", "r2");
            assertTrue(Gui.all(idle, JMenuItem.class).stream().noneMatch(JMenuItem::isEnabled), "no server: every item disabled");
        });
        int port = start();
        try (TestRobot r1 = new TestRobot(port, "127.0.0.2"); TestRobot r2 = new TestRobot(port, "127.0.0.3")) {
            ServerSocket r1Accepts = r1.initAccepting("r1");
            ServerSocket r2Accepts = r2.initAccepting("r2");
            int toR2 = r1.dns("r2", 0);
            int toR1 = r2.dns("r1", 0);
            List<String> r1r2 = List.of("r1", "r2", String.valueOf(r2Accepts.getLocalPort()), String.valueOf(toR2), "yes", "DNS");
            List<String> r2r1 = List.of("r2", "r1", String.valueOf(r1Accepts.getLocalPort()), String.valueOf(toR1), "yes", "DNS");
            waitForPorts(List.of(r1r2, r2r1));

            try (Socket data = r1.connect(toR2); Socket atR2 = r2Accepts.accept()) {
                click("r1", "r2", ForceMenu.DOWN);
                waitForPorts(List.of(no(r1r2), no(r2r1)));
                assertClosedByPeer(atR2, "the established connection, at r2");
                assertClosedByPeer(data, "the established connection, at r1");
            }
            assertThrows(ConnectException.class, () -> r1.connect(toR2).close(), "forced down: refused");

            click("r2", "r1", ForceMenu.RELEASE);
            waitForPorts(List.of(r1r2, r2r1));
            click("r1", "r2", ForceMenu.UP);
            until("the log says r1 - r2 was forced up", () -> find(frame.getContentPane(), javax.swing.JTextArea.class, "log")
                    .getText().contains("forced r1 - r2 up"));
            waitForPorts(List.of(r1r2, r2r1));
        }
    }

    private static List<String> no(List<String> portRow) {
        return List.of(portRow.get(0), portRow.get(1), portRow.get(2), portRow.get(3), "no", portRow.get(5));
    }

    @Test
    void limitRateRefusesABadRateInTheFieldAndPinsTheRateAndDelayItIsGiven() throws Exception {
        close();
        open(TestHub.config(true, 65536, 600, 1000, 30).withShaping(new ShapingConfig(true, RateTable.DEFAULT, 2, true), Map.of()));
        int port = start();
        try (TestRobot r1 = new TestRobot(port, "127.0.0.2"); TestRobot r2 = new TestRobot(port, "127.0.0.3")) {
            r1.init("r1");
            r2.initAccepting("r2");
            r1.dns("r2", 0);
            Hub hub = servers.hubs().get(0);
            Wait.until("the pair at the table's rate (Noop: 0 dBm, the top rate)", () -> rates(hub).equals(List.of(54_000_000L, 54_000_000L)));

            // The dialog is modal: its item is clicked later, as a user's click would be.
            SwingUtilities.invokeLater(() -> Gui.all(menu.menuFor("r1", "r2"), JMenuItem.class).stream()
                    .filter(item -> item.getText().equals(ForceMenu.LIMIT)).findFirst().orElseThrow().doClick());
            String title = "Limit rate r1 - r2";
            until(title + " shows", () -> Gui.showing(title).size() == 1);
            Window dialog = onEdt(() -> Gui.showing(title).get(0));
            JTextField rate = onEdt(() -> find(dialog, JTextField.class, RateLimitDialog.RATE));
            JTextField delay = onEdt(() -> find(dialog, JTextField.class, RateLimitDialog.DELAY));
            JTextField jitter = onEdt(() -> find(dialog, JTextField.class, RateLimitDialog.JITTER));
            JLabel message = onEdt(() -> find(dialog, JLabel.class, DialogParts.MESSAGE));
            JButton ok = onEdt(() -> find(dialog, JButton.class, DialogParts.OK));
            Color normal = onEdt(delay::getBackground);

            run(() -> rate.setText("fast"));
            assertEquals(DialogParts.INVALID, onEdt(rate::getBackground), "red as it is typed");
            run(ok::doClick);
            assertEquals(1, onEdt(() -> Gui.showing(title).size()), "OK refuses: the dialog stays");
            assertTrue(onEdt(message::getText).contains("Rate: \"fast\" is not a bit rate (a number of bit/s, with k for 1000 or M"),
                    onEdt(message::getText));
            run(() -> delay.setText("soon"));
            assertEquals(DialogParts.INVALID, onEdt(delay::getBackground));
            run(() -> rate.setText("1M"));
            assertEquals(normal, onEdt(rate::getBackground), "no longer red once it is a rate");
            run(ok::doClick);
            assertTrue(onEdt(message::getText).contains("Delay: soon is not a whole number of milliseconds"), onEdt(message::getText));
            run(() -> delay.setText("50"));
            assertEquals(normal, onEdt(delay::getBackground));
            run(() -> jitter.setText("10001"));
            assertEquals(DialogParts.INVALID, onEdt(jitter::getBackground));
            run(ok::doClick);
            assertTrue(onEdt(message::getText).contains("Jitter: 10001 is above 10000"), onEdt(message::getText));
            run(() -> jitter.setText("20"));
            assertEquals(List.of(54_000_000L, 54_000_000L), rates(hub), "nothing pinned before OK accepts");
            run(ok::doClick);
            until("the dialog closed", () -> Gui.showing(title).isEmpty());

            Wait.until("the hub has the pinned rate both ways", () -> rates(hub).equals(List.of(1_000_000L, 1_000_000L)));
            assertEquals(PairState.FORCED_UP, hub.snapshot().pairs().get(0).state());
            until("the log says who limited it", () -> find(frame.getContentPane(), javax.swing.JTextArea.class, "log")
                    .getText().contains("window: limit rate r1 - r2 to 1 Mbit/s, delay 50 ms, jitter 20 ms (forced up)"));
        }
    }

    @Test
    void cancelPinsNothing() throws Exception {
        close();
        open(TestHub.config(true, 65536, 600, 1000, 30).withShaping(new ShapingConfig(true, RateTable.DEFAULT, 2, true), Map.of()));
        int port = start();
        try (TestRobot r1 = new TestRobot(port, "127.0.0.2"); TestRobot r2 = new TestRobot(port, "127.0.0.3")) {
            r1.init("r1");
            r2.initAccepting("r2");
            r1.dns("r2", 0);
            Hub hub = servers.hubs().get(0);
            SwingUtilities.invokeLater(() -> Gui.all(menu.menuFor("r2", "r1"), JMenuItem.class).stream()
                    .filter(item -> item.getText().equals(ForceMenu.LIMIT)).findFirst().orElseThrow().doClick());
            String title = "Limit rate r2 - r1";
            until(title + " shows", () -> Gui.showing(title).size() == 1);
            Window dialog = onEdt(() -> Gui.showing(title).get(0));
            run(() -> find(dialog, JTextField.class, RateLimitDialog.RATE).setText("1M"));
            run(() -> find(dialog, JButton.class, DialogParts.CANCEL).doClick());
            until("the dialog closed", () -> Gui.showing(title).isEmpty());
            Wait.until("the pair at the table's rate", () -> rates(hub).equals(List.of(54_000_000L, 54_000_000L)));
            assertEquals(PairState.UP, hub.snapshot().pairs().get(0).state(), "not forced");
        }
    }

    /** The rates of the hub's one pair, first to second and back; none while it has no pair. */
    private static List<Long> rates(Hub hub) {
        List<HubSnapshot.PairEntry> pairs = hub.snapshot().pairs();
        return pairs.size() != 1 ? List.of() : List.of(pairs.get(0).linkRateFirstToSecond(), pairs.get(0).linkRateSecondToFirst());
    }
}
