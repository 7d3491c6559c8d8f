package org.usarsim.wss.hub;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.OptionalDouble;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import java.util.function.LongSupplier;
import java.util.logging.Level;
import java.util.logging.Logger;
import org.usarsim.wss.hub.core.Changes;
import org.usarsim.wss.hub.core.Connection;
import org.usarsim.wss.hub.core.Force;
import org.usarsim.wss.hub.core.HubCore;
import org.usarsim.wss.hub.core.HubEvent;
import org.usarsim.wss.hub.core.Measurement;
import org.usarsim.wss.hub.core.OrderedPair;
import org.usarsim.wss.hub.core.RatePin;
import org.usarsim.wss.hub.core.RegisteredRobot;
import org.usarsim.wss.hub.core.WssPort;
import org.usarsim.wss.hub.tcp.Closing;
import org.usarsim.wss.hub.tcp.ControlListener;
import org.usarsim.wss.hub.tcp.Closes;
import org.usarsim.wss.hub.tcp.ControlSession;
import org.usarsim.wss.hub.tcp.Descriptors;
import org.usarsim.wss.hub.tcp.KeepAlive;
import org.usarsim.wss.hub.tcp.Link;
import org.usarsim.wss.hub.tcp.PortListener;
import org.usarsim.wss.hub.tcp.PortSelector;
import org.usarsim.wss.hub.tcp.PortSockets;
import org.usarsim.wss.hub.tcp.Shaping;
import org.usarsim.wss.hub.tcp.SocketBuffers;
import org.usarsim.wss.hub.tcp.Switchboard;
import org.usarsim.wss.model.ModelPoll;
import org.usarsim.wss.model.ModelStartException;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.Replay;
import org.usarsim.wss.model.RobotLinkModel;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.model.WssEventListener;
import org.usarsim.wss.shaping.Airtime;

/**
 * The server: runs the {@link HubCore} (the rules and the state) under one lock, and applies what
 * each of its steps returns after the lock: the socket work (ports to listen on, stop or give
 * back, connections to close) in the order of the steps, then the events, in order, through the
 * {@link Outbox}. Control sessions, port listeners and links call in through {@link Switchboard};
 * the propagation model through {@link RobotLinkModel}.
 *
 * <p>Under the lock there is no I/O, no call into the model (a model may call back in from its
 * own thread) and no listener: a DNS binds a new port's number before it takes the lock to
 * allocate it, and a link's sockets are opened between two checks ({@link #accepted}).
 */
public final class Hub implements RobotLinkModel, Switchboard, AutoCloseable {

    private static final Logger LOG = Logger.getLogger(Hub.class.getName());
    /** How long an INIT of a taken name waits for the name to be freed. */
    private static final long NAME_RELEASE_WAIT_NS = TimeUnit.MILLISECONDS.toNanos(250);
    /** How long a departure waits for its ports to hand over the connections already completed. */
    private static final long DRAIN_NS = TimeUnit.SECONDS.toNanos(1);
    /**
     * How many remembered ports of robots that left are given back, at least, each time
     * descriptors run short: room for a few robots' arrivals and connections before the next time.
     */
    private static final int GIVE_BACK_AT_LEAST = 64;

    static {
        // Loaded now, while a descriptor is free: they are used when descriptors have run out
        // (to say so, and to give some back), and loading a class from a directory of classes takes one.
        Descriptors.ranOut(new IOException());
        HubEvent.class.getPermittedSubclasses();
        WarningLimiter.class.getDeclaredClasses();
        Changes.class.getDeclaredClasses();
    }

    private final HubConfig config;
    private final PropagationModel model;
    private final ModelAnswers answers;
    private final LongSupplier clock;
    private final EventFanOut events;
    private final SocketBuffers socketBuffers;
    /** Every WARNING a client can cause goes through it (docs/reliability.md). */
    private final WarningLimiter warnings;
    private final Object lock = new Object();
    private final HubCore core;
    private final Outbox outbox;
    private final ForgetTimer forgetTimer = new ForgetTimer(this::forgetIfGone);
    private final ChangeApplier applier;
    /** Every listening WSS port, on one thread. */
    private final PortSelector portSelector;
    private final KeepAlive keepAlive;
    /** The robots' radios, when links are shaped (docs/shaping.md). */
    private final Airtime airtime;
    /** Asks the model a few times a second what the shaped pairs' rates are now; null when links are not shaped. */
    private final Sampler sampler;
    private volatile ControlListener controlListener;

    public Hub(HubConfig config, PropagationModel model) {
        this(config, model, System::nanoTime);
    }

    /** With the clock the core, the statistics and the warnings' limit read ({@link System#nanoTime()} in use). */
    Hub(HubConfig config, PropagationModel model, LongSupplier clock) {
        this.config = config;
        this.model = model;
        this.answers = new ModelAnswers(model);
        this.clock = clock;
        this.warnings = WarningLimiter.standard(clock);
        this.events = new EventFanOut(LOG, warnings);
        this.outbox = new Outbox(events);
        this.socketBuffers = SocketBuffers.of(config.socketBuffer());
        this.core = new HubCore(model.name(), config.matchSourceAddress(), config.portMemorySeconds(), config.maxPortsPerRobot(),
                config.maxPortsPerAddress(), config.shaping());
        this.airtime = config.shaping().airtime() ? Airtime.shared() : Airtime.unshared();
        this.sampler = config.shaping().on() ? new Sampler(this::measure) : null;
        this.keepAlive = KeepAlive.within(config.deadPeerSeconds());
        this.portSelector = new PortSelector(this);
        this.applier = new ChangeApplier(outbox, forgetTimer, this, portSelector,
                (action, e) -> step(out -> core.couldNotListen(action.port(), action.epoch(), e.getMessage(), out)));
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
        controlListener = new ControlListener(this, new InetSocketAddress(config.bindAddress(), config.controlPort()));
        try {
            model.setRobotLinkModel(this);
            model.setEventListener(new ModelEvents());
            model.start();
        } catch (ModelStartException | RuntimeException e) {
            controlListener.close();
            throw e;
        }
        synchronized (lock) {
            if (core.isClosed()) {
                // Stopped while the model was starting (a slow simulator connection, say).
                controlListener.close();
                model.shutdown();
                throw new IOException("stopped while starting");
            }
        }
        // Before the first robot can come; a start that failed forced nothing.
        config.forced().forEach((pair, force) -> force(pair.first(), pair.second(), force,
                config.pins().getOrDefault(pair, RatePin.NONE)));
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
        forgetTimer.close();
        if (sampler != null) {
            sampler.close();
        }
        step(core::close);
        portSelector.close();
        warnings.close();
        LOG.info("WSS stopped");
    }

    @Override
    public KeepAlive keepAlive() {
        return keepAlive;
    }

    /** The sockets of the control connections and of both legs of every link, for the tests of their options. */
    List<SocketChannel> openSockets() {
        List<SocketChannel> open = new ArrayList<>(controlListener.channels());
        synchronized (lock) {
            for (WssPort port : core.ports()) {
                for (Connection link : port.links()) {
                    open.addAll(((Link) link).channels());
                }
            }
        }
        return open;
    }

    // ---- applying the core's steps ----

    /** One step of the core under the lock, its changes applied after it. */
    private void step(Consumer<Changes> step) {
        Changes out = new Changes();
        ChangeApplier.Applying applying;
        synchronized (lock) {
            step.accept(out);
            applying = applier.taken(out);
        }
        applier.apply(applying);
    }

    // ---- called by control sessions ----

    /**
     * Registers a robot. When the name is taken, waits a moment for it to be freed: a robot whose
     * control connection dropped reconnects at once, and its old connection's end may not have
     * been read yet; one that is leaving frees it once its ports drained.
     *
     * @return false when the name stays taken (nothing changes then)
     */
    @Override
    public boolean register(String name, InetAddress address, List<Integer> acceptPorts, ControlSession session) {
        RegisteredRobot robot = new RegisteredRobot(name, address, acceptPorts, session);
        Changes out = new Changes();
        ChangeApplier.Applying applying;
        synchronized (lock) {
            long start = System.nanoTime();
            HubCore.NameCheck check;
            while ((check = core.register(robot, clock.getAsLong(), out)) != HubCore.NameCheck.REGISTERED) {
                long wait = check == HubCore.NameCheck.TAKEN_BY_LEAVING ? NAME_RELEASE_WAIT_NS + DRAIN_NS : NAME_RELEASE_WAIT_NS;
                long left = start + wait - System.nanoTime();
                if (check == HubCore.NameCheck.CLOSED || left <= 0) {
                    return false;
                }
                try {
                    TimeUnit.NANOSECONDS.timedWait(lock, left);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    return false;
                }
            }
            applying = applier.taken(out);
        }
        applier.apply(applying);
        return true;
    }

    /**
     * The robot's control connection closed: it is gone, its ports stop listening, its links live
     * on. First every connection the kernel already completed on its listening ports is forwarded
     * (a robot that sends and leaves at once loses nothing): the robot stays registered until its
     * ports have drained, for at most {@link #DRAIN_NS}.
     */
    @Override
    public void deregister(String name, ControlSession session) {
        List<PortSockets> toDrain = new ArrayList<>();
        synchronized (lock) {
            List<WssPort> listening = core.beginLeaving(name, session);
            if (listening == null) {
                return;
            }
            lock.notifyAll(); // an INIT of the name waits for the drain now
            listening.stream().map(applier::socketsOf).filter(Objects::nonNull).forEach(toDrain::add);
        }
        // The drains' own connections are started without the lock (a listener stopped meanwhile declines).
        List<PortListener> draining = toDrain.stream().map(PortSockets::beginDrain).filter(Objects::nonNull).toList();
        long deadline = System.nanoTime() + DRAIN_NS;
        draining.forEach(listener -> listener.awaitEnd(deadline));
        // Drained, they stop now, together: once the robot is gone, a connect to them is refused. The
        // departure's step stops them in its turn too (nothing left to do then); stopping is the
        // same whenever it is done, and a port that listens again later is a new listening.
        Closes closes = portSelector.closes();
        toDrain.forEach(sockets -> sockets.stop(closes));
        closes.await();
        step(out -> {
            core.left(name, session, clock.getAsLong(), out);
            lock.notifyAll();
        });
    }

    @Override
    public boolean isOperator(InetAddress address) {
        return config.operators().contains(address);
    }

    @Override
    public Optional<Replay> replay() {
        return answers.replay();
    }

    @Override
    public OptionalDouble signalStrength(String from, String to) {
        synchronized (lock) {
            if (!core.isRegistered(to)) {
                return OptionalDouble.empty();
            }
        }
        return answers.signalStrength(from, to);
    }

    /**
     * The WSS port for connections from {@code from} to {@code to} on {@code targetPort} (0: the
     * first). A new port's number and its listening socket are bound first, without the lock,
     * then allocated under it: a port that cannot listen is not allocated (Could.Not.Allocate.Port).
     * The socket is bound before the hub knows whether the port is new, so that a new port (every
     * DNS of a mesh forming) takes the lock once; a DNS of a port that exists closes it unused.
     * Returns once the port listens (when it should): a robot may connect as soon as it has the answer.
     */
    @Override
    public HubCore.DnsResult dns(String from, String to, int targetPort) {
        if (from.equals(to)) {
            return new HubCore.DnsResult(HubCore.DnsOutcome.NO_SUCH_ROBOT, -1, null, false);
        }
        boolean allowed = answers.allows(from, to);
        if (sampler != null && bothRegistered(from, to)) { // a new pair starts at its own rate, not the lowest
            Map<OrderedPair, Measurement> measurements = answers.measure(List.of(RobotPair.of(from, to)));
            step(out -> core.measured(measurements, out));
        }
        ServerSocketChannel ahead;
        try {
            portSelector.start(); // once: not under the lock, where a new port joins it
            ahead = PortSockets.bindNew(config.bindAddress());
        } catch (IOException e) {
            ahead = null; // out of descriptors, say: asked again below if the port is new
        }
        HubCore.DnsResult result = dns(from, to, targetPort, allowed, ahead);
        if (!result.numberUsed()) {
            Closing.quietly(ahead); // the port exists, or the DNS is refused
        }
        if (result.outcome() != HubCore.DnsOutcome.NEEDS_NUMBER) {
            return result;
        }
        ServerSocketChannel bound;
        try {
            bound = bindNewPort();
        } catch (IOException e) {
            step(out -> core.couldNotAllocate(result.key(), e.getMessage(), out));
            return new HubCore.DnsResult(HubCore.DnsOutcome.NO_PORT, -1, result.key(), false);
        }
        HubCore.DnsResult allocated = dns(from, to, targetPort, allowed, bound);
        if (!allocated.numberUsed()) {
            Closing.quietly(bound); // another DNS allocated the port meanwhile, or the robots left
        }
        return allocated;
    }

    /** A new port's listening socket; out of descriptors, remembered ports of robots that left give theirs back first. */
    private ServerSocketChannel bindNewPort() throws IOException {
        try {
            return PortSockets.bindNew(config.bindAddress());
        } catch (IOException e) {
            if (Descriptors.ranOut(e) && descriptorsShort()) {
                return PortSockets.bindNew(config.bindAddress());
            }
            throw e;
        }
    }

    private boolean bothRegistered(String a, String b) {
        synchronized (lock) {
            return core.isRegistered(a) && core.isRegistered(b);
        }
    }

    private HubCore.DnsResult dns(String from, String to, int targetPort, boolean allowed, ServerSocketChannel bound) {
        Changes out = new Changes();
        HubCore.DnsResult result;
        ChangeApplier.Applying applying;
        synchronized (lock) {
            int number = bound == null ? -1 : PortSockets.numberOf(bound);
            result = core.dns(from, to, targetPort, allowed, number, clock.getAsLong(), out);
            if (result.numberUsed()) {
                WssPort port = core.port(result.key());
                try {
                    applier.put(port, PortSockets.adopt(port, config.bindAddress(), portSelector, bound));
                } catch (IOException e) {
                    core.couldNotListen(port, port.epoch(), e.getMessage(), out);
                }
            }
            applying = applier.taken(out);
        }
        applier.apply(applying);
        return result;
    }

    @Override
    public String reverseDns(String asker, int port) {
        synchronized (lock) {
            return core.reverseDns(asker, port);
        }
    }

    // ---- called by the port listeners and links ----

    /**
     * A connection arrived on a WSS port: forward it, or close it at once and say why. The link's
     * sockets and selector are opened without the lock, between a first check of the rules
     * (a refused connection opens nothing) and a second one, under which the link is committed
     * to the port. A port that stopped listening meanwhile (its listener's epoch is old) refuses it.
     */
    @Override
    public void accepted(WssPort port, int epoch, SocketChannel socket) {
        InetAddress peer = socket.socket().getInetAddress();
        boolean allowed = answers.allows(port.key.from(), port.key.to());
        HubCore.Admission admission;
        Changes out = new Changes();
        ChangeApplier.Applying applying;
        synchronized (lock) {
            admission = core.admit(port, epoch, peer, allowed, clock.getAsLong(), out);
            applying = applier.taken(out);
        }
        applier.apply(applying);
        if (admission.refusal() != null) {
            refuse(port, socket, peer, admission.refusal());
            return;
        }
        Link link;
        try {
            link = newLink(port, socket, admission);
        } catch (IOException e) {
            warnings.warn(LOG, "connections not forwarded", peer, port + ": could not open a socket to the target: " + e.getMessage());
            Closing.quietly(socket);
            return;
        }
        String refusal;
        synchronized (lock) {
            refusal = core.commit(port, epoch, peer, allowed, link);
        }
        if (refusal != null) {
            link.discard();
            refuse(port, socket, peer, refusal);
            return;
        }
        try {
            link.start();
        } catch (Throwable e) {
            // No thread for the link: undone here, and the listener's AcceptLoop says so.
            synchronized (lock) {
                core.uncommit(port, link);
            }
            link.discard();
            throw e;
        }
    }

    /** The link's sockets; out of descriptors, remembered ports of robots that left give theirs back first. */
    private Link newLink(WssPort port, SocketChannel socket, HubCore.Admission admission) throws IOException {
        Shaping shaping = config.shaping().on() ? new Shaping(airtime, admission.up(), admission.down(), clock) : null;
        try {
            return new Link(this, port, socket, admission.target(), config.chunkSize(), socketBuffers, events, admission.stats(),
                    shaping);
        } catch (IOException e) {
            if (Descriptors.ranOut(e) && descriptorsShort()) {
                return new Link(this, port, socket, admission.target(), config.chunkSize(), socketBuffers, events,
                        admission.stats(), shaping);
            }
            throw e;
        }
    }

    private void refuse(WssPort port, SocketChannel socket, InetAddress peer, String refusal) {
        warnings.warn(LOG, "refused connections", peer, port + ": refused a connection: " + refusal);
        Closing.quietly(socket);
    }

    @Override
    public void established(Link link) {
        long last;
        synchronized (lock) {
            last = outbox.append(List.of(new HubEvent.Established(link.port().key)));
        }
        outbox.deliverThrough(last);
    }

    @Override
    public void linkEnded(Link link, boolean wasEstablished) {
        step(out -> core.linkEnded(link.port(), link, wasEstablished, clock.getAsLong(), out));
    }

    /**
     * Descriptors ran short: remembered ports of robots that left are given back, the longest gone
     * first, before anyone here is refused. Their sockets are closed at once, even from inside
     * another step's turn (a port given back is done with).
     */
    @Override
    public boolean descriptorsShort() {
        Changes out = new Changes();
        ChangeApplier.Applying applying;
        int given;
        synchronized (lock) {
            given = core.giveBackRemembered(GIVE_BACK_AT_LEAST, clock.getAsLong(), out);
            applying = applier.takenOutOfTurn(out);
        }
        applier.applyOutOfTurn(applying);
        return given > 0;
    }

    @Override
    public void note(Logger log, String category, InetAddress client, String message) {
        warnings.info(log, category, client, message);
    }

    @Override
    public void warn(Logger log, String category, InetAddress client, String message, Throwable cause) {
        if (cause == null) {
            warnings.warn(log, category, client, message);
        } else {
            warnings.warn(log, category, client, message, cause);
        }
    }

    // ---- RobotLinkModel: called by the model ----

    @Override
    public boolean breakConnectionsForPair(String robotA, String robotB) {
        RobotPair pair = RobotPair.of(robotA, robotB);
        boolean[] changed = new boolean[1];
        step(out -> changed[0] = core.breakPair(pair, clock.getAsLong(), out));
        return changed[0];
    }

    @Override
    public boolean resumeConnectionsForPair(String robotA, String robotB) {
        RobotPair pair = RobotPair.of(robotA, robotB);
        boolean[] changed = new boolean[1];
        step(out -> changed[0] = core.resumePair(pair, clock.getAsLong(), out));
        return changed[0];
    }

    /** Every pair's break or resume in one step: their ports stop (or listen again) together, in one turn. */
    @Override
    public Set<RobotPair> applyLinkStates(Map<RobotPair, Boolean> inRange) {
        Set<RobotPair> changed = new LinkedHashSet<>();
        step(out -> {
            long now = clock.getAsLong();
            inRange.forEach((pair, live) -> {
                if (live ? core.resumePair(pair, now, out) : core.breakPair(pair, now, out)) {
                    changed.add(pair);
                }
            });
        });
        return changed;
    }

    @Override
    public void kickOutRobot(String name) {
        step(out -> {
            core.kick(name, clock.getAsLong(), out);
            lock.notifyAll();
        });
    }

    @Override
    public List<String> getListOfRegisteredRobots() {
        synchronized (lock) {
            return core.robotNames();
        }
    }

    // ---- forced pairs: an operator's hand on the switch (issue 12) ----

    /**
     * Forces the pair down or up: a forced state wins over the model's verdict until
     * {@link #release}. Forced down stops the pair's ports and closes its connections as a break
     * does, and the model's resume does not reopen them; forced up lets them listen (where both
     * robots are registered) and forwards their connections whatever the model breaks or forbids.
     * The names need not be registered: the state holds for the pair whenever its robots come,
     * leave and come back.
     *
     * @throws IllegalArgumentException when the names are empty or the same
     */
    @Override
    public void force(String robotA, String robotB, Force force) {
        force(robotA, robotB, force, RatePin.NONE);
    }

    /** As {@link #force(String, String, Force)}, up with the pair's rate and delay pinned (docs/shaping.md). */
    @Override
    public void force(String robotA, String robotB, Force force, RatePin pin) {
        RobotPair pair = pairOf(robotA, robotB);
        Objects.requireNonNull(force, "force");
        Objects.requireNonNull(pin, "pin");
        step(out -> core.force(pair, force, pin, clock.getAsLong(), out));
    }

    /**
     * Gives the pair back to the model: its verdict counts again at once. That verdict is the
     * model's last break or resume of the pair, and {@code connectionIsPossibleForPair} asked now
     * for each direction.
     */
    @Override
    public void release(String robotA, String robotB) {
        RobotPair pair = pairOf(robotA, robotB);
        boolean firstToSecond = answers.allows(pair.first(), pair.second());
        boolean secondToFirst = answers.allows(pair.second(), pair.first());
        step(out -> core.release(pair, firstToSecond, secondToFirst, clock.getAsLong(), out));
    }

    /** The pair's forced state, or null when the model decides it (for the tests; the window and the log read it in the pairs' states). */
    Force forced(RobotPair pair) {
        synchronized (lock) {
            return core.forced(pair);
        }
    }

    private static RobotPair pairOf(String robotA, String robotB) {
        if (robotA == null || robotB == null || robotA.isEmpty() || robotB.isEmpty() || robotA.equals(robotB)) {
            throw new IllegalArgumentException("a pair is two different robot names, not '" + robotA + "' and '" + robotB + "'");
        }
        return RobotPair.of(robotA, robotB);
    }

    // ---- port memory ----

    /** The timer's call, wss.portMemory seconds after a robot left: forget its ports unless it came back. */
    private void forgetIfGone(String name) {
        step(out -> core.forgetIfGone(name, clock.getAsLong(), out));
    }

    // ---- shaping ----

    /** The sampler's call: what the model says of each shaped pair now, both ways, asked without the lock. */
    private void measure() {
        List<RobotPair> pairs;
        synchronized (lock) {
            pairs = core.pairsToMeasure();
        }
        Map<OrderedPair, Measurement> measurements = answers.measure(pairs);
        step(out -> core.measured(measurements, out));
    }

    /** The robots, the WSS ports, the established links and the pairs' statistics, all at one instant. */
    public HubSnapshot snapshot() {
        Snapshots.Copied copied;
        synchronized (lock) {
            copied = Snapshots.copy(core, config.shaping().on() ? airtime : null, clock.getAsLong());
        }
        return Snapshots.complete(copied, answers, clock.getAsLong());
    }

    /** The model's own events join the hub's, in order with them. */
    private final class ModelEvents implements WssEventListener {

        private void append(HubEvent event) {
            synchronized (lock) {
                outbox.append(List.of(event));
            }
            outbox.deliver();
        }

        @Override
        public void robotOutOfBattery(String robot) {
            append(new HubEvent.OutOfBattery(robot));
        }

        @Override
        public void connectionOutOfRange(String from, String to, double strength, double distance) {
            append(new HubEvent.OutOfRange(from, to, strength, distance));
        }

        @Override
        public void connectionInRange(String from, String to) {
            append(new HubEvent.InRange(from, to));
        }

        @Override
        public void polled(ModelPoll poll) {
            append(new HubEvent.Polled(poll));
        }

        @Override
        public void replayMoved(double timeSeconds, double speed, boolean playing) {
            append(new HubEvent.ReplayMoved(timeSeconds, speed, playing));
        }
    }
}
