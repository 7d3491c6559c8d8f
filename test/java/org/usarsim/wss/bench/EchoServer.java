package org.usarsim.wss.bench;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;

/** A robot that echoes each message of a fixed size back in one write, a thread per connection. */
final class EchoServer implements AutoCloseable {

    private final ServerSocket server;
    private final int messageSize;
    /** Whether a connection is closed by the server after one message (no TIME_WAIT on the client's side). */
    private final boolean once;
    private final Set<Socket> open = ConcurrentHashMap.newKeySet();

    EchoServer(int messageSize) throws IOException {
        this(messageSize, false);
    }

    /** With {@code once}, each connection is closed by the server after it echoed one message. */
    EchoServer(int messageSize, boolean once) throws IOException {
        this.messageSize = messageSize;
        this.once = once;
        server = new ServerSocket();
        server.bind(new InetSocketAddress("127.0.0.1", 0), 1024);
        Thread acceptor = new Thread(this::acceptLoop, "echo-accept " + server.getLocalPort());
        acceptor.setDaemon(true);
        acceptor.start();
    }

    int port() {
        return server.getLocalPort();
    }

    private void acceptLoop() {
        while (!server.isClosed()) {
            try {
                Socket socket = server.accept();
                socket.setTcpNoDelay(true);
                open.add(socket);
                Thread echo = new Thread(null, () -> echo(socket), "echo", 128 * 1024);
                echo.setDaemon(true);
                echo.start();
            } catch (IOException e) {
                return;
            }
        }
    }

    private void echo(Socket socket) {
        byte[] message = new byte[messageSize];
        try (socket) {
            InputStream in = socket.getInputStream();
            OutputStream out = socket.getOutputStream();
            while (in.readNBytes(message, 0, messageSize) == messageSize) {
                out.write(message);
                if (once) {
                    break;
                }
            }
        } catch (IOException ignored) {
            // The peer went away.
        } finally {
            open.remove(socket);
        }
    }

    @Override
    public void close() throws IOException {
        server.close();
        for (Socket socket : open) {
            socket.close();
        }
    }
}
