package org.usarsim.wss.model.simulator;

import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.Base64;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * A rosbridge server as small as a test needs (RFC 6455 by hand, on 127.0.0.1, a port of its own):
 * it takes WebSocket clients, keeps the text messages they send (the subscriptions), and sends
 * them what the test publishes, whole or in fragments. No ROS, no JSON: the test writes the frames.
 */
public final class TinyRosbridge implements AutoCloseable {

    private static final String GUID = "258EAFA5-E914-47DA-95CA-C5AB0DC85B11";

    private final ServerSocket server;
    private final List<Socket> clients = new CopyOnWriteArrayList<>();
    private final List<String> received = new CopyOnWriteArrayList<>();
    private final AtomicInteger connections = new AtomicInteger();
    private final Thread acceptor;

    public TinyRosbridge() throws IOException {
        this(0);
    }

    /** On this port of 127.0.0.1 (0: any free one). */
    public TinyRosbridge(int port) throws IOException {
        server = new ServerSocket(port, 50, InetAddress.getByName("127.0.0.1"));
        acceptor = new Thread(this::accept, "tiny-rosbridge");
        acceptor.setDaemon(true);
        acceptor.start();
    }

    public int port() {
        return server.getLocalPort();
    }

    public String url() {
        return "ws://127.0.0.1:" + port();
    }

    /** The text messages the clients sent, in order. */
    public List<String> received() {
        return List.copyOf(received);
    }

    /** How many WebSocket clients have connected so far. */
    public int connections() {
        return connections.get();
    }

    private void accept() {
        while (!server.isClosed()) {
            try {
                Socket client = server.accept();
                Thread reader = new Thread(() -> serve(client), "tiny-rosbridge client");
                reader.setDaemon(true);
                reader.start();
            } catch (IOException e) {
                return;
            }
        }
    }

    private void serve(Socket client) {
        try (client) {
            InputStream in = client.getInputStream();
            String key = null;
            for (String line = readLine(in); !line.isEmpty(); line = readLine(in)) {
                if (line.toLowerCase(java.util.Locale.ROOT).startsWith("sec-websocket-key:")) {
                    key = line.substring(line.indexOf(':') + 1).strip();
                }
            }
            String accept = Base64.getEncoder().encodeToString(MessageDigest.getInstance("SHA-1")
                    .digest((key + GUID).getBytes(StandardCharsets.US_ASCII)));
            OutputStream out = client.getOutputStream();
            synchronized (client) {
                out.write(("HTTP/1.1 101 Switching Protocols\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
                        + "Sec-WebSocket-Accept: " + accept + "\r\n\r\n").getBytes(StandardCharsets.US_ASCII));
                out.flush();
            }
            clients.add(client);
            connections.incrementAndGet();
            DataInputStream frames = new DataInputStream(in);
            ByteArrayOutputStream message = new ByteArrayOutputStream();
            while (true) {
                int first = frames.readUnsignedByte();
                int second = frames.readUnsignedByte();
                long length = second & 0x7f;
                if (length == 126) {
                    length = frames.readUnsignedShort();
                } else if (length == 127) {
                    length = frames.readLong();
                }
                byte[] mask = new byte[4];
                if ((second & 0x80) != 0) {
                    frames.readFully(mask);
                }
                byte[] payload = new byte[(int) length];
                frames.readFully(payload);
                for (int i = 0; i < payload.length; i++) {
                    payload[i] ^= mask[i % 4];
                }
                int opcode = first & 0x0f;
                if (opcode == 8) {
                    return;
                } else if (opcode == 9) {
                    send(client, 0x8a, payload);
                } else if (opcode == 1 || opcode == 0) {
                    message.write(payload);
                    if ((first & 0x80) != 0) {
                        received.add(message.toString(StandardCharsets.UTF_8));
                        message.reset();
                    }
                }
            }
        } catch (IOException | NoSuchAlgorithmException e) {
            // the client went, or the server closed
        } finally {
            clients.remove(client);
        }
    }

    private static String readLine(InputStream in) throws IOException {
        ByteArrayOutputStream line = new ByteArrayOutputStream();
        for (int b = in.read(); b != '\n'; b = in.read()) {
            if (b < 0) {
                throw new IOException("closed in the handshake");
            }
            if (b != '\r') {
                line.write(b);
            }
        }
        return line.toString(StandardCharsets.US_ASCII);
    }

    /** A {@code /gazebo/model_states} frame as rosbridge writes it ({@code \/} escaped): each model at (x, y, 0), in the map's order. */
    public static String modelStates(java.util.Map<String, double[]> models) {
        StringBuilder names = new StringBuilder();
        StringBuilder poses = new StringBuilder();
        models.forEach((name, at) -> {
            names.append(names.length() == 0 ? "" : ",").append('"').append(name).append('"');
            poses.append(poses.length() == 0 ? "" : ",").append("{\"position\":{\"x\":").append(at[0]).append(",\"y\":").append(at[1])
                    .append(",\"z\":0.0},\"orientation\":{\"x\":0.0,\"y\":0.0,\"z\":0.0,\"w\":1.0}}");
        });
        return "{\"op\":\"publish\",\"topic\":\"\\/gazebo\\/model_states\",\"msg\":{\"name\":[" + names + "],\"pose\":[" + poses
                + "]}}";
    }

    /** Sends the text to every client, one frame. */
    public void publish(String text) {
        publish(text, 1);
    }

    /** Sends the text to every client in {@code parts} fragments (a text frame, then continuations). */
    public void publish(String text, int parts) {
        byte[] bytes = text.getBytes(StandardCharsets.UTF_8);
        List<byte[]> pieces = new ArrayList<>();
        int size = (bytes.length + parts - 1) / parts;
        for (int start = 0; start < bytes.length; start += size) {
            pieces.add(java.util.Arrays.copyOfRange(bytes, start, Math.min(bytes.length, start + size)));
        }
        for (Socket client : clients) {
            try {
                synchronized (client) {
                    for (int i = 0; i < pieces.size(); i++) {
                        int opcode = i == 0 ? 1 : 0;
                        int fin = i == pieces.size() - 1 ? 0x80 : 0;
                        send(client, fin | opcode, pieces.get(i));
                    }
                }
            } catch (IOException e) {
                clients.remove(client);
            }
        }
    }

    private static void send(Socket client, int first, byte[] payload) throws IOException {
        ByteArrayOutputStream frame = new ByteArrayOutputStream(payload.length + 10);
        frame.write(first);
        if (payload.length < 126) {
            frame.write(payload.length);
        } else if (payload.length < 65536) {
            frame.write(126);
            frame.write(payload.length >> 8);
            frame.write(payload.length & 0xff);
        } else {
            frame.write(127);
            for (int shift = 56; shift >= 0; shift -= 8) {
                frame.write((int) ((long) payload.length >> shift) & 0xff);
            }
        }
        frame.write(payload);
        synchronized (client) {
            OutputStream out = client.getOutputStream();
            out.write(frame.toByteArray());
            out.flush();
        }
    }

    /** Cuts every client off, as a crashed rosbridge or a lost network would: no close frame. */
    public void dropClients() {
        for (Socket client : clients) {
            try {
                client.close();
            } catch (IOException e) {
                // already gone
            }
        }
        clients.clear();
    }

    @Override
    public void close() throws IOException {
        server.close();
        dropClients();
    }
}
