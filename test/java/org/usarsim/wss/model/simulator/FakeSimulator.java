package org.usarsim.wss.model.simulator;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.LongFunction;
import java.util.function.Supplier;
import org.usarsim.wss.model.RobotPair;

/**
 * A scripted USARSim position socket on 127.0.0.1: answers GETPOS with the robots placed here (or
 * with what a script gives for the n-th GETPOS) and GETOBS with the counts set here; can go
 * silent, send garbage, drop its clients, and stop and start listening on its port.
 */
public final class FakeSimulator implements AutoCloseable {

    public enum Mode { ANSWER, SILENT, GARBAGE, NO_GETOBS }

    private final Map<String, ReportedRobot> robots = new LinkedHashMap<>();
    private final Map<RobotPair, Double> obstacles = new ConcurrentHashMap<>();
    private final List<Socket> clients = new CopyOnWriteArrayList<>();
    private final List<String> getobs = new CopyOnWriteArrayList<>();
    private final AtomicLong getpos = new AtomicLong();
    private final AtomicLong connections = new AtomicLong();
    private final int port;
    private volatile ServerSocket server;
    private volatile Mode mode = Mode.ANSWER;
    private volatile long getobsDelayMs;
    private volatile Supplier<String> garbage = () -> "this is not a reply";
    /** The answer to GETWALLS; null: none, as USARSim. */
    private volatile String wallsReply;
    private LongFunction<List<ReportedRobot>> script;
    private long scriptBase;

    public FakeSimulator() throws IOException {
        server = bind(0);
        port = server.getLocalPort();
        acceptOn(server);
    }

    public int port() {
        return port;
    }

    public synchronized void place(String name, double x, double y, double z) {
        ReportedRobot old = robots.get(name);
        robots.put(name, new ReportedRobot(name, x, y, z, old != null && old.batteryEmpty()));
    }

    public synchronized void remove(String name) {
        robots.remove(name);
    }

    public synchronized void emptyBattery(String name) {
        ReportedRobot old = robots.get(name);
        robots.put(name, new ReportedRobot(name, old.x(), old.y(), old.z(), true));
    }

    /** From now on the k-th GETPOS from now (counting from 1) is answered with {@code script.apply(k)}. */
    public synchronized void script(LongFunction<List<ReportedRobot>> script) {
        this.script = script;
        scriptBase = getpos.get();
    }

    public void obstacles(String a, String b, double count) {
        obstacles.put(RobotPair.of(a, b), count);
    }

    /** Answers each GETOBS this much later: a slow simulator. */
    public void delayGetobs(long ms) {
        getobsDelayMs = ms;
    }

    public void mode(Mode mode) {
        this.mode = mode;
    }

    /** Answers GETWALLS with this line from now on (null: no answer, as USARSim). */
    public void answerGetwalls(String line) {
        wallsReply = line;
    }

    /** Answers each GETPOS with the next of these lines (no line end in them) from now on: mode GARBAGE. */
    public void garbage(Supplier<String> lines) {
        garbage = lines;
        mode = Mode.GARBAGE;
    }

    public long getposCount() {
        return getpos.get();
    }

    public long connectionCount() {
        return connections.get();
    }

    /** Every GETOBS line received, in order. */
    public List<String> getobsLines() {
        return new ArrayList<>(getobs);
    }

    /** Closes every client connection; the port keeps listening. */
    public void dropClients() {
        for (Socket client : clients) {
            close(client);
        }
    }

    /** Stops listening and drops every client: connects are refused until {@link #listenAgain()}. */
    public void stopListening() throws IOException {
        server.close();
        dropClients();
    }

    public void listenAgain() throws IOException {
        server = bind(port);
        acceptOn(server);
    }

    private static ServerSocket bind(int port) throws IOException {
        ServerSocket socket = new ServerSocket();
        socket.setReuseAddress(true);
        socket.bind(new InetSocketAddress(InetAddress.getByName("127.0.0.1"), port));
        return socket;
    }

    private void acceptOn(ServerSocket listening) {
        Thread thread = new Thread(() -> {
            while (!listening.isClosed()) {
                try {
                    Socket client = listening.accept();
                    connections.incrementAndGet();
                    clients.add(client);
                    Thread serving = new Thread(() -> serve(client), "fake simulator client");
                    serving.setDaemon(true);
                    serving.start();
                } catch (IOException e) {
                    return;
                }
            }
        }, "fake simulator accept");
        thread.setDaemon(true);
        thread.start();
    }

    private void serve(Socket client) {
        try (client) {
            BufferedReader in = new BufferedReader(new InputStreamReader(client.getInputStream(), StandardCharsets.UTF_8));
            OutputStream out = client.getOutputStream();
            String line;
            while ((line = in.readLine()) != null) {
                String reply = answer(line.strip());
                if (reply != null) {
                    out.write((reply + "\r\n").getBytes(StandardCharsets.UTF_8));
                    out.flush();
                }
            }
        } catch (IOException e) {
            // the client went away or was dropped
        } finally {
            clients.remove(client);
        }
    }

    private String answer(String line) {
        Mode now = mode;
        if (line.equals("GETPOS")) {
            synchronized (this) {
                long n = getpos.incrementAndGet();
                return switch (now) {
                    case SILENT -> null;
                    case GARBAGE -> garbage.get();
                    default -> positions(n);
                };
            }
        }
        if (line.equals("GETWALLS")) {
            return wallsReply;
        }
        if (line.startsWith("GETOBS")) {
            getobs.add(line);
            if (now != Mode.ANSWER) {
                return null;
            }
            if (getobsDelayMs > 0) {
                try {
                    Thread.sleep(getobsDelayMs); // the slow simulator this fake plays
                } catch (InterruptedException e) {
                    return null;
                }
            }
            String[] words = line.replace("{", " ").replace("}", " ").trim().split("\\s+");
            String from = words[2];
            String to = words[4];
            double count = obstacles.getOrDefault(RobotPair.of(from, to), -1.0);
            return String.format(Locale.ROOT, "NUMOBS {From %s} {To %s} {ObstCount %.4f}", from, to, count);
        }
        return null;
    }

    /** Under the lock. */
    private String positions(long n) {
        List<ReportedRobot> listed = script != null ? script.apply(n - scriptBase) : new ArrayList<>(robots.values());
        StringBuilder reply = new StringBuilder("POSITIONS {Robots " + listed.size() + "}");
        for (ReportedRobot robot : listed) {
            reply.append(String.format(Locale.ROOT, " {Name %s Location %.4f,%.4f,%.4f BatteryEmpty %s}", robot.name(),
                    robot.x(), robot.y(), robot.z(), robot.batteryEmpty() ? "True" : "False"));
        }
        return reply.toString();
    }

    private static void close(Socket socket) {
        try {
            socket.close();
        } catch (IOException e) {
            // already closed
        }
    }

    @Override
    public void close() throws IOException {
        stopListening();
    }
}
