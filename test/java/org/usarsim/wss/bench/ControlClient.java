package org.usarsim.wss.bench;

import java.io.BufferedInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.channels.SocketChannel;
import java.nio.charset.StandardCharsets;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * A robot's control connection, as little as the benchmark needs. Its replies are read through a
 * buffer (a read per byte cost the robots' side 36 system calls a DNS); the connection is a
 * channel, so that {@link MeshAsker} can drive many from one thread.
 */
public final class ControlClient implements AutoCloseable {

    private static final Pattern DNS_PORT = Pattern.compile("DNSREPLY \\{Robot \\S+\\} \\{Port (\\d+)\\}");

    private final SocketChannel channel;
    private final Socket socket;
    /** Buffered: holds nothing between two replies, as the server never writes unasked. */
    private final InputStream in;

    public ControlClient(int wssPort, String name, int acceptPort) throws IOException {
        this("127.0.0.1", wssPort, name, acceptPort);
    }

    /** A robot whose control connection goes to the WSS at {@code host} (a benchmark's own address across a veth, say). */
    ControlClient(String host, int wssPort, String name, int acceptPort) throws IOException {
        this(host, wssPort);
        String reply = ask("INIT {Robot " + name + "} {Port " + acceptPort + "}");
        if (!reply.equals("INITREPLY {Status OK}")) {
            throw new IOException("INIT " + name + ": " + reply);
        }
    }

    private ControlClient(String host, int wssPort) throws IOException {
        channel = SocketChannel.open();
        socket = channel.socket();
        socket.connect(new InetSocketAddress(host, wssPort), 5000);
        socket.setSoTimeout(10_000);
        socket.setTcpNoDelay(true);
        in = new BufferedInputStream(socket.getInputStream(), 512);
    }

    /** An operator's control connection from 127.0.0.1: no INIT, for FORCE. */
    static ControlClient operator(int wssPort) throws IOException {
        return new ControlClient("127.0.0.1", wssPort);
    }

    /** The connection itself, for {@link MeshAsker} (non-blocking while it asks, blocking again after). */
    SocketChannel channel() {
        return channel;
    }

    /** FORCE {Robot a} {Peer b} {State Up} {Rate rate} {Delay delayMs}: pins the pair's rate and delay. */
    void forceUp(String a, String b, String rate, int delayMs) throws IOException {
        String reply = ask("FORCE {Robot " + a + "} {Peer " + b + "} {State Up} {Rate " + rate + "} {Delay " + delayMs + "}");
        if (!reply.equals("FORCEREPLY {Status OK}")) {
            throw new IOException("FORCE " + a + " " + b + ": " + reply);
        }
    }

    public String ask(String command) throws IOException {
        socket.getOutputStream().write((command + "\r\n").getBytes(StandardCharsets.UTF_8));
        ByteArrayOutputStream line = new ByteArrayOutputStream();
        int b;
        while ((b = in.read()) != '\n') {
            if (b < 0) {
                throw new IOException("control connection closed");
            }
            if (b != '\r') {
                line.write(b);
            }
        }
        return line.toString(StandardCharsets.UTF_8);
    }

    int dns(String robot) throws IOException {
        String reply = ask("DNS {Robot " + robot + "}");
        Matcher matcher = DNS_PORT.matcher(reply);
        if (!matcher.matches()) {
            throw new IOException("DNS " + robot + ": " + reply);
        }
        return Integer.parseInt(matcher.group(1));
    }

    @Override
    public void close() throws IOException {
        channel.close();
    }
}
