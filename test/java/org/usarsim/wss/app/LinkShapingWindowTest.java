package org.usarsim.wss.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.usarsim.wss.gui.Gui.cells;
import static org.usarsim.wss.gui.Gui.find;
import static org.usarsim.wss.gui.Gui.onEdt;
import static org.usarsim.wss.gui.Gui.run;
import static org.usarsim.wss.gui.Gui.until;

import java.awt.Color;
import java.awt.Window;
import java.awt.event.WindowEvent;
import java.util.List;
import java.util.Map;
import java.util.Properties;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.logging.Logger;
import java.util.prefs.Preferences;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.swing.JButton;
import javax.swing.JCheckBox;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JTable;
import javax.swing.JTextArea;
import javax.swing.JTextField;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.usarsim.wss.gui.Gui;
import org.usarsim.wss.gui.Launch;
import org.usarsim.wss.gui.MainWindow;
import org.usarsim.wss.gui.ModelPreferences;
import org.usarsim.wss.gui.TestPreferences;
import org.usarsim.wss.gui.WindowLog;
import org.usarsim.wss.gui.WindowPreferences;
import org.usarsim.wss.hub.TestRobot;
import org.usarsim.wss.model.ModelProvider;
import org.usarsim.wss.model.noop.NoopPropagationModel;
import org.usarsim.wss.shaping.ShapingConfig;

/**
 * The window's "Link shaping...", for real: the dialog typed into (a refused rate table, delay and
 * queue, then good ones), the server the application starts ({@link WindowServers}) shaping the links of
 * robots over real sockets as the dialog said, and the choice remembered by the next window, with a
 * --config file's keys over it.
 */
@Timeout(60)
@Tag("slow")
class LinkShapingWindowTest {

    private static final Pattern LISTENING = Pattern.compile("debug: WSS listening for robots on 127\\.0\\.0\\.1:(\\d+)");
    private static final String TITLE = "Link shaping";
    /** A refused field's background (DialogParts.INVALID). */
    private static final Color INVALID = new Color(255, 205, 205);
    private static final String RATES = "wss.shaping.rates";
    private static final String DELAY = "wss.shaping.delayMs";
    private static final String QUEUE = "wss.shaping.queueMs";

    private Preferences preferences;
    private WindowLog windowLog;
    private CountDownLatch closed;
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
        frame = openWindow(null);
    }

    /** A window on the Noop model, its servers on 127.0.0.1; {@code fileShaping}: the wss.shaping keys a --config file sets (null: none). */
    private JFrame openWindow(Map<String, String> fileShaping) throws Exception {
        CountDownLatch windowClosed = new CountDownLatch(1);
        closed = windowClosed;
        Properties properties = new Properties();
        properties.setProperty("wss.bindAddress", "127.0.0.1");
        if (fileShaping != null) {
            fileShaping.forEach(properties::setProperty);
        }
        ConfigFile config = ConfigFile.of(properties, "test");
        WindowServers servers = new WindowServers(config);
        Launch launch = new Launch("0", "NoopPropagationModel", false, null,
                fileShaping == null ? null : config.shapingKeysSetBy(properties), false);
        return onEdt(() -> MainWindow.open(servers, List.of(ModelProvider.of(NoopPropagationModel::new)),
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
    }

    private <T extends java.awt.Component> T component(Class<T> type, String name) {
        return onEdt(() -> find(frame.getContentPane(), type, name));
    }

    /** Presses "Link shaping..." (the dialog is modal: from invokeLater) and returns the dialog once it shows. */
    private Window dialog() {
        JButton shaping = component(JButton.class, "shaping");
        assertEquals("Link shaping...", onEdt(shaping::getText));
        SwingUtilities.invokeLater(shaping::doClick);
        until("the dialog shows", () -> Gui.showing(TITLE).size() == 1);
        return onEdt(() -> Gui.showing(TITLE).get(0));
    }

    private static void type(Window dialog, String key, String text) {
        run(() -> find(dialog, JTextField.class, key).setText(text));
    }

    private static String text(Window dialog, String key) {
        return onEdt(() -> find(dialog, JTextField.class, key).getText());
    }

    private static boolean refused(Window dialog, String key) {
        return onEdt(() -> find(dialog, JTextField.class, key).getBackground().equals(INVALID));
    }

    private static String message(Window dialog) {
        return onEdt(() -> find(dialog, JLabel.class, "message").getText());
    }

    private static void press(Window dialog, String button) {
        run(() -> find(dialog, JButton.class, button).doClick());
    }

    /** Types {@code text} into the field of {@code key}, presses OK and returns what the dialog says under its fields. */
    private static String okWith(Window dialog, String key, String text) {
        type(dialog, key, text);
        press(dialog, "ok");
        return message(dialog);
    }

    private String summary() {
        JLabel summary = component(JLabel.class, "shapingSummary");
        return onEdt(summary::getText);
    }

    /** Presses Start and waits for "Stop"; returns the control port the log names. */
    private int start() {
        JButton start = component(JButton.class, "start");
        run(start::doClick);
        until("the server runs", () -> start.getText().equals("Stop"));
        until("the log names the port", () -> LISTENING.matcher(find(frame.getContentPane(), JTextArea.class, "log").getText()).find());
        Matcher matcher = LISTENING.matcher(onEdt(() -> find(frame.getContentPane(), JTextArea.class, "log").getText()));
        assertTrue(matcher.find());
        return Integer.parseInt(matcher.group(1));
    }

    /** The cells of the table's column with that header. Event thread. */
    private static List<String> column(JTable table, String header) {
        int index = table.getColumnModel().getColumnIndex(header);
        return cells(table).stream().map(row -> row.get(index)).toList();
    }

    @Test
    void aBadRateTableIsRefusedAndAGoodOneShapesTheLinksOfTheNextStart() throws Exception {
        assertEquals("Links not shaped", summary());
        Window dialog = dialog();
        assertEquals("-72:54M,-73:48M,-77:36M,-81:24M,-83:18M,-85:12M,-86:9M,-87:6M", text(dialog, RATES), "the default table");
        assertEquals("2", text(dialog, DELAY));
        assertEquals(String.valueOf(ShapingConfig.DEFAULT_QUEUE_MS), text(dialog, QUEUE), "the default queue");
        assertFalse(onEdt(() -> find(dialog, JCheckBox.class, "wss.shaping").isSelected()), "off by default");
        assertTrue(onEdt(() -> find(dialog, JCheckBox.class, "wss.shaping.airtime").isSelected()), "shared airtime by default");

        // Refused as typed: red, the reason in the tooltip; OK names it under the fields and stays open.
        type(dialog, RATES, "-72:fast,-80:6M");
        assertTrue(refused(dialog, RATES), "the rate table's field is red");
        String reason = "\"-72:fast,-80:6M\": step 1 (-72:fast): fast is not a bit rate"
                + " (a number of bit/s, with k for 1000 or M for 1000000: 800, 512k, 1.5M, 54M)";
        assertEquals(reason, onEdt(() -> find(dialog, JTextField.class, RATES).getToolTipText()));
        type(dialog, DELAY, "soon");
        assertTrue(refused(dialog, DELAY), "the delay's field is red");
        type(dialog, QUEUE, "5");
        assertTrue(refused(dialog, QUEUE), "the queue's field is red");
        assertEquals("5 is below 10", onEdt(() -> find(dialog, JTextField.class, QUEUE).getToolTipText()));
        press(dialog, "ok");
        assertEquals("<html>Rates by strength: " + reason + " (and 2 more marked)</html>", message(dialog));
        assertEquals(1, onEdt(() -> Gui.showing(TITLE).size()), "OK refused: the dialog stays open");

        assertEquals("<html>Rates by strength: \"-74:48M,-72:54M\": steps must go from the strongest to the weakest signal"
                + " (and 2 more marked)</html>", okWith(dialog, RATES, "-74:48M,-72:54M"));
        assertEquals("<html>Delay: soon is not a whole number of milliseconds (and 1 more marked)</html>",
                okWith(dialog, RATES, " -50:11M, -90:2M "));
        assertFalse(refused(dialog, RATES));
        assertEquals("<html>Delay: 10001 is above 10000 (and 1 more marked)</html>", okWith(dialog, DELAY, "10001"));
        assertEquals("<html>Queue: 5 is below 10</html>", okWith(dialog, DELAY, "5"));
        assertEquals("<html>Queue: long is not a whole number of milliseconds</html>", okWith(dialog, QUEUE, "long"));
        assertEquals("<html>Queue: 10001 is above 10000</html>", okWith(dialog, QUEUE, "10001"));

        // Good values, shaping on: OK stores them, and the window says what the next Start uses.
        type(dialog, QUEUE, " 300 ");
        assertFalse(refused(dialog, QUEUE));
        run(() -> find(dialog, JCheckBox.class, "wss.shaping").setSelected(true));
        press(dialog, "ok");
        until("the dialog closed", () -> Gui.showing(TITLE).isEmpty());
        assertEquals("Links shaped: 2 to 11 Mbit/s by strength, 5 ms delay, shared airtime", summary());

        int port = start();
        until("the log says the shaping the server started with, its queue too", () -> find(frame.getContentPane(), JTextArea.class, "log")
                .getText().contains("links are shaped (wss.shaping = on): rate table -50:11M,-90:2M, delay 5 ms, airtime shared, queue 300 ms"));
        try (TestRobot r1 = new TestRobot(port, "127.0.0.2"); TestRobot r2 = new TestRobot(port, "127.0.0.3")) {
            r1.init("r1");
            r2.initAccepting("r2");
            r1.dns("r2", 0);
            JTable stats = component(JTable.class, "stats");
            // The Noop model's 0 dBm is above every step: the table's top rate, 11 Mbit/s, both ways.
            until("the statistics show the table's top rate", () -> column(stats, "Rate A>B").equals(List.of("11 Mbit/s"))
                    && column(stats, "Rate B>A").equals(List.of("11 Mbit/s")));

            // While the server runs, the dialog shows what it runs with, read-only.
            Window running = dialog();
            assertEquals("-50:11M, -90:2M", text(running, RATES), "as entered");
            assertEquals("300", text(running, QUEUE));
            assertFalse(onEdt(() -> find(running, JTextField.class, QUEUE).isEnabled()));
            assertFalse(onEdt(() -> find(running, JTextField.class, RATES).isEnabled()));
            assertFalse(onEdt(() -> find(running, JCheckBox.class, "wss.shaping").isEnabled()));
            assertEquals(List.of("Close"), onEdt(() -> Gui.all(running, JButton.class).stream().map(JButton::getText)
                    .filter(text -> !text.isEmpty()).toList()), "the jitter distribution's list has an arrow button without text");
            assertFalse(onEdt(() -> find(running, javax.swing.JComboBox.class, "wss.shaping.jitterDistribution").isEnabled()));
            press(running, "close");
            until("the read-only dialog closed", () -> Gui.showing(TITLE).isEmpty());
        }
    }

    @Test
    void theChoiceSurvivesANewWindowAndAConfigFilesKeysGoOverIt() throws Exception {
        Window dialog = dialog();
        run(() -> find(dialog, JCheckBox.class, "wss.shaping").setSelected(true));
        type(dialog, RATES, "-60:24M,-80:1.5M");
        type(dialog, DELAY, "30");
        type(dialog, QUEUE, "400");
        run(() -> find(dialog, JCheckBox.class, "wss.shaping.airtime").setSelected(false));
        assertEquals("0", text(dialog, "wss.shaping.jitter"), "no jitter by default");
        type(dialog, "wss.shaping.jitter", "10001");
        assertTrue(refused(dialog, "wss.shaping.jitter"), "the jitter's field is red");
        type(dialog, "wss.shaping.jitter", "15");
        run(() -> find(dialog, javax.swing.JComboBox.class, "wss.shaping.jitterDistribution").setSelectedItem("normal"));
        run(() -> find(dialog, JCheckBox.class, "wss.shaping.reorder").setSelected(true));
        press(dialog, "ok");
        until("the dialog closed", () -> Gui.showing(TITLE).isEmpty());
        closeWindow();

        // The next window: the stored choice, in the summary and in the dialog.
        frame = openWindow(null);
        assertEquals("Links shaped: 1.5 to 24 Mbit/s by strength, 30 ms delay (jitter 15 ms normal), airtime not shared", summary());
        Window again = dialog();
        assertTrue(onEdt(() -> find(again, JCheckBox.class, "wss.shaping").isSelected()));
        assertEquals("-60:24M,-80:1.5M", text(again, RATES));
        assertEquals("30", text(again, DELAY));
        assertEquals("400", text(again, QUEUE));
        assertFalse(onEdt(() -> find(again, JCheckBox.class, "wss.shaping.airtime").isSelected()));
        assertEquals("15", text(again, "wss.shaping.jitter"));
        assertEquals("normal", onEdt(() -> find(again, javax.swing.JComboBox.class, "wss.shaping.jitterDistribution").getSelectedItem()));
        assertTrue(onEdt(() -> find(again, JCheckBox.class, "wss.shaping.reorder").isSelected()));
        press(again, "cancel");
        until("the dialog closed", () -> Gui.showing(TITLE).isEmpty());
        closeWindow();

        // With --config: the keys the file sets go over the stored ones (the others stay), and are not stored...
        frame = openWindow(Map.of("wss.shaping.delayMs", "7", "wss.shaping", "off", QUEUE, "250"));
        assertEquals("Links not shaped", summary());
        Window withFile = dialog();
        assertFalse(onEdt(() -> find(withFile, JCheckBox.class, "wss.shaping").isSelected()), "the file's off");
        assertEquals("7", text(withFile, DELAY), "the file's, over the stored 30");
        assertEquals("-60:24M,-80:1.5M", text(withFile, RATES), "the stored, which the file does not set");
        assertEquals("250", text(withFile, QUEUE), "the file's, over the stored 400");
        press(withFile, "cancel");
        until("the dialog closed", () -> Gui.showing(TITLE).isEmpty());
        WindowPreferences stored = new WindowPreferences(preferences.node("window"));
        assertEquals(Map.of("wss.shaping", "on", RATES, "-60:24M,-80:1.5M", DELAY, "30", "wss.shaping.airtime", "false", QUEUE, "400",
                "wss.shaping.jitter", "15", "wss.shaping.jitterDistribution", "normal", "wss.shaping.reorder", "true"), stored.shaping());

        // ...until OK stores what the dialog shows: from then on, what was entered.
        Window entered = dialog();
        type(entered, DELAY, "9");
        press(entered, "ok");
        until("the dialog closed", () -> Gui.showing(TITLE).isEmpty());
        assertEquals("9", stored.shaping().get(DELAY));
        assertEquals("250", stored.shaping().get(QUEUE), "the file's value, shown and OK'd");
        assertEquals("off", stored.shaping().get("wss.shaping"), "the file's value, shown and OK'd");
        Window after = dialog();
        assertEquals("9", text(after, DELAY), "what was entered, no longer the file's 7");
        press(after, "cancel");
        until("the dialog closed", () -> Gui.showing(TITLE).isEmpty());
    }
}
