package org.usarsim.wss.world;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.OptionalDouble;
import java.util.Random;
import java.util.concurrent.TimeUnit;
import java.util.logging.Level;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Fuzzed client bytes through the world server's WebSocket reader and rosbridge session: valid
 * masked frames of valid requests, then bytes flipped, cut and spliced, and random bytes. Nothing
 * escapes but the reader's close codes and the session's log lines; the session keeps
 * publishing. Seeded: {@code -Dwss.fuzz.seed=N} replays a run ({@code -Dwss.fuzz.frames=N}: how
 * many byte strings, 20,000 by default: the JSON beneath has its own 100,000 in the ros package).
 */
@Timeout(value = 120, unit = TimeUnit.SECONDS)
class RosbridgeFuzzTest {

    private static final String[] REQUESTS = {
        "{\"op\":\"subscribe\",\"id\":\"s1\",\"topic\":\"/gazebo/model_states\",\"type\":\"gazebo_msgs/ModelStates\","
            + "\"throttle_rate\":200,\"queue_length\":1}",
        "{\"op\":\"subscribe\",\"topic\":\"/tf\",\"type\":\"tf2_msgs/msg/TFMessage\",\"throttle_rate\":0}",
        "{\"op\":\"subscribe\",\"topic\":\"/Scout/odom\"}",
        "{\"op\":\"unsubscribe\",\"topic\":\"/tf\"}",
        "{\"op\":\"call_service\",\"id\":\"cs1\",\"service\":\"/rosapi/topics\"}",
        "{\"op\":\"subscribe\",\"topic\":\"/tf\",",
        "{\"topic\":\"/tf\"}",
        "{\"op\":\"frobnicate\",\"id\":\"x1\"}",
        "{\"op\":\"subscribe\",\"id\":\"f\",\"topic\":\"/tf_static\",\"queue_length\":2,\"throttle_rate\":10,\"fragment_size\":50}",
        "{\"op\":\"subscribe\",\"id\":7,\"topic\":\"/gazebo/model_states\",\"throttle_rate\":10.0,\"queue_length\":-1}",
        "{\"op\":\"unsubscribe\",\"id\":\"f\",\"topic\":\"/tf_static\",\"fragment_size\":\"big\"}"};

    private final long seed = Long.getLong("wss.fuzz.seed", new Random().nextLong());
    private final String replay = " (seed " + seed + "; replay with -Dwss.fuzz.seed=" + seed + ")";

    private final World world = new World(List.of(new WorldRobot("Scout", new Point(1, 2, 0), null, OptionalDouble.empty())),
            List.of(new Wall(5, -10, 5, 10)));

    @Test
    void fuzzedBytesEndInACloseCodeOrALogLineAndNothingElse() {
        System.out.println("RosbridgeFuzzTest seed " + seed);
        Random random = new Random(seed);
        int strings = Integer.getInteger("wss.fuzz.frames", 20_000);
        int[] sent = {0};
        int[] logged = {0};
        int[] failed = {0};
        RosbridgeSession.Out out = new RosbridgeSession.Out() {
            @Override
            public void send(String frame) {
                sent[0]++;
            }

            @Override
            public void log(Level level, String kind, String message) {
                assertTrue(!message.isBlank(), "a log line says something" + replay);
                logged[0]++;
            }
        };
        String map = RosbridgeMessages.map(world.walls(), 0);
        RosGraph graph = new RosGraph(world.robotNames(), 20, 0);
        for (int i = 0; i < strings; i++) {
            byte[] bytes = fuzzed(random);
            RosbridgeSession session = new RosbridgeSession(world, graph, () -> map, out);
            WebSocketFrames frames = new WebSocketFrames(RosbridgeServer.MAX_MESSAGE_BYTES);
            WebSocketFrames.Sink sink = new WebSocketFrames.Sink() {
                @Override
                public void text(String message) {
                    session.request(message, 1_000_000_000L);
                }

                @Override
                public void binary(byte[] message) {
                }

                @Override
                public void ping(byte[] payload) {
                }

                @Override
                public void close(int code) {
                }

                @Override
                public void failed(int code, String reason) {
                    assertTrue(code == WebSocketFrames.PROTOCOL_ERROR || code == WebSocketFrames.TOO_BIG
                            || code == WebSocketFrames.NOT_UTF8, "a close code of RFC 6455: " + code + replay);
                    failed[0]++;
                }
            };
            try {
                int at = 0;
                while (at < bytes.length) {
                    int n = 1 + random.nextInt(bytes.length - at);
                    frames.feed(bytes, at, n, sink);
                    at += n;
                }
                session.advance(1_060_000_000L);
            } catch (RuntimeException e) {
                throw new AssertionError("byte string " + i + " threw " + e + replay, e);
            }
        }
        assertTrue(sent[0] > strings / 10 && logged[0] > strings / 10 && failed[0] > strings / 10,
                "all kinds were tried: " + sent[0] + " sent, " + logged[0] + " logged, " + failed[0] + " failed" + replay);
    }

    /** Masked frames of one to three requests (some in fragments), mutated; or random bytes. */
    private static byte[] fuzzed(Random random) {
        if (random.nextInt(10) == 0) {
            byte[] bytes = new byte[random.nextInt(300)];
            random.nextBytes(bytes);
            return bytes;
        }
        ByteArrayOutputStream stream = new ByteArrayOutputStream();
        for (int r = 1 + random.nextInt(3); r > 0; r--) {
            byte[] request = REQUESTS[random.nextInt(REQUESTS.length)].getBytes(StandardCharsets.UTF_8);
            if (random.nextInt(3) == 0) {
                int cut = random.nextInt(request.length + 1);
                stream.writeBytes(WebSocketFramesTest.clientFrame(false, WebSocketFrames.TEXT, java.util.Arrays.copyOf(request, cut)));
                if (random.nextBoolean()) {
                    stream.writeBytes(WebSocketFramesTest.clientFrame(true, WebSocketFrames.PING, new byte[random.nextInt(10)]));
                }
                stream.writeBytes(WebSocketFramesTest.clientFrame(true, 0, java.util.Arrays.copyOfRange(request, cut, request.length)));
            } else {
                stream.writeBytes(WebSocketFramesTest.clientFrame(true, WebSocketFrames.TEXT, request));
            }
        }
        byte[] bytes = stream.toByteArray();
        for (int m = random.nextInt(4); m > 0 && bytes.length > 0; m--) {
            int at = random.nextInt(bytes.length);
            switch (random.nextInt(3)) {
                case 0 -> bytes[at] ^= (byte) (1 << random.nextInt(8));
                case 1 -> bytes = java.util.Arrays.copyOf(bytes, at);
                default -> bytes[at] = (byte) random.nextInt(256);
            }
        }
        return bytes;
    }
}
