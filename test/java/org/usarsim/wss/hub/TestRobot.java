package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * A robot as a team's client is: a control connection to the WSS (from a chosen loopback
 * address) and, when it accepts connections, server sockets on that address.
 */
public final class TestRobot implements AutoCloseable {

    public static final int TIMEOUT_MS = 5000;
    private static final Pattern DNS_PORT = Pattern.compile("DNSREPLY \\{Robot \\S+\\} \\{Port (-?\\d+)\\}");

    public final String address;
    public final Socket control;
    private final InputStream in;
    private final OutputStream out;
    private final List<ServerSocket> listeners = new ArrayList<>();

    public TestRobot(int wssPort, String address) throws IOException {
        this.address = address;
        control = new Socket();
        control.bind(new InetSocketAddress(address, 0));
        control.connect(new InetSocketAddress("127.0.0.1", wssPort), TIMEOUT_MS);
        control.setSoTimeout(TIMEOUT_MS);
        control.setTcpNoDelay(true);
        in = control.getInputStream();
        out = control.getOutputStream();
    }

    /** A server socket on this robot's address, as the robot's accepting port. */
    public ServerSocket listen() throws IOException {
        ServerSocket server = new ServerSocket();
        server.bind(new InetSocketAddress(address, 0));
        server.setSoTimeout(TIMEOUT_MS);
        listeners.add(server);
        return server;
    }

    /** Registers with one accepting port, a server socket on this robot's address; returns that socket. */
    public ServerSocket initAccepting(String name) throws IOException {
        ServerSocket accepts = listen();
        init(name, accepts.getLocalPort());
        return accepts;
    }

    public void send(String text) throws IOException {
        out.write(text.getBytes(StandardCharsets.UTF_8));
        out.flush();
    }

    /** Reads one reply line, CR LF included, byte by byte (so that nothing after it is consumed). */
    public String readLine() throws IOException {
        ByteArrayOutputStream line = new ByteArrayOutputStream();
        int previous = -1;
        while (true) {
            int b = in.read();
            if (b < 0) {
                throw new IOException("control connection closed after '" + line + "'");
            }
            line.write(b);
            if (previous == '\r' && b == '\n') {
                String text = line.toString(StandardCharsets.UTF_8);
                return text.substring(0, text.length() - 2);
            }
            previous = b;
        }
    }

    /** Sends a command and returns its reply (without CR LF). */
    public String ask(String command) throws IOException {
        send(command + "\r\n");
        return readLine();
    }

    public void init(String name, int... ports) throws IOException {
        StringBuilder list = new StringBuilder();
        for (int port : ports) {
            list.append(list.length() == 0 ? "" : ",").append(port);
        }
        String command = ports.length == 0 ? "INIT {Robot " + name + "}" : "INIT {Robot " + name + "} {Port " + list + "}";
        assertEquals("INITREPLY {Status OK}", ask(command));
    }

    /** DNS to a robot (port 0: no Port field); returns the WSS port, asserting an OK reply. */
    public int dns(String robot, int port) throws IOException {
        String reply = ask(port == 0 ? "DNS {Robot " + robot + "}" : "DNS {Robot " + robot + "} {Port " + port + "}");
        Matcher matcher = DNS_PORT.matcher(reply);
        assertTrue(matcher.matches(), "DNS reply: " + reply);
        int wssPort = Integer.parseInt(matcher.group(1));
        assertTrue(wssPort > 0, "DNS reply: " + reply);
        return wssPort;
    }

    /** Opens a data connection to a WSS port from this robot's address. */
    public Socket connect(int wssPort) throws IOException {
        Socket socket = new Socket();
        socket.bind(new InetSocketAddress(address, 0));
        socket.connect(new InetSocketAddress(InetAddress.getByName("127.0.0.1"), wssPort), TIMEOUT_MS);
        socket.setSoTimeout(TIMEOUT_MS);
        socket.setTcpNoDelay(true);
        return socket;
    }

    @Override
    public void close() throws IOException {
        control.close();
        for (ServerSocket server : listeners) {
            server.close();
        }
    }
}
