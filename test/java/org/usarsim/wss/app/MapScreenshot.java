package org.usarsim.wss.app;

import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.InputStream;
import java.io.Reader;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Properties;
import java.util.concurrent.atomic.AtomicReference;
import java.util.prefs.Preferences;
import javax.imageio.ImageIO;
import javax.swing.JFrame;
import javax.swing.JTabbedPane;
import javax.swing.SwingUtilities;
import org.usarsim.wss.gui.Gui;
import org.usarsim.wss.gui.Launch;
import org.usarsim.wss.gui.MainWindow;
import org.usarsim.wss.gui.MapProbe;
import org.usarsim.wss.gui.ModelPreferences;
import org.usarsim.wss.gui.Servers;
import org.usarsim.wss.gui.WindowLog;
import org.usarsim.wss.gui.WindowPreferences;
import java.util.Optional;
import org.usarsim.wss.model.DialogLayout;
import org.usarsim.wss.model.FakeReplay;
import org.usarsim.wss.model.LinkQuality;
import org.usarsim.wss.model.ModelProvider;
import org.usarsim.wss.model.ModelStartException;
import org.usarsim.wss.model.Position;
import org.usarsim.wss.model.Replay;
import org.usarsim.wss.model.RobotLinkModel;
import org.usarsim.wss.model.Wall;
import org.usarsim.wss.model.WssEventListener;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.Setting;
import org.usarsim.wss.model.ModelSettings;
import org.usarsim.wss.model.distance.DistanceOnlyPropagationModel;
import org.usarsim.wss.model.obstacle.ObstaclePropagationModel;
import org.usarsim.wss.world.WorldServer;

/**
 * Takes the map screenshots of docs/images (docs/gui.md, "For developers"): serves the world file,
 * opens the window with the properties file's model, registers the world's robots with the WSS,
 * shows the map, waits SECONDS of world time, selects ROBOT and paints the window to PNG. Each
 * KEY=VALUE after them goes over the file's; the file's server keys ({@code wss.shaping},
 * {@code wss.force.up}, ...; not the port, model or address) apply to the window's server. With
 * {@code wss.shaping=on} every robot also asks a DNS of every other, so that the hub shapes every
 * pair and the map draws each line as wide as its rate. With {@code screenshot.replay=TIME/DURATION}
 * the model also offers a replay's controls (a {@link FakeReplay} standing at TIME of DURATION
 * seconds, at 1x, playing), so that the window shows its time bar (docs/images/replay-bar.png,
 * taken before the replay model existed). With {@code screenshot.route=A,B} every robot asks a DNS of
 * every other too (routes go over the pairs the hub knows), and the map draws the route from A to B
 * (docs/images/map-route.png, with {@code wss.route.base} for the cut-off robots); with
 * {@code screenshot.tab=Routes} the window shows that tab instead of the map, with {@code screenshot.filter=TEXT}
 * typed in its filter (docs/images/routes-table.png).
 *
 *     xvfb-run -a -s "-screen 0 1280x900x24" java -cp target/classes:target/test-classes \
 *         org.usarsim.wss.app.MapScreenshot WORLD PROPERTIES SECONDS ROBOT OUT.png [KEY=VALUE...]
 */
public final class MapScreenshot {

    private MapScreenshot() {
    }

    public static void main(String[] args) throws Exception {
        Path worldFile = Path.of(args[0]);
        Properties properties = new Properties();
        try (Reader in = Files.newBufferedReader(Path.of(args[1]))) {
            properties.load(in);
        }
        for (int i = 5; i < args.length; i++) {
            String[] keyValue = args[i].split("=", 2);
            properties.setProperty(keyValue[0], keyValue[1]);
        }
        String fakeReplay = (String) properties.remove("screenshot.replay");
        String route = (String) properties.remove("screenshot.route");
        String tab = (String) properties.remove("screenshot.tab");
        String filter = (String) properties.remove("screenshot.filter");
        long millis = (long) (Double.parseDouble(args[2]) * 1000);
        String selected = args[3];
        Path out = Path.of(args[4]);

        int simulatorPort;
        try (ServerSocket free = new ServerSocket(0, 1, InetAddress.getByName("127.0.0.1"))) {
            simulatorPort = free.getLocalPort();
        }
        WorldServer world = WorldServer.start(worldFile, InetAddress.getByName("127.0.0.1"), simulatorPort);
        long started = System.nanoTime();
        PropagationModel simulatorModel = properties.getProperty("wss.model").contains("Obstacle")
                ? new ObstaclePropagationModel() : new DistanceOnlyPropagationModel();
        PropagationModel model = fakeReplay == null ? simulatorModel : new Replaying(simulatorModel, fakeReplay(fakeReplay));
        Map<String, String> settings = new HashMap<>(Setting.defaults(model.settings()));
        properties.stringPropertyNames().stream().filter(key -> !key.startsWith("wss."))
                .forEach(key -> settings.put(key, properties.getProperty(key).strip()));
        settings.put("usarsim.port", String.valueOf(simulatorPort));
        settings.put("usarsim.interval", "200");

        Preferences preferences = Preferences.userRoot().node("wss-map-screenshot-" + ProcessHandle.current().pid());
        Properties serverProperties = new Properties();
        properties.stringPropertyNames().stream().filter(key -> key.startsWith("wss."))
                .filter(key -> !List.of("wss.port", "wss.model", "wss.bindAddress").contains(key))
                .forEach(key -> serverProperties.setProperty(key, properties.getProperty(key).strip()));
        serverProperties.setProperty("wss.bindAddress", "127.0.0.1");
        boolean shaped = "on".equalsIgnoreCase(serverProperties.getProperty("wss.shaping", "off"));
        ConfigFile serverConfig = ConfigFile.of(serverProperties, "screenshot");
        WindowServers application = new WindowServers(serverConfig);
        AtomicReference<Servers.Running> running = new AtomicReference<>();
        Servers servers = (port, runModel, values, eventLog, record, shaping, listener) -> {
            Servers.Running run = application.start(port, runModel, values, eventLog, record, shaping, listener);
            running.set(run);
            return run;
        };
        WindowLog windowLog = new WindowLog();
        java.util.logging.Logger.getLogger("").addHandler(windowLog);
        AtomicReference<JFrame> frame = new AtomicReference<>();
        SwingUtilities.invokeAndWait(() -> {
            JFrame window = MainWindow.open(servers, List.of(ModelProvider.of(() -> model)), new WindowPreferences(preferences.node("window")),
                    new ModelPreferences(preferences.node("models")), windowLog,
                    new Launch("0", model.name(), false, new ModelSettings(settings), serverConfig.shapingKeysSetBy(serverProperties), true), () -> { })
                    .frame();
            window.setBounds(0, 0, 960, 700); // the size the window opens at
            frame.set(window);
        });
        Gui.until("the server runs", () -> running.get() != null);
        int port = running.get().port();

        List<Socket> robots = new ArrayList<>();
        List<String> names = new ArrayList<>();
        for (String line : Files.readAllLines(worldFile)) {
            String[] words = line.strip().split("\\s+");
            if (words[0].equals("robot")) {
                Socket robot = new Socket("127.0.0.1", port);
                // With links shaped each robot gives a port, so that the others may ask a DNS of it.
                robot.getOutputStream().write(("INIT {Robot " + words[1] + "}" + (shaped || route != null ? " {Port 7000}" : "") + "\r\n")
                        .getBytes(StandardCharsets.UTF_8));
                readLine(robot.getInputStream());
                robots.add(robot);
                names.add(words[1]);
            }
        }
        if (shaped || route != null) { // a DNS makes a pair known to the hub, which shapes it and routes over it from then on
            for (int i = 0; i < robots.size(); i++) {
                for (int j = i + 1; j < robots.size(); j++) {
                    robots.get(i).getOutputStream().write(("DNS {Robot " + names.get(j) + "}\r\n").getBytes(StandardCharsets.UTF_8));
                    readLine(robots.get(i).getInputStream());
                }
            }
        }
        MapProbe map = MapProbe.of(frame.get());
        map.showMap();
        Thread.sleep(Math.max(0, millis - (System.nanoTime() - started) / 1_000_000));
        map.select(selected);
        if (route != null) {
            String[] ends = route.split(",");
            map.pick(ends[0], ends[1]);
        }
        if (tab != null) {
            map.showTab(tab);
        }
        if (filter != null) {
            map.filter("routes", filter);
        }
        Thread.sleep(500); // a poll and a refresh of the window after the last move
        if (route != null) {
            System.out.println(map.status());
        }
        BufferedImage image = Gui.onEdt(() -> {
            JFrame window = frame.get();
            BufferedImage shot = new BufferedImage(window.getRootPane().getWidth(), window.getRootPane().getHeight(),
                    BufferedImage.TYPE_INT_RGB);
            Graphics2D g = shot.createGraphics();
            window.getRootPane().printAll(g);
            g.dispose();
            return shot;
        });
        ImageIO.write(image, "png", out.toFile());
        for (Socket robot : robots) {
            robot.close();
        }
        world.close();
        preferences.removeNode();
        System.exit(0);
    }

    /** A fake replay standing at TIME of DURATION seconds ({@code TIME/DURATION}). */
    private static FakeReplay fakeReplay(String timeAndDuration) {
        String[] parts = timeAndDuration.split("/");
        FakeReplay replay = new FakeReplay(Double.parseDouble(parts[1]));
        replay.time(Double.parseDouble(parts[0]));
        return replay;
    }

    /** A model as it is, offering a replay's controls besides. */
    private static final class Replaying implements PropagationModel {
        private final PropagationModel model;
        private final Replay replay;

        Replaying(PropagationModel model, Replay replay) {
            this.model = model;
            this.replay = replay;
        }

        @Override
        public Optional<Replay> replay() {
            return Optional.of(replay);
        }

        @Override
        public String name() {
            return model.name();
        }

        @Override
        public List<Setting> settings() {
            return model.settings();
        }

        @Override
        public void configure(ModelSettings settings) {
            model.configure(settings);
        }

        @Override
        public void setRobotLinkModel(RobotLinkModel linkModel) {
            model.setRobotLinkModel(linkModel);
        }

        @Override
        public void setEventListener(WssEventListener listener) {
            model.setEventListener(listener);
        }

        @Override
        public void start() throws ModelStartException {
            model.start();
        }

        @Override
        public void shutdown() {
            model.shutdown();
        }

        @Override
        public boolean isActive() {
            return model.isActive();
        }

        @Override
        public DialogLayout dialogLayout() {
            return model.dialogLayout();
        }

        @Override
        public double getSignalStrengthForPair(String from, String to) {
            return model.getSignalStrengthForPair(from, to);
        }

        @Override
        public boolean connectionIsPossibleForPair(String from, String to) {
            return model.connectionIsPossibleForPair(from, to);
        }

        @Override
        public Optional<LinkQuality> linkQualityForPair(String from, String to) {
            return model.linkQualityForPair(from, to);
        }

        @Override
        public Optional<Position> positionOf(String robot) {
            return model.positionOf(robot);
        }

        @Override
        public double rangeFor(String from, String to) {
            return model.rangeFor(from, to);
        }

        @Override
        public List<Wall> walls() {
            return model.walls();
        }

        @Override
        public double cutoff() {
            return model.cutoff();
        }
    }

    private static String readLine(InputStream in) throws IOException {
        StringBuilder line = new StringBuilder();
        for (int c = in.read(); c != '\n' && c >= 0; c = in.read()) {
            line.append((char) c);
        }
        return line.toString();
    }
}
