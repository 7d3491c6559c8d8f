package org.usarsim.wss.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.usarsim.wss.gui.Gui.cells;
import static org.usarsim.wss.gui.Gui.find;
import static org.usarsim.wss.gui.Gui.onEdt;
import static org.usarsim.wss.gui.Gui.run;
import static org.usarsim.wss.gui.Gui.until;

import java.awt.event.WindowEvent;
import java.io.IOException;
import java.net.ConnectException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Properties;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.logging.Logger;
import java.util.prefs.Preferences;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import javax.swing.JButton;
import javax.swing.JCheckBox;
import javax.swing.JComboBox;
import javax.swing.JFrame;
import javax.swing.JMenuItem;
import javax.swing.JTable;
import javax.swing.JTextArea;
import javax.swing.JTextField;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.usarsim.wss.Version;
import org.usarsim.wss.gui.Gui;
import org.usarsim.wss.gui.Launch;
import org.usarsim.wss.gui.MainWindow;
import org.usarsim.wss.gui.ModelPreferences;
import org.usarsim.wss.gui.TestPreferences;
import org.usarsim.wss.gui.WindowLog;
import org.usarsim.wss.gui.WindowPreferences;
import org.usarsim.wss.hub.ScriptedModel;
import org.usarsim.wss.hub.TestRobot;
import org.usarsim.wss.model.ModelProvider;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.Setting;
import org.usarsim.wss.model.ModelSettings;
import org.usarsim.wss.model.distance.DistanceOnlyPropagationModel;
import org.usarsim.wss.model.noop.NoopPropagationModel;
import org.usarsim.wss.model.obstacle.ObstaclePropagationModel;
import org.usarsim.wss.world.WorldServer;

/**
 * The main window, for real: opened under a display, driven through its components (buttons
 * pressed, fields typed, tables and the log read), with real robots over real sockets and the
 * servers the application itself starts ({@link WindowServers}).
 */
@Timeout(60)
@Tag("slow")
class WindowTest {

    private static final Pattern LISTENING = Pattern.compile("debug: WSS listening for robots on 127\\.0\\.0\\.1:(\\d+)");

    @TempDir
    Path eventLogs;

    private final ScriptedModel model = new ScriptedModel();
    private CountDownLatch closed;
    private Preferences preferences;
    private WindowLog windowLog;
    private JFrame frame;

    @BeforeAll
    static void display() {
        Gui.requireDisplay();
    }

    @BeforeEach
    void open() throws Exception {
        preferences = TestPreferences.create();
        windowLog = new WindowLog();
        Logger.getLogger("").addHandler(windowLog);
        frame = openWindow(new Launch("0", "ScriptedModel", false, null, false));
    }

    private JFrame openWindow(Launch launch) throws Exception {
        return openWindow(launch, List.of(new NoopPropagationModel(), model));
    }

    private JFrame openWindow(Launch launch, List<PropagationModel> models) throws Exception {
        return openWindow(launch, models, Map.of());
    }

    /** The window, its servers built from a properties file with these keys besides the address and the event log's folder. */
    private JFrame openWindow(Launch launch, List<PropagationModel> models, Map<String, String> file) throws Exception {
        CountDownLatch windowClosed = new CountDownLatch(1);
        closed = windowClosed;
        Properties properties = new Properties();
        properties.setProperty("wss.bindAddress", "127.0.0.1");
        properties.setProperty("wss.eventLogDir", eventLogs.toString());
        file.forEach(properties::setProperty);
        WindowServers servers = new WindowServers(ConfigFile.of(properties, "test"));
        List<ModelProvider> providers = models.stream().map(model -> ModelProvider.of(() -> model)).toList();
        return onEdt(() -> MainWindow.open(servers, providers,
                new WindowPreferences(preferences.node("window")), new ModelPreferences(preferences.node("models")),
                windowLog, launch, windowClosed::countDown).frame());
    }

    @AfterEach
    void close() throws Exception {
        if (closed.getCount() > 0) {
            closeWindow();
        }
        Logger.getLogger("").removeHandler(windowLog);
        TestPreferences.remove(preferences);
    }

    private void closeWindow() throws InterruptedException {
        run(() -> frame.dispatchEvent(new WindowEvent(frame, WindowEvent.WINDOW_CLOSING)));
        assertTrue(closed.await(10, TimeUnit.SECONDS), "the window closed");
        assertFalse(onEdt(frame::isDisplayable));
    }

    /** The window's component of that type and name; from the test's thread or the event thread. */
    private <T extends java.awt.Component> T component(Class<T> type, String name) {
        if (javax.swing.SwingUtilities.isEventDispatchThread()) {
            return find(frame.getContentPane(), type, name);
        }
        return onEdt(() -> find(frame.getContentPane(), type, name));
    }

    private String button() {
        JButton start = component(JButton.class, "start");
        return onEdt(start::getText);
    }

    private String log() {
        JTextArea log = component(JTextArea.class, "log");
        return onEdt(log::getText);
    }

    private List<List<String>> table(String name) {
        JTable table = component(JTable.class, name);
        return onEdt(() -> cells(table));
    }

    private void waitForTable(String name, List<List<String>> expected) {
        JTable table = component(JTable.class, name);
        until(name + " shows " + expected, () -> cells(table).equals(expected));
    }

    /** Presses Start and waits for "Stop"; returns the control port the log names. */
    private int start() {
        JButton start = component(JButton.class, "start");
        run(start::doClick);
        until("the server runs", () -> start.getText().equals("Stop"));
        until("the log names the port", () -> LISTENING.matcher(find(frame.getContentPane(), JTextArea.class, "log").getText()).find());
        Matcher matcher = LISTENING.matcher(log());
        int port = -1;
        while (matcher.find()) {
            port = Integer.parseInt(matcher.group(1)); // the last start's
        }
        return port;
    }

    /** A port nothing listens on now (where a world server starts later). */
    private static int freePort() throws IOException {
        try (ServerSocket free = new ServerSocket(0, 1, InetAddress.getByName("127.0.0.1"))) {
            return free.getLocalPort();
        }
    }

    /** Presses Configure (the dialog is modal: from invokeLater) and returns the dialog once it shows. */
    private java.awt.Window configureDialog(String title) {
        javax.swing.SwingUtilities.invokeLater(() -> component(JButton.class, "configure").doClick());
        until(title + " shows", () -> Gui.showing(title).size() == 1);
        return onEdt(() -> Gui.showing(title).get(0));
    }

    private void stop() {
        JButton start = component(JButton.class, "start");
        run(start::doClick);
        until("the server stopped", () -> start.getText().equals("Start"));
    }

    @Test
    void helpAboutNamesTheVersionTheLicenceAndTheManual() {
        assertTrue(Version.current().matches("\\d+\\.\\d+\\.\\d+.*"), "the pom's version: " + Version.current());
        // File (Attach...), then Help, the last menu.
        assertEquals(List.of("File", "Help"), onEdt(() -> java.util.stream.IntStream.range(0, frame.getJMenuBar().getMenuCount())
                .mapToObj(i -> frame.getJMenuBar().getMenu(i).getText()).toList()));
        JMenuItem about = onEdt(() -> frame.getJMenuBar().getMenu(1).getItem(0));
        assertEquals("About WSS", onEdt(about::getText));
        javax.swing.SwingUtilities.invokeLater(about::doClick); // the dialog is modal
        String text = Gui.closeMessage("About WSS");
        assertTrue(text.contains("Version " + Version.current()), text);
        assertTrue(text.contains("GNU General Public License, version 2"), text);
        assertTrue(text.contains("Wireless Simulation Server Documentation</i>, Max Pfingsthorn, October 8, 2008"), text);
    }

    @Test
    void showsRobotsPortsAndLinksAsTheyComeBreakResumeAndGo() throws Exception {
        assertEquals("WSS " + Version.current(), onEdt(frame::getTitle));
        assertEquals("Start", button());
        int port = start();
        assertFalse(onEdt(() -> component(JTextField.class, "port").isEnabled()), "the port is locked while running");
        assertFalse(onEdt(() -> component(JComboBox.class, "model").isEnabled()), "the model is locked while running");
        assertFalse(onEdt(() -> component(JCheckBox.class, "eventLog").isEnabled()), "logging is locked while running");
        try (TestRobot r1 = new TestRobot(port, "127.0.0.2"); TestRobot r2 = new TestRobot(port, "127.0.0.3")) {
            ServerSocket r1Accepts = r1.initAccepting("r1");
            ServerSocket r2Accepts = r2.initAccepting("r2");
            waitForTable("robots", List.of(
                    List.of("r1", "127.0.0.2", String.valueOf(r1Accepts.getLocalPort()), "-"),
                    List.of("r2", "127.0.0.3", String.valueOf(r2Accepts.getLocalPort()), "-")));

            int toR2 = r1.dns("r2", 0);
            int toR1 = r2.dns("r1", 0);
            List<String> r1r2 = List.of("r1", "r2", String.valueOf(r2Accepts.getLocalPort()), String.valueOf(toR2), "yes", "DNS");
            List<String> r2r1 = List.of("r2", "r1", String.valueOf(r1Accepts.getLocalPort()), String.valueOf(toR1), "yes", "DNS");
            waitForTable("ports", List.of(r1r2, r2r1));

            try (Socket data = r1.connect(toR2); Socket atR2 = r2Accepts.accept()) {
                waitForTable("links", List.of(List.of("r1", "r2", String.valueOf(atR2.getPort()))));

                model.links().breakConnectionsForPair("r1", "r2");
                waitForTable("ports", List.of(no(r1r2), no(r2r1)));
                waitForTable("links", List.of());
                assertThrows(ConnectException.class, () -> r1.connect(toR2).close());

                model.links().resumeConnectionsForPair("r1", "r2");
                waitForTable("ports", List.of(r1r2, r2r1));
            }

            // The filter: case-insensitive wildcards over "from to"; Clear shows every row again.
            JTextField filter = component(JTextField.class, "portsFilter");
            run(() -> filter.setText("R2 *1"));
            waitForTable("ports", List.of(r2r1));
            run(() -> filter.setText("r?"));
            waitForTable("ports", List.of(r1r2, r2r1));
            run(() -> filter.setText("nobody"));
            waitForTable("ports", List.of());
            run(() -> component(JButton.class, "portsClear").doClick());
            assertEquals("", onEdt(filter::getText));
            waitForTable("ports", List.of(r1r2, r2r1));

            // Sortable: a click on "From" sorts the robots, a second one reverses them.
            JTable robots = component(JTable.class, "robots");
            run(() -> robots.getRowSorter().toggleSortOrder(0));
            run(() -> robots.getRowSorter().toggleSortOrder(0));
            until("r2 comes first", () -> cells(robots).get(0).get(0).equals("r2"));

            model.links().kickOutRobot("r2");
            waitForTable("robots", List.of(List.of("r1", "127.0.0.2", String.valueOf(r1Accepts.getLocalPort()), "-")));
            waitForTable("ports", List.of());
            until("the log says r2 was kicked", () -> find(frame.getContentPane(), JTextArea.class, "log").getText()
                    .contains("debug: kicked out r2"));
            stop();
            waitForTable("robots", List.of());
            assertThrows(IOException.class, () -> new Socket("127.0.0.1", port).close(), "nothing listens after Stop");
        }
        assertTrue(onEdt(() -> component(JTextField.class, "port").isEnabled()), "the port is editable again");
    }

    private static List<String> no(List<String> portRow) {
        return List.of(portRow.get(0), portRow.get(1), portRow.get(2), portRow.get(3), "no", "DNS");
    }

    @Test
    void theLinkStatisticsTableCountsBytesAndBreaksAndARightClickOffersTheForceMenu() throws Exception {
        int port = start();
        try (TestRobot r1 = new TestRobot(port, "127.0.0.2"); TestRobot r2 = new TestRobot(port, "127.0.0.3")) {
            r1.init("r1");
            ServerSocket r2Accepts = r2.initAccepting("r2");
            int toR2 = r1.dns("r2", 0);
            JTable stats = component(JTable.class, "stats");
            try (Socket data = r1.connect(toR2); Socket atR2 = r2Accepts.accept()) {
                data.getOutputStream().write(new byte[12345]);
                assertEquals(12345, atR2.getInputStream().readNBytes(12345).length);
                atR2.getOutputStream().write(new byte[678]);
                assertEquals(678, data.getInputStream().readNBytes(678).length);
                // Robot A, B, state, strength, distance, bytes A>B, B>A, rate A>B, B>A (links not shaped),
                // connections, breaks, resumes, up %, UDP (none), last close
                until("the statistics count the bytes", () -> statistics(stats).equals(
                        List.of("r1", "r2", "up", "0.0", "", "12345", "678", "-", "-", "1", "0", "0", "100.0", "", "")));
                model.links().breakConnectionsForPair("r1", "r2");
                until("the statistics show the break", () -> {
                    List<String> row = statistics(stats);
                    return row.subList(0, 12).equals(List.of("r1", "r2", "broken", "0.0", "", "12345", "678", "-", "-", "1", "1", "0"))
                            && row.get(14).equals("out of range") && Double.parseDouble(row.get(12)) < 100;
                });
            }
            // The filter works as on the other tables.
            run(() -> component(JTextField.class, "statsFilter").setText("nobody"));
            waitForTable("stats", List.of());
            run(() -> component(JButton.class, "statsClear").doClick());
            until("the row is back", () -> cells(stats).size() == 1);

            javax.swing.JTabbedPane tabs = component(javax.swing.JTabbedPane.class, "tabs");
            run(() -> tabs.setSelectedIndex(tabs.indexOfTab("Link statistics")));
            until("the statistics tab shows", stats::isShowing);
            // "Last close" is wide enough for its longest reasons, not cut to "out of r..." (960 wide, the first run's size).
            int lastCloseWidth = onEdt(() -> stats.getColumnModel()
                    .getColumn(stats.getColumnModel().getColumnIndex("Last close")).getWidth());
            for (String reason : List.of("out of range", "target refused", "peer closed", "server stopped")) {
                int needed = onEdt(() -> stats.getFontMetrics(stats.getFont()).stringWidth(reason) + 4);
                assertTrue(needed < lastCloseWidth, reason + " needs " + needed + " px, has " + lastCloseWidth);
            }
            run(() -> {
                java.awt.Rectangle cell = stats.getCellRect(0, 0, true);
                stats.dispatchEvent(new java.awt.event.MouseEvent(stats, java.awt.event.MouseEvent.MOUSE_PRESSED,
                        System.currentTimeMillis(), java.awt.event.InputEvent.BUTTON3_DOWN_MASK, cell.x + 2, cell.y + 2, 1, true,
                        java.awt.event.MouseEvent.BUTTON3));
            });
            until("the force menu of r1 - r2 shows", () -> !popupItems().isEmpty());
            assertEquals(List.of("Force down r1 - r2", "Force up r1 - r2", "Limit rate...", "Release to the model"),
                    onEdt(this::popupItems));
            run(() -> javax.swing.MenuSelectionManager.defaultManager().clearSelectedPath());
            run(() -> Stream.of(java.awt.Window.getWindows()).flatMap(w -> Gui.all(w, javax.swing.JPopupMenu.class).stream())
                    .forEach(menu -> menu.setVisible(false)));
        }
    }

    @Test
    void withLinksShapedTheStatisticsShowEachPairsRateAndTheRobotsTheirAirtime() throws Exception {
        closeWindow();
        // r1 - r2 pinned at 2 Mbit/s by the file; r1 - r3 at the rate table's, for ScriptedModel's 0 dBm its top rate.
        // As --config gives them: the file's wss.shaping keys go over the window's stored link shaping.
        frame = openWindow(new Launch("0", "ScriptedModel", false, null, Map.of("wss.shaping", "on"), false),
                List.of(new NoopPropagationModel(), model), Map.of("wss.shaping", "on", "wss.force.up", "r1:r2:2M"));
        int port = start();
        ExecutorService traffic = Executors.newFixedThreadPool(2);
        try (TestRobot r1 = new TestRobot(port, "127.0.0.2"); TestRobot r2 = new TestRobot(port, "127.0.0.3");
                TestRobot r3 = new TestRobot(port, "127.0.0.4")) {
            r1.init("r1");
            ServerSocket r2Accepts = r2.initAccepting("r2");
            r3.initAccepting("r3");
            int toR2 = r1.dns("r2", 0);
            r1.dns("r3", 0);
            JTable stats = component(JTable.class, "stats");
            JTable robots = component(JTable.class, "robots");
            until("the statistics show each pair's rate both ways", () -> column(stats, "Robot B").equals(List.of("r2", "r3"))
                    && column(stats, "Rate A>B").equals(List.of("2 Mbit/s", "54 Mbit/s"))
                    && column(stats, "Rate B>A").equals(List.of("2 Mbit/s", "54 Mbit/s")));
            assertEquals(List.of("forced up", "up"), onEdt(() -> column(stats, "State")));
            until("idle radios", () -> column(robots, "Airtime").equals(List.of("0 %", "0 %", "0 %")));

            try (Socket data = r1.connect(toR2); Socket atR2 = r2Accepts.accept()) {
                // r1 sends to r2 as fast as the link takes it (4 MB: 16 s at 2 Mbit/s); both radios are on the air.
                traffic.execute(() -> {
                    try {
                        byte[] chunk = new byte[64 * 1024];
                        for (int i = 0; i < 64; i++) {
                            data.getOutputStream().write(chunk);
                        }
                    } catch (IOException closedAtTheEnd) {
                        // the test is over
                    }
                });
                traffic.execute(() -> {
                    try {
                        atR2.getInputStream().transferTo(java.io.OutputStream.nullOutputStream());
                    } catch (IOException closedAtTheEnd) {
                        // the test is over
                    }
                });
                until("r1's and r2's radios busy, r3's idle", () -> {
                    List<String> airtime = column(robots, "Airtime");
                    return percent(airtime.get(0)) >= 50 && percent(airtime.get(1)) >= 50 && airtime.get(2).equals("0 %");
                });
                assertEquals(List.of("r1", "r2", "r3"), onEdt(() -> column(robots, "Name")));
            }
        } finally {
            traffic.shutdownNow();
        }
    }

    /** The cells of the table's column with that header, row by row as sorted and filtered. Event thread. */
    private static List<String> column(JTable table, String header) {
        int index = table.getColumnModel().getColumnIndex(header);
        return cells(table).stream().map(row -> row.get(index)).toList();
    }

    /** "37 %" as 37; -1 for anything else. */
    private static int percent(String cell) {
        return cell.matches("\\d+ %") ? Integer.parseInt(cell.substring(0, cell.indexOf(' '))) : -1;
    }

    /** The statistics table's one row, without the throughput columns (they move with time). Event thread. */
    private static List<String> statistics(JTable stats) {
        List<List<String>> rows = cells(stats);
        if (rows.size() != 1) {
            return List.of();
        }
        List<String> row = new java.util.ArrayList<>(rows.get(0));
        row.subList(7, 9).clear();
        return row;
    }

    /** The enabled items of the showing popup menus. Event thread. */
    private List<String> popupItems() {
        return Stream.of(java.awt.Window.getWindows())
                .flatMap(w -> Gui.all(w, javax.swing.JPopupMenu.class).stream())
                .filter(java.awt.Component::isShowing)
                .flatMap(menu -> Gui.all(menu, javax.swing.JMenuItem.class).stream())
                .filter(java.awt.Component::isEnabled)
                .map(javax.swing.JMenuItem::getText)
                .toList();
    }

    @Test
    void aPortInUseOrABadPortIsSaidAndStartWorksOnceFixed() throws Exception {
        try (ServerSocket taken = new ServerSocket()) {
            taken.bind(new InetSocketAddress("127.0.0.1", 0));
            JTextField portField = component(JTextField.class, "port");
            run(() -> portField.setText(String.valueOf(taken.getLocalPort())));
            run(() -> component(JButton.class, "start").doClick());
            String message = Gui.closeMessage("WSS");
            assertTrue(message.startsWith("cannot listen for robots on 127.0.0.1:" + taken.getLocalPort()), message);
            until("the log says it", () -> find(frame.getContentPane(), JTextArea.class, "log").getText()
                    .contains("WARNING: " + message));
            assertEquals("Start", button());

            run(() -> portField.setText("70000"));
            run(() -> component(JButton.class, "start").doClick());
            assertEquals("the port '70000' is not a port number from 0 to 65535 (0: any free port)", Gui.closeMessage("WSS"));

            run(() -> portField.setText("0"));
            start();
            stop();
        }
    }

    /** A fixed port's number taken after the --config file was read: Start's dialog names wss.fixed and its value. */
    @Test
    void aFixedPortTakenSinceTheWindowOpenedIsSaidAndStartWorksOnceFree() throws Exception {
        closeWindow();
        int number = freePort();
        String fixed = "Scout->Base:1883@" + number;
        frame = openWindow(new Launch("0", "ScriptedModel", false, null, false), List.of(new NoopPropagationModel(), model),
                Map.of("wss.robot.Scout", "", "wss.robot.Base", "", "wss.fixed", fixed));
        try (ServerSocket taken = new ServerSocket(number, 50, InetAddress.getByName("127.0.0.1"))) {
            run(() -> component(JButton.class, "start").doClick());
            String message = Gui.closeMessage("WSS");
            assertTrue(message.startsWith("wss.fixed = '" + fixed + "' is not ")
                    && message.contains(": tcp " + fixed + ": tcp port " + number + " is in use ("), message);
            assertEquals("Start", button());
        }
        start();
        stop();
    }

    @Test
    void aModelThatDoesNotStartIsSaidAndStartWorksOnceFixed() throws Exception {
        model.failStarts("the simulator at 127.0.0.1:1 cannot be reached");
        run(() -> component(JButton.class, "start").doClick());
        assertEquals("ScriptedModel did not start: the simulator at 127.0.0.1:1 cannot be reached", Gui.closeMessage("WSS"));
        until("the log says it", () -> find(frame.getContentPane(), JTextArea.class, "log").getText()
                .contains("WARNING: ScriptedModel did not start"));
        assertEquals("Start", button());
        assertTrue(onEdt(() -> component(JComboBox.class, "model").isEnabled()));
        model.failStarts(null);
        int port = start();
        new Socket("127.0.0.1", port).close();
    }

    @Test
    void aSimulatorThatCannotBeReachedIsSaidAndStartWorksOnceItRuns() throws Exception {
        closeWindow();
        int simulatorPort = freePort();
        DistanceOnlyPropagationModel distanceOnly = new DistanceOnlyPropagationModel();
        Map<String, String> settings = new HashMap<>(Setting.defaults(distanceOnly.settings()));
        settings.put("usarsim.host", "127.0.0.1");
        settings.put("usarsim.port", String.valueOf(simulatorPort));
        settings.put("usarsim.timeout", "500");
        // As --config gives them: the file's model settings for this session's starts.
        frame = openWindow(new Launch("0", "DistanceOnlyPropagationModel", false, new ModelSettings(settings), false),
                List.of(new NoopPropagationModel(), distanceOnly));
        assertTrue(onEdt(() -> component(JButton.class, "configure").isEnabled()), "DistanceOnly has settings");
        run(() -> component(JButton.class, "start").doClick());
        String message = Gui.closeMessage("WSS");
        assertTrue(message.startsWith("DistanceOnlyPropagationModel did not start: cannot reach the simulator at 127.0.0.1:"
                + simulatorPort), message);
        assertEquals("Start", button());

        WorldServer world = WorldServer.start(Path.of("docs/examples/corridor.world"), InetAddress.getByName("127.0.0.1"), simulatorPort);
        try {
            int port = start();
            try (TestRobot base = new TestRobot(port, "127.0.0.2"); TestRobot scout = new TestRobot(port, "127.0.0.3")) {
                base.init("Base");
                scout.init("Scout");
                waitForTable("robots", List.of(List.of("Base", "127.0.0.2", "", "-"), List.of("Scout", "127.0.0.3", "", "-")));
            }
            stop();
        } finally {
            world.close();
        }
    }

    @Test
    void closingTheWindowStopsTheServer() throws Exception {
        int port = start();
        try (TestRobot robot = new TestRobot(port, "127.0.0.2")) {
            robot.init("r1");
            waitForTable("robots", List.of(List.of("r1", "127.0.0.2", "", "-")));
            closeWindow();
            assertEquals(-1, robot.control.getInputStream().read(), "the robot's control connection is closed");
        }
        assertThrows(IOException.class, () -> new Socket("127.0.0.1", port).close(), "nothing listens after closing");
    }

    @Test
    void enableLoggingWritesTheCsvEventLog() throws Exception {
        run(() -> component(JCheckBox.class, "eventLog").setSelected(true));
        int port = start();
        try (TestRobot robot = new TestRobot(port, "127.0.0.2")) {
            robot.init("r1");
            waitForTable("robots", List.of(List.of("r1", "127.0.0.2", "", "-")));
        }
        waitForTable("robots", List.of());
        stop();
        try (Stream<Path> files = Files.list(eventLogs)) {
            List<Path> logs = files.toList();
            assertEquals(1, logs.size(), logs.toString());
            List<String> lines = Files.readAllLines(logs.get(0));
            assertTrue(lines.get(0).startsWith("SETTING,") && lines.get(0).endsWith(",wss.seed,0"), lines.toString());
            lines = lines.subList(1, lines.size());
            assertTrue(lines.get(0).startsWith("REGISTERED,") && lines.get(0).contains(",r1,127.0.0.2,"), lines.toString());
            assertTrue(lines.get(1).startsWith("DEREGISTERED,") && lines.get(1).endsWith(",r1"), lines.toString());
        }
    }

    @Test
    void remembersPortModelAndLoggingAndStartsAtOnceWhenAsked() throws Exception {
        run(() -> component(JCheckBox.class, "eventLog").setSelected(false));
        run(() -> component(JTextField.class, "port").setText("0"));
        start();
        closeWindow();
        WindowPreferences stored = new WindowPreferences(preferences.node("window"));
        assertEquals("0", stored.port());
        assertEquals("ScriptedModel", stored.model());
        assertFalse(stored.eventLog());

        // A second window opens with what the first stored, and --start presses Start.
        CountDownLatch secondClosed = new CountDownLatch(1);
        Properties properties = new Properties();
        properties.setProperty("wss.bindAddress", "127.0.0.1");
        WindowServers servers = new WindowServers(ConfigFile.of(properties, "test"));
        frame = onEdt(() -> MainWindow.open(servers, List.of(ModelProvider.of(NoopPropagationModel::new), ModelProvider.of(() -> model)),
                new WindowPreferences(preferences.node("window")), new ModelPreferences(preferences.node("models")),
                windowLog, new Launch(null, null, null, null, true), secondClosed::countDown).frame());
        until("the second window's server runs", () -> find(frame.getContentPane(), JButton.class, "start").getText().equals("Stop"));
        assertEquals("ScriptedModel", onEdt(() -> component(JComboBox.class, "model").getSelectedItem()));
        stop();
        assertEquals("0", onEdt(() -> component(JTextField.class, "port").getText()));
        run(() -> frame.dispatchEvent(new WindowEvent(frame, WindowEvent.WINDOW_CLOSING)));
        assertTrue(secondClosed.await(10, TimeUnit.SECONDS));
    }

    @Test
    void thePortFieldShowsThePortListeningWhileTheServerRunsAndTheTypedOneAfter() throws Exception {
        assertEquals("0", onEdt(() -> component(JTextField.class, "port").getText()));
        int port = start();
        assertTrue(port > 0, "the OS chose a port");
        assertEquals(String.valueOf(port), onEdt(() -> component(JTextField.class, "port").getText()),
                "while it runs, the field shows the port robots connect to");
        new Socket("127.0.0.1", port).close();
        stop();
        assertEquals("0", onEdt(() -> component(JTextField.class, "port").getText()), "after Stop, what was typed");
        assertEquals("0", new WindowPreferences(preferences.node("window")).port(), "the stored choice is still 0");
    }

    @Test
    void configureShowsTheFilesSettingsOverTheStoredOnesAndOkKeepsWhatWasEntered() throws Exception {
        closeWindow();
        int simulatorPort = freePort();
        DistanceOnlyPropagationModel distanceOnly = new DistanceOnlyPropagationModel();
        ModelPreferences stored = new ModelPreferences(preferences.node("models"));
        stored.store(distanceOnly, Map.of("usarsim.port", "1", "positions.interval", "400", "distance.n", "2"));
        // As --config gives them: only the model keys the file sets.
        Map<String, String> file = Map.of("usarsim.host", "127.0.0.1", "usarsim.port", String.valueOf(simulatorPort),
                "positions.interval", "150");
        frame = openWindow(new Launch("0", "DistanceOnlyPropagationModel", false, new ModelSettings(file), false),
                List.of(new NoopPropagationModel(), distanceOnly, new ObstaclePropagationModel()));

        String title = "DistanceOnlyPropagationModel Configuration";
        java.awt.Window dialog = configureDialog(title);
        assertEquals(String.valueOf(simulatorPort), onEdt(() -> find(dialog, JTextField.class, "usarsim.port").getText()),
                "the file's port, over the stored 1");
        assertEquals("150", onEdt(() -> find(dialog, JTextField.class, "positions.interval").getText()), "the file's, over the stored 400");
        assertEquals("2", onEdt(() -> find(dialog, JTextField.class, "distance.n").getText()), "the stored, which the file does not set");
        run(() -> find(dialog, JTextField.class, "positions.interval").setText("175"));
        run(() -> find(dialog, JButton.class, "ok").doClick());
        until("the dialog closed", () -> Gui.showing(title).isEmpty());
        assertEquals("175", stored.load(distanceOnly).get("positions.interval"), "OK stored what was entered");
        assertEquals(String.valueOf(simulatorPort), stored.load(distanceOnly).get("usarsim.port"), "and what it showed");

        // Another model's dialog still shows the file's values: OK stored DistanceOnly's only.
        run(() -> component(JComboBox.class, "model").setSelectedItem("ObstaclePropagationModel"));
        String obstacleTitle = "ObstaclePropagationModel Configuration";
        java.awt.Window obstacleDialog = configureDialog(obstacleTitle);
        assertEquals("150", onEdt(() -> find(obstacleDialog, JTextField.class, "positions.interval").getText()));
        run(() -> find(obstacleDialog, JButton.class, "cancel").doClick());
        until("the Obstacle dialog closed", () -> Gui.showing(obstacleTitle).isEmpty());
        run(() -> component(JComboBox.class, "model").setSelectedItem("DistanceOnlyPropagationModel"));

        WorldServer world = WorldServer.start(Path.of("docs/examples/corridor.world"), InetAddress.getByName("127.0.0.1"), simulatorPort);
        try {
            start();
            until("the model says how it runs", () -> find(frame.getContentPane(), JTextArea.class, "log").getText()
                    .contains("DistanceOnlyPropagationModel polls the simulator at 127.0.0.1:" + simulatorPort + " every 175 ms"));
            stop();
        } finally {
            world.close();
        }
    }
}
