package org.usarsim.wss.hub;

import java.io.IOException;
import java.net.InetAddress;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.logging.Logger;
import org.usarsim.wss.hub.core.Admission;
import org.usarsim.wss.hub.core.DeclaredRobot;
import org.usarsim.wss.hub.core.FixedPort;
import org.usarsim.wss.hub.core.HubClock;
import org.usarsim.wss.hub.core.Measurement;
import org.usarsim.wss.hub.core.OrderedPair;
import org.usarsim.wss.hub.core.RegisteredRobot;
import org.usarsim.wss.hub.core.RobotSession;
import org.usarsim.wss.hub.udp.UdpRelay;
import org.usarsim.wss.model.WssEventListener;
import org.usarsim.wss.shaping.Airtime;

/**
 * What the hub does at Start for the declared robots and the fixed ports (docs/fixed-ports.md):
 * the robots registered as if they had sent INIT; each fixed TCP port opened where a DNS opens
 * its port ({@link PortOpener#fix}), on its configured number; each fixed UDP port's relay
 * started over the pair's conditions and counters. No new rule: the core breaks, resumes,
 * forces, shapes and counts them as any WSS port. All before the control port accepts
 * ({@link Hub#start}).
 */
final class FixedPortsStart {

    private static final Logger LOG = Logger.getLogger(FixedPortsStart.class.getName());

    /** A declared robot's session: it has no control connection, and a kick leaves it registered. */
    private static final RobotSession DECLARED = () -> { };

    private FixedPortsStart() {
    }

    /**
     * Declares the robots, makes the fixed TCP ports and starts the UDP relays.
     *
     * @return the UDP relays, for the hub to close at Stop
     * @throws IOException when a fixed port's number cannot be bound (the relays started are closed)
     */
    static List<UdpRelay> open(HubConfig config, StepExecutor executor, PortOpener opener, ModelAnswers answers, Airtime airtime,
            HubClock clock, WssEventListener events)
            throws IOException {
        FixedSetup setup = config.fixed();
        for (DeclaredRobot robot : setup.robots()) {
            RegisteredRobot registered = new RegisteredRobot(robot.name(), robot.address(), setup.portsOf(robot.name()), DECLARED);
            executor.step((core, now, out) -> core.declare(registered, now, out));
        }
        List<UdpRelay> relays = new ArrayList<>();
        try {
            for (FixedPort port : setup.ports()) {
                if (port.transport() == FixedPort.Transport.TCP) {
                    opener.fix(port);
                } else {
                    relays.add(relay(port, config, executor, answers, airtime, clock, events));
                }
                LOG.info("fixed port " + port.number() + "/" + port.transport().word() + ": " + port.key().from() + " -> "
                        + port.key().to() + ":" + port.key().targetPort());
            }
        } catch (IOException | RuntimeException e) {
            relays.forEach(UdpRelay::close);
            throw e;
        }
        return relays;
    }

    private static UdpRelay relay(FixedPort port, HubConfig config, StepExecutor executor, ModelAnswers answers, Airtime airtime,
            HubClock clock, WssEventListener events)
            throws IOException {
        // Shaped, the pair starts at its own rate and loss, not those of a strength not known yet.
        Map<OrderedPair, Measurement> measurements = config.shaping().on() ? answers.measure(List.of(port.key().pair())) : Map.of();
        Admission pair = executor.step((core, now, out) -> {
            Admission admission = core.relay(port.key(), now, out);
            if (!measurements.isEmpty()) {
                core.measured(measurements, out);
            }
            return admission;
        });
        if (pair.refusal() != null) {
            throw new IOException("cannot make fixed port " + port + ": " + pair.refusal());
        }
        InetAddress source = config.matchSourceAddress() ? config.fixed().robots().stream()
                .filter(robot -> robot.name().equals(port.key().from())).findFirst().orElseThrow().address() : null;
        UdpRelay relay;
        try {
            relay = new UdpRelay(port, config.bindAddress(), pair.target(), source,
                    new UdpRelay.Pair(pair.up(), pair.down(), pair.stats().udpFrom(port.key().from()), pair.stats().udpFrom(port.key().to())),
                    airtime, config.shaping().jitter(), TimeUnit.SECONDS.toNanos(config.fixed().udpIdleSeconds()), clock,
                    (from, to, udp) -> events.udpCounted(from, to, port.number(), udp.datagrams(), udp.bytes(), udp.droppedBroken(), udp.droppedQueue(),
                            udp.lost()));
        } catch (IOException e) {
            throw new IOException("cannot listen on fixed port " + port + ": " + e.getMessage(), e);
        }
        relay.start();
        return relay;
    }
}
