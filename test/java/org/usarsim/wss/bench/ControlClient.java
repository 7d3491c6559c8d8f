package org.usarsim.wss.bench;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/** A robot's control connection, as little as the benchmark needs. */
final class ControlClient implements AutoCloseable {

    private static final Pattern DNS_PORT = Pattern.compile("DNSREPLY \\{Robot \\S+\\} \\{Port (\\d+)\\}");

    private final Socket socket;
    private final InputStream in;

    ControlClient(int wssPort, String name, int acceptPort) throws IOException {
        socket = new Socket();
        socket.connect(new InetSocketAddress("127.0.0.1", wssPort), 5000);
        socket.setSoTimeout(10_000);
        socket.setTcpNoDelay(true);
        in = socket.getInputStream();
        String reply = ask("INIT {Robot " + name + "} {Port " + acceptPort + "}");
        if (!reply.equals("INITREPLY {Status OK}")) {
            throw new IOException("INIT " + name + ": " + reply);
        }
    }

    String ask(String command) throws IOException {
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
        socket.close();
    }
}
