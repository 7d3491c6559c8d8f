package org.usarsim.wss.bench;

import java.io.IOException;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.usarsim.wss.model.simulator.TinyRosbridge;

/**
 * The CPU run's robots from a rosbridge in this JVM ({@link TinyRosbridge}, the tests' own): each
 * of its publishers a thread sending its message at its rate to every client, whatever the client
 * asked (it honours no {@code throttle_rate}: at 20 Hz with the WSS's throttle of 20 ms that is what
 * a real rosbridge sends too).
 */
final class TinyPoseStream implements PoseStream {

    /** One publisher's message at a time (s). */
    private interface Message {
        String at(double seconds);
    }

    private final TinyRosbridge rosbridge;
    private final List<String> settings;
    private final List<Thread> threads = new ArrayList<>();
    private final AtomicLong sent = new AtomicLong();
    private final long start = System.nanoTime();
    private volatile boolean running = true;

    private TinyPoseStream(List<String> settings, TinyRosbridge rosbridge) {
        this.rosbridge = rosbridge;
        this.settings = settings;
    }

    /** {@code /gazebo/model_states} of all robots at {@code hz}. */
    static TinyPoseStream modelStates(int robots, int hz) throws IOException {
        TinyRosbridge rosbridge = new TinyRosbridge();
        TinyPoseStream stream = new TinyPoseStream(List.of("positions=rosbridge", "rosbridge.url=" + rosbridge.url()), rosbridge);
        stream.publisher("model_states", hz, seconds -> {
            Map<String, double[]> models = new LinkedHashMap<>();
            for (int i = 0; i < robots; i++) {
                models.put("R" + i, Circles.at(i, seconds));
            }
            return TinyRosbridge.modelStates(models);
        });
        return stream;
    }

    /** {@code publishers} publishers on a tf topic, each a {@code TFMessage} of its share of the robots at {@code hz}. */
    static TinyPoseStream tf(String topic, int robots, int publishers, int hz) throws IOException {
        TinyRosbridge rosbridge = new TinyRosbridge();
        TinyPoseStream stream = new TinyPoseStream(List.of("positions=rosbridge", "rosbridge.url=" + rosbridge.url(),
                "rosbridge.topic=" + topic, "rosbridge.type=tf2_msgs/TFMessage"), rosbridge);
        for (int k = 0; k < publishers; k++) {
            int first = k * robots / publishers;
            int end = (k + 1) * robots / publishers;
            stream.publisher("tf " + k, hz, seconds -> tfMessage(topic, first, end, seconds));
        }
        return stream;
    }

    /** A tf2_msgs/TFMessage frame as rosbridge 1 writes it: {@code world -> Ri/base_link} for robots first to end - 1, stamped now. */
    private static String tfMessage(String topic, int first, int end, double seconds) {
        long stamp = System.currentTimeMillis();
        StringBuilder transforms = new StringBuilder();
        for (int i = first; i < end; i++) {
            double[] at = Circles.at(i, seconds);
            transforms.append(i == first ? "" : ",").append(String.format(Locale.ROOT, "{\"header\":{\"seq\":0,\"stamp\":{\"secs\":%d,"
                    + "\"nsecs\":%d},\"frame_id\":\"world\"},\"child_frame_id\":\"R%d\\/base_link\",\"transform\":{\"translation\":"
                    + "{\"x\":%s,\"y\":%s,\"z\":0.0},\"rotation\":{\"x\":0.0,\"y\":0.0,\"z\":0.0,\"w\":1.0}}}", stamp / 1000,
                    stamp % 1000 * 1_000_000, i, at[0], at[1]));
        }
        return "{\"op\":\"publish\",\"topic\":\"" + topic.replace("/", "\\/") + "\",\"msg\":{\"transforms\":[" + transforms + "]}}";
    }

    private void publisher(String name, int hz, Message message) {
        long period = TimeUnit.SECONDS.toNanos(1) / hz;
        Thread thread = new Thread(() -> {
            long next = System.nanoTime();
            while (running) {
                rosbridge.publish(message.at((System.nanoTime() - start) / 1e9));
                sent.incrementAndGet();
                next += period;
                long wait = next - System.nanoTime();
                try {
                    TimeUnit.NANOSECONDS.sleep(Math.max(0, wait));
                } catch (InterruptedException e) {
                    return;
                }
            }
        }, "publisher " + name);
        thread.setDaemon(true);
        thread.start();
        threads.add(thread);
    }

    @Override
    public List<String> wssSettings() {
        return settings;
    }

    @Override
    public String finish() throws InterruptedException {
        running = false;
        for (Thread thread : threads) {
            thread.interrupt();
            thread.join(5_000);
        }
        double seconds = (System.nanoTime() - start) / 1e9;
        return String.format(Locale.ROOT, "sent %d messages in %.1f s (%.1f a second, %d publishers, in this JVM)", sent.get(), seconds,
                sent.get() / seconds, threads.size());
    }

    @Override
    public void close() throws Exception {
        if (running) {
            finish();
        }
        rosbridge.close();
    }
}
