package org.usarsim.wss.hub.core;

import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.logging.Level;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.shaping.ShapingConfig;

/**
 * The hub's rules and state, without sockets or threads: the registered robots and those leaving,
 * the WSS ports and whether each listens; with its parts, each a rule of its own: {@link Pairs}
 * (the model's breaks, an operator's forces, the statistics, the {@link PairConditions}),
 * {@link PortCaps}, {@link Admissions} and {@link PortForgetting} (the port memory, and the one
 * place a port is given back). Every method is one step: it changes
 * the state and appends what must happen because of it to a {@link Changes} (events, port work,
 * connections to close), which the hub applies after its lock. The time comes in with each step
 * that needs it ({@code nowNs}, the {@link HubClock}'s nanoseconds), so tests move it by hand.
 *
 * <p>Single-threaded: the hub calls it under its lock only. What the model answers
 * ({@code connectionIsPossibleForPair}) is asked by the hub before the step and passed in, since
 * a model may call back into the hub.
 */
public final class HubCore {

    private final PortCaps caps;
    private final Map<String, RegisteredRobot> robots = new HashMap<>();
    private final Ports ports = new Ports();
    /** The robots declared instead of registering (docs/fixed-ports.md): they never leave. */
    private final Set<String> declared = new HashSet<>();
    /** The fixed TCP ports: WSS ports made at Start, kept to Stop. */
    private final Set<PortKey> fixed = new HashSet<>();
    /** The control connections whose robots are leaving: their ports drain, their names are freed soon. */
    private final Set<RobotSession> leaving = new HashSet<>();
    /** The model's breaks, the operator's forces, the statistics and the conditions of each pair. */
    private final Pairs pairs;
    /** When the ports of robots that left are forgotten. */
    private final PortForgetting forgetting;
    /** Whether a connection accepted on a WSS port may be forwarded. */
    private final Admissions admissions;
    /** When a WSS port listens. */
    private final Listening listening;
    /** Set by {@link #close}: nothing registers or listens any more. */
    private boolean closed;

    /**
     * @param modelName          the model's name, as a refusal says it
     * @param matchSourceAddress a connection on a WSS port is forwarded only from the source robot's control address
     * @param portMemorySeconds  how long the ports of a robot that left keep their numbers (0: not at all, -1: for ever)
     * @param maxPortsPerRobot   the most WSS ports one robot may hold as source
     * @param maxPortsPerAddress the most WSS ports the robots registered from one address may hold as source, together
     * @param shaping            how links are shaped (docs/shaping.md)
     */
    public HubCore(String modelName, boolean matchSourceAddress, int portMemorySeconds, int maxPortsPerRobot,
            int maxPortsPerAddress, ShapingConfig shaping) {
        this.caps = new PortCaps(maxPortsPerRobot, maxPortsPerAddress);
        this.pairs = new Pairs(shaping, robots::containsKey);
        this.forgetting = new PortForgetting(ports, new PortMemory(portMemorySeconds), pairs, robots::containsKey);
        this.listening = new Listening(robots, pairs, () -> closed);
        this.admissions = new Admissions(modelName, matchSourceAddress, robots, ports, pairs);
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
        forgetting.arrived(name);
        // A kick forgot the model's breaks of the robot's pairs: their statistics follow the state they are in now.
        pairs.arrived(name, nowNs, out);
        ports.of(name).forEach(port -> listening.listenIfItShould(port, true, out));
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
        pairs.left(name, nowNs);
        for (WssPort port : ports.of(name)) {
            listening.stopListening(port, out);
        }
        forgetting.left(name, nowNs, out);
    }

    /**
     * A robot declared in the configuration: registered now, as if it had sent INIT, until the hub
     * closes; an INIT of its name is refused as for any taken name.
     */
    public NameCheck declare(RegisteredRobot robot, long nowNs, Changes out) {
        NameCheck check = register(robot, nowNs, out);
        if (check == NameCheck.REGISTERED) {
            declared.add(robot.name());
        }
        return check;
    }

    /**
     * A fixed TCP port (docs/fixed-ports.md): the WSS port of {@code key}, allocated as a DNS would
     * with the number configured, and kept: its robots are declared, so it is never forgotten.
     */
    public DnsResult fix(PortKey key, boolean allowed, int number, long nowNs, Changes out) {
        DnsResult result = dns(key.from(), key.to(), key.targetPort(), allowed, number, nowNs, out);
        if (result.outcome() == DnsOutcome.OK) {
            fixed.add(key);
        }
        return result;
    }

    /** Whether the port is a fixed one, made at Start, rather than one a DNS asked for. */
    public boolean isFixed(PortKey key) {
        return fixed.contains(key);
    }

    /**
     * A fixed UDP port's pair (docs/fixed-ports.md): its counters and its conditions both ways,
     * live (from the port's source to its target: {@code up}), and the target's address.
     */
    public Admission relay(PortKey key, long nowNs, Changes out) {
        RegisteredRobot target = robots.get(key.to());
        if (target == null || !robots.containsKey(key.from())) {
            return new Admission("no such robot", null, null, null, null);
        }
        PairStats pairStats = pairs.seen(key.pair(), nowNs, out);
        OrderedPair up = new OrderedPair(key.from(), key.to());
        return new Admission(null, new InetSocketAddress(target.address(), key.targetPort()), pairStats,
                pairs.condition(up), pairs.condition(up.reversed()));
    }

    /** The model kicked the robot out: its ports are given back at once, its links closed, its control connection closed. */
    public void kick(String name, long nowNs, Changes out) {
        if (declared.contains(name)) { // declared: it stays, its ports too; its connections close
            for (WssPort port : ports.of(name)) {
                port.closeLinks(CloseReason.KICKED, out);
            }
            out.add(new HubEvent.Said(Level.INFO, "declared robots kicked", "kicked out " + name + "'s connections (a declared robot: it stays)"));
            return;
        }
        RegisteredRobot robot = robots.remove(name);
        if (robot != null) {
            out.add(new HubEvent.Deregistered(name));
        }
        for (WssPort port : ports.of(name)) {
            port.closeLinks(CloseReason.KICKED, out);
            forgetting.forget(port, out);
        }
        pairs.kicked(name, nowNs);
        forgetting.kicked(name, nowNs, out); // its pairs' statistics are remembered as long as its ports would have been
        if (robot != null) {
            out.closeSession(robot.session());
            out.add(new HubEvent.Said(Level.INFO, "kicked out robots", "kicked out " + name));
        }
    }

    /** The hub's timer, wss.portMemory after a robot left: forget its ports unless it came back. */
    public void forgetIfGone(String name, long nowNs, Changes out) {
        if (!closed) {
            forgetting.forgetIfGone(name, nowNs, out);
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
     * first). A new port takes {@code newNumber}, bound by the hub before its lock (-1: it could
     * not bind one; the answer is then NEEDS_NUMBER); a port that exists does not (then
     * {@code numberUsed} is false and the hub closes the socket it bound).
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
        pairs.seen(key.pair(), nowNs, out);
        WssPort port = ports.get(key);
        if (port != null) {
            listening.listenIfItShould(port, allowed, out);
            return new DnsResult(DnsOutcome.OK, port.number, key, false);
        }
        if (caps.refuse(key, robots.values(), ports, robots.get(from).address(), out)) {
            return DnsResult.of(DnsOutcome.NO_PORT);
        }
        if (newNumber < 0) {
            return new DnsResult(DnsOutcome.NEEDS_NUMBER, -1, key, false);
        }
        port = new WssPort(key, newNumber);
        ports.add(port);
        boolean listens = listening.shouldListen(key, allowed);
        if (listens) {
            port.listen();
            out.port(Changes.PortWork.LISTEN, port);
        }
        out.add(new HubEvent.Said(Level.INFO, "allocated WSS ports", "allocated " + port + (listens ? "" : ", not listening")));
        out.add(new HubEvent.PortAllocated(key, port.number, listens));
        return new DnsResult(DnsOutcome.OK, port.number, key, true);
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

    /** Whether a connection a listener of {@code epoch} accepted may be forwarded ({@code allowed}: the model's say); before its sockets open. */
    public Admission admit(WssPort port, int epoch, InetAddress peer, boolean allowed, long nowNs, Changes out) {
        return admissions.admit(port, epoch, peer, allowed, nowNs, out);
    }

    /** Asked again once the link's sockets are open: commits the link to the port, or says why not. */
    public String commit(WssPort port, int epoch, InetAddress peer, boolean allowed, Connection link) {
        return admissions.commit(port, epoch, peer, allowed, link);
    }

    /**
     * The link reached its target: whether it is announced established (and forwards). Not once a
     * step closed it (a FORCE down, a break, a kick, the stop answered while it was connecting to
     * its target), so that no CON_ESTABLISHED follows the event that closed it (issue 36).
     */
    public boolean established(WssPort port, Connection link) {
        return port.carries(link);
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
        if (wasEstablished && !closed) { // closed: said by close
            out.add(new HubEvent.Terminated(port.key));
        }
        forgetting.linkEnded(port, nowNs, out);
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
        out.add(new HubEvent.Said(Level.WARNING, "ports that could not listen again", port + ": could not listen again: " + why));
    }

    public List<WssPort> ports() {
        return List.copyOf(ports.all());
    }
    // ---- the model's verdicts ----

    /**
     * The model broke the pair. @return whether anything changed (the pair, a port). The links a
     * break closes are those of a pair that was not broken: a pair broken again (the next poll)
     * while they still end is no change (issue 36, item 10: it was told, and recorded, twice).
     */
    public boolean breakPair(RobotPair pair, long nowNs, Changes out) {
        boolean changed = pairs.broke(pair, nowNs, out);
        // Forced up: the break is only remembered, for the release.
        for (WssPort port : pairs.forced(pair) == Force.UP ? List.<WssPort>of() : ports.between(pair)) {
            changed |= listening.stopListening(port, out);
            port.closeLinks(CloseReason.OUT_OF_RANGE, out);
        }
        return changed;
    }

    /** The model resumed the pair. @return whether anything changed */
    public boolean resumePair(RobotPair pair, long nowNs, Changes out) {
        boolean changed = pairs.resumed(pair, nowNs, out);
        for (WssPort port : ports.between(pair)) {
            changed |= listening.listenIfItShould(port, true, out);
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
        pairs.force(pair, force, pin, out);
        for (WssPort port : ports.between(pair)) {
            listening.followVerdict(port, force == Force.UP, CloseReason.FORCED, out);
        }
        pairs.record(pair, false, nowNs, out);
    }

    /**
     * Gives the pair back to the model: its verdict counts again at once, the model's last break or
     * resume and what it answers now for each direction ({@code firstToSecond}, {@code secondToFirst}).
     */
    public void release(RobotPair pair, boolean firstToSecond, boolean secondToFirst, long nowNs, Changes out) {
        if (pairs.release(pair, out)) {
            for (WssPort port : ports.between(pair)) {
                boolean allowed = port.key.from().equals(pair.first()) ? firstToSecond : secondToFirst;
                listening.followVerdict(port, allowed && !pairs.isBroken(pair), CloseReason.OUT_OF_RANGE, out);
            }
        }
        pairs.record(pair, true, nowNs, out);
    }

    /** The pair's forced state, or null when the model decides it. */
    public Force forced(RobotPair pair) {
        return pairs.forced(pair);
    }

    // ---- statistics ----

    /** The statistics of every pair seen, and fresh ones of present robots' pairs forced before they were seen. */
    public List<PairStats> pairStats(long nowNs) {
        return pairs.stats(nowNs);
    }

    // ---- the end ----

    /**
     * The hub stops: every port is given back, every connection closed and said terminated, then
     * every robot deregistered, all here, so that they are told before the hub says it stopped
     * (issue 36, item 13); a link that ends after this says nothing more ({@link #linkEnded}).
     */
    public void close(Changes out) {
        closed = true;
        for (WssPort port : ports.all()) {
            PortForgetting.giveBack(port, out);
            port.closeAtStop(out);
        }
        for (String name : new java.util.TreeSet<>(robots.keySet())) {
            out.add(new HubEvent.Deregistered(name));
        }
        ports.clear();
        robots.clear();
    }

    public boolean isClosed() {
        return closed;
    }

    // ---- rules ----

    /** With links shaped: the pairs whose strength the hub asks the model for, a few times a second. */
    public List<RobotPair> pairsToMeasure() {
        return pairs.toMeasure();
    }

    /**
     * What the model said of these pairs, each way: their rates follow (the hub's sampler asks
     * a few times a second, a DNS before it allocates, so a new pair starts at its own rate).
     */
    public void measured(Map<OrderedPair, Measurement> measurements, Changes out) {
        pairs.measured(measurements, out);
    }

    /** Every seen pair's condition one way, now. */
    public Map<OrderedPair, PairCondition> conditions() {
        return pairs.conditions();
    }

    /**
     * Descriptors ran short: the remembered ports of robots that left are given back
     * ({@link PortForgetting#giveBackRemembered}). @return how many ports were given back
     */
    public int giveBackRemembered(int atLeast, long nowNs, Changes out) {
        return forgetting.giveBackRemembered(atLeast, nowNs, out);
    }
}
