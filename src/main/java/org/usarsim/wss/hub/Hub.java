package org.usarsim.wss.hub;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.OptionalDouble;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.ReentrantLock;
import java.util.logging.Level;
import java.util.logging.Logger;
import org.usarsim.wss.model.ModelStartException;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.RobotLinkModel;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.model.WssEventListener;

/**
 * The server: the registry of robots, their WSS ports and the links through them. Control
 * sessions and the port listeners call in; the propagation model calls in as a {@link RobotLinkModel}.
 *
 * <p>One lock guards the registry, the ports and the broken and forced pairs. The model is never called
 * while it is held (a model may call back in from its own thread), nor is a listener (events are
 * queued under it and delivered after it, {@link #deliverEvents}). Little I/O happens under it:
 * closing server sockets, and binding a new port for a DNS or one a resume reopens; a link's
 * sockets are opened before it is taken ({@link #accepted}), a registration binds the ports it
 * reopens before it takes it again to adopt them ({@link #listenAgain}), and a departure starts
 * its ports' drains between its two holds.
 */
public final class Hub implements RobotLinkModel, AutoCloseable {

    private static final Logger LOG = Logger.getLogger(Hub.class.getName());
    /** How long an INIT of a taken name waits for the name to be freed. */
    private static final long NAME_RELEASE_WAIT_NS = TimeUnit.MILLISECONDS.toNanos(250);
    /** How long a departure waits for its ports to hand over the connections already completed. */
    private static final long DRAIN_NS = TimeUnit.SECONDS.toNanos(1);

    /** The outcome of a DNS. */
    enum DnsOutcome { OK, NO_SUCH_ROBOT, NO_SUCH_TARGET_PORT, NO_PORT }

    record DnsResult(DnsOutcome outcome, int port) {
    }

    private final HubConfig config;
    private final PropagationModel model;
    private final EventFanOut events = new EventFanOut();
    private final SocketBuffers socketBuffers;
    /** Every WARNING a client can cause goes through it (docs/reliability.md). */
    final WarningLimiter warnings = WarningLimiter.standard();
    private final Object lock = new Object();
    private final Map<String, RegisteredRobot> robots = new HashMap<>();
    private final Ports ports = new Ports();
    /** Pairs the model broke and has not resumed. */
    private final Set<RobotPair> broken = new HashSet<>();
    /** Pairs an operator forced down or up: they win over {@link #broken} and the model's answers. */
    private final ForcedPairs forcedPairs = new ForcedPairs();
    /** The control sessions whose robots are leaving: their ports drain, their names are freed soon. */
    private final Set<ControlSession> leaving = new HashSet<>();
    /** The statistics of every pair seen, forgotten with the pair's ports. */
    private final LinkStats stats = new LinkStats();
    private final PortMemory memory;
    private final KeepAlive keepAlive;
    /** Set by {@link #close}: nothing registers or listens any more. */
    private boolean closed;
    private volatile ControlListener controlListener;
    /**
     * The events of the hub's state changes (robots, ports), appended under the lock in the order
     * the changes happened there, and delivered after it by {@link #deliverEvents}: so a listener
     * (the event log, the window) sees a robot's DEREGISTERED before its next REGISTERED, and no
     * listener is ever called with the lock held.
     */
    private final List<Runnable> pendingEvents = new ArrayList<>();
    /** Held by the one thread that delivers {@link #pendingEvents} (not the hub's lock). */
    private final ReentrantLock delivering = new ReentrantLock();

    public Hub(HubConfig config, PropagationModel model) {
        this.config = config;
        this.model = model;
        this.socketBuffers = SocketBuffers.of(config.socketBuffer());
        events.add(new EventLogger());
        memory = new PortMemory(config.portMemorySeconds(), this::forgetIfGone);
        keepAlive = KeepAlive.within(config.deadPeerSeconds());
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
            model.setEventListener(events);
            model.start();
        } catch (ModelStartException | RuntimeException e) {
            controlListener.close();
            throw e;
        }
        synchronized (lock) {
            if (closed) {
                // Stopped while the model was starting (a slow simulator connection, say).
                controlListener.close();
                model.shutdown();
                throw new IOException("stopped while starting");
            }
        }
        // Before the first robot can come; a start that failed forced nothing.
        config.forced().forEach((pair, force) -> force(pair.first(), pair.second(), force));
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
        memory.close();
        List<Link> links = new ArrayList<>();
        synchronized (lock) {
            closed = true;
            lock.notifyAll(); // an INIT waiting for a name gives up at once
            for (WssPort port : ports.all()) {
                port.release();
                links.addAll(port.links());
            }
            ports.clear();
            robots.clear();
        }
        closeLinks(links, CloseReason.SERVER_STOPPED);
        warnings.close();
        LOG.info("WSS stopped");
    }

    /** How control connections and links find a peer that vanished. */
    KeepAlive keepAlive() {
        return keepAlive;
    }

    /** The sockets of the control connections and of both legs of every link, for the tests of their options. */
    List<SocketChannel> openSockets() {
        List<SocketChannel> sockets = new ArrayList<>(controlListener.channels());
        synchronized (lock) {
            for (WssPort port : ports.all()) {
                port.links().forEach(link -> sockets.addAll(link.channels()));
            }
        }
        return sockets;
    }

    // ---- called by control sessions ----

    /**
     * Registers a robot. When the name is taken, waits a moment for it to be freed: a robot whose
     * control connection dropped reconnects at once, and its old connection's end may not have
     * been read yet.
     *
     * @return false when the name stays taken (nothing changes then)
     */
    boolean register(String name, InetAddress address, List<Integer> acceptPorts, ControlSession session) {
        RegisteredRobot robot = new RegisteredRobot(name, address, acceptPorts, session);
        List<WssPort> toListen = new ArrayList<>();
        synchronized (lock) {
            long start = System.nanoTime();
            while (robots.containsKey(name) && !closed) {
                // A robot that is leaving frees its name once its ports drained: wait for that too.
                long wait = leaving.contains(robots.get(name).session()) ? NAME_RELEASE_WAIT_NS + DRAIN_NS : NAME_RELEASE_WAIT_NS;
                long left = start + wait - System.nanoTime();
                if (left <= 0) {
                    return false;
                }
                try {
                    TimeUnit.NANOSECONDS.timedWait(lock, left);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    return false;
                }
            }
            if (closed) {
                return false;
            }
            robots.put(name, robot);
            pendingEvents.add(() -> events.robotRegistered(name, address.getHostAddress(), robot.ports()));
            memory.clear(name);
            // A kick forgot the model's breaks of the robot's pairs: their statistics follow the state they are in now.
            stats.pairsOf(name).forEach(pair -> recordState(pair, true));
            for (WssPort port : ports.of(name)) {
                if (shouldListen(port.key, true) && !port.listening()) {
                    toListen.add(port);
                }
            }
        }
        listenAgain(toListen, session);
        deliverEvents();
        return true;
    }

    /**
     * The ports a registration reopens: their sockets are bound without the lock (beside the
     * placeholders, which keep the numbers), adopted under it if they still should listen, and
     * their threads started after it.
     */
    private void listenAgain(List<WssPort> toListen, ControlSession session) {
        Map<WssPort, ServerSocketChannel> bound = new HashMap<>();
        for (WssPort port : toListen) {
            try {
                bound.put(port, port.bindListening());
            } catch (IOException e) {
                LOG.warning(port + ": could not listen again: " + e.getMessage());
            }
        }
        List<PortListener> started = new ArrayList<>();
        synchronized (lock) {
            for (Map.Entry<WssPort, ServerSocketChannel> entry : bound.entrySet()) {
                WssPort port = entry.getKey();
                boolean stillOurs = ports.get(port.key) == port && !closed && isRegisteredSession(session);
                if (stillOurs && !port.listening() && shouldListen(port.key, true)) {
                    started.add(port.adopt(entry.getValue()));
                    pendingEvents.add(listeningEvent(port));
                } else {
                    Closing.quietly(entry.getValue());
                }
            }
        }
        started.forEach(PortListener::start);
    }

    /** Under the lock: whether the session's robot is registered now. */
    private boolean isRegisteredSession(ControlSession session) {
        return robots.values().stream().anyMatch(robot -> robot.session() == session);
    }

    /**
     * The robot's control connection closed: it is gone, its ports stop listening, its links live
     * on. First every connection the kernel already completed on its listening ports is forwarded
     * (a robot that sends and leaves at once loses nothing): the robot stays registered until its
     * ports have drained, for at most {@link #DRAIN_NS}.
     */
    void deregister(String name, ControlSession session) {
        Map<PortListener, InetAddress> toDrain = new HashMap<>();
        synchronized (lock) {
            if (!isSessionOf(name, session)) {
                return;
            }
            leaving.add(session);
            lock.notifyAll(); // an INIT of the name waits for the drain now
            for (WssPort port : ports.of(name)) {
                PortListener listener = port.listener();
                if (listener != null) {
                    toDrain.put(listener, port.reach());
                }
            }
        }
        // The drains' own connections are started without the lock (a listener stopped meanwhile declines).
        List<PortListener> draining = new ArrayList<>();
        toDrain.forEach((listener, reach) -> {
            if (listener.beginDrain(reach)) {
                draining.add(listener);
            }
        });
        long deadline = System.nanoTime() + DRAIN_NS;
        draining.forEach(listener -> listener.awaitEnd(deadline));
        synchronized (lock) {
            leaving.remove(session);
            if (!isSessionOf(name, session)) {
                return; // kicked out meanwhile
            }
            robots.remove(name);
            lock.notifyAll();
            pendingEvents.add(() -> events.robotDeregistered(name));
            stats.left(name, System.nanoTime());
            for (WssPort port : ports.of(name)) {
                if (port.stopListening()) {
                    pendingEvents.add(listeningEvent(port));
                }
            }
            if (memory.left(name)) {
                forgetPortsOf(name);
            }
        }
        deliverEvents();
    }

    /** Under the lock. */
    private boolean isSessionOf(String name, ControlSession session) {
        RegisteredRobot robot = robots.get(name);
        return robot != null && robot.session() == session;
    }

    /** Whether a control connection from this address may use the operator command (wss.operators). */
    boolean isOperator(InetAddress address) {
        return config.operators().contains(address);
    }

    /** The model's strength from one robot to another; empty when {@code to} is not registered. */
    OptionalDouble signalStrength(String from, String to) {
        synchronized (lock) {
            if (!robots.containsKey(to)) {
                return OptionalDouble.empty();
            }
        }
        try {
            return OptionalDouble.of(model.getSignalStrengthForPair(from, to));
        } catch (RuntimeException e) {
            LOG.log(Level.WARNING, model.name() + " failed to give the strength " + from + " -> " + to + ": " + e, e);
            return OptionalDouble.of(Double.NaN);
        }
    }

    /** The WSS port for connections from {@code from} to {@code to} on {@code targetPort} (0: the first). */
    DnsResult dns(String from, String to, int targetPort) {
        if (from.equals(to)) {
            return new DnsResult(DnsOutcome.NO_SUCH_ROBOT, -1);
        }
        boolean allowed = modelAllows(from, to);
        DnsResult result = dnsLocked(from, to, targetPort, allowed);
        deliverEvents();
        return result;
    }

    private DnsResult dnsLocked(String from, String to, int targetPort, boolean allowed) {
        synchronized (lock) {
            RegisteredRobot target = robots.get(to);
            if (closed || !robots.containsKey(from) || target == null) {
                return new DnsResult(DnsOutcome.NO_SUCH_ROBOT, -1);
            }
            int resolved = target.resolvePort(targetPort);
            if (resolved < 0) {
                return new DnsResult(DnsOutcome.NO_SUCH_TARGET_PORT, -1);
            }
            PortKey key = new PortKey(from, to, resolved);
            pairStats(key.pair());
            WssPort port = ports.get(key);
            if (port == null) {
                long held = ports.fromCount(from);
                InetAddress fromAddress = robots.get(from).address();
                if (held >= config.maxPortsPerRobot()) {
                    pendingEvents.add(() -> warnings.warn(LOG, "DNS beyond the port limit", fromAddress, from + " holds " + held
                            + " WSS ports as source, the most wss.maxPortsPerRobot allows; no new one for " + key));
                    return new DnsResult(DnsOutcome.NO_PORT, -1);
                }
                try {
                    port = WssPort.allocate(this, key, config.bindAddress(), shouldListen(key, allowed));
                } catch (IOException e) {
                    pendingEvents.add(() -> warnings.warn(LOG, "ports not allocated", fromAddress,
                            "could not allocate a WSS port for " + key + ": " + e.getMessage()));
                    return new DnsResult(DnsOutcome.NO_PORT, -1);
                }
                ports.add(port);
                String allocated = "allocated " + port + (port.listening() ? "" : ", not listening");
                pendingEvents.add(() -> LOG.info(allocated));
                int number = port.number;
                boolean listening = port.listening();
                pendingEvents.add(() -> events.portAllocated(from, to, key.targetPort(), number, listening));
            } else if (!port.listening() && shouldListen(key, allowed)) {
                listen(port);
            }
            return new DnsResult(DnsOutcome.OK, port.number);
        }
    }

    /** The source robot of the link whose outgoing port {@code port} leads to {@code asker}, or null. */
    String reverseDns(String asker, int port) {
        synchronized (lock) {
            for (WssPort wssPort : ports.of(asker)) {
                if (wssPort.key.to().equals(asker) && wssPort.hasLinkFrom(port)) {
                    return wssPort.key.from();
                }
            }
            return null;
        }
    }

    // ---- called by the port listeners and links ----

    /**
     * A connection arrived on a WSS port: forward it, or close it at once and say why. The link's
     * sockets and selector are opened without the lock, between a first check of the rules
     * (a refused connection opens nothing) and a second one, under which the link is committed
     * to the port. A robot that left or came back in between has stopped the port's listener, so
     * {@code listensWith} then fails, and the target's address read at the first check still holds.
     */
    void accepted(WssPort port, PortListener listener, SocketChannel socket) {
        PortKey key = port.key;
        InetAddress peer = socket.socket().getInetAddress();
        boolean allowed = modelAllows(key.from(), key.to());
        String refusal;
        InetSocketAddress targetAddress = null;
        PairStats pairStats = null;
        synchronized (lock) {
            refusal = refusal(port, listener, peer, allowed);
            if (refusal == null) {
                targetAddress = new InetSocketAddress(robots.get(key.to()).address(), key.targetPort());
                pairStats = pairStats(key.pair());
            }
        }
        if (refusal != null) {
            refuse(port, socket, peer, refusal);
            return;
        }
        Link link;
        try {
            link = new Link(this, port, socket, targetAddress, config.chunkSize(), socketBuffers, events, pairStats);
        } catch (IOException e) {
            warnings.warn(LOG, "connections not forwarded", peer, port + ": could not open a socket to the target: " + e.getMessage());
            Closing.quietly(socket);
            return;
        }
        synchronized (lock) {
            refusal = refusal(port, listener, peer, allowed);
            if (refusal == null) {
                port.addLink(link);
            }
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
                port.removeLink(link);
            }
            link.discard();
            throw e;
        }
    }

    /** Why a connection on the port cannot be forwarded now, or null when it can. Under the lock. */
    private String refusal(WssPort port, PortListener listener, InetAddress peer, boolean allowed) {
        PortKey key = port.key;
        RegisteredRobot source = robots.get(key.from());
        if (closed || !port.listensWith(listener) || source == null || !robots.containsKey(key.to())) {
            return "the port no longer listens";
        }
        if (config.matchSourceAddress() && !peer.equals(source.address())) {
            return "the connection came from " + peer.getHostAddress() + " but " + key.from()
                    + " registered from " + source.address().getHostAddress();
        }
        if (!forcedPairs.allows(key.pair(), allowed && !broken.contains(key.pair()))) {
            return forcedPairs.of(key.pair()) == Force.DOWN ? key.pair() + " is forced down"
                    : model.name() + " does not allow " + key.from() + " -> " + key.to() + " now";
        }
        return null;
    }

    private void refuse(WssPort port, SocketChannel socket, InetAddress peer, String refusal) {
        warnings.warn(LOG, "refused connections", peer, port + ": refused a connection: " + refusal);
        Closing.quietly(socket);
    }

    void linkEstablished(Link link) {
        PortKey key = link.port.key;
        events.connectionEstablished(key.from(), key.to(), key.targetPort());
    }

    /**
     * The link's end goes out with the hub's ordered events: after those of the change that closed
     * it (a force, a break, a kick), even while another thread is still delivering them.
     */
    void linkClosed(Link link, boolean wasEstablished) {
        PortKey key = link.port.key;
        synchronized (lock) {
            link.port.removeLink(link);
            if (wasEstablished) {
                pendingEvents.add(() -> events.connectionTerminated(key.from(), key.to(), key.targetPort()));
            }
            // A port kept only for its last connection is forgotten with it.
            for (String robot : List.of(link.port.key.from(), link.port.key.to())) {
                if (!link.port.hasLinks() && !robots.containsKey(robot) && memory.expired(robot)) {
                    forgetPortsOf(robot);
                }
            }
        }
        deliverEvents();
    }

    // ---- RobotLinkModel: called by the model ----

    @Override
    public boolean breakConnectionsForPair(String robotA, String robotB) {
        RobotPair pair = RobotPair.of(robotA, robotB);
        List<Link> links = new ArrayList<>();
        boolean changed;
        synchronized (lock) {
            PairStats pairStats = pairStats(pair); // first seen now: seen up until this break
            changed = broken.add(pair);
            if (changed) {
                pairStats.modelChanged(true);
                recordState(pair, true);
            }
            // Forced up: the break is only remembered, for the release.
            for (WssPort port : forcedPairs.of(pair) == Force.UP ? List.<WssPort>of() : ports.between(pair)) {
                if (port.stopListening()) {
                    changed = true;
                    pendingEvents.add(listeningEvent(port));
                }
                links.addAll(port.links());
            }
        }
        closeLinks(links, CloseReason.OUT_OF_RANGE);
        deliverEvents();
        return changed || !links.isEmpty();
    }

    @Override
    public boolean resumeConnectionsForPair(String robotA, String robotB) {
        RobotPair pair = RobotPair.of(robotA, robotB);
        boolean changed;
        synchronized (lock) {
            PairStats pairStats = pairStats(pair);
            changed = broken.remove(pair);
            if (changed) {
                pairStats.modelChanged(false);
                recordState(pair, true);
            }
            for (WssPort port : ports.between(pair)) {
                if (!port.listening() && shouldListen(port.key, true)) {
                    changed |= listen(port);
                }
            }
        }
        deliverEvents();
        return changed;
    }

    @Override
    public void kickOutRobot(String name) {
        RegisteredRobot robot;
        List<Link> links = new ArrayList<>();
        synchronized (lock) {
            robot = robots.remove(name);
            lock.notifyAll();
            if (robot != null) {
                pendingEvents.add(() -> events.robotDeregistered(name));
            }
            for (WssPort port : ports.of(name)) {
                port.release();
                links.addAll(port.links());
                ports.remove(port);
                pendingEvents.add(forgottenEvent(port));
            }
            stats.left(name, System.nanoTime());
            broken.removeIf(pair -> pair.contains(name));
            memory.clear(name);
            if (memory.left(name)) { // its pairs' statistics are remembered as long as its ports would have been
                forgetPortsOf(name);
            }
        }
        closeLinks(links, CloseReason.KICKED);
        if (robot != null) {
            robot.session().close();
            LOG.info("kicked out " + name);
        }
        deliverEvents();
    }

    @Override
    public List<String> getListOfRegisteredRobots() {
        synchronized (lock) {
            return robots.keySet().stream().sorted().toList();
        }
    }

    // ---- forced pairs: an operator's hand on the switch (issue 12) ----

    /**
     * Forces the pair down or up: a forced state wins over the model's verdict until
     * {@link #release} ({@link ForcedPairs}). Forced down stops the pair's ports and closes its
     * connections as a break does, and the model's resume does not reopen them; forced up lets
     * them listen (where both robots are registered) and forwards their connections whatever the
     * model breaks or forbids. The names need not be registered: the state holds for the pair
     * whenever its robots come, leave and come back.
     *
     * @throws IllegalArgumentException when the names are empty or the same
     */
    public void force(String robotA, String robotB, Force force) {
        RobotPair pair = pairOf(robotA, robotB);
        Objects.requireNonNull(force, "force");
        List<Link> links = new ArrayList<>();
        synchronized (lock) {
            Force before = forcedPairs.force(pair, force);
            if (before != force) {
                pendingEvents.add(() -> events.pairForced(pair.first(), pair.second(), force == Force.UP));
            }
            for (WssPort port : ports.between(pair)) {
                followVerdict(port, force == Force.UP, links);
            }
            recordState(pair, false);
        }
        closeLinks(links, CloseReason.FORCED);
        deliverEvents();
    }

    /**
     * Gives the pair back to the model: its verdict counts again at once. That verdict is the
     * model's last break or resume of the pair, and {@code connectionIsPossibleForPair} asked now
     * for each direction: a direction it broke or forbids stops listening and its connections
     * close; one it allows listens again (where both robots are registered).
     */
    public void release(String robotA, String robotB) {
        RobotPair pair = pairOf(robotA, robotB);
        boolean firstToSecond = modelAllows(pair.first(), pair.second());
        boolean secondToFirst = modelAllows(pair.second(), pair.first());
        List<Link> links = new ArrayList<>();
        synchronized (lock) {
            Force before = forcedPairs.release(pair);
            if (before != null) {
                pendingEvents.add(() -> events.pairReleased(pair.first(), pair.second()));
            }
            for (WssPort port : before == null ? List.<WssPort>of() : ports.between(pair)) {
                boolean allowed = port.key.from().equals(pair.first()) ? firstToSecond : secondToFirst;
                followVerdict(port, allowed && !broken.contains(pair), links);
            }
            recordState(pair, true);
        }
        closeLinks(links, CloseReason.OUT_OF_RANGE);
        deliverEvents();
    }

    /**
     * Under the lock: a port of a pair just forced or released follows the verdict at once. Not
     * talking, it stops listening and its links go to {@code links}, to be closed after the lock;
     * talking, it listens again where both robots are registered.
     */
    private void followVerdict(WssPort port, boolean talks, List<Link> links) {
        if (!talks) {
            if (port.stopListening()) {
                pendingEvents.add(listeningEvent(port));
            }
            links.addAll(port.links());
        } else if (!port.listening() && shouldListen(port.key, true)) {
            listen(port);
        }
    }

    /** The pair's forced state, or null when the model decides it (for the tests; the window and the log read it in the pairs' states). */
    Force forced(RobotPair pair) {
        synchronized (lock) {
            return forcedPairs.of(pair);
        }
    }

    private static RobotPair pairOf(String robotA, String robotB) {
        if (robotA == null || robotB == null || robotA.isEmpty() || robotB.isEmpty() || robotA.equals(robotB)) {
            throw new IllegalArgumentException("a pair is two different robot names, not '" + robotA + "' and '" + robotB + "'");
        }
        return RobotPair.of(robotA, robotB);
    }

    /** The robots, the WSS ports and the established links, all at one instant. */
    public HubSnapshot snapshot() {
        List<HubSnapshot.RobotEntry> robotEntries = new ArrayList<>();
        List<HubSnapshot.PortEntry> portEntries = new ArrayList<>();
        List<HubSnapshot.LinkEntry> linkEntries = new ArrayList<>();
        List<PairStats> pairStats;
        synchronized (lock) {
            pairStats = stats.all();
            for (RegisteredRobot robot : robots.values()) {
                robotEntries.add(new HubSnapshot.RobotEntry(robot.name(), robot.address().getHostAddress(), robot.ports()));
            }
            for (WssPort port : ports.all()) {
                PortKey key = port.key;
                portEntries.add(new HubSnapshot.PortEntry(key.from(), key.to(), key.targetPort(), port.number, port.listening()));
                for (Link link : port.links()) {
                    if (link.isEstablished() && !link.isClosed()) {
                        linkEntries.add(new HubSnapshot.LinkEntry(key.from(), key.to(), key.targetPort(), port.number,
                                link.outgoingPort()));
                    }
                }
            }
        }
        robotEntries.sort(Comparator.comparing(HubSnapshot.RobotEntry::name));
        portEntries.sort(Comparator.comparing(HubSnapshot.PortEntry::from).thenComparing(HubSnapshot.PortEntry::to)
                .thenComparingInt(HubSnapshot.PortEntry::targetPort));
        linkEntries.sort(Comparator.comparing(HubSnapshot.LinkEntry::from).thenComparing(HubSnapshot.LinkEntry::to)
                .thenComparingInt(HubSnapshot.LinkEntry::targetPort).thenComparingInt(HubSnapshot.LinkEntry::outgoingPort));
        return new HubSnapshot(robotEntries, portEntries, linkEntries, pairEntries(pairStats));
    }

    /** The pairs' statistics, sorted by pair; the model is asked for strengths and positions here, without the lock. */
    private List<HubSnapshot.PairEntry> pairEntries(List<PairStats> pairStats) {
        long now = System.nanoTime();
        List<HubSnapshot.PairEntry> entries = new ArrayList<>();
        for (PairStats pair : pairStats) {
            String first = pair.pair.first();
            String second = pair.pair.second();
            double[] rates = pair.rates(now);
            CloseReason lastClose = pair.lastClose();
            entries.add(new HubSnapshot.PairEntry(first, second, pair.state(), strength(first, second), distance(first, second),
                    pair.bytesFirstToSecond(), pair.bytesSecondToFirst(), rates[0], rates[1], pair.connections(),
                    pair.breaks(), pair.resumes(), pair.upShare(now), lastClose == null ? null : lastClose.toString()));
        }
        entries.sort(Comparator.comparing(HubSnapshot.PairEntry::first).thenComparing(HubSnapshot.PairEntry::second));
        return entries;
    }

    private double strength(String first, String second) {
        try {
            return model.getSignalStrengthForPair(first, second);
        } catch (RuntimeException e) {
            return Double.NaN; // a robot the model does not know (gone, say)
        }
    }

    /** The distance between the robots' positions, NaN unless the model knows both. */
    private double distance(String first, String second) {
        try {
            var a = model.positionOf(first);
            var b = model.positionOf(second);
            return a.isPresent() && b.isPresent() ? a.get().distanceTo(b.get()) : Double.NaN;
        } catch (RuntimeException e) {
            return Double.NaN;
        }
    }

    // ---- port memory ----

    /** The timer's call, wss.portMemory seconds after a robot left: forget its ports unless it came back. */
    private void forgetIfGone(String name) {
        synchronized (lock) {
            if (!closed && !robots.containsKey(name) && memory.expired(name)) {
                forgetPortsOf(name);
            }
        }
        deliverEvents();
    }

    /**
     * Under the lock: gives back the numbers of a gone robot's WSS ports, as source and as target,
     * but those with open connections, which are forgotten when their last connection closes. The
     * ports' events go to {@link #pendingEvents}.
     */
    private void forgetPortsOf(String name) {
        int forgotten = 0;
        boolean kept = false;
        for (WssPort port : ports.of(name)) {
            if (!port.hasLinks()) {
                port.release();
                ports.remove(port);
                pendingEvents.add(forgottenEvent(port));
                forgotten++;
            } else {
                kept = true;
            }
        }
        if (forgotten > 0) {
            String forgot = "forgot " + forgotten + " WSS port" + (forgotten == 1 ? "" : "s") + " of " + name + ", gone for "
                    + memory.goneSeconds(name) + " s";
            pendingEvents.add(() -> LOG.info(forgot));
        }
        if (!kept) {
            memory.clear(name);
        }
        stats.forget(name, pair -> ports.between(pair).isEmpty());
    }

    // ---- events ----

    /**
     * Delivers the pending events in order, never under the lock. One thread delivers at a time;
     * a thread that finds another delivering leaves its events to it, and the deliverer looks
     * again after letting go, so none is left behind. A listener that changes the hub from its
     * event (the delivering thread itself) leaves its events to the loop it is called from, which
     * delivers them after the rest of the batch it is in: the lock is reentrant, and delivering
     * them at once would put them before events that came first.
     */
    private void deliverEvents() {
        if (delivering.isHeldByCurrentThread()) {
            return;
        }
        while (delivering.tryLock()) {
            try {
                List<Runnable> batch;
                while (!(batch = takePendingEvents()).isEmpty()) {
                    batch.forEach(Runnable::run);
                }
            } finally {
                delivering.unlock();
            }
            synchronized (lock) {
                if (pendingEvents.isEmpty()) {
                    return;
                }
            }
        }
    }

    private List<Runnable> takePendingEvents() {
        synchronized (lock) {
            List<Runnable> batch = List.copyOf(pendingEvents);
            pendingEvents.clear();
            return batch;
        }
    }

    // ---- rules ----

    /** The pair's state now: an operator's force wins over the model's verdict. Under the lock. */
    private PairState stateOf(RobotPair pair) {
        Force force = forcedPairs.of(pair);
        if (force != null) {
            return force == Force.DOWN ? PairState.FORCED_DOWN : PairState.FORCED_UP;
        }
        return broken.contains(pair) ? PairState.BROKEN : PairState.UP;
    }

    /** The pair's statistics, from now on when it was not seen yet. Under the lock. */
    private PairStats pairStats(RobotPair pair) {
        return stats.of(pair, stateOf(pair), bothPresent(pair));
    }

    /**
     * Under the lock: records the state now of a pair seen (after a break, a resume, a force or a
     * release); with {@code say}, a change is logged, one line, delivered after the lock with the
     * events (a force says itself: the event's line "forced A - B down").
     */
    private void recordState(RobotPair pair, boolean say) {
        PairStats pairStats = stats.get(pair);
        PairState now = stateOf(pair);
        if (pairStats != null && pairStats.moveTo(now, bothPresent(pair), System.nanoTime()) && say) {
            pendingEvents.add(() -> LOG.info("pair " + pair.first() + " - " + pair.second() + ": " + now.text()));
        }
    }

    /** Whether both robots of the pair are registered. Under the lock. */
    private boolean bothPresent(RobotPair pair) {
        return robots.containsKey(pair.first()) && robots.containsKey(pair.second());
    }

    /** Closes the links after the lock, saying why (the last close their pairs' statistics show). */
    private static void closeLinks(List<Link> links, CloseReason reason) {
        links.forEach(link -> link.close(reason));
    }

    /**
     * A WSS port listens while both robots are registered, the target still accepts on the
     * target port, and the model neither broke nor forbids the pair, unless an operator forced
     * it ({@link ForcedPairs#allows}). Under the lock.
     */
    private boolean shouldListen(PortKey key, boolean modelAllows) {
        RegisteredRobot target = robots.get(key.to());
        return robots.containsKey(key.from()) && target != null && target.ports().contains(key.targetPort())
                && forcedPairs.allows(key.pair(), modelAllows && !broken.contains(key.pair()));
    }

    /** Under the lock; the port's event goes to {@link #pendingEvents}. @return true when it listens now */
    private boolean listen(WssPort port) {
        try {
            port.listen();
            pendingEvents.add(listeningEvent(port));
            return true;
        } catch (IOException e) {
            String why = port + ": could not listen again: " + e.getMessage();
            pendingEvents.add(() -> LOG.warning(why));
            return false;
        }
    }

    /** The event saying the port's number was given back, to be fired after the lock is released. Under the lock. */
    private Runnable forgottenEvent(WssPort port) {
        PortKey key = port.key;
        int number = port.number;
        return () -> events.portForgotten(key.from(), key.to(), key.targetPort(), number);
    }

    /** The event saying whether the port listens now, to be fired after the lock is released. Under the lock. */
    private Runnable listeningEvent(WssPort port) {
        PortKey key = port.key;
        int number = port.number;
        boolean listening = port.listening();
        return () -> events.portListening(key.from(), key.to(), key.targetPort(), number, listening);
    }

    private boolean modelAllows(String from, String to) {
        try {
            return model.connectionIsPossibleForPair(from, to);
        } catch (RuntimeException e) {
            LOG.log(Level.WARNING, model.name() + " failed to say whether " + from + " -> " + to + " may connect: " + e, e);
            return false;
        }
    }
}
