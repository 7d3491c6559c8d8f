package org.usarsim.wss.gui;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.GridLayout;
import java.awt.Rectangle;
import java.awt.event.KeyEvent;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ExecutionException;
import java.util.logging.Logger;
import javax.swing.BorderFactory;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JMenu;
import javax.swing.JMenuBar;
import javax.swing.JMenuItem;
import javax.swing.JOptionPane;
import javax.swing.JPanel;
import javax.swing.JSplitPane;
import javax.swing.JTabbedPane;
import javax.swing.SwingUtilities;
import javax.swing.SwingWorker;
import javax.swing.Timer;
import javax.swing.WindowConstants;
import org.usarsim.wss.attach.MonitorClient;
import org.usarsim.wss.hub.HubSnapshot;
import org.usarsim.wss.model.ModelProvider;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.Replay;
import org.usarsim.wss.model.ModelSettings;
import org.usarsim.wss.shaping.ShapingConfig;

/**
 * The main window (the manual's Figure 1): the control bar, four tabs ("Connections": "Connected
 * Robots", the ports and connections tables; "Map"; "Link statistics"; "Routes"), under them the time bar
 * while the model replays a recording ({@link ReplayBar}), and the log. Starts and
 * stops a server through {@link Servers}, off the event thread; shows the hub through a
 * {@link NetworkView} and the log through a {@link WindowLog}, both taken on a Swing timer every
 * {@link #REFRESH_MS} ms. Everything here runs on the event thread.
 */
public final class MainWindow {

    /** The title of the window's message dialogs; the window's own adds the version. */
    static final String TITLE = "WSS";
    static final int REFRESH_MS = 250;
    private static final Logger LOG = Logger.getLogger(MainWindow.class.getName());

    private final JFrame frame = new JFrame(TITLE);
    private final ControlBar bar;
    private final RobotsPanel robots = new RobotsPanel();
    private final PortsPanel ports = new PortsPanel();
    private final LinksPanel links = new LinksPanel();
    private final ForceMenu forceMenu;
    private final StatsPanel stats;
    private final RoutesPanel routes = new RoutesPanel();
    private final LogPanel log = new LogPanel();
    /** Above the tabs while an attached window's connection is lost. */
    private final JLabel banner = new JLabel();
    private final MapPanel map;
    /** The time bar under the tabs, shown while the running model replays a recording. */
    private final ReplayBar replayBar = new ReplayBar();
    /** What the window shows and steers through; {@link #local} too when the server is the window's own, else null. */
    private final WindowSource source;
    private final LocalSource local;
    /** The replay the time bar follows (null: none). */
    private Replay replayShown;
    private final Timer timer;
    private final Servers servers;
    private final Map<String, ModelProvider> models = new LinkedHashMap<>();
    private final WindowPreferences windowPreferences;
    private final ModelPreferences modelPreferences;
    private final Runnable onClosed;
    /** What each model's next start uses, and its dialog shows: the stored settings, a --config file's over them. */
    private final NextRunValues nextRunValues;
    /** The link shaping of the next start, which its dialog shows: the stored values, a --config file's over them. */
    private final NextRunShaping nextRunShaping;
    private ControlBar.State state = ControlBar.State.STOPPED;
    private Servers.Running running;
    /** The port typed for the server that runs, shown again at Stop (the field shows the actual one meanwhile). */
    private String askedPort;
    private boolean closing;

    private MainWindow(WindowSource source, Servers servers, List<ModelProvider> modelList, WindowPreferences windowPreferences,
            ModelPreferences modelPreferences, Launch launch, Runnable onClosed) {
        this.source = source;
        this.local = source instanceof LocalSource own ? own : null;
        this.servers = servers;
        forceMenu = new ForceMenu(source::controls, source.offersForce());
        stats = new StatsPanel(forceMenu);
        map = new MapPanel(forceMenu);
        frame.setTitle(source.title());
        modelList.forEach(model -> models.put(model.name(), model));
        this.windowPreferences = windowPreferences;
        this.modelPreferences = modelPreferences;
        this.onClosed = onClosed;
        this.nextRunValues = new NextRunValues(modelPreferences, launch.modelValues());
        this.nextRunShaping = new NextRunShaping(windowPreferences, launch.shapingValues());
        bar = new ControlBar(List.copyOf(models.keySet()));
        timer = new Timer(REFRESH_MS, e -> refresh());
        if (local != null) {
            ownServer(launch);
        } else {
            bar.serversOwn(source.title());
        }
        layOut();
    }

    /** The bar of a window that runs its server: the launch's or the stored values, Start / Stop and the dialogs. */
    private void ownServer(Launch launch) {
        bar.port.setText(launch.port() != null ? launch.port() : windowPreferences.port());
        bar.eventLog.setSelected(launch.eventLog() != null ? launch.eventLog() : windowPreferences.eventLog());
        bar.record.setSelected(launch.record() != null ? launch.record() : windowPreferences.record());
        String model = launch.model() != null ? launch.model() : windowPreferences.model();
        if (models.containsKey(model)) {
            bar.model.setSelectedItem(model);
        } else {
            LOG.warning("the model " + model + " of the last run is not here any more; " + bar.model.getSelectedItem() + " instead");
        }
        bar.start.addActionListener(e -> startOrStop());
        bar.model.addActionListener(e -> showState());
        bar.configure.addActionListener(e -> configure());
        bar.shaping.addActionListener(e -> shaping());
        bar.showShaping(nextRunShaping.config());
        showState();
    }

    /**
     * Builds and shows the window, offering {@code models} (each Start runs a new instance of the
     * one selected); presses Start when the launch asks. {@code onClosed} runs once the window is
     * closed and the server stopped (the application exits there). Event thread.
     */
    public static MainWindow open(Servers servers, List<ModelProvider> models, WindowPreferences windowPreferences,
            ModelPreferences modelPreferences, WindowLog windowLog, Launch launch, Runnable onClosed) {
        MainWindow window = new MainWindow(new LocalSource(windowLog), servers, models, windowPreferences, modelPreferences, launch,
                onClosed);
        window.frame.setVisible(true);
        window.timer.start();
        if (launch.start()) {
            SwingUtilities.invokeLater(window.bar.start::doClick);
        }
        return window;
    }

    /**
     * Builds and shows a window attached to a server's monitor endpoint (docs/monitor.md): its
     * tables, map, log and time bar from the stream, the force menu with an operator's token, the
     * bar read-only. {@code onClosed} runs once it is closed. Event thread.
     */
    public static MainWindow openAttached(MonitorClient client, WindowPreferences windowPreferences, Runnable onClosed) {
        AttachedSource attached = new AttachedSource(client);
        MainWindow window = new MainWindow(attached, null, List.of(), windowPreferences, null, Launch.STORED, onClosed);
        window.frame.setVisible(true);
        window.timer.start();
        attached.start(window::refresh);
        return window;
    }

    /** The window itself (tests and the benchmark find its components by name). */
    public JFrame frame() {
        return frame;
    }

    private void layOut() {
        frame.setName("wss");
        frame.setDefaultCloseOperation(WindowConstants.DO_NOTHING_ON_CLOSE);
        frame.addWindowListener(new WindowAdapter() {
            @Override
            public void windowClosing(WindowEvent e) {
                close();
            }
        });
        JPanel right = new JPanel(new GridLayout(2, 1, 0, 8));
        right.add(ports);
        right.add(links);
        JSplitPane tables = new JSplitPane(JSplitPane.HORIZONTAL_SPLIT, robots, right);
        tables.setResizeWeight(0.3);
        tables.setBorder(null);
        JTabbedPane tabs = new JTabbedPane();
        tabs.setName("tabs");
        tabs.addTab("Connections", tables);
        tabs.addTab("Map", map);
        tabs.addTab("Link statistics", stats);
        tabs.addTab("Routes", routes);
        JPanel tabsAndReplay = new JPanel(new BorderLayout());
        tabsAndReplay.add(tabs, BorderLayout.CENTER);
        tabsAndReplay.add(replayBar, BorderLayout.SOUTH);
        JSplitPane center = new JSplitPane(JSplitPane.VERTICAL_SPLIT, tabsAndReplay, log);
        center.setResizeWeight(0.75);
        center.setBorder(null);
        JPanel content = new JPanel(new BorderLayout(0, 8));
        content.setBorder(BorderFactory.createEmptyBorder(8, 8, 8, 8));
        JPanel top = new JPanel(new BorderLayout(0, 4));
        top.add(bar, BorderLayout.NORTH);
        top.add(banner, BorderLayout.SOUTH);
        banner.setName("banner");
        banner.setOpaque(true);
        banner.setBackground(new java.awt.Color(0xFFF3C4));
        banner.setBorder(BorderFactory.createEmptyBorder(4, 6, 4, 6));
        banner.setVisible(false);
        content.add(top, BorderLayout.NORTH);
        content.add(center, BorderLayout.CENTER);
        frame.setContentPane(content);
        frame.setJMenuBar(menuBar());
        frame.setIconImages(Icons.all());
        frame.setMinimumSize(new Dimension(640, 480));
        Rectangle bounds = windowPreferences.bounds();
        if (bounds != null) {
            frame.setBounds(bounds);
        } else {
            frame.setSize(960, 700);
            frame.setLocationByPlatform(true);
        }
    }

    /** File, with Attach..., and Help, with About. */
    private JMenuBar menuBar() {
        JMenuItem attach = new JMenuItem("Attach...");
        attach.setName("attach");
        attach.setMnemonic(KeyEvent.VK_A);
        attach.setToolTipText("Open a window attached to a WSS that runs elsewhere (docs/monitor.md)");
        attach.addActionListener(e -> Attaching.fromMenu(frame, windowPreferences));
        JMenu file = new JMenu("File");
        file.setName("file");
        file.setMnemonic(KeyEvent.VK_F);
        file.add(attach);
        JMenuItem about = new JMenuItem("About WSS");
        about.setName("about");
        about.setMnemonic(KeyEvent.VK_A);
        about.addActionListener(e -> AboutDialog.show(frame));
        JMenu help = new JMenu("Help");
        help.setName("help");
        help.setMnemonic(KeyEvent.VK_H);
        help.add(about);
        JMenuBar menus = new JMenuBar();
        menus.add(file);
        menus.add(help);
        return menus;
    }

    private ModelProvider selectedModel() {
        return models.get((String) bar.model.getSelectedItem());
    }

    private void showState() {
        ModelProvider model = selectedModel();
        bar.show(state, model != null && ModelDialogs.isConfigurable(model.model()));
    }

    private void setState(ControlBar.State newState) {
        state = newState;
        showState();
    }

    private void refresh() {
        HubSnapshot snapshot = source.poll();
        if (snapshot != null) {
            robots.show(snapshot.robots());
            ports.show(snapshot.ports());
            links.show(snapshot.links());
            stats.show(snapshot.pairs());
        }
        MapData mapData = source.pollMap();
        if (mapData != null) {
            map.show(mapData);
            routes.show(mapData.routes(), mapData.allRoutes());
        }
        log.append(source.drainLog());
        String lost = source.banner();
        banner.setVisible(lost != null);
        banner.setText(lost == null ? "" : lost);
        if (snapshot != null && source instanceof AttachedSource attached) {
            bar.showServer(attached.last().model(), attached.last().controlPort());
        }
        showReplay();
        replayBar.follow();
    }

    /** The time bar shows the source's replay, when it has one. */
    private void showReplay() {
        Replay now = source.replay();
        if (now != replayShown) {
            replayShown = now;
            replayBar.attach(now);
        }
    }

    private void startOrStop() {
        if (state == ControlBar.State.STOPPED) {
            start();
        } else if (state == ControlBar.State.RUNNING) {
            stop();
        }
    }

    private void start() {
        String port = bar.port.getText().strip();
        ModelProvider model = selectedModel();
        boolean eventLog = bar.eventLog.isSelected();
        boolean record = bar.record.isSelected();
        ModelSettings values = new ModelSettings(nextRunValues.values(model.model()));
        ShapingConfig shaping = nextRunShaping.config();
        setState(ControlBar.State.STARTING);
        new SwingWorker<Servers.Running, Void>() {
            @Override
            protected Servers.Running doInBackground() throws Exception {
                return servers.start(port, model, values, eventLog, record, shaping, local.listener());
            }

            @Override
            protected void done() {
                try {
                    running = get();
                } catch (ExecutionException e) {
                    setState(ControlBar.State.STOPPED);
                    if (closing) {
                        finishClosing();
                    } else {
                        Throwable cause = e.getCause();
                        failed(cause.getMessage() != null ? cause.getMessage() : cause.toString());
                    }
                    return;
                } catch (InterruptedException e) {
                    throw new IllegalStateException("the event thread was interrupted", e);
                }
                windowPreferences.storeRun(port, model.name(), eventLog, record);
                askedPort = port;
                bar.port.setText(String.valueOf(running.port()));
                local.started(running);
                showReplay();
                setState(ControlBar.State.RUNNING);
                if (closing) {
                    stop();
                }
            }
        }.execute();
    }

    /** Says why in the log and in a message dialog, wrapped to a readable width; the window stays usable. */
    private void failed(String message) {
        LOG.warning(message);
        SwingUtilities.invokeLater(() -> JOptionPane.showMessageDialog(frame, WrappedMessage.of(message), TITLE,
                JOptionPane.ERROR_MESSAGE));
    }

    private void stop() {
        Servers.Running stopping = running;
        running = null;
        local.stopping();
        showReplay();
        setState(ControlBar.State.STOPPING);
        new SwingWorker<Void, Void>() {
            @Override
            protected Void doInBackground() {
                stopping.stop();
                return null;
            }

            @Override
            protected void done() {
                local.stopped();
                bar.port.setText(askedPort);
                setState(ControlBar.State.STOPPED);
                if (closing) {
                    finishClosing();
                }
            }
        }.execute();
    }

    private void configure() {
        PropagationModel model = selectedModel().model();
        if (ModelDialogs.show(frame, model, state == ControlBar.State.STOPPED, modelPreferences, nextRunValues.values(model))) {
            nextRunValues.entered(model);
        }
    }

    /** "Link shaping...": the dialog, read-only unless stopped (as Configure's). */
    private void shaping() {
        if (LinkShapingDialog.show(frame, state == ControlBar.State.STOPPED, windowPreferences, nextRunShaping.values())) {
            nextRunShaping.entered();
            bar.showShaping(nextRunShaping.config());
        }
    }

    /** Closing the window: stops the server as SIGTERM does, then {@code onClosed}. */
    private void close() {
        if (closing) {
            return;
        }
        closing = true;
        if (state == ControlBar.State.STOPPED) {
            finishClosing();
        } else if (state == ControlBar.State.RUNNING) {
            stop();
        }
        // STARTING or STOPPING: the worker's done() goes on from here.
    }

    private void finishClosing() {
        windowPreferences.storeBounds(frame.getBounds());
        timer.stop();
        source.close();
        forceMenu.close();
        frame.dispose();
        onClosed.run();
    }
}
