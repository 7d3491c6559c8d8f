package org.usarsim.wss.hub;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.nio.channels.SocketChannel;
import java.util.ArrayList;
import java.util.List;
import java.util.function.LongSupplier;
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
import org.usarsim.wss.hub.udp.UdpRelay;
import org.usarsim.wss.model.ModelStartException;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.RobotLinkModel;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.model.WssEventListener;
import org.usarsim.wss.shaping.Airtime;

/**
 * The server: builds the hub's parts and starts and stops them. The {@link HubCore} (the rules
 * and the state) runs under one lock in the {@link StepExecutor}; the control sessions call in
 * through {@link ControlSide}, the WSS ports and links through {@link LinkSide}, the propagation
 * model through {@link ModelSide}; the window and the tests read {@link #snapshot()} and listen.
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
        Changes.class.getDeclaredClasses();
    }

    private final HubConfig config;
    private final PropagationModel model;
    private final LongSupplier clock = System::nanoTime;
    private final EventFanOut events;
    /** Every WARNING a client can cause goes through it (docs/reliability.md). */
    private final WarningLimiter warnings;
    private final ModelAnswers answers;
    private final StepExecutor executor;
    private final ControlSide controlSide;
    private final ModelSide modelSide;
    /** The robots' radios, when links are shaped (docs/shaping.md). */
    private final Airtime airtime;
    /** Asks the model a few times a second what the shaped pairs' rates are now; null when links are not shaped. */
    private final Sampler sampler;
    private volatile ControlListener controlListener;
    /** The fixed UDP ports' relays, made at Start (docs/fixed-ports.md). */
    private volatile List<UdpRelay> relays = List.of();

    public Hub(HubConfig config, PropagationModel model) {
        this.config = config;
        this.model = model;
        this.answers = new ModelAnswers(model);
        this.warnings = WarningLimiter.standard(clock);
        this.events = new EventFanOut(LOG, warnings);
        this.airtime = config.shaping().airtime() ? Airtime.shared() : Airtime.unshared();
        HubCore core = new HubCore(model.name(), config.matchSourceAddress(), config.portMemorySeconds(), config.maxPortsPerRobot(),
                config.maxPortsPerAddress(), config.shaping());
        KeepAlive keepAlive = KeepAlive.within(config.deadPeerSeconds());
        this.executor = new StepExecutor(core, clock, new Outbox(events), config.bindAddress(),
                steps -> new LinkSide(steps, answers, config, warnings, keepAlive, events, airtime, HubClock.SYSTEM, LOG));
        this.controlSide = new ControlSide(executor, answers, config, warnings, keepAlive);
        this.modelSide = new ModelSide(executor, answers);
        this.sampler = config.shaping().on() ? new Sampler(modelSide::measure) : null;
        events.add(new EventLogger(warnings));
    }

    public void addListener(WssEventListener listener) {
        events.add(listener);
    }

    public void removeListener(WssEventListener listener) {
        events.remove(listener);
    }

    /**
     * Binds the control port, starts the model, then accepts robots.
     *
     * @throws IOException         when the control port cannot be bound (in use, bad address), or
     *                             {@link #close} was called before the start finished
     * @throws ModelStartException when the model will not start; nothing is left listening
     */
    public void start() throws IOException, ModelStartException {
        controlListener = new ControlListener(controlSide, new InetSocketAddress(config.bindAddress(), config.controlPort()));
        try {
            model.setRobotLinkModel(modelSide);
            model.setEventListener(modelSide.events());
            model.start();
        } catch (ModelStartException | RuntimeException e) {
            controlListener.close();
            throw e;
        }
        if (executor.locked(HubCore::isClosed)) {
            // Stopped while the model was starting (a slow simulator connection, say).
            controlListener.close();
            model.shutdown();
            throw new IOException("stopped while starting");
        }
        // Before the first robot can come; a start that failed forced nothing.
        config.forced().forEach((pair, force) -> controlSide.force(pair.first(), pair.second(), force,
                config.pins().getOrDefault(pair, RatePin.NONE)));
        try {
            relays = FixedPortsStart.open(config, executor, answers, airtime, clock, events);
        } catch (IOException | RuntimeException e) {
            controlListener.close();
            model.shutdown();
            executor.close();
            throw e;
        }
        if (sampler != null) {
            sampler.start();
        }
        controlListener.start();
        LOG.info("WSS listening for robots on " + config.bindAddress().getHostAddress() + ":" + controlPort()
                + " with " + model.name());
    }

    /** The control port robots connect to (the one the OS chose when configured as 0). */
    public int controlPort() {
        return controlListener.port();
    }

    /** Stops the model and closes every socket: control connections, WSS ports, links. */
    @Override
    public void close() {
        if (controlListener != null) {
            controlListener.close();
        }
        try {
            model.shutdown();
        } catch (RuntimeException e) {
            LOG.log(Level.WARNING, "the model failed to shut down: " + e, e);
        }
        if (sampler != null) {
            sampler.close();
        }
        relays.forEach(UdpRelay::close);
        executor.close();
        warnings.close();
        LOG.info("WSS stopped");
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

    /** The pair's forced state, or null when the model decides it (for the tests; the window and the log read it in the pairs' states). */
    Force forced(RobotPair pair) {
        return executor.locked(core -> core.forced(pair));
    }

    /** The sockets of the control connections and of both legs of every link, for the tests of their options. */
    List<SocketChannel> openSockets() {
        List<SocketChannel> open = new ArrayList<>(controlListener.channels());
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

    /** The robots, the WSS ports, the established links and the pairs' statistics, all at one instant. */
    public HubSnapshot snapshot() {
        Airtime radios = config.shaping().on() ? airtime : null;
        Snapshots.Copied copied = executor.locked(core -> Snapshots.copy(core, radios, relays, clock.getAsLong()));
        return Snapshots.complete(copied, answers, clock.getAsLong());
    }
}
