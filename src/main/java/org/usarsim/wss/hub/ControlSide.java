package org.usarsim.wss.hub;

import java.net.InetAddress;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
import java.util.OptionalDouble;
import java.util.concurrent.TimeUnit;
import java.util.function.Supplier;
import org.usarsim.wss.hub.core.DnsResult;
import org.usarsim.wss.hub.core.Force;
import org.usarsim.wss.hub.core.HubClock;
import org.usarsim.wss.hub.core.NameCheck;
import org.usarsim.wss.hub.core.RatePin;
import org.usarsim.wss.hub.core.RegisteredRobot;
import org.usarsim.wss.hub.core.WssPort;
import org.usarsim.wss.hub.tcp.Closes;
import org.usarsim.wss.hub.tcp.ControlHub;
import org.usarsim.wss.hub.tcp.ControlSession;
import org.usarsim.wss.hub.tcp.Descriptors;
import org.usarsim.wss.hub.tcp.KeepAlive;
import org.usarsim.wss.hub.tcp.PortListener;
import org.usarsim.wss.hub.tcp.PortSelector;
import org.usarsim.wss.hub.tcp.PortSockets;
import org.usarsim.wss.model.Replay;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.routes.RouteTable;

/**
 * The hub as the control sessions see it ({@link ControlHub}): each command one step of the core
 * through the {@link StepExecutor}, the model asked before it, without the lock; a DNS through the
 * {@link PortOpener}, a departure's drain on the ports' sockets ({@link ChangeApplier}).
 */
final class ControlSide extends SocketSide implements ControlHub {

    /** How long an INIT of a taken name waits for the name to be freed. */
    private static final long NAME_RELEASE_WAIT_NS = TimeUnit.MILLISECONDS.toNanos(250);
    /** How long a departure waits for its ports to hand over the connections already completed. */
    private static final long DRAIN_NS = TimeUnit.SECONDS.toNanos(1);

    private final StepExecutor executor;
    private final PortOpener opener;
    /** The ports' sockets: a departure drains and stops them. */
    private final ChangeApplier sockets;
    private final ModelAnswers answers;
    private final HubConfig config;
    private final HubClock clock;
    /** The routes as last found (ROUTE). */
    private final Supplier<RouteTable> routes;

    ControlSide(StepExecutor executor, PortOpener opener, ChangeApplier sockets, ModelAnswers answers, HubConfig config, HubClock clock,
            WarningLimiter warnings, KeepAlive keepAlive, Descriptors descriptors, Supplier<RouteTable> routes) {
        super(warnings, keepAlive, descriptors);
        this.routes = routes;
        this.executor = executor;
        this.opener = opener;
        this.sockets = sockets;
        this.answers = answers;
        this.config = config;
        this.clock = clock;
    }

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
        return executor.stepWaiting((core, now, out) -> core.register(robot, now, out), ControlSide::patience)
                == NameCheck.REGISTERED;
    }

    /**
     * How long a registration waits for the name, from its first try. A name taken by a robot that
     * is leaving is freed once its departure ends ({@link #deregister}: the drain, at most
     * {@link #DRAIN_NS}, then its ports' closes, together at most {@link PortSelector#CLOSE_WAIT_NS}),
     * and the registration is woken then: it waits for all of that. (It waited for the drain
     * alone: a whole team reconnecting at once on a loaded machine, 40 robots' 1,560 ports
     * draining and closing through the one port selector, had an INIT refused for a name
     * that was freed a moment later; MeshReconnectTest, 1 run in 4 beside two busy loops.)
     */
    private static long patience(NameCheck check) {
        return check == NameCheck.TAKEN ? NAME_RELEASE_WAIT_NS
                : check == NameCheck.TAKEN_BY_LEAVING ? NAME_RELEASE_WAIT_NS + DRAIN_NS + PortSelector.CLOSE_WAIT_NS : 0;
    }

    /**
     * The robot's control connection closed: it is gone, its ports stop listening, its links live
     * on. First every connection the kernel already completed on its listening ports is forwarded
     * (a robot that sends and leaves at once loses nothing): the robot stays registered until its
     * ports have drained, for at most {@link #DRAIN_NS}.
     */
    @Override
    public void deregister(String name, ControlSession session) {
        // A step: its name stays taken until its ports drained, and an INIT of it waiting is woken to wait for that.
        List<PortSockets> toDrain = executor.step((core, now, out) -> {
            List<WssPort> listening = core.beginLeaving(name, session);
            return listening == null ? null : sockets.socketsOf(listening);
        });
        if (toDrain == null) {
            return;
        }
        // The drains' own connections are started without the lock (a listener stopped meanwhile declines).
        List<PortListener> draining = toDrain.stream().map(PortSockets::beginDrain).filter(Objects::nonNull).toList();
        long deadline = clock.nanoTime() + DRAIN_NS;
        draining.forEach(listener -> listener.awaitEnd(deadline));
        // Drained, they stop now, together: once the robot is gone, a connect to them is refused. The
        // departure's step stops them in its turn too (nothing left to do then); stopping is the
        // same whenever it is done, and a port that listens again later is a new listening.
        Closes closes = sockets.closes();
        toDrain.forEach(sockets -> sockets.stop(closes));
        closes.await();
        executor.run((core, now, out) -> core.left(name, session, now, out));
    }

    @Override
    public RouteTable routes() {
        return routes.get();
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
        if (!executor.locked(core -> core.isRegistered(to))) {
            return OptionalDouble.empty();
        }
        return answers.signalStrength(from, to);
    }

    /** DNS: the one way a port is opened ({@link PortOpener}). */
    @Override
    public DnsResult dns(String from, String to, int targetPort) {
        return opener.dns(from, to, targetPort);
    }

    @Override
    public String reverseDns(String asker, int port) {
        return executor.locked(core -> core.reverseDns(asker, port));
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
        executor.run((core, now, out) -> core.force(pair, force, pin, now, out));
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
        executor.run((core, now, out) -> core.release(pair, firstToSecond, secondToFirst, now, out));
    }

    private static RobotPair pairOf(String robotA, String robotB) {
        if (robotA == null || robotB == null || robotA.isEmpty() || robotB.isEmpty() || robotA.equals(robotB)) {
            throw new IllegalArgumentException("a pair is two different robot names, not '" + robotA + "' and '" + robotB + "'");
        }
        return RobotPair.of(robotA, robotB);
    }
}
