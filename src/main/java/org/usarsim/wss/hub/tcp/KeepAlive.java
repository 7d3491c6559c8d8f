package org.usarsim.wss.hub.tcp;

import java.io.IOException;
import java.net.StandardSocketOptions;
import java.nio.channels.SocketChannel;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.logging.Logger;
import jdk.net.ExtendedSocketOptions;

/**
 * TCP keepalive on a control connection or a link's socket, tuned so that a peer that vanished
 * (power, cable: nothing ever closes its end) is found within {@code wss.deadPeerSeconds}: the
 * first probe after {@link #idle} idle seconds, then one every {@link #interval} seconds, and the
 * connection fails after {@link #count} unanswered probes, so idle + interval * count is at most
 * the setting. The OS's defaults (two hours on Linux) are left where the setting is 0 or the
 * platform has no per-socket options.
 */
public final class KeepAlive {

    private static final Logger LOG = Logger.getLogger(KeepAlive.class.getName());
    /** Probes before the peer counts as dead (Linux allows up to 127). */
    private static final int PROBES = 4;
    /** The per-socket options are missing on this platform: said once per process. */
    private static final AtomicBoolean UNSUPPORTED_SAID = new AtomicBoolean();

    final int idle;
    final int interval;
    final int count;

    private KeepAlive(int idle, int interval, int count) {
        this.idle = idle;
        this.interval = interval;
        this.count = count;
    }

    /** @param seconds within how long a dead peer is found (1 acts as 2, the least possible); 0 leaves the timing to the OS */
    public static KeepAlive within(int seconds) {
        if (seconds == 0) {
            return new KeepAlive(0, 0, 0);
        }
        int idle = Math.max(1, seconds / 3);
        int interval = Math.max(1, (seconds - idle) / PROBES);
        int count = Math.max(1, Math.min(PROBES, (seconds - idle) / interval));
        return new KeepAlive(idle, interval, count);
    }

    /** The longest a dead peer goes unnoticed on an idle connection, in seconds (0: the OS's). */
    int detectionSeconds() {
        return idle + interval * count;
    }

    void apply(SocketChannel channel) throws IOException {
        channel.setOption(StandardSocketOptions.SO_KEEPALIVE, true);
        if (idle == 0) {
            return;
        }
        if (!channel.supportedOptions().contains(ExtendedSocketOptions.TCP_KEEPIDLE)) {
            if (UNSUPPORTED_SAID.compareAndSet(false, true)) {
                LOG.warning("this platform cannot tune TCP keepalive per socket: a vanished robot is found only"
                        + " after the OS's keepalive time (two hours by default), not within wss.deadPeerSeconds");
            }
            return;
        }
        channel.setOption(ExtendedSocketOptions.TCP_KEEPIDLE, idle);
        channel.setOption(ExtendedSocketOptions.TCP_KEEPINTERVAL, interval);
        channel.setOption(ExtendedSocketOptions.TCP_KEEPCOUNT, count);
    }

    @Override
    public String toString() {
        return idle == 0 ? "the OS's keepalive" : "keepalive after " + idle + " s idle, " + count + " probes "
                + interval + " s apart";
    }
}
