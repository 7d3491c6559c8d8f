package org.usarsim.wss.hub;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.channels.SocketChannel;
import java.util.ArrayList;
import java.util.List;
import java.util.logging.Level;
import java.util.logging.Logger;
import org.usarsim.wss.hub.core.Changes;
import org.usarsim.wss.hub.core.Connection;
import org.usarsim.wss.hub.core.Force;
import org.usarsim.wss.hub.core.HubClock;
import org.usarsim.wss.hub.core.HubCore;
import org.usarsim.wss.hub.core.HubEvent;
import org.usarsim.wss.hub.core.RatePin;
import org.usarsim.wss.hub.core.WssPort;
import org.usarsim.wss.hub.tcp.ControlListener;
import org.usarsim.wss.hub.tcp.Descriptors;
import org.usarsim.wss.hub.tcp.KeepAlive;
import org.usarsim.wss.hub.tcp.Link;
import org.usarsim.wss.hub.tcp.OperatorCommands;
import org.usarsim.wss.hub.tcp.PortSelector;
import org.usarsim.wss.hub.udp.UdpRelay;
import org.usarsim.wss.model.ModelStartException;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.RobotLinkModel;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.model.WssEventListener;
import org.usarsim.wss.protocol.Command;
import org.usarsim.wss.protocol.CommandParser;
import org.usarsim.wss.protocol.ProtocolException;
import org.usarsim.wss.protocol.Replies;
import org.usarsim.wss.routes.RouteListener;
import org.usarsim.wss.routes.RouteRule;
import org.usarsim.wss.routes.RouteTable;
import org.usarsim.wss.shaping.RateTable;
import org.usarsim.wss.shaping.Airtime;

/**
 * The server: builds the hub's parts, each from parts built before it, and starts and stops them.
 * The {@link HubCore} (the rules and the state) runs under one lock in the {@link StepExecutor};
 * the WSS ports' sockets are the {@link ChangeApplier}'s and the {@link PortSelector}'s, and a port
 * is opened by the {@link PortOpener} alone; the control sessions call in through
 * {@link ControlSide}, the WSS ports and links through {@link LinkSide}, the propagation model
 * through {@link ModelSide}; the window and the tests read {@link #snapshot()} and listen. Every
 * part reads the one {@link HubClock} it is given.
 */
public final class Hub implements AutoCloseable {

    private static final Logger LOG = Logger.getLogger(Hub.class.getName());

    static {
        // Loaded now, while a descriptor is free: they are used when descriptors have run out
        // (to say so, and to give some back), and loading a class from a directory of classes takes one.
        Descriptors.ranOut(new IOException());
        Descriptors.Work.class.getDeclaredMethods();
        HubEvent.class.getPermittedSubclasses();
        WarningLimiter.class.getDeclaredClasses();
        ClockTimer.class.getDeclaredClasses();
        Changes.class.getDeclaredClasses();
    }

    private final HubConfig config;
    private final PropagationModel model;
    /** The hub's one clock: every part that needs the time reads it. */
    private final HubClock clock;
    private final EventFanOut events;
    /** Every WARNING a client can cause goes through it (docs/reliability.md). */
    private final WarningLimiter warnings;
    private final ModelAnswers answers;
    private final PortSelector portSelector;
    private final ChangeApplier applier;
    private final StepExecutor executor;
    private final PortOpener opener;
    private final ControlSide controlSide;
    private final ModelSide modelSide;
    /** The robots' radios, when links are shaped (docs/shaping.md). */
    private final Airtime airtime;
    /** Asks the model a few times a second what the shaped pairs' rates are now; null when links are not shaped. */
    private final Sampler sampler;
    /** The current routes, recomputed on their own thread when pairs change (docs/routes.md). */
    private final RouteKeeper routes;
    /** Guarded by this: set once the control port accepts; whether {@link #close} was called. */
    private ControlListener controlListener;
    private boolean closed;
    /** The fixed UDP ports' relays, made at Start (docs/fixed-ports.md). */
    private volatile List<UdpRelay> relays = List.of();

    /** A hub on the machine's clock. */
    public Hub(HubConfig config, PropagationModel model) {
        this(config, model, HubClock.SYSTEM);
    }

    /** A hub whose every part reads {@code clock} (a test's, moved by hand). */
    public Hub(HubConfig config, PropagationModel model, HubClock clock) {
        this.config = config;
        this.model = model;
        this.clock = clock;
        this.answers = new ModelAnswers(model);
        this.warnings = WarningLimiter.standard(clock);
        this.events = new EventFanOut(LOG, warnings);
        this.airtime = config.shaping().airtime() ? Airtime.shared() : Airtime.unshared();
        HubCore core = new HubCore(model.name(), config.matchSourceAddress(), config.portMemorySeconds(), config.maxPortsPerRobot(),
                config.maxPortsPerAddress(), config.shaping());
        KeepAlive keepAlive = KeepAlive.within(config.deadPeerSeconds());
        Outbox outbox = new Outbox(events);
        this.portSelector = new PortSelector(clock);
        this.applier = new ChangeApplier(outbox, portSelector, config.bindAddress(), clock);
        this.executor = new StepExecutor(core, clock, outbox, applier);
        Descriptors descriptors = new Descriptors(executor::giveBackRemembered);
        LinkSide linkSide = new LinkSide(executor, answers, config, warnings, keepAlive, descriptors, events, airtime, clock, LOG);
        this.opener = new PortOpener(executor, applier, portSelector, linkSide, descriptors, answers, config);
        RouteRule rule = RouteRule.of(config.shaping());
        RateTable rates = config.shaping().on() ? config.shaping().rates() : null;
        this.routes = new RouteKeeper(base -> RouteGraphs.of(snapshot(), rule, base, model, rates), executor::announce);
        this.controlSide = new ControlSide(executor, opener, applier, answers, config, clock, warnings, keepAlive, descriptors,
                routes::current);
        this.modelSide = new ModelSide(executor, answers, routes::stale);
        this.sampler = config.shaping().on() ? new Sampler(modelSide::measure) : null;
        events.add(new EventLogger(warnings));
        events.add(routes);
    }

    public void addListener(WssEventListener listener) {
        events.add(listener);
    }

    public void removeListener(WssEventListener listener) {
        events.remove(listener);
    }

    /**
     * Checks that the control port is free, starts the model, declares the robots and opens the
     * fixed ports (docs/fixed-ports.md), then binds the control port: once it accepts, every fixed
     * port listens, so a program started with the server may connect to both at once.
     *
     * @throws IOException         when the control port or a fixed port cannot be bound (in use,
     *                             bad address), or {@link #close} was called before the start finished
     * @throws ModelStartException when the model will not start; nothing is left listening
     */
    public void start() throws IOException, ModelStartException {
        InetSocketAddress controlAddress = new InetSocketAddress(config.bindAddress(), config.controlPort());
        ControlListener.checkFree(controlAddress);
        model.setRobotLinkModel(modelSide);
        model.setEventListener(modelSide.events());
        model.start();
        ControlListener listener;
        try {
            if (executor.locked(HubCore::isClosed)) {
                // Stopped while the model was starting (a slow simulator connection, say).
                throw new IOException("stopped while starting");
            }
            // Before the first robot can come; a start that failed forced nothing.
            config.forced().forEach((pair, force) -> controlSide.force(pair.first(), pair.second(), force,
                    config.pins().getOrDefault(pair, RatePin.NONE)));
            relays = FixedPortsStart.open(config, executor, opener, answers, airtime, clock, events);
            listener = new ControlListener(controlSide, controlAddress);
        } catch (IOException | RuntimeException e) {
            stopParts();
            throw e;
        }
        boolean stopped;
        synchronized (this) {
            stopped = closed;
            if (!stopped) {
                controlListener = listener;
            }
        }
        if (stopped) { // closed meanwhile, maybe before the relays were made: they close now
            listener.close();
            stopParts();
            throw new IOException("stopped while starting");
        }
        routes.start();
        if (sampler != null) {
            sampler.start();
        }
        listener.start();
        LOG.info("WSS listening for robots on " + config.bindAddress().getHostAddress() + ":" + controlPort()
                + " with " + model.name());
    }

    /** The control port robots connect to (the one the OS chose when configured as 0). */
    public synchronized int controlPort() {
        return controlListener.port();
    }

    /** Stops the model and closes every socket: control connections, WSS ports, links. */
    @Override
    public void close() {
        ControlListener listener;
        synchronized (this) {
            closed = true;
            listener = controlListener;
        }
        if (listener != null) {
            listener.close();
        }
        stopParts();
        warnings.close();
        LOG.info("WSS stopped");
    }

    /** Everything but the control port and the warnings, stopped: the model, the sampler, the relays, the ports and links. */
    private void stopParts() {
        try {
            model.shutdown();
        } catch (RuntimeException e) {
            LOG.log(Level.WARNING, "the model failed to shut down: " + e, e);
        }
        if (sampler != null) {
            sampler.close();
        }
        routes.close();
        relays.forEach(UdpRelay::close);
        applier.close(); // no port memory timer runs any more
        executor.close(); // the core closes: every port stops, every link closes
        portSelector.close();
    }

    /** What the model is given: for a test or a benchmark that plays the model. */
    public RobotLinkModel robotLinks() {
        return modelSide;
    }

    /** The registered robots' names, sorted. */
    public List<String> getListOfRegisteredRobots() {
        return modelSide.getListOfRegisteredRobots();
    }

    /** An operator forces the pair down or up ({@link ControlSide#force(String, String, Force, RatePin)}). */
    public void force(String robotA, String robotB, Force force) {
        controlSide.force(robotA, robotB, force);
    }

    /** As {@link #force(String, String, Force)}, up with the pair's rate and delay pinned (docs/shaping.md). */
    public void force(String robotA, String robotB, Force force, RatePin pin) {
        controlSide.force(robotA, robotB, force, pin);
    }

    /** Gives the pair back to the model ({@link ControlSide#release}). */
    public void release(String robotA, String robotB) {
        controlSide.release(robotA, robotB);
    }

    /**
     * An operator's FORCE or REPLAY given elsewhere than on the control port (the monitor's POSTs,
     * docs/monitor.md): {@code line} is the whole control line, answered by the same code as the
     * control port's ({@link OperatorCommands}), its reply line returned; {@code who} names the asker in
     * the log line. The caller has checked that the asker is an operator.
     */
    public String operatorLine(String line, InetAddress address, String who) {
        try {
            Command command = CommandParser.parse(line);
            if (command != null && command.type().equals("FORCE") && !command.hasNoSegment()) {
                return OperatorCommands.force(controlSide, command, address, who);
            }
            if (command != null && command.type().equals("REPLAY")) {
                return OperatorCommands.replay(controlSide, command, address, who);
            }
            return Replies.error(Replies.MALFORMED_NO_COMMAND);
        } catch (ProtocolException e) {
            return e.reply();
        }
    }

    /** The pair's forced state, or null when the model decides it (for the tests; the window and the log read it in the pairs' states). */
    Force forced(RobotPair pair) {
        return executor.locked(core -> core.forced(pair));
    }

    /** The sockets of the control connections and of both legs of every link, for the tests of their options. */
    List<SocketChannel> openSockets() {
        List<SocketChannel> open;
        synchronized (this) {
            open = new ArrayList<>(controlListener.channels());
        }
        executor.locked(core -> {
            for (WssPort port : core.ports()) {
                for (Connection link : port.links()) {
                    open.addAll(((Link) link).channels());
                }
            }
            return null;
        });
        return open;
    }

    /** The routes as last computed (docs/routes.md): {@link RouteTable#EMPTY} until the first, soon after the start. */
    public RouteTable routes() {
        return routes.current();
    }

    /** Told each time the routes change, on the hub's {@code wss-routes} thread. */
    public void addRouteListener(RouteListener listener) {
        routes.addListener(listener);
    }

    public void removeRouteListener(RouteListener listener) {
        routes.removeListener(listener);
    }

    /** The base robots are cut off from ({@code wss.route.base}; null: none); the routes are found again with it. */
    public void setRouteBase(String robot) {
        routes.base(robot);
    }

    /** The robots, the WSS ports, the established links and the pairs' statistics, all at one instant. */
    public HubSnapshot snapshot() {
        Airtime radios = config.shaping().on() ? airtime : null;
        Snapshots.Copied copied = executor.locked(core -> Snapshots.copy(core, radios, relays, clock.nanoTime()));
        return Snapshots.complete(copied, answers, clock.nanoTime());
    }
}
