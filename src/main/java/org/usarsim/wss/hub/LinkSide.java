package org.usarsim.wss.hub;

import org.usarsim.wss.hub.core.Admission;
import java.io.IOException;
import java.net.InetAddress;
import java.nio.channels.SocketChannel;
import java.util.logging.Logger;
import org.usarsim.wss.hub.core.HubClock;
import org.usarsim.wss.hub.core.HubEvent;
import org.usarsim.wss.hub.core.WssPort;
import org.usarsim.wss.hub.tcp.Closing;
import org.usarsim.wss.hub.tcp.Descriptors;
import org.usarsim.wss.hub.tcp.KeepAlive;
import org.usarsim.wss.hub.tcp.Link;
import org.usarsim.wss.hub.tcp.LinkHub;
import org.usarsim.wss.hub.tcp.Shaping;
import org.usarsim.wss.hub.tcp.SocketBuffers;
import org.usarsim.wss.model.WssEventListener;
import org.usarsim.wss.shaping.Airtime;

/**
 * The hub as the WSS ports and the links see it ({@link LinkHub}): a connection accepted on a
 * port becomes a {@link Link} (or is refused), a link's establishment and end join the ordered
 * events, each through the {@link StepExecutor}.
 */
final class LinkSide extends SocketSide implements LinkHub {

    /** The hub's own log, where a refused connection is said (within the warnings' limits). */
    private final Logger log;
    private final StepExecutor executor;
    private final ModelAnswers answers;
    private final HubConfig config;
    private final SocketBuffers socketBuffers;
    /** Where a link says what it sent (DATA_SENT): the listeners, as it happens. */
    private final WssEventListener events;
    /** The robots' radios, when links are shaped (docs/shaping.md). */
    private final Airtime airtime;
    /** The hub's clock: a shaped link's (docs/shaping.md). */
    private final HubClock clock;

    LinkSide(StepExecutor executor, ModelAnswers answers, HubConfig config, WarningLimiter warnings, KeepAlive keepAlive,
            Descriptors descriptors, WssEventListener events, Airtime airtime, HubClock clock, Logger log) {
        super(warnings, keepAlive, descriptors);
        this.log = log;
        this.executor = executor;
        this.answers = answers;
        this.config = config;
        this.socketBuffers = SocketBuffers.of(config.socketBuffer());
        this.events = events;
        this.airtime = airtime;
        this.clock = clock;
    }

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
        Admission admission = executor.step((core, now, out) -> core.admit(port, epoch, peer, allowed, now, out));
        if (admission.refusal() != null) {
            refuse(port, socket, peer, admission.refusal());
            return;
        }
        Link link;
        try {
            link = descriptors().retrying(() -> newLink(port, socket, admission));
        } catch (IOException e) {
            warnings.warn(log, "connections not forwarded", peer, port + ": could not open a socket to the target: " + e.getMessage());
            Closing.quietly(socket);
            return;
        }
        String refusal = executor.locked(core -> core.commit(port, epoch, peer, allowed, link));
        if (refusal != null) {
            link.discard();
            refuse(port, socket, peer, refusal);
            return;
        }
        try {
            link.start();
        } catch (Throwable e) {
            // No thread for the link: undone here, and the listener's AcceptLoop says so.
            executor.locked(core -> {
                core.uncommit(port, link);
                return null;
            });
            link.discard();
            throw e;
        }
    }

    private Link newLink(WssPort port, SocketChannel socket, Admission admission) throws IOException {
        Shaping shaping = config.shaping().on() ? new Shaping(airtime, admission.up(), admission.down(), config.shaping().queueMs(),
                config.shaping().jitter()) : null;
        return new Link(this, port, socket, admission.target(), config.chunkSize(), socketBuffers, events, admission.stats(), clock, shaping);
    }

    private void refuse(WssPort port, SocketChannel socket, InetAddress peer, String refusal) {
        warnings.warn(log, "refused connections", peer, port + ": refused a connection: " + refusal);
        Closing.quietly(socket);
    }

    @Override
    public boolean established(Link link, Runnable opened) {
        return executor.announceDeliveredIf(core -> {
            boolean still = core.established(link.port(), link);
            if (still) {
                opened.run(); // under the lock: counted before any step after this one, and before the listeners hear of it
            }
            return still;
        }, new HubEvent.Established(link.port().key));
    }

    @Override
    public void linkEnded(Link link, boolean wasEstablished) {
        executor.run((core, now, out) -> core.linkEnded(link.port(), link, wasEstablished, now, out));
    }
}
