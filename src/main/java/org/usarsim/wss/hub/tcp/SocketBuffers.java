package org.usarsim.wss.hub.tcp;

import java.io.IOException;
import java.net.StandardSocketOptions;
import java.nio.channels.SocketChannel;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.logging.Logger;

/**
 * The send and receive buffer size a link sets on both of its sockets. Large buffers let the
 * robots and the link each move more per wake-up, which is most of the relay's cost on a busy
 * machine (docs/performance.md). The OS silently caps a size above net.core.rmem_max or
 * wmem_max, and a capped size does worse than leaving the OS to size the buffers itself, so
 * such a request is not applied at all.
 */
public final class SocketBuffers {

    private static final Logger LOG = Logger.getLogger(SocketBuffers.class.getName());

    private final int size;

    private SocketBuffers(int size) {
        this.size = size;
    }

    /** @param requested bytes; 0 leaves the buffers to the OS */
    public static SocketBuffers of(int requested) {
        if (requested == 0) {
            return new SocketBuffers(0);
        }
        long receiveLimit = limit("rmem_max");
        long sendLimit = limit("wmem_max");
        if (receiveLimit < requested || sendLimit < requested) {
            LOG.info("socket buffers of " + requested + " bytes exceed this machine's limits (net.core.rmem_max "
                    + receiveLimit + ", net.core.wmem_max " + sendLimit + "); links leave them to the OS");
            return new SocketBuffers(0);
        }
        return new SocketBuffers(requested);
    }

    /** The OS's limit in bytes, or Long.MAX_VALUE where it cannot be read (not Linux): the OS caps it there. */
    private static long limit(String name) {
        try {
            return Long.parseLong(Files.readAllLines(Path.of("/proc/sys/net/core", name)).get(0).strip());
        } catch (IOException | RuntimeException e) {
            return Long.MAX_VALUE;
        }
    }

    void apply(SocketChannel channel) throws IOException {
        if (size > 0) {
            channel.setOption(StandardSocketOptions.SO_SNDBUF, size);
            channel.setOption(StandardSocketOptions.SO_RCVBUF, size);
        }
    }
}
