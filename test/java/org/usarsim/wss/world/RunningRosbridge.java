package org.usarsim.wss.world;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.http.WebSocket;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.function.DoubleSupplier;

/** A world server and its rosbridge on 127.0.0.1 for a test, with the test's WebSocket clients; closed together. */
final class RunningRosbridge implements AutoCloseable {

    final WorldServer world;
    final RosbridgeServer server;
    private final List<WebSocket> sockets = new ArrayList<>();

    /** @param clock the world's seconds */
    RunningRosbridge(World world, DoubleSupplier clock, double rateHz, Duration connectionDelay) throws IOException {
        this.world = new WorldServer(world, new InetSocketAddress(InetAddress.getLoopbackAddress(), 0), clock);
        this.server = RosbridgeServer.start(this.world, InetAddress.getLoopbackAddress(), 0, rateHz, connectionDelay);
    }

    /** A client, which has sent these requests, its frames received by {@code received}. */
    WebSocket connect(ReceivedFrames received, String... requests) {
        WebSocket socket = received.connect(server.port());
        sockets.add(socket);
        for (String request : requests) {
            socket.sendText(request, true).join();
        }
        return socket;
    }

    @Override
    public void close() {
        sockets.forEach(WebSocket::abort);
        server.close();
        world.close();
    }
}
