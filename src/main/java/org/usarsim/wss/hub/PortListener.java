package org.usarsim.wss.hub;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.StandardSocketOptions;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.util.logging.Logger;

/**
 * A WSS port while it listens: a blocking server socket and the thread that accepts on it and
 * hands each connection to the hub. Closing it stops the listening at once: a blocking channel's
 * socket is released by close() itself, whereas one registered with a Selector is released only
 * when that selector next runs, which would let a connect through after a break.
 */
final class PortListener implements Runnable {

    private static final Logger LOG = Logger.getLogger(PortListener.class.getName());
    private static final int BACKLOG = 128;

    private final Hub hub;
    private final WssPort port;
    private final ServerSocketChannel channel;

    PortListener(Hub hub, WssPort port, ServerSocketChannel channel) {
        this.hub = hub;
        this.port = port;
        this.channel = channel;
    }

    /** A blocking server socket bound to the address (port 0: the OS chooses). */
    static ServerSocketChannel bind(InetSocketAddress address) throws IOException {
        ServerSocketChannel channel = ServerSocketChannel.open();
        try {
            channel.setOption(StandardSocketOptions.SO_REUSEADDR, true);
            channel.bind(address, BACKLOG);
            return channel;
        } catch (IOException e) {
            channel.close();
            throw e;
        }
    }

    void start() {
        Thread thread = new Thread(this, "wss-port " + port.number);
        thread.setDaemon(true);
        thread.start();
    }

    void close() {
        Closing.quietly(channel);
    }

    @Override
    public void run() {
        while (channel.isOpen()) {
            SocketChannel socket;
            try {
                socket = channel.accept();
            } catch (IOException e) {
                if (channel.isOpen()) {
                    LOG.warning(port + ": accept failed, no longer listening: " + e);
                    close();
                }
                return;
            }
            hub.accepted(port, socket);
        }
    }
}
