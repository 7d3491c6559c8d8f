package org.usarsim.wss.ros;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.List;

/** The frames a real rosbridge sent (test/resources/ros, copied byte for byte from ../shared/ros), one a line, as they are. */
final class RosFixtures {

    static final String TF = "tf.jsonl";
    static final String MODEL_STATES = "model_states.jsonl";
    static final String SCOUT_ODOM = "Scout_odom.jsonl";

    private RosFixtures() {
    }

    /** The lines of a fixture under /ros, without their line ends. */
    static List<String> frames(String name) {
        try (InputStream in = RosFixtures.class.getResourceAsStream("/ros/" + name)) {
            if (in == null) {
                throw new IllegalStateException("no fixture /ros/" + name + " on the test class path");
            }
            String text = new String(in.readAllBytes(), StandardCharsets.UTF_8);
            return Arrays.stream(text.split("\n")).filter(line -> !line.isEmpty()).toList();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** Every fixture frame: the three topics and the server's answers. */
    static List<String> all() {
        List<String> answers = List.of("call_service_rosapi_topic_type.recv.jsonl", "call_service_rosapi_topics.recv.jsonl",
                "call_service_unknown.recv.jsonl", "malformed_then_valid.recv.jsonl");
        return java.util.stream.Stream.concat(java.util.stream.Stream.of(TF, MODEL_STATES, SCOUT_ODOM),
                answers.stream().map(name -> "responses/" + name)).flatMap(name -> frames(name).stream()).toList();
    }
}
