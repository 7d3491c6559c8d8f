package org.usarsim.wss.hub;

import java.io.IOException;
import java.net.InetAddress;
import java.nio.channels.ServerSocketChannel;
import java.util.List;
import java.util.Map;
import org.usarsim.wss.hub.core.DnsOutcome;
import org.usarsim.wss.hub.core.DnsResult;
import org.usarsim.wss.hub.core.FixedPort;
import org.usarsim.wss.hub.core.HubCore;
import org.usarsim.wss.hub.core.Measurement;
import org.usarsim.wss.hub.core.OrderedPair;
import org.usarsim.wss.hub.core.PortKey;
import org.usarsim.wss.hub.tcp.Closing;
import org.usarsim.wss.hub.tcp.Descriptors;
import org.usarsim.wss.hub.tcp.LinkHub;
import org.usarsim.wss.hub.tcp.PortSelector;
import org.usarsim.wss.hub.tcp.PortSockets;
import org.usarsim.wss.model.RobotPair;

/**
 * The one place a WSS port is opened, whatever asks for it: a DNS (on a number the OS chooses) or
 * a fixed TCP port at Start (on its configured number, docs/fixed-ports.md). Every rule is
 * applied here once, for both, in one order:
 * <ol>
 * <li>a robot asks for no port to itself;</li>
 * <li>without the lock: the model is asked whether the pair may talk and, with links shaped,
 * what it says of the pair (a new pair starts at its own rate, not the lowest); the port
 * selector is started (once: not under the lock, where a new port joins it); a socket is bound
 * for the port, out of descriptors after some are given back ({@link Descriptors}), since
 * whether the port is new is only known under the lock;</li>
 * <li>in one step: the model's measurement kept when both robots are registered (a DNS for a
 * robot not here keeps nothing; a fixed port's robots are declared before it opens); the port
 * allocated by the core ({@link HubCore#dns}, {@link HubCore#fix}), a new one with the socket's
 * number, or not allocated when no socket could be bound (said as a WARNING); the socket
 * adopted as the port's ({@link ChangeApplier#adopt});</li>
 * <li>a socket the port did not take (it existed, or was refused) closed.</li>
 * </ol>
 * Returns once the port listens (when it should): a robot may connect as soon as it has the answer.
 */
final class PortOpener {

    /** The number of a port a DNS opens: the OS chooses it. */
    private static final int ANY_NUMBER = 0;

    /** What an opening came to: the core's answer, and why no socket could be bound (null when one was). */
    private record Opened(DnsResult result, IOException unbound) {
    }

    private final StepExecutor executor;
    private final ChangeApplier sockets;
    private final PortSelector selector;
    /** Where the port selector hands what it accepts. */
    private final LinkHub links;
    private final Descriptors descriptors;
    private final ModelAnswers answers;
    private final InetAddress bindAddress;
    private final boolean shaped;

    PortOpener(StepExecutor executor, ChangeApplier sockets, PortSelector selector, LinkHub links, Descriptors descriptors,
            ModelAnswers answers, HubConfig config) {
        this.executor = executor;
        this.sockets = sockets;
        this.selector = selector;
        this.links = links;
        this.descriptors = descriptors;
        this.answers = answers;
        this.bindAddress = config.bindAddress();
        this.shaped = config.shaping().on();
    }

    /**
     * DNS: the WSS port for connections from {@code from} to {@code to} on {@code targetPort} (0:
     * the first). A port that cannot be bound is not allocated (Could.Not.Allocate.Port).
     */
    DnsResult dns(String from, String to, int targetPort) {
        return open(from, to, targetPort, ANY_NUMBER).result();
    }

    /**
     * A fixed TCP port, at Start: allocated as a DNS allocates a port, on its configured number,
     * and kept (its robots are declared: {@link HubCore#fix}).
     *
     * @throws IOException when its number cannot be bound, or the core does not allocate it
     */
    void fix(FixedPort port) throws IOException {
        PortKey key = port.key();
        Opened opened = open(key.from(), key.to(), key.targetPort(), port.number());
        if (opened.unbound() != null) {
            throw new IOException("cannot listen on fixed port " + port + ": " + opened.unbound().getMessage(), opened.unbound());
        }
        if (!opened.result().numberUsed()) {
            throw new IOException("cannot make fixed port " + port + ": " + opened.result().outcome());
        }
    }

    /** @param number the new port's number: {@link #ANY_NUMBER} for a DNS's, a fixed port's own */
    private Opened open(String from, String to, int targetPort, int number) {
        if (from.equals(to)) {
            return new Opened(new DnsResult(DnsOutcome.NO_SUCH_ROBOT, -1, null, false), null);
        }
        boolean allowed = answers.allows(from, to);
        Map<OrderedPair, Measurement> measurements = shaped ? answers.measure(List.of(RobotPair.of(from, to))) : Map.of();
        ServerSocketChannel bound = null;
        IOException unbound = null;
        try {
            selector.start(links);
            bound = descriptors.retrying(() -> PortSockets.bind(bindAddress, number));
        } catch (IOException e) {
            unbound = e;
        }
        ServerSocketChannel socket = bound;
        String why = unbound == null ? null : unbound.getMessage();
        DnsResult result = executor.step((core, now, out) -> {
            if (!measurements.isEmpty() && core.isRegistered(from) && core.isRegistered(to)) {
                core.measured(measurements, out);
            }
            int newNumber = socket == null ? -1 : PortSockets.numberOf(socket);
            DnsResult answer = number == ANY_NUMBER ? core.dns(from, to, targetPort, allowed, newNumber, now, out)
                    : core.fix(new PortKey(from, to, targetPort), allowed, newNumber, now, out);
            if (answer.outcome() == DnsOutcome.NEEDS_NUMBER) { // new, and no socket could be bound
                core.couldNotAllocate(answer.key(), why, out);
                return new DnsResult(DnsOutcome.NO_PORT, -1, answer.key(), false);
            }
            if (answer.numberUsed()) {
                sockets.adopt(core, core.port(answer.key()), socket, out);
            }
            return answer;
        });
        if (!result.numberUsed()) {
            Closing.quietly(bound); // the port exists, or it is refused
        }
        return new Opened(result, unbound);
    }
}
