package org.usarsim.wss.model.simulator;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.nio.charset.StandardCharsets;
import java.util.Collection;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.model.Wall;

/**
 * Positions from a USARSim-compatible position socket: one connection, {@code GETPOS} and
 * {@code GETOBS}, each answered by one line, and once {@code GETWALLS}, which only the world server
 * answers. Used by one thread at a time. Every request waits at most the timeout for its answer; a
 * stale answer to an earlier request (a late {@code NUMOBS}) is skipped.
 */
public final class UsarsimSource implements PositionSource {

    /** Longer lines are garbage: about 15 000 robots would fit. */
    static final int MAX_LINE_BYTES = 1024 * 1024;

    private final Socket socket;
    private final InputStream in;
    private final OutputStream out;
    private final int timeoutMs;
    private final byte[] buffer = new byte[8192];
    /** The start of a line whose end has not come yet; kept across a timeout, so the line is whole when it comes. */
    private final ByteArrayOutputStream partial = new ByteArrayOutputStream();
    private int bufferStart;
    private int bufferEnd;
    /** Whether GETWALLS goes with the next GETPOS (once per connection). */
    private boolean wallsToAsk = true;
    /** Whether the answer to GETWALLS may still come before the next POSITIONS. */
    private boolean wallsAsked;
    /** The simulator's walls: null until it answered GETWALLS or showed it will not; empty for none. */
    private List<Wall> walls;
    /** Why the simulator's WALLS answer was not used; null when it was, or none came. */
    private String wallsProblem;
    /** A WALLS line over {@link #MAX_LINE_BYTES} is being dropped up to its end: it costs the walls, not the simulator. */
    private boolean droppingWalls;

    private UsarsimSource(Socket socket, int timeoutMs) throws IOException {
        this.socket = socket;
        this.timeoutMs = timeoutMs;
        socket.setTcpNoDelay(true);
        in = socket.getInputStream();
        out = socket.getOutputStream();
    }

    /** How a run opens it: {@code host:port}, its connection refused at the start as it is today. */
    static PositionSource.Opener opener(String host, int port, int timeoutMs) {
        return new PositionSource.Opener() {
            @Override
            public PositionSource open() throws IOException {
                return UsarsimSource.open(host, port, timeoutMs);
            }

            @Override
            public String where() {
                return host + ":" + port;
            }

            @Override
            public boolean startsSilent() {
                return false;
            }
        };
    }

    /** Connects, waiting at most {@code timeoutMs}; the same timeout bounds every answer. */
    public static UsarsimSource open(String host, int port, int timeoutMs) throws IOException {
        Socket socket = new Socket();
        try {
            socket.connect(new InetSocketAddress(host, port), timeoutMs);
            return new UsarsimSource(socket, timeoutMs);
        } catch (IOException | RuntimeException e) {
            socket.close();
            throw e;
        }
    }

    /**
     * Sends {@code GETPOS}; the robots the simulator lists, by name (whoever is registered). The
     * first time on a connection, {@code GETWALLS} goes before it in the same write: the walls come
     * in their own time ({@link #walls()}), never delaying the positions.
     */
    @Override
    public Map<String, ReportedRobot> positions(List<String> registered) throws IOException {
        send(wallsToAsk ? "GETWALLS\r\nGETPOS\r\n" : "GETPOS\r\n");
        wallsAsked |= wallsToAsk;
        wallsToAsk = false;
        long deadline = System.nanoTime() + timeoutMs * 1_000_000L;
        while (true) {
            String line = readLine(deadline, "GETPOS");
            switch (SimulatorReplies.type(line)) {
                case SimulatorReplies.POSITIONS:
                    if (wallsAsked) {
                        // Answered in order: a simulator that answers GETPOS but said nothing to GETWALLS does not know it.
                        wallsAsked = false;
                        walls = List.of();
                    }
                    return SimulatorReplies.positions(line);
                case SimulatorReplies.NUMOBS:
                    continue; // a late answer to an earlier GETOBS
                case SimulatorReplies.WALLS:
                    wallsAsked = false;
                    try {
                        walls = SimulatorReplies.walls(line);
                    } catch (SimulatorReplyException e) {
                        // The walls only draw the map: a bad list costs the walls, not the simulator.
                        wallsProblem = e.getMessage();
                        walls = List.of();
                    }
                    continue;
                default:
                    if (wallsAsked) {
                        // Its answer to GETWALLS, an unknown command to it: no walls.
                        wallsAsked = false;
                        walls = List.of();
                        continue;
                    }
                    throw unexpected(line);
            }
        }
    }

    /**
     * The walls the simulator gave on this connection; empty when it does not know {@code GETWALLS};
     * null until the first {@link #positions()} showed which.
     */
    @Override
    public List<Wall> walls() {
        return walls;
    }

    /** Why the WALLS answer was not used (malformed); null when it was, or none came. */
    @Override
    public String wallsProblem() {
        return wallsProblem;
    }

    /**
     * Sends one {@code GETOBS} per pair in a single write and collects the answers that come
     * within the timeout: the count per answered pair, NaN where the simulator answered a negative
     * count. A pair without an answer is absent from the result (a simulator may not know GETOBS).
     */
    @Override
    public Map<RobotPair, Double> obstacles(Collection<RobotPair> pairs) throws IOException {
        Map<RobotPair, Double> counts = new HashMap<>();
        if (pairs.isEmpty()) {
            return counts;
        }
        StringBuilder requests = new StringBuilder();
        for (RobotPair pair : pairs) {
            requests.append("GETOBS {From ").append(pair.first()).append("} {To ").append(pair.second()).append("}\r\n");
        }
        send(requests.toString());
        Set<RobotPair> asked = Set.copyOf(pairs);
        long deadline = System.nanoTime() + timeoutMs * 1_000_000L;
        try {
            while (counts.size() < asked.size()) {
                String line = readLine(deadline, "GETOBS");
                if (!SimulatorReplies.type(line).equals(SimulatorReplies.NUMOBS)) {
                    throw unexpected(line);
                }
                SimulatorReplies.ObstacleCount count = SimulatorReplies.obstacles(line);
                if (asked.contains(count.pair())) {
                    counts.put(count.pair(), count.count());
                }
            }
        } catch (SocketTimeoutException e) {
            // The rest stay unanswered; a late answer is skipped when it comes.
        }
        return counts;
    }

    private void send(String text) throws IOException {
        out.write(text.getBytes(StandardCharsets.UTF_8));
        out.flush();
    }

    /** The next line (CR LF or LF), waiting until the deadline at most. */
    private String readLine(long deadline, String request) throws IOException {
        ByteArrayOutputStream line = partial;
        while (true) {
            for (int i = bufferStart; i < bufferEnd; i++) {
                if (buffer[i] == '\n' && droppingWalls) {
                    droppingWalls = false;
                    bufferStart = i + 1;
                    wallsAsked = false;
                    walls = List.of();
                    wallsProblem = "a WALLS line longer than " + MAX_LINE_BYTES + " bytes";
                    continue;
                }
                if (buffer[i] == '\n') {
                    line.write(buffer, bufferStart, i - bufferStart);
                    bufferStart = i + 1;
                    String text = line.toString(StandardCharsets.UTF_8).strip();
                    line.reset();
                    if (!text.isEmpty()) {
                        return text;
                    }
                    continue; // a blank line: skipped
                }
            }
            if (!droppingWalls) {
                line.write(buffer, bufferStart, bufferEnd - bufferStart);
            }
            bufferStart = bufferEnd;
            if (line.size() > MAX_LINE_BYTES) {
                if (!wallsAsked || !SimulatorReplies.WALLS.equals(SimulatorReplies.type(firstWords(line)))) {
                    throw new SimulatorReplyException("a reply line longer than " + MAX_LINE_BYTES + " bytes");
                }
                droppingWalls = true;
                line.reset();
            }
            long left = (deadline - System.nanoTime()) / 1_000_000L;
            if (left <= 0) {
                throw new SocketTimeoutException("no answer to " + request + " within " + timeoutMs + " ms");
            }
            socket.setSoTimeout((int) left);
            int read;
            try {
                read = in.read(buffer);
            } catch (SocketTimeoutException e) {
                throw new SocketTimeoutException("no answer to " + request + " within " + timeoutMs + " ms");
            }
            if (read < 0) {
                throw new IOException("the simulator closed the connection");
            }
            bufferStart = 0;
            bufferEnd = read;
        }
    }

    /** The start of a long line, enough for its first word. */
    private static String firstWords(ByteArrayOutputStream line) {
        byte[] bytes = line.toByteArray();
        return new String(bytes, 0, Math.min(bytes.length, 64), StandardCharsets.UTF_8);
    }

    private static SimulatorReplyException unexpected(String line) {
        String shown = line.length() > 200 ? line.substring(0, 200) + "..." : line;
        return new SimulatorReplyException("unexpected reply: " + shown);
    }

    @Override
    public void close() {
        try {
            socket.close();
        } catch (IOException e) {
            // closing: nothing left to do
        }
    }
}
