package org.usarsim.wss.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.Socket;
import java.net.http.WebSocket;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.OptionalDouble;
import java.util.concurrent.TimeUnit;
import java.util.function.Function;
import java.util.stream.Collectors;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.usarsim.wss.hub.Wait;
import org.usarsim.wss.ros.JsonLimits;
import org.usarsim.wss.ros.MessageType;
import org.usarsim.wss.ros.OccupancyGrid;
import org.usarsim.wss.ros.PoseDecoder;
import org.usarsim.wss.ros.RobotPose;
import org.usarsim.wss.ros.RosFrame;

/**
 * The world server's rosbridge over a real WebSocket on 127.0.0.1, with the JDK's client
 * ({@code java.net.http.WebSocket}): subscriptions published as the world's publishers publish,
 * a message sent in fragments, ping, close, a message over the limit, a request that is no
 * WebSocket. Slow: the world's time runs as the wall clock does (from 4 s on, moved on by a test).
 */
@Tag("slow")
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class RosbridgeServerTest {

    private static final long WAIT_S = ReceivedFrames.WAIT_S;

    private final World world = new World(List.of(
            new WorldRobot("Scout", new Point(1.25, -3, 0.45), null, OptionalDouble.empty()),
            new WorldRobot("Mover", new Point(0, 0, 0), new Route(new Point(0, 0, 0), List.of(new Point(10, 0, 0)), 1, false),
                    OptionalDouble.empty())),
            List.of(new Wall(5, -10, 5, 10)));
    private final long started = System.nanoTime();
    /** The world's time when the test started. */
    private volatile double offset = 4;
    private RunningRosbridge running;
    private WorldServer worldServer;
    private RosbridgeServer server;

    @BeforeEach
    void start() throws IOException {
        running = new RunningRosbridge(world, () -> offset + (System.nanoTime() - started) / 1e9, RosbridgeServer.DEFAULT_RATE_HZ,
                RosbridgeServer.DEFAULT_CONNECTION_DELAY);
        worldServer = running.world;
        server = running.server;
    }

    @AfterEach
    void stop() {
        running.close();
    }

    private WebSocket connect(ReceivedFrames received) {
        return running.connect(received);
    }

    private static Map<String, RobotPose> poses(MessageType type, String frame) throws Exception {
        return new PoseDecoder(type).decode(frame).stream().collect(Collectors.toMap(RobotPose::name, Function.identity()));
    }

    @Test
    void modelStatesArePublishedWithTheWorldsPositions() throws Exception {
        ReceivedFrames received = new ReceivedFrames();
        WebSocket socket = connect(received);
        socket.sendText("{\"op\":\"subscribe\",\"id\":\"s\",\"topic\":\"/gazebo/model_states\",\"type\":\"gazebo_msgs/ModelStates\","
                + "\"throttle_rate\":100,\"queue_length\":1}", true).join();
        Map<String, RobotPose> first = poses(MessageType.MODEL_STATES, received.next());
        double mover = first.get("Mover").x();
        assertTrue(mover >= 4 && mover <= worldServer.time(), "Mover at 1 m/s from 4 m at 4 s: " + mover);
        assertEquals(new RobotPose("Scout", 1.25, -3, 0.45, RobotPose.NO_STAMP), first.get("Scout"));
        offset = 7;
        Map<String, RobotPose> later;
        do {
            later = poses(MessageType.MODEL_STATES, received.next());
        } while (later.get("Mover").x() < 7);
        assertTrue(later.get("Mover").x() <= 10, "the world as it is at each publication");
        socket.sendText("{\"op\":\"unsubscribe\",\"topic\":\"/gazebo/model_states\"}", true).join();
        socket.sendText("{\"op\":\"call_service\",\"id\":\"c\",\"service\":\"/rosapi/topics\"}", true).join();
        String answer;
        do {
            answer = received.next();
        } while (answer.contains("\"publish\""));
        assertEquals("service_response", RosFrame.parse(answer, JsonLimits.DEFAULT).op(), "after the last publish, only the answer");
    }

    @Test
    void aRequestSentInFragmentsIsOneRequest() throws Exception {
        ReceivedFrames received = new ReceivedFrames();
        WebSocket socket = connect(received);
        socket.sendText("{\"op\":\"subscribe\",\"topic\":", false).join();
        socket.sendText("\"/tf\",\"throttle_rate\":", false).join();
        socket.sendText("50}", true).join();
        RobotPose robot = poses(MessageType.TF, received.next()).values().iterator().next();
        Point at = world.at(robot.stampNanos() / 1e9).robot(robot.name().replace("/base_link", "")).orElseThrow().position();
        assertEquals(new RobotPose(robot.name(), at.x(), at.y(), at.z(), robot.stampNanos()), robot,
                "one robot's transform (each robot has its publisher), where it is at its stamp");
    }

    @Test
    void theMapComesOnceOnSubscribe() throws Exception {
        ReceivedFrames received = new ReceivedFrames();
        WebSocket socket = connect(received);
        socket.sendText("{\"op\":\"subscribe\",\"topic\":\"/map\"}", true).join();
        OccupancyGrid grid = OccupancyGrid.of(RosFrame.parse(received.next(), JsonLimits.DEFAULT).msg());
        assertEquals(1, grid.crossings(0, 0, 10, 0));
        assertEquals(0, grid.crossings(0, 0, 4, 0));
        socket.sendPing(ByteBuffer.wrap("after the map".getBytes(StandardCharsets.UTF_8))).join();
        assertEquals("after the map", received.pongs.poll(WAIT_S, TimeUnit.SECONDS));
        assertTrue(received.texts.isEmpty(), "latched: no second map");
    }

    @Test
    void aCloseIsAnsweredAndAMessageOverTheLimitClosesWith1009() throws Exception {
        ReceivedFrames closing = new ReceivedFrames();
        connect(closing).sendClose(WebSocket.NORMAL_CLOSURE, "bye").join();
        assertEquals(WebSocket.NORMAL_CLOSURE, closing.closes.poll(WAIT_S, TimeUnit.SECONDS));

        ReceivedFrames large = new ReceivedFrames();
        WebSocket socket = connect(large);
        socket.sendText("{\"op\":\"subscribe\",\"topic\":\"" + "x".repeat(RosbridgeServer.MAX_MESSAGE_BYTES) + "\"}", true);
        assertEquals(1009, large.closes.poll(WAIT_S, TimeUnit.SECONDS));
    }

    @Test
    void aRequestThatIsNoWebSocketIsAnswered400() throws IOException {
        try (Socket socket = new Socket(InetAddress.getLoopbackAddress(), server.port())) {
            socket.setSoTimeout((int) TimeUnit.SECONDS.toMillis(WAIT_S));
            OutputStream out = socket.getOutputStream();
            out.write("GET / HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n".getBytes(StandardCharsets.ISO_8859_1));
            InputStream in = socket.getInputStream();
            String answer = new String(in.readAllBytes(), StandardCharsets.ISO_8859_1);
            assertTrue(answer.startsWith("HTTP/1.1 400 Bad Request\r\n"), answer);
        }
    }

    /** A raw connection's handshake; its status line. */
    private static String handshake(Socket socket) throws IOException {
        socket.setSoTimeout((int) TimeUnit.SECONDS.toMillis(WAIT_S));
        socket.getOutputStream().write(("GET / HTTP/1.1\r\nHost: 127.0.0.1\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
                + "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n\r\n").getBytes(StandardCharsets.ISO_8859_1));
        StringBuilder line = new StringBuilder();
        InputStream in = socket.getInputStream();
        int c;
        while ((c = in.read()) >= 0 && c != '\r') {
            line.append((char) c);
        }
        return line.toString();
    }

    @Test
    void theClientBeyondTheLimitIsAnswered503UntilOneLeaves() throws IOException {
        List<Socket> clients = new ArrayList<>();
        try {
            for (int i = 0; i < RosbridgeServer.MAX_CLIENTS; i++) {
                Socket client = new Socket(InetAddress.getLoopbackAddress(), server.port());
                clients.add(client);
                assertEquals("HTTP/1.1 101 Switching Protocols", handshake(client));
            }
            try (Socket refused = new Socket(InetAddress.getLoopbackAddress(), server.port())) {
                assertEquals("HTTP/1.1 503 Service Unavailable", handshake(refused));
            }
            clients.remove(0).close();
            Wait.until("a client's place is free", () -> server.clientCount() < RosbridgeServer.MAX_CLIENTS);
            try (Socket again = new Socket(InetAddress.getLoopbackAddress(), server.port())) {
                assertEquals("HTTP/1.1 101 Switching Protocols", handshake(again));
            }
        } finally {
            for (Socket client : clients) {
                client.close();
            }
        }
    }
}
