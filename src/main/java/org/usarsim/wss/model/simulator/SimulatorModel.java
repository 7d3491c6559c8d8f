package org.usarsim.wss.model.simulator;

import java.io.IOException;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.logging.Level;
import java.util.logging.Logger;
import org.usarsim.wss.model.ModelSettings;
import org.usarsim.wss.model.ModelStartException;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.RobotLinkModel;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.model.Setting;
import org.usarsim.wss.model.WssEventListener;

/**
 * A propagation model driven by robot positions polled from a USARSim-compatible simulator. Every
 * interval it sends {@code GETPOS}; then it kicks the registered robots the simulator no longer
 * lists or whose battery is empty, and breaks or resumes every pair of listed robots by its
 * strength (events only on change). When the simulator goes away, answers late or sends garbage,
 * the model says so once, keeps the last known link state and reconnects with a growing pause.
 *
 * <p>Subclasses give the strength of a pair; the rest is here, in one place.
 */
public abstract class SimulatorModel implements PropagationModel {

    private static final long MAX_BACKOFF_MS = 10_000;

    /** The settings of every simulator model: the simulator's connection, the path loss, the link stability. */
    static final List<Setting> SETTINGS = List.of(
            Setting.host("usarsim.host", "Host", "127.0.0.1")
                    .help("The machine of the simulator's position socket: a host name or an IP address"),
            Setting.integer("usarsim.port", "Port", 7435).from(1).to(65535).noun("a port number")
                    .help("The simulator's position port, 7435 as a rule; not 3000, which is USARSim's robot port"),
            Setting.integer("usarsim.interval", "Poll interval", 1000).from(100).to(60000).unit("ms")
                    .help("Milliseconds between two requests for the robots' positions (GETPOS)"),
            Setting.integer("usarsim.timeout", "Timeout", 2000).from(100).to(60000).unit("ms")
                    .help("Milliseconds to wait for the simulator's answer"),
            Setting.number("distance.cutoff", "Cutoff", "-93").unit("dBm")
                    .help("Below this signal strength two robots cannot talk; -93 dBm is a property of the channel, best left as it is"),
            Setting.number("distance.pd0", "Pd0", "-49.67").unit("dBm").help("The signal strength at distance d0"),
            Setting.number("distance.n", "N", "1").above(0)
                    .help("The attenuation factor of the environment: how fast the signal fades with distance"),
            Setting.number("distance.d0", "d0", "2").above(0).unit("m").help("The distance at which the strength is Pd0"),
            Setting.number("distance.margin", "Margin", "0").from(0).unit("dB")
                    .help("A broken link resumes only when the strength is above Cutoff + Margin, so that a pair at the edge does not flap"),
            Setting.number("distance.holdTime", "Hold time", "0").from(0).unit("s")
                    .help("A link stays broken, or resumed, at least this many seconds before it changes again"));

    private final Logger log = Logger.getLogger(getClass().getName());

    /** The declared defaults: the values until {@link #configure}. */
    private static final ModelSettings DEFAULTS = new ModelSettings(Setting.defaults(SETTINGS));

    private String host = DEFAULTS.getString("usarsim.host", null);
    private int port = DEFAULTS.getInt("usarsim.port", 0);
    private int intervalMs = DEFAULTS.getInt("usarsim.interval", 0);
    private int timeoutMs = DEFAULTS.getInt("usarsim.timeout", 0);
    private PathLoss pathLoss = new PathLoss(DEFAULTS.getDouble("distance.pd0", 0), DEFAULTS.getDouble("distance.n", 0),
            DEFAULTS.getDouble("distance.d0", 0), DEFAULTS.getDouble("distance.cutoff", 0));
    private double margin = DEFAULTS.getDouble("distance.margin", 0);
    private double holdSeconds = DEFAULTS.getDouble("distance.holdTime", 0);

    private volatile RobotLinkModel linkModel;
    private volatile WssEventListener listener = new WssEventListener() {
    };
    private volatile Map<String, ReportedRobot> positions = Map.of();
    private volatile LinkStates links = new LinkStates(pathLoss.cutoff(), 0, 0);
    /** The polling of the current run, from a start to its shutdown; null while stopped. */
    private volatile Poller poller;

    /** The simulator's connection (usarsim.*), the path loss (distance.*) and the link stability (distance.margin, distance.holdTime). */
    @Override
    public List<Setting> settings() {
        return SETTINGS;
    }

    @Override
    public void configure(ModelSettings settings) {
        host = settings.getString("usarsim.host", host);
        port = settings.getInt("usarsim.port", port);
        intervalMs = settings.getInt("usarsim.interval", intervalMs);
        timeoutMs = settings.getInt("usarsim.timeout", timeoutMs);
        pathLoss = new PathLoss(settings.getDouble("distance.pd0", pathLoss.pd0()), settings.getDouble("distance.n", pathLoss.n()),
                settings.getDouble("distance.d0", pathLoss.d0()), settings.getDouble("distance.cutoff", pathLoss.cutoff()));
        margin = settings.getDouble("distance.margin", margin);
        holdSeconds = settings.getDouble("distance.holdTime", holdSeconds);
    }

    @Override
    public void setRobotLinkModel(RobotLinkModel linkModel) {
        this.linkModel = linkModel;
    }

    @Override
    public void setEventListener(WssEventListener listener) {
        this.listener = listener;
    }

    /** Checks the settings, connects to the simulator and starts polling it. */
    @Override
    public synchronized void start() throws ModelStartException {
        if (poller != null) {
            return;
        }
        check(pathLoss.n() > 0 && Double.isFinite(pathLoss.n()), "distance.n must be above 0, not " + pathLoss.n());
        check(pathLoss.d0() > 0 && Double.isFinite(pathLoss.d0()), "distance.d0 must be above 0, not " + pathLoss.d0());
        check(Double.isFinite(pathLoss.pd0()) && Double.isFinite(pathLoss.cutoff()), "distance.pd0 and distance.cutoff must be numbers");
        check(margin >= 0 && holdSeconds >= 0, "distance.margin and distance.holdTime must be 0 or more");
        check(intervalMs > 0 && timeoutMs > 0, "usarsim.interval and usarsim.timeout must be above 0");
        check(port > 0 && port < 65536, "usarsim.port must be from 1 to 65535, not " + port);
        check(linkModel != null, "no server to act on (setRobotLinkModel was not called)");
        SimulatorConnection connection;
        try {
            connection = SimulatorConnection.open(host, port, timeoutMs);
        } catch (IOException | RuntimeException e) {
            throw new ModelStartException("cannot reach the simulator at " + where() + " (" + e.getMessage() + ")", e);
        }
        positions = Map.of();
        links = new LinkStates(pathLoss.cutoff(), margin, holdSeconds);
        started();
        log.info(name() + " polls the simulator at " + where() + " every " + intervalMs + " ms; range " + metres(pathLoss.range())
                + " (cutoff " + pathLoss.cutoff() + " dBm" + (margin > 0 ? ", margin " + margin + " dB" : "")
                + (holdSeconds > 0 ? ", hold time " + holdSeconds + " s" : "") + ")");
        poller = new Poller(connection);
    }

    private static void check(boolean ok, String message) throws ModelStartException {
        if (!ok) {
            throw new ModelStartException(message);
        }
    }

    /** Stops polling; a poll under way is abandoned (its connection closed) and acts on nothing more. */
    @Override
    public void shutdown() {
        Poller stopping;
        synchronized (this) {
            stopping = poller;
            poller = null;
        }
        if (stopping != null) {
            stopping.stop();
        }
    }

    @Override
    public boolean isActive() {
        return poller != null;
    }

    /** The strength from the last known positions: NaN while either robot's position is unknown. */
    @Override
    public double getSignalStrengthForPair(String from, String to) {
        Map<String, ReportedRobot> known = positions;
        ReportedRobot a = known.get(from);
        ReportedRobot b = known.get(to);
        return a == null || b == null ? Double.NaN : strength(a, b);
    }

    /**
     * The pair's link state as last decided; for a pair not decided yet, its strength against the
     * cutoff, or {@link #allowsUnknownRobots()} while a position is unknown.
     */
    @Override
    public boolean connectionIsPossibleForPair(String from, String to) {
        Boolean live = links.live(RobotPair.of(from, to));
        if (live != null) {
            return live;
        }
        Map<String, ReportedRobot> known = positions;
        ReportedRobot a = known.get(from);
        ReportedRobot b = known.get(to);
        return a == null || b == null ? allowsUnknownRobots() : strength(a, b) >= pathLoss.cutoff();
    }

    // ---- what a subclass decides ----

    /** The strength in dBm between two robots the simulator lists; NaN when it cannot be known. */
    protected abstract double strength(ReportedRobot a, ReportedRobot b);

    /** Whether a robot with no known position may connect. */
    protected abstract boolean allowsUnknownRobots();

    /** Whether registered robots absent from this position list are kicked. */
    protected abstract boolean kicksRobotsAbsentFrom(Map<String, ReportedRobot> listed);

    /** Called at every poll before the pairs are decided, with the pairs to decide. */
    protected void beforeDecisions(Map<String, ReportedRobot> listed, List<RobotPair> pairs, SimulatorConnection simulator)
            throws IOException {
    }

    /** Called at every start, before the first poll: a subclass forgets what the last run learned. */
    protected void started() {
    }

    protected final PathLoss pathLoss() {
        return pathLoss;
    }

    // ---- the poller ----

    /**
     * One run of polling, from a start to its shutdown: its own thread, connection and trouble
     * state, so that a run that is slow to stop can never touch the next one's.
     */
    private final class Poller implements Runnable {

        private final Thread thread;
        private volatile boolean stopped;
        private volatile SimulatorConnection connection;
        /** Why the simulator is unusable since {@link #troubleSince}; null while it answers. */
        private String trouble;
        private long troubleSince;
        /** A failure that is not the simulator's, already logged; null after a good poll. */
        private String failure;

        Poller(SimulatorConnection connection) {
            this.connection = connection;
            thread = new Thread(this, name() + " poller");
            thread.setDaemon(true);
            thread.start();
        }

        void stop() {
            stopped = true;
            thread.interrupt();
            close();
            try {
                thread.join(TimeUnit.SECONDS.toMillis(5));
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }

        @Override
        public void run() {
            long backoffMs = intervalMs;
            long next = System.nanoTime();
            try {
                while (pause(next)) {
                    next = System.nanoTime() + intervalMs * 1_000_000L;
                    try {
                        SimulatorConnection simulator = connection;
                        if (simulator == null) {
                            simulator = SimulatorConnection.open(host, port, timeoutMs);
                            connection = simulator;
                        }
                        poll(simulator);
                        back();
                        backoffMs = intervalMs;
                    } catch (IOException e) {
                        if (stopped) {
                            return;
                        }
                        lost(e);
                        close();
                        next = System.nanoTime() + backoffMs * 1_000_000L;
                        backoffMs = Math.min(backoffMs * 2, Math.max(MAX_BACKOFF_MS, intervalMs));
                    } catch (RuntimeException | Error e) {
                        failed(e);
                    }
                }
            } finally {
                close();
            }
        }

        /** Waits until {@code deadline}; false when the run was stopped meanwhile. */
        private boolean pause(long deadline) {
            long left;
            while (!stopped && (left = deadline - System.nanoTime()) > 0) {
                try {
                    TimeUnit.NANOSECONDS.sleep(left);
                } catch (InterruptedException e) {
                    return false;
                }
            }
            return !stopped;
        }

        /** One poll: positions, kicks, then every pair of listed robots broken or resumed. */
        private void poll(SimulatorConnection simulator) throws IOException {
            RobotLinkModel hub = linkModel;
            List<String> registeredBefore = hub.getListOfRegisteredRobots();
            Map<String, ReportedRobot> listed = simulator.positions();
            if (stopped) {
                return;
            }
            boolean kickAbsent = kicksRobotsAbsentFrom(listed);
            for (String robot : registeredBefore) {
                ReportedRobot state = listed.get(robot);
                if (state == null && kickAbsent) {
                    log.info("kicking " + robot + ": the simulator does not list it");
                    hub.kickOutRobot(robot);
                } else if (state != null && state.batteryEmpty()) {
                    log.info("kicking " + robot + ": its battery is empty");
                    listener.robotOutOfBattery(robot);
                    hub.kickOutRobot(robot);
                }
            }
            List<String> present = new ArrayList<>();
            for (String robot : hub.getListOfRegisteredRobots()) {
                ReportedRobot state = listed.get(robot);
                if (state != null && !state.batteryEmpty()) {
                    present.add(robot);
                }
            }
            List<RobotPair> pairs = new ArrayList<>();
            for (int i = 0; i < present.size(); i++) {
                for (int j = i + 1; j < present.size(); j++) {
                    pairs.add(RobotPair.of(present.get(i), present.get(j)));
                }
            }
            beforeDecisions(listed, pairs, simulator);
            if (stopped) {
                return;
            }
            // Only now: a GETSS meanwhile answers from the last positions with what goes with them.
            positions = listed;
            LinkStates states = links;
            states.retainOnly(new HashSet<>(present));
            long now = System.nanoTime();
            for (RobotPair pair : pairs) {
                ReportedRobot a = listed.get(pair.first());
                ReportedRobot b = listed.get(pair.second());
                double strength = strength(a, b);
                if (states.decide(pair, strength, now)) {
                    if (hub.resumeConnectionsForPair(pair.first(), pair.second())) {
                        log.fine(pair + " in range: " + strength + " dBm");
                        listener.connectionInRange(pair.first(), pair.second());
                    }
                } else if (hub.breakConnectionsForPair(pair.first(), pair.second())) {
                    log.fine(pair + " out of range: " + strength + " dBm at " + metres(a.distanceTo(b)));
                    listener.connectionOutOfRange(pair.first(), pair.second(), strength, a.distanceTo(b));
                }
            }
            failure = null;
        }

        private void lost(IOException e) {
            String reason = e.getMessage() == null ? e.toString() : e.getMessage();
            if (trouble == null) {
                troubleSince = System.nanoTime();
                log.warning("lost the simulator at " + where() + ": " + reason + "; keeping the last known link state and reconnecting");
            } else if (!reason.equals(trouble)) {
                log.fine("the simulator at " + where() + " is still unusable: " + reason);
            }
            trouble = reason;
        }

        private void back() {
            if (trouble != null) {
                long seconds = TimeUnit.NANOSECONDS.toSeconds(System.nanoTime() - troubleSince);
                log.info("the simulator at " + where() + " answers again after " + seconds + " s");
                trouble = null;
            }
        }

        /** A failure that is not the simulator's (a bug, a listener that throws): logged once, then polling goes on. */
        private void failed(Throwable e) {
            if (failure == null) {
                log.log(Level.WARNING, name() + ": a poll failed (" + e + "); polling goes on", e);
            }
            failure = e.toString();
        }

        private void close() {
            SimulatorConnection open = connection;
            connection = null;
            if (open != null) {
                open.close();
            }
        }
    }

    private String where() {
        return host + ":" + port;
    }

    private static String metres(double metres) {
        return String.format(java.util.Locale.ROOT, "%.2f m", metres);
    }
}
