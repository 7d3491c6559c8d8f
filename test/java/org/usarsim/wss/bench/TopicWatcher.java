package org.usarsim.wss.bench;

import java.io.IOException;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.WebSocket;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import org.usarsim.wss.ros.Json;
import org.usarsim.wss.ros.JsonException;
import org.usarsim.wss.ros.JsonLimits;
import org.usarsim.wss.ros.JsonNode;

/**
 * One robot's x on a {@code gazebo_msgs/ModelStates} topic as a rosbridge sends it, seen from a
 * subscriber of its own (the JDK's WebSocket client) that asks for {@code throttle_rate} 0 and
 * {@code queue_length} 0, so that rosbridge sends every message as it is published: the arrival of
 * the first message that shows a new place is that place's publish time, black-box.
 */
final class TopicWatcher implements WebSocket.Listener, AutoCloseable {

    /** A place the robot was seen at, when it first was (System.nanoTime), and its index among the places seen. */
    record Seen(double x, long nanos, int index) {
    }

    private final String robot;
    private final List<Seen> seen = new ArrayList<>();
    private final StringBuilder message = new StringBuilder();
    private WebSocket socket;
    private volatile String problem;

    private TopicWatcher(String robot) {
        this.robot = robot;
    }

    /** Subscribes to the topic at the rosbridge's address and watches the robot on it. */
    static TopicWatcher open(String url, String topic, String robot) throws IOException, InterruptedException {
        TopicWatcher watcher = new TopicWatcher(robot);
        try {
            watcher.socket = HttpClient.newHttpClient().newWebSocketBuilder().buildAsync(URI.create(url), watcher)
                    .get(10, TimeUnit.SECONDS);
        } catch (ExecutionException | TimeoutException e) {
            throw new IOException("no WebSocket to " + url, e);
        }
        watcher.socket.sendText("{\"op\":\"subscribe\",\"id\":\"bench\",\"topic\":" + Json.quote(topic)
                + ",\"type\":\"gazebo_msgs/ModelStates\",\"throttle_rate\":0,\"queue_length\":0}", true);
        return watcher;
    }

    @Override
    public CompletionStage<?> onText(WebSocket webSocket, CharSequence data, boolean last) {
        message.append(data);
        if (last) {
            long now = System.nanoTime();
            try {
                JsonNode msg = JsonNode.parse(message.toString(), JsonLimits.DEFAULT).get("msg");
                List<?> names = msg.get("name").list();
                int index = names.indexOf(robot);
                if (index >= 0) {
                    saw(msg.get("pose").items().get(index).get("position").get("x").number(), now);
                }
            } catch (JsonException | RuntimeException e) {
                problem = e.toString();
            }
            message.setLength(0);
        }
        webSocket.request(1);
        return null;
    }

    @Override
    public void onError(WebSocket webSocket, Throwable error) {
        problem = error.toString();
    }

    private synchronized void saw(double x, long now) {
        if (seen.isEmpty() || seen.get(seen.size() - 1).x() != x) {
            seen.add(new Seen(x, now, seen.size()));
            notifyAll();
        }
    }

    /** The place seen last; waits for the first up to the deadline (System.nanoTime). */
    synchronized Seen latest(long deadline) throws IOException, InterruptedException {
        while (seen.isEmpty()) {
            waitUntil(deadline, "nothing of " + robot + " came");
        }
        return seen.get(seen.size() - 1);
    }

    /** The first place within a micrometre of {@code x} seen at index {@code from} or later, waited for up to the deadline. */
    synchronized Seen await(double x, int from, long deadline) throws IOException, InterruptedException {
        for (int i = from;; i++) {
            while (i >= seen.size()) {
                waitUntil(deadline, robot + " never came to x " + x);
            }
            if (Math.abs(seen.get(i).x() - x) < 1e-6) {
                return seen.get(i);
            }
        }
    }

    private void waitUntil(long deadline, String what) throws IOException, InterruptedException {
        long left = deadline - System.nanoTime();
        if (left <= 0) {
            throw new IOException(what + (problem == null ? "" : " (" + problem + ")"));
        }
        TimeUnit.NANOSECONDS.timedWait(this, left);
    }

    @Override
    public void close() {
        socket.abort();
    }
}
