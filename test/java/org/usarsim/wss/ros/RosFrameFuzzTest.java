package org.usarsim.wss.ros;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Fuzzed rosbridge frames: the fixture frames (and a small map) truncated, with chars flipped,
 * deleted and spliced, nested up to 10,000 deep, with huge numbers, and random bytes. Parsing and decoding
 * them with every decoder (tf's keeping its tree across all of them) and reading them as a map
 * either gives poses or a {@link JsonException} with a one-line message; nothing else escapes,
 * nothing hangs. Seeded: the seed is in every failure message, {@code -Dwss.fuzz.seed=N} replays
 * a run ({@code -Dwss.fuzz.frames=N}: how many frames, 100,000 by default).
 */
@Timeout(value = 120, unit = TimeUnit.SECONDS)
class RosFrameFuzzTest {

    private static final String MAP = "{\"op\":\"publish\",\"topic\":\"\\/map\",\"msg\":{\"header\":{\"seq\":0,\"stamp\":"
            + "{\"secs\":0,\"nsecs\":0},\"frame_id\":\"map\"},\"info\":{\"resolution\":0.5,\"width\":4,\"height\":3,\"origin\":"
            + "{\"position\":{\"x\":-1.0,\"y\":2.0,\"z\":0.0},\"orientation\":{\"x\":0.0,\"y\":0.0,\"z\":0.0,\"w\":1.0}}},"
            + "\"data\":[0,0,100,0,-1,0,100,0,0,0,100,0]}}";
    private static final String[] ODD = {"1e999", "-1e400", "NaN", "Infinity", "null", "true", "\"\"", "{}", "[]", "\\",
        "\\u", "\\ud800", "\\uZZZZ", "\"", ",", ":", "{", "}", "[", "]", "-", "0", "01", "1.", "9".repeat(400),
        "0." + "0".repeat(400) + "1", "1e-99999", "\u0000", "\u00e9", "\ud83d\ude00", "\ud800", " ", "\t", "\n"};

    /** The chars that make JSON's structure. */
    private static final String SIGNS = "{}[]\",:\\0-e.ntf ";

    private final long seed = Long.getLong("wss.fuzz.seed", new Random().nextLong());
    private final String replay = " (seed " + seed + "; replay with -Dwss.fuzz.seed=" + seed + ")";

    @Test
    void everyFuzzedFrameIsDecodedOrRefusedWithAReason() {
        System.out.println("RosFrameFuzzTest seed " + seed);
        Random random = new Random(seed);
        List<String> valid = new ArrayList<>(RosFixtures.all());
        valid.add(MAP);
        List<PoseDecoder> decoders = new ArrayList<>();
        for (MessageType type : MessageType.values()) {
            decoders.add(new PoseDecoder(type));
        }
        JsonLimits limits = new JsonLimits(64 * 1024, JsonLimits.DEFAULT_MAX_DEPTH);
        int decoded = 0;
        int refused = 0;
        int frames = Integer.getInteger("wss.fuzz.frames", 100_000);
        for (int i = 0; i < frames; i++) {
            String text = fuzzed(random, valid);
            RosFrame frame;
            try {
                frame = RosFrame.parse(text, limits);
            } catch (JsonException e) {
                assertOneLine(e, text);
                refused++;
                continue;
            } catch (RuntimeException | StackOverflowError e) {
                throw new AssertionError("'" + shown(text) + "' threw " + e + replay, e);
            }
            for (PoseDecoder decoder : decoders) {
                try {
                    List<RobotPose> poses = decoder.decode(frame);
                    poses.forEach(pose -> assertTrue(Double.isFinite(pose.x()) && Double.isFinite(pose.y())
                            && Double.isFinite(pose.z()), () -> pose + " from '" + shown(text) + "'" + replay));
                    decoded++;
                } catch (JsonException e) {
                    assertOneLine(e, text);
                    refused++;
                } catch (RuntimeException e) {
                    throw new AssertionError("'" + shown(text) + "' threw " + e + replay, e);
                }
            }
            if (frame.isPublish() && "/map".equals(frame.topic())) {
                try {
                    OccupancyGrid grid = OccupancyGrid.of(frame.msg());
                    grid.crossings(random.nextGaussian() * 3, random.nextGaussian() * 3, random.nextGaussian() * 3,
                            random.nextGaussian() * 3);
                } catch (JsonException e) {
                    assertOneLine(e, text);
                } catch (RuntimeException e) {
                    throw new AssertionError("'" + shown(text) + "' threw " + e + replay, e);
                }
            }
        }
        assertTrue(decoded > frames / 20 && refused > frames / 10, "both kinds were tried: " + decoded + " decoded, "
                + refused + " refused" + replay);
    }

    private void assertOneLine(JsonException e, String text) {
        String message = e.getMessage();
        assertTrue(message != null && !message.isBlank() && message.indexOf('\n') < 0 && message.length() < 400,
                () -> "'" + shown(text) + "' refused with '" + message + "'" + replay);
    }

    private static String shown(String text) {
        return text.length() <= 300 ? text : text.substring(0, 300) + "... (" + text.length() + " chars)";
    }

    /** Random bytes, or a valid frame with one to four mutations. */
    private static String fuzzed(Random random, List<String> valid) {
        if (random.nextInt(10) == 0) {
            byte[] bytes = new byte[random.nextInt(200)];
            random.nextBytes(bytes);
            return new String(bytes, StandardCharsets.UTF_8);
        }
        StringBuilder frame = new StringBuilder(valid.get(random.nextInt(valid.size())));
        for (int m = 1 + random.nextInt(4); m > 0; m--) {
            int at = random.nextInt(frame.length() + 1);
            switch (random.nextInt(8)) {
                case 0 -> frame.setLength(at);
                case 1 -> {
                    if (at < frame.length()) {
                        frame.setCharAt(at, (char) (frame.charAt(at) ^ (1 << random.nextInt(8))));
                    }
                }
                case 2 -> frame.insert(at, ODD[random.nextInt(ODD.length)]);
                case 3 -> frame.delete(at, Math.min(frame.length(), at + 1 + random.nextInt(20)));
                case 4 -> {
                    int depth = random.nextInt(3) == 0 ? 1 + random.nextInt(10_000) : 1 + random.nextInt(80);
                    boolean array = random.nextBoolean();
                    frame.insert(at, (array ? "[" : "{\"a\":").repeat(depth) + "1" + (array ? "]" : "}").repeat(depth));
                }
                case 5 -> replaceANumber(frame, random);
                case 6 -> {
                    int from = random.nextInt(frame.length() + 1);
                    int to = Math.min(frame.length(), from + random.nextInt(200));
                    frame.insert(at, frame.substring(from, to));
                }
                default -> frame.setCharAt(Math.min(at, frame.length() - 1), SIGNS.charAt(random.nextInt(SIGNS.length())));
            }
            if (frame.length() == 0) {
                break;
            }
        }
        return frame.toString();
    }

    /** A number of the frame replaced by a huge, tiny or long one. */
    private static void replaceANumber(StringBuilder frame, Random random) {
        int start = frame.indexOf(":", random.nextInt(frame.length() + 1));
        if (start < 0 || start + 1 >= frame.length() || !Character.isDigit(frame.charAt(start + 1)) && frame.charAt(start + 1) != '-') {
            return;
        }
        int end = start + 1;
        while (end < frame.length() && "0123456789.eE+-".indexOf(frame.charAt(end)) >= 0) {
            end++;
        }
        String[] numbers = {"1e308", "1.7976931348623157e308", "-1e308", "1e309", "4.9e-324", "1" + "0".repeat(350),
            "123456789012345678901234567890", "-0", "0e0", "2147483648", "9007199254740993"};
        frame.replace(start + 1, end, numbers[random.nextInt(numbers.length)]);
    }
}
