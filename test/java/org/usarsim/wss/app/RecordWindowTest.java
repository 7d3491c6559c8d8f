package org.usarsim.wss.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.usarsim.wss.gui.Gui.find;
import static org.usarsim.wss.gui.Gui.onEdt;
import static org.usarsim.wss.gui.Gui.run;
import static org.usarsim.wss.gui.Gui.until;

import java.awt.event.WindowEvent;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Properties;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.logging.Logger;
import java.util.prefs.Preferences;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import javax.swing.JButton;
import javax.swing.JCheckBox;
import javax.swing.JFrame;
import javax.swing.JTextArea;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
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
import org.usarsim.wss.recording.Entry;
import org.usarsim.wss.recording.Recording;
import org.usarsim.wss.recording.RecordingReader;

/** The window's "Record": ticked, Start records the run to a new file in the event log's folder (or to a --config file's wss.record). */
@Timeout(60)
@Tag("slow")
class RecordWindowTest {

    private static final Pattern LISTENING = Pattern.compile("WSS listening for robots on 127\\.0\\.0\\.1:(\\d+)");
    private static final Pattern RUN_FILE = Pattern.compile("run-\\d{4}\\.\\d{2}\\.\\d{2}-\\d{2}\\.\\d{2}\\.\\d{2}\\.\\d{3}\\.rec");

    @TempDir
    Path eventLogs;

    private Preferences preferences;
    private WindowLog windowLog;
    private CountDownLatch closed;
    private JFrame frame;

    @BeforeAll
    static void display() {
        Gui.requireDisplay();
    }

    @BeforeEach
    void logs() {
        preferences = TestPreferences.create();
        windowLog = new WindowLog();
        Logger.getLogger("").addHandler(windowLog);
    }

    @AfterEach
    void close() throws Exception {
        if (frame != null && closed.getCount() > 0) {
            run(() -> frame.dispatchEvent(new WindowEvent(frame, WindowEvent.WINDOW_CLOSING)));
            assertTrue(closed.await(10, TimeUnit.SECONDS), "the window closed");
        }
        Logger.getLogger("").removeHandler(windowLog);
        TestPreferences.remove(preferences);
    }

    /** The window, its servers built from a properties file with the address, the event log's folder and these keys. */
    private void open(Launch launch, Map<String, String> file) throws Exception {
        closed = new CountDownLatch(1);
        Properties properties = new Properties();
        properties.setProperty("wss.bindAddress", "127.0.0.1");
        properties.setProperty("wss.eventLogDir", eventLogs.toString());
        file.forEach(properties::setProperty);
        WindowServers servers = new WindowServers(ConfigFile.of(properties, "test"));
        frame = onEdt(() -> MainWindow.open(servers, List.of(ModelProvider.of(NoopPropagationModel::new)),
                new WindowPreferences(preferences.node("window")), new ModelPreferences(preferences.node("models")),
                windowLog, launch, closed::countDown).frame());
    }

    private <T extends java.awt.Component> T component(Class<T> type, String name) {
        return onEdt(() -> find(frame.getContentPane(), type, name));
    }

    /** Presses Start, waits for the server; returns the control port the log names. */
    private int start() {
        JButton start = component(JButton.class, "start");
        run(start::doClick);
        until("the server runs", () -> start.getText().equals("Stop"));
        JTextArea log = component(JTextArea.class, "log");
        until("the log names the port", () -> LISTENING.matcher(log.getText()).find());
        Matcher matcher = LISTENING.matcher(onEdt(log::getText));
        int port = -1;
        while (matcher.find()) {
            port = Integer.parseInt(matcher.group(1));
        }
        return port;
    }

    private void stop() {
        JButton start = component(JButton.class, "start");
        run(start::doClick);
        until("the server stopped", () -> start.getText().equals("Start"));
    }

    private List<Path> recordings() throws Exception {
        try (Stream<Path> files = Files.list(eventLogs)) {
            return files.filter(file -> file.getFileName().toString().endsWith(".rec")).sorted().toList();
        }
    }

    @Test
    void recordTickedMakesStartRecordTheRunToANewFileInTheEventLogsFolder() throws Exception {
        open(new Launch("0", "NoopPropagationModel", false, null, false), Map.of());
        JCheckBox record = component(JCheckBox.class, "record");
        assertFalse(onEdt(record::isSelected), "not ticked before a first run");
        assertEquals("Record", onEdt(record::getText));
        run(() -> record.setSelected(true));
        int port = start();
        assertFalse(onEdt(record::isEnabled), "locked while running, as Enable Logging");
        try (TestRobot robot = new TestRobot(port, "127.0.0.1")) {
            robot.init("Alpha");
        }
        List<Path> files = recordings();
        assertEquals(1, files.size(), files.toString());
        Path file = files.get(0);
        assertTrue(RUN_FILE.matcher(file.getFileName().toString()).matches(), file.toString());
        JTextArea log = component(JTextArea.class, "log");
        until("the log says where", () -> log.getText().contains("recording the run to " + file));
        stop();
        assertTrue(onEdt(record::isEnabled));
        Recording recording = RecordingReader.read(file);
        assertEquals("NoopPropagationModel", recording.header().model());
        assertFalse(recording.cutShort(), "ends with end");
        assertEquals(new Entry.Registered(recording.events().get(0).millis(), "Alpha", "127.0.0.1"), recording.events().get(0));
        assertTrue(recording.events().get(recording.events().size() - 1) instanceof Entry.End);
        assertTrue(new WindowPreferences(preferences.node("window")).record(), "remembered");

        // Unticked: the next run records nothing.
        run(() -> record.setSelected(false));
        start();
        stop();
        assertEquals(files, recordings());
        assertFalse(new WindowPreferences(preferences.node("window")).record());
    }

    @Test
    void aConfigFilesRecordTicksTheBoxAndIsWhereStartRecords() throws Exception {
        Path asked = eventLogs.resolve("mine/team.rec.gz");
        open(new Launch("0", "NoopPropagationModel", false, null, null, false, true), Map.of("wss.record", asked.toString()));
        JCheckBox record = component(JCheckBox.class, "record");
        assertTrue(onEdt(record::isSelected), "the file's wss.record ticks Record");
        start();
        stop();
        start(); // the same name again: the first is kept
        stop();
        Recording first = RecordingReader.read(asked);
        assertFalse(first.cutShort());
        try (Stream<Path> files = Files.list(asked.getParent())) {
            List<String> names = files.map(file -> file.getFileName().toString()).sorted().toList();
            assertEquals(2, names.size(), names.toString());
            assertTrue(names.get(0).matches("team-\\d{4}\\.\\d{2}\\.\\d{2}-\\d{2}\\.\\d{2}\\.\\d{2}\\.rec\\.gz"), names.toString());
            assertFalse(RecordingReader.read(asked.resolveSibling(names.get(0))).cutShort());
        }
    }
}
