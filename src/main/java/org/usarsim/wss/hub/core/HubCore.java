package org.usarsim.wss.hub.core;

import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.atomic.AtomicReference;
import java.util.logging.Level;
import org.usarsim.wss.model.LinkQuality;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.shaping.ShapingConfig;

/**
 * The hub's rules and state, without sockets or threads: the registered robots, the WSS ports and
 * whether each listens, the pairs the model broke and those an operator forced, the robots that
 * are leaving, the per-pair statistics and the port memory. Every method is one step: it changes
 * the state and appends what must happen because of it to a {@link Changes} (events, port work,
 * connections to close), which the hub applies after its lock. The time comes in with each step
 * that needs it ({@code nowNs}, as {@link System#nanoTime()}), so tests move it by hand.
 *
 * <p>Single-threaded: the hub calls it under its lock only. What the model answers
 * ({@code connectionIsPossibleForPair}) is asked by the hub before the step and passed in, since
 * a model may call back into the hub.
 */
public final class HubCore {

    /** The outcome of a DNS. */
    public enum DnsOutcome { OK, NO_SUCH_ROBOT, NO_SUCH_TARGET_PORT, NO_PORT, NEEDS_NUMBER }

    /**
     * A DNS's answer: the port's number when OK; the key of a port to allocate when
     * NEEDS_NUMBER; {@code numberUsed} when the number the hub offered is the port's now.
     */
    public record DnsResult(DnsOutcome outcome, int port, PortKey key, boolean numberUsed) {
        static DnsResult of(DnsOutcome outcome) {
            return new DnsResult(outcome, -1, null, false);
        }
    }

    /** Whether a name is free for a registration. */
    public enum NameCheck { REGISTERED, TAKEN, TAKEN_BY_LEAVING, CLOSED }

    /**
     * Whether a connection accepted on a WSS port may be forwarded: null refusal, where to, the
     * pair's counters, and its live conditions each way (from the port's source to its target: {@code up}).
     */
    public record Admission(String refusal, InetSocketAddress target, PairStats stats,
            AtomicReference<PairCondition> up, AtomicReference<PairCondition> down) {
    }

    private final String modelName;
    private final boolean matchSourceAddress;
    private final int maxPortsPerRobot;
    private final int maxPortsPerAddress;
    private final Map<String, RegisteredRobot> robots = new HashMap<>();
    private final Ports ports = new Ports();
    /** Pairs the model broke and has not resumed. */
    private final Set<RobotPair> broken = new HashSet<>();
    /** Pairs an operator forced down or up: they win over {@link #broken} and the model's answers. */
    private final ForcedPairs forcedPairs = new ForcedPairs();
    /** The control connections whose robots are leaving: their ports drain, their names are freed soon. */
    private final Set<RobotSession> leaving = new HashSet<>();
    /** The statistics of every pair seen, forgotten with the pair's ports. */
    private final PairStatsTable stats = new PairStatsTable();
    private final PortMemory memory;
    private final ShapingConfig shaping;
    /** What the model last said of each pair one way (with shaping on). */
    private final Map<OrderedPair, Measurement> measured = new HashMap<>();
    /**
     * Each seen pair's condition one way, the one value the link threads read as they forward
     * (a volatile cell each), the statistics and the snapshot too; recomputed by {@link #refresh}.
     */
    private final Map<OrderedPair, AtomicReference<PairCondition>> conditions = new HashMap<>();
    /** The ways whose rate the event log has been told (a RATE line): each is said once, then at each change. */
    private final Set<OrderedPair> said = new HashSet<>();
    /** Set by {@link #close}: nothing registers or listens any more. */
    private boolean closed;

    /**
     * @param modelName          the model's name, as a refusal says it
     * @param matchSourceAddress a connection on a WSS port is forwarded only from the source robot's control address
     * @param portMemorySeconds  how long the ports of a robot that left keep their numbers (0: not at all, -1: for ever)
     * @param maxPortsPerRobot   the most WSS ports one robot may hold as source
     */
    public HubCore(String modelName, boolean matchSourceAddress, int portMemorySeconds, int maxPortsPerRobot) {
        this(modelName, matchSourceAddress, portMemorySeconds, maxPortsPerRobot, ShapingConfig.OFF);
    }

    /** @param shaping how links are shaped (docs/shaping.md) */
    public HubCore(String modelName, boolean matchSourceAddress, int portMemorySeconds, int maxPortsPerRobot,
            ShapingConfig shaping) {
        this(modelName, matchSourceAddress, portMemorySeconds, maxPortsPerRobot, Integer.MAX_VALUE, shaping);
    }

    /** @param maxPortsPerAddress the most WSS ports the robots registered from one address may hold as source, together */
    public HubCore(String modelName, boolean matchSourceAddress, int portMemorySeconds, int maxPortsPerRobot,
            int maxPortsPerAddress, ShapingConfig shaping) {
        this.shaping = shaping;
        this.modelName = modelName;
        this.matchSourceAddress = matchSourceAddress;
        this.maxPortsPerRobot = maxPortsPerRobot;
        this.maxPortsPerAddress = maxPortsPerAddress;
        this.memory = new PortMemory(portMemorySeconds);
    }

    // ---- robots ----

    /** Registers the robot unless its name is taken (or the hub closed); its ports that should listen again do. */
    public NameCheck register(RegisteredRobot robot, long nowNs, Changes out) {
        if (closed) {
            return NameCheck.CLOSED;
        }
        RegisteredRobot holder = robots.get(robot.name());
        if (holder != null) {
            return leaving.contains(holder.session()) ? NameCheck.TAKEN_BY_LEAVING : NameCheck.TAKEN;
        }
        String name = robot.name();
        robots.put(name, robot);
        out.add(new HubEvent.Registered(name, robot.address().getHostAddress(), robot.ports()));
        memory.clear(name);
        // A kick forgot the model's breaks of the robot's pairs: their statistics follow the state they are in now.
        stats.pairsOf(name).forEach(pair -> recordState(pair, true, nowNs, out));
        for (WssPort port : ports.of(name)) {
            if (!port.listening() && shouldListen(port.key, true)) {
                listen(port, out);
            }
        }
        return NameCheck.REGISTERED;
    }

    /**
     * The robot's control connection closed: it begins to leave. Its name stays taken until
     * {@link #left}; meanwhile the hub drains the ports returned here.
     *
     * @return the ports that listen now, to drain; null when the session is not the robot's
     */
    public List<WssPort> beginLeaving(String name, RobotSession session) {
        if (!isSessionOf(name, session)) {
            return null;
        }
        leaving.add(session);
        return ports.of(name).stream().filter(WssPort::listening).toList();
    }

    /** The robot's ports have drained: it is gone, its ports stop listening, its links live on. */
    public void left(String name, RobotSession session, long nowNs, Changes out) {
        leaving.remove(session);
        if (!isSessionOf(name, session)) {
            return; // kicked out meanwhile
        }
        robots.remove(name);
        out.add(new HubEvent.Deregistered(name));
        stats.left(name, nowNs);
        for (WssPort port : ports.of(name)) {
            stopListening(port, out);
        }
        remember(name, nowNs, out);
    }

    /** The model kicked the robot out: its ports are given back at once, its links closed, its control connection closed. */
    public void kick(String name, long nowNs, Changes out) {
        RegisteredRobot robot = robots.remove(name);
        if (robot != null) {
            out.add(new HubEvent.Deregistered(name));
        }
        for (WssPort port : ports.of(name)) {
            out.port(Changes.PortWork.RELEASE, port);
            port.stopListening();
            out.close(port.links(), CloseReason.KICKED);
            ports.remove(port);
            out.add(new HubEvent.PortForgotten(port.key, port.number));
        }
        stats.left(name, nowNs);
        broken.removeIf(pair -> pair.contains(name));
        memory.clear(name);
        remember(name, nowNs, out); // its pairs' statistics are remembered as long as its ports would have been
        if (robot != null) {
            out.closeSession(robot.session());
            out.add(new HubEvent.Said(Level.INFO, "kicked out " + name));
        }
    }

    /** A robot left: its ports are forgotten now (wss.portMemory = 0) or later. */
    private void remember(String name, long nowNs, Changes out) {
        if (memory.left(name, nowNs)) {
            forgetPortsOf(name, nowNs, out);
        } else if (!memory.never()) {
            out.forgetLater(name, memory.memoryNs());
        }
    }

    /** The hub's timer, wss.portMemory after a robot left: forget its ports unless it came back. */
    public void forgetIfGone(String name, long nowNs, Changes out) {
        if (!closed && !robots.containsKey(name) && memory.expired(name, nowNs)) {
            forgetPortsOf(name, nowNs, out);
        }
    }

    public boolean isRegistered(String name) {
        return robots.containsKey(name);
    }

    /** Whether this control connection is the one the robot registered with now. */
    public boolean isSessionOf(String name, RobotSession session) {
        RegisteredRobot robot = robots.get(name);
        return robot != null && robot.session() == session;
    }

    /** The registered robots' names, sorted. */
    public List<String> robotNames() {
        return robots.keySet().stream().sorted().toList();
    }

    public List<RegisteredRobot> robots() {
        return List.copyOf(robots.values());
    }

    // ---- DNS and REVERSEDNS ----

    /**
     * The WSS port for connections from {@code from} to {@code to} on {@code targetPort} (0: the
     * first). A new port needs a number the hub binds without its lock: without {@code newNumber}
     * (-1) the answer is then NEEDS_NUMBER; asked again with one, the port is allocated with it,
     * unless another DNS did meanwhile (then {@code numberUsed} is false and the hub gives it back).
     *
     * @param allowed the model's {@code connectionIsPossibleForPair(from, to)}
     */
    public DnsResult dns(String from, String to, int targetPort, boolean allowed, int newNumber, long nowNs, Changes out) {
        RegisteredRobot target = robots.get(to);
        if (closed || from.equals(to) || !robots.containsKey(from) || target == null) {
            return DnsResult.of(DnsOutcome.NO_SUCH_ROBOT);
        }
        int resolved = target.resolvePort(targetPort);
        if (resolved < 0) {
            return DnsResult.of(DnsOutcome.NO_SUCH_TARGET_PORT);
        }
        PortKey key = new PortKey(from, to, resolved);
        seen(key.pair(), nowNs, out);
        WssPort port = ports.get(key);
        if (port != null) {
            if (!port.listening() && shouldListen(key, allowed)) {
                listen(port, out);
            }
            return new DnsResult(DnsOutcome.OK, port.number, key, false);
        }
        InetAddress address = robots.get(from).address();
        int held = ports.fromCount(from);
        if (held >= maxPortsPerRobot) {
            out.add(new HubEvent.Warned("DNS beyond the port limit", address, from + " holds " + held
                    + " WSS ports as source, the most wss.maxPortsPerRobot allows; no new one for " + key));
            return DnsResult.of(DnsOutcome.NO_PORT);
        }
        long heldFromAddress = heldFrom(address);
        if (heldFromAddress >= maxPortsPerAddress) {
            out.add(new HubEvent.Warned("DNS beyond the address limit", address, "the robots registered from "
                    + address.getHostAddress() + " hold " + heldFromAddress
                    + " WSS ports as source, the most wss.maxPortsPerAddress allows; no new one for " + key));
            return DnsResult.of(DnsOutcome.NO_PORT);
        }
        if (newNumber < 0) {
            return new DnsResult(DnsOutcome.NEEDS_NUMBER, -1, key, false);
        }
        port = new WssPort(key, newNumber);
        ports.add(port);
        boolean listens = shouldListen(key, allowed);
        if (listens) {
            port.listen();
            out.port(Changes.PortWork.LISTEN, port);
        }
        out.add(new HubEvent.Said(Level.INFO, "allocated " + port + (listens ? "" : ", not listening")));
        out.add(new HubEvent.PortAllocated(key, port.number, listens));
        return new DnsResult(DnsOutcome.OK, port.number, key, true);
    }

    /**
     * The WSS ports held as source by the robots registered from the address now: what
     * wss.maxPortsPerAddress caps, so that one client cannot take every descriptor by registering
     * many names. Ports of robots that left are not counted: they give their descriptors back when
     * descriptors run short ({@link #giveBackRemembered}).
     */
    private long heldFrom(InetAddress address) {
        long held = 0;
        for (RegisteredRobot robot : robots.values()) {
            if (robot.address().equals(address)) {
                held += ports.fromCount(robot.name());
            }
        }
        return held;
    }

    /** A DNS's port could not be bound: said as the WARNING its client caused. */
    public void couldNotAllocate(PortKey key, String why, Changes out) {
        RegisteredRobot from = robots.get(key.from());
        if (from != null) {
            out.add(new HubEvent.Warned("ports not allocated", from.address(), "could not allocate a WSS port for " + key + ": " + why));
        }
    }

    /** The source robot of the link whose outgoing port {@code port} leads to {@code asker}, or null. */
    public String reverseDns(String asker, int port) {
        for (WssPort wssPort : ports.of(asker)) {
            if (wssPort.key.to().equals(asker) && wssPort.hasLinkFrom(port)) {
                return wssPort.key.from();
            }
        }
        return null;
    }

    // ---- connections on WSS ports ----

    /**
     * Whether a connection that a listener of {@code epoch} accepted on the port may be forwarded:
     * asked before the hub opens the link's sockets (a refused one opens nothing).
     *
     * @param allowed the model's {@code connectionIsPossibleForPair(from, to)}
     */
    public Admission admit(WssPort port, int epoch, InetAddress peer, boolean allowed, long nowNs, Changes out) {
        PortKey key = port.key;
        String refusal = refusal(port, epoch, peer, allowed);
        if (refusal != null) {
            return new Admission(refusal, null, null, null, null);
        }
        InetSocketAddress target = new InetSocketAddress(robots.get(key.to()).address(), key.targetPort());
        PairStats pairStats = seen(key.pair(), nowNs, out);
        OrderedPair up = new OrderedPair(key.from(), key.to());
        return new Admission(null, target, pairStats, conditions.get(up), conditions.get(up.reversed()));
    }

    /** Asked again once the link's sockets are open: commits the link to the port, or says why not. */
    public String commit(WssPort port, int epoch, InetAddress peer, boolean allowed, Connection link) {
        String refusal = refusal(port, epoch, peer, allowed);
        if (refusal == null) {
            port.addLink(link);
        }
        return refusal;
    }

    /** Why a connection on the port cannot be forwarded now, or null when it can. */
    private String refusal(WssPort port, int epoch, InetAddress peer, boolean allowed) {
        PortKey key = port.key;
        RegisteredRobot source = robots.get(key.from());
        if (closed || ports.get(key) != port || !port.listensWith(epoch) || source == null || !robots.containsKey(key.to())) {
            return "the port no longer listens";
        }
        if (matchSourceAddress && !peer.equals(source.address())) {
            return "the connection came from " + peer.getHostAddress() + " but " + key.from()
                    + " registered from " + source.address().getHostAddress();
        }
        if (!forcedPairs.allows(key.pair(), allowed && !broken.contains(key.pair()))) {
            return forcedPairs.of(key.pair()) == Force.DOWN ? key.pair() + " is forced down"
                    : modelName + " does not allow " + key.from() + " -> " + key.to() + " now";
        }
        return null;
    }

    /** A link whose thread could not start: it never was. */
    public void uncommit(WssPort port, Connection link) {
        port.removeLink(link);
    }

    /**
     * The link's thread ended. Its end goes out with the ordered events: after those of the change
     * that closed it (a force, a break, a kick). A port kept only for its last connection is
     * forgotten with it.
     */
    public void linkEnded(WssPort port, Connection link, boolean wasEstablished, long nowNs, Changes out) {
        port.removeLink(link);
        if (wasEstablished) {
            out.add(new HubEvent.Terminated(port.key));
        }
        for (String robot : List.of(port.key.from(), port.key.to())) {
            if (!port.hasLinks() && !robots.containsKey(robot) && memory.expired(robot, nowNs)) {
                forgetPortsOf(robot, nowNs, out);
            }
        }
    }

    /** The port for the key now, or null. */
    public WssPort port(PortKey key) {
        return ports.get(key);
    }

    /** A port's listener could not bind: the port does not listen after all. */
    public void couldNotListen(WssPort port, int epoch, String why, Changes out) {
        if (ports.get(port.key) == port && port.listensWith(epoch)) {
            port.stopListening();
            out.add(new HubEvent.PortListening(port.key, port.number, false));
        }
        out.add(new HubEvent.Said(Level.WARNING, port + ": could not listen again: " + why));
    }

    public List<WssPort> ports() {
        return List.copyOf(ports.all());
    }

    // ---- the model's verdicts ----

    /** The model broke the pair. @return whether anything changed (the pair, a port, a connection) */
    public boolean breakPair(RobotPair pair, long nowNs, Changes out) {
        PairStats pairStats = seen(pair, nowNs, out); // first seen now: seen up until this break
        boolean changed = broken.add(pair);
        if (changed) {
            pairStats.modelChanged(true);
            recordState(pair, true, nowNs, out);
        }
        // Forced up: the break is only remembered, for the release.
        for (WssPort port : forcedPairs.of(pair) == Force.UP ? List.<WssPort>of() : ports.between(pair)) {
            changed |= stopListening(port, out);
            changed |= port.hasLinks();
            out.close(port.links(), CloseReason.OUT_OF_RANGE);
        }
        return changed;
    }

    /** The model resumed the pair. @return whether anything changed */
    public boolean resumePair(RobotPair pair, long nowNs, Changes out) {
        PairStats pairStats = seen(pair, nowNs, out);
        boolean changed = broken.remove(pair);
        if (changed) {
            pairStats.modelChanged(false);
            recordState(pair, true, nowNs, out);
        }
        for (WssPort port : ports.between(pair)) {
            if (!port.listening() && shouldListen(port.key, true)) {
                listen(port, out);
                changed = true;
            }
        }
        return changed;
    }

    // ---- forced pairs: an operator's hand on the switch ----

    /** Forces the pair down or up ({@link ForcedPairs}); the names need not be registered. */
    public void force(RobotPair pair, Force force, long nowNs, Changes out) {
        force(pair, force, RatePin.NONE, nowNs, out);
    }

    /** Forces the pair, up with its rate and delay pinned (or not: {@link RatePin#NONE}). */
    public void force(RobotPair pair, Force force, RatePin pin, long nowNs, Changes out) {
        boolean pinned = forcedPairs.pin(pair, force == Force.UP ? pin : RatePin.NONE);
        Force before = forcedPairs.force(pair, force);
        if (before != force || pinned) { // a new rate or delay for a pair forced up is a force that changed something
            out.add(new HubEvent.PairForced(pair.first(), pair.second(), force == Force.UP));
        }
        for (WssPort port : ports.between(pair)) {
            followVerdict(port, force == Force.UP, CloseReason.FORCED, out);
        }
        recordState(pair, false, nowNs, out);
    }

    /**
     * Gives the pair back to the model: its verdict counts again at once, the model's last break or
     * resume and what it answers now for each direction ({@code firstToSecond}, {@code secondToFirst}).
     */
    public void release(RobotPair pair, boolean firstToSecond, boolean secondToFirst, long nowNs, Changes out) {
        Force before = forcedPairs.release(pair);
        if (before != null) {
            out.add(new HubEvent.PairReleased(pair.first(), pair.second()));
            for (WssPort port : ports.between(pair)) {
                boolean allowed = port.key.from().equals(pair.first()) ? firstToSecond : secondToFirst;
                followVerdict(port, allowed && !broken.contains(pair), CloseReason.OUT_OF_RANGE, out);
            }
        }
        recordState(pair, true, nowNs, out);
    }

    /** The pair's forced state, or null when the model decides it. */
    public Force forced(RobotPair pair) {
        return forcedPairs.of(pair);
    }

    /**
     * A port of a pair just forced or released follows the verdict at once: not talking, it stops
     * listening and its links close; talking, it listens again where both robots are registered.
     */
    private void followVerdict(WssPort port, boolean talks, CloseReason reason, Changes out) {
        if (!talks) {
            stopListening(port, out);
            out.close(port.links(), reason);
        } else if (!port.listening() && shouldListen(port.key, true)) {
            listen(port, out);
        }
    }

    // ---- statistics ----

    /** The statistics of every pair seen. */
    public List<PairStats> pairStats() {
        return stats.all();
    }

    // ---- the end ----

    /** The hub stops: every port is given back and every connection closed. */
    public void close(Changes out) {
        closed = true;
        for (WssPort port : ports.all()) {
            out.port(Changes.PortWork.RELEASE, port);
            port.stopListening();
            out.close(port.links(), CloseReason.SERVER_STOPPED);
        }
        ports.clear();
        robots.clear();
    }

    public boolean isClosed() {
        return closed;
    }

    // ---- rules ----

    /** The pair's state now: an operator's force wins over the model's verdict. */
    private PairState stateOf(RobotPair pair) {
        Force force = forcedPairs.of(pair);
        if (force != null) {
            return force == Force.DOWN ? PairState.FORCED_DOWN : PairState.FORCED_UP;
        }
        return broken.contains(pair) ? PairState.BROKEN : PairState.UP;
    }

    /**
     * The pair's statistics, from now on when it was not seen yet; its conditions both ways too
     * (their rates said, with shaping on).
     */
    private PairStats seen(RobotPair pair, long nowNs, Changes out) {
        for (OrderedPair way : ways(pair)) {
            if (!conditions.containsKey(way)) {
                PairCondition condition = conditionOf(way);
                conditions.put(way, new AtomicReference<>(condition));
                if (condition.shaped() && measured.containsKey(way)) { // otherwise said at the first measurement
                    said.add(way);
                    out.add(new HubEvent.RateChanged(way, condition.bitsPerSecond()));
                }
            }
        }
        return stats.of(pair, stateOf(pair), bothPresent(pair), nowNs);
    }

    private static List<OrderedPair> ways(RobotPair pair) {
        OrderedPair way = new OrderedPair(pair.first(), pair.second());
        return List.of(way, way.reversed());
    }

    /**
     * The one place a pair's condition one way is computed: its state (a force wins over the
     * model's verdict), and with shaping on its rate and delay: an operator's pin wins, then what
     * the model says of the link ({@code linkQualityForPair}), then the rate table for the
     * model's strength and the delay setting.
     */
    private PairCondition conditionOf(OrderedPair way) {
        RobotPair pair = RobotPair.of(way.from(), way.to());
        PairState state = stateOf(pair);
        if (!shaping.on()) {
            return new PairCondition(state, 0, 0);
        }
        RatePin pin = forcedPairs.pinOf(pair);
        Measurement measurement = measured.getOrDefault(way, Measurement.NONE);
        long rate = pin.pinsRate() ? pin.bitsPerSecond()
                : measurement.quality().map(LinkQuality::bitsPerSecond).orElseGet(() -> shaping.rates().rateFor(measurement.strength()));
        int delay = pin.pinsDelay() ? pin.delayMs() : measurement.quality().map(LinkQuality::delayMs).orElse(shaping.delayMs());
        return new PairCondition(state, rate, delay);
    }

    /** Recomputes the pair's conditions both ways (those kept); a rate that changed is said. */
    private void refresh(RobotPair pair, Changes out) {
        for (OrderedPair way : ways(pair)) {
            AtomicReference<PairCondition> cell = conditions.get(way);
            if (cell != null) {
                PairCondition now = conditionOf(way);
                PairCondition before = cell.getAndSet(now);
                boolean firstSaid = measured.containsKey(way) && !said.contains(way);
                if (now.shaped() && (now.bitsPerSecond() != before.bitsPerSecond() || firstSaid)) {
                    said.add(way);
                    out.add(new HubEvent.RateChanged(way, now.bitsPerSecond()));
                }
            }
        }
    }

    /** With links shaped: the pairs whose strength the hub asks the model for, a few times a second. */
    public List<RobotPair> pairsToMeasure() {
        return conditions.keySet().stream().map(way -> RobotPair.of(way.from(), way.to())).distinct().toList();
    }

    /**
     * What the model said of these pairs, each way: their rates follow (the hub's sampler asks
     * a few times a second, a DNS before it allocates, so a new pair starts at its own rate).
     */
    public void measured(Map<OrderedPair, Measurement> measurements, Changes out) {
        measured.putAll(measurements);
        measurements.keySet().stream().map(way -> RobotPair.of(way.from(), way.to())).distinct().forEach(pair -> refresh(pair, out));
    }

    /** Every seen pair's condition one way, now. */
    public Map<OrderedPair, PairCondition> conditions() {
        Map<OrderedPair, PairCondition> now = new HashMap<>();
        conditions.forEach((way, cell) -> now.put(way, cell.get()));
        return now;
    }

    /**
     * Records the state now of a pair seen (after a break, a resume, a force or a release); with
     * {@code say}, a change is logged, one line (a force says itself: the event's line).
     */
    private void recordState(RobotPair pair, boolean say, long nowNs, Changes out) {
        refresh(pair, out);
        PairStats pairStats = stats.get(pair);
        PairState now = stateOf(pair);
        if (pairStats != null && pairStats.moveTo(now, bothPresent(pair), nowNs) && say) {
            out.add(new HubEvent.Said(Level.INFO, "pair " + pair.first() + " - " + pair.second() + ": " + now.text()));
        }
    }

    private boolean bothPresent(RobotPair pair) {
        return robots.containsKey(pair.first()) && robots.containsKey(pair.second());
    }

    /**
     * A WSS port listens while both robots are registered, the target still accepts on the
     * target port, and the model neither broke nor forbids the pair, unless an operator forced
     * it ({@link ForcedPairs#allows}).
     */
    private boolean shouldListen(PortKey key, boolean modelAllows) {
        RegisteredRobot target = robots.get(key.to());
        return !closed && robots.containsKey(key.from()) && target != null && target.ports().contains(key.targetPort())
                && forcedPairs.allows(key.pair(), modelAllows && !broken.contains(key.pair()));
    }

    private void listen(WssPort port, Changes out) {
        port.listen();
        out.port(Changes.PortWork.LISTEN, port);
        out.add(new HubEvent.PortListening(port.key, port.number, true));
    }

    /** @return true when it was listening */
    private boolean stopListening(WssPort port, Changes out) {
        if (!port.stopListening()) {
            return false;
        }
        out.port(Changes.PortWork.STOP, port);
        out.add(new HubEvent.PortListening(port.key, port.number, false));
        return true;
    }

    /**
     * Gives back the numbers of a gone robot's WSS ports, as source and as target, but those with
     * open connections, which are forgotten when their last connection closes.
     */
    private int forgetPortsOf(String name, long nowNs, Changes out) {
        int forgotten = 0;
        boolean kept = false;
        for (WssPort port : ports.of(name)) {
            if (!port.hasLinks()) {
                port.stopListening();
                out.port(Changes.PortWork.RELEASE, port);
                ports.remove(port);
                out.add(new HubEvent.PortForgotten(port.key, port.number));
                forgotten++;
            } else {
                kept = true;
            }
        }
        if (forgotten > 0) {
            out.add(new HubEvent.Said(Level.INFO, "forgot " + forgotten + " WSS port" + (forgotten == 1 ? "" : "s") + " of " + name
                    + ", gone for " + memory.goneSeconds(name, nowNs) + " s"));
        }
        if (!kept) {
            memory.clear(name);
        }
        stats.forget(name, pair -> ports.between(pair).isEmpty());
        conditions.keySet().removeIf(way -> (way.from().equals(name) || way.to().equals(name))
                && stats.get(RobotPair.of(way.from(), way.to())) == null);
        measured.keySet().retainAll(conditions.keySet());
        said.retainAll(conditions.keySet());
        return forgotten;
    }

    /**
     * Descriptors ran short: the remembered ports of robots that left are given back, the robot
     * gone longest first, a whole robot at a time, until at least {@code atLeast} were (or none is
     * left to give), whatever wss.portMemory says. A robot that is here never loses a port so.
     *
     * @return how many ports were given back
     */
    public int giveBackRemembered(int atLeast, long nowNs, Changes out) {
        int given = 0;
        int of = 0;
        for (String name : memory.longestGoneFirst()) {
            if (given >= atLeast) {
                break;
            }
            if (!robots.containsKey(name)) {
                int forgotten = forgetPortsOf(name, nowNs, out);
                given += forgotten;
                of += forgotten > 0 ? 1 : 0;
            }
        }
        if (given > 0) {
            out.add(new HubEvent.Said(Level.INFO, "descriptors ran short: gave back " + given + " remembered WSS port"
                    + (given == 1 ? "" : "s") + " of " + of + " robot" + (of == 1 ? "" : "s") + " that left, the longest gone first"));
        }
        return given;
    }
}
