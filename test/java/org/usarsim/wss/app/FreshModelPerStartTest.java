package org.usarsim.wss.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.usarsim.wss.gui.Gui.find;
import static org.usarsim.wss.gui.Gui.onEdt;
import static org.usarsim.wss.gui.Gui.run;
import static org.usarsim.wss.gui.Gui.until;

import java.awt.event.WindowEvent;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Properties;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.logging.Logger;
import java.util.prefs.Preferences;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.swing.JButton;
import javax.swing.JFrame;
import javax.swing.JTextArea;
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
import org.usarsim.wss.model.Setting;
import org.usarsim.wss.model.ModelSettings;
import org.usarsim.wss.model.StubModel;

/**
 * Each Start of the window runs a new instance of the selected model, configured from what is
 * stored now, through the application's own servers ({@link WindowServers}, {@link Server}): one
 * run's values and state never reach the next. Before, the window started the catalog's one
 * instance again and again.
 */
@Timeout(60)
@Tag("slow")
class FreshModelPerStartTest {

    private static final Pattern LISTENING = Pattern.compile("WSS listening for robots on 127\\.0\\.0\\.1:(\\d+)");

    /**
     * A plugin-like model with one setting, whose configure keeps what it was given before (as
     * the simulator models do): the strength of every pair is minus its level.
     */
    static final class Levelled extends StubModel {
        static final List<Setting> SETTINGS = List.of(Setting.integer("levelled.level", "Level", 1).from(1).to(100));

        final Map<String, String> given = new HashMap<>();
        final AtomicInteger starts = new AtomicInteger();
        final AtomicInteger shutdowns = new AtomicInteger();
        volatile boolean configured;

        @Override
        public String name() {
            return "Levelled";
        }

        @Override
        public List<Setting> settings() {
            return SETTINGS;
        }

        @Override
        public synchronized void configure(ModelSettings values) {
            configured = true;
            given.putAll(values.asMap());
        }

        synchronized String level() {
            return given.get("levelled.level");
        }

        @Override
        public void start() {
            starts.incrementAndGet();
        }

        @Override
        public void shutdown() {
            shutdowns.incrementAndGet();
        }

        @Override
        public boolean isActive() {
            return starts.get() > shutdowns.get();
        }

        @Override
        public double getSignalStrengthForPair(String from, String to) {
            return -Double.parseDouble(level());
        }
    }

    /** Every instance the provider made, in order: the first is the one the window asks what it declares. */
    private final List<Levelled> made = new CopyOnWriteArrayList<>();
    private final CountDownLatch closed = new CountDownLatch(1);
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
        ModelProvider levelled = ModelProvider.of(() -> {
            Levelled model = new Levelled();
            made.add(model);
            return model;
        });
        new ModelPreferences(preferences.node("models")).store(levelled.model(), Map.of("levelled.level", "7"));
        Properties properties = new Properties();
        properties.setProperty("wss.bindAddress", "127.0.0.1");
        WindowServers servers = new WindowServers(ConfigFile.of(properties, "test"));
        frame = onEdt(() -> MainWindow.open(servers, List.of(levelled), new WindowPreferences(preferences.node("window")),
                new ModelPreferences(preferences.node("models")), windowLog,
                new Launch("0", "Levelled", false, null, false), closed::countDown).frame());
    }

    @AfterEach
    void close() throws Exception {
        run(() -> frame.dispatchEvent(new WindowEvent(frame, WindowEvent.WINDOW_CLOSING)));
        assertTrue(closed.await(10, TimeUnit.SECONDS), "the window closed");
        Logger.getLogger("").removeHandler(windowLog);
        TestPreferences.remove(preferences);
    }

    /** Presses Start, waits for the server; returns the control port of this start. */
    private int start() {
        JButton start = onEdt(() -> find(frame.getContentPane(), JButton.class, "start"));
        JTextArea log = onEdt(() -> find(frame.getContentPane(), JTextArea.class, "log"));
        int before = listening(onEdt(log::getText)).size();
        run(start::doClick);
        until("the server runs", () -> start.getText().equals("Stop"));
        until("the log names the port", () -> listening(log.getText()).size() > before);
        List<Integer> ports = listening(onEdt(log::getText));
        return ports.get(ports.size() - 1);
    }

    private void stop() {
        JButton start = onEdt(() -> find(frame.getContentPane(), JButton.class, "start"));
        run(start::doClick);
        until("the server stopped", () -> start.getText().equals("Start"));
    }

    private static List<Integer> listening(String log) {
        Matcher matcher = LISTENING.matcher(log);
        List<Integer> ports = new ArrayList<>();
        while (matcher.find()) {
            ports.add(Integer.parseInt(matcher.group(1)));
        }
        return ports;
    }

    /** What the server answers A's GETSS to B: the strength of the model instance it runs. */
    private static String strength(int port) throws Exception {
        try (TestRobot a = new TestRobot(port, "127.0.0.1"); TestRobot b = new TestRobot(port, "127.0.0.1")) {
            a.init("A");
            b.init("B");
            return a.ask("GETSS {Robot B}");
        }
    }

    @Test
    void eachStartRunsANewInstanceConfiguredFromWhatIsStoredNow() throws Exception {
        Levelled asked = made.get(0);

        int port = start();
        assertEquals(2, made.size(), "Start made an instance of its own");
        Levelled first = made.get(1);
        assertEquals("7", first.level());
        assertEquals(1, first.starts.get());
        assertEquals("SS {Robot B} {Strength -7}", strength(port));
        stop();
        assertEquals(1, first.shutdowns.get());

        // The stored level is removed: the next run has the default, not the 7 of the run before.
        preferences.node("models").node("Levelled").remove("levelled.level");
        port = start();
        assertEquals(3, made.size(), "the second Start made another instance");
        Levelled second = made.get(2);
        assertNotSame(first, second);
        assertEquals("1", second.level(), "the default: nothing of the first run");
        assertEquals("SS {Robot B} {Strength -1}", strength(port));
        assertEquals(1, first.starts.get(), "the first run's instance was not started again");
        stop();

        assertEquals(0, asked.starts.get(), "the instance the window asks what it declares never runs");
        assertFalse(asked.configured, "nor does a Start configure it");
    }
}
