package org.usarsim.wss.bench;

import java.util.List;
import java.util.Random;

/**
 * A and B published by a real ROS node ({@link PublisherProcess}: {@code latency_publisher.py --mode
 * place}) as {@code gazebo_msgs/ModelStates} at a rate, read through a real rosbridge; a move's
 * publish is the time the script took just before its publish, on this machine's realtime clock.
 */
final class RealRosbridgeFeed implements PositionFeed {

    private final String url;
    private final String topic;
    private final int hz;
    private final int pollMs;
    private final PublisherProcess publisher;
    private final Random random = new Random(23);

    RealRosbridgeFeed(String url, String command, String topic, int hz, int pollMs) throws Exception {
        this.url = url;
        this.topic = topic;
        this.hz = hz;
        this.pollMs = pollMs;
        publisher = PublisherProcess.start(command, "--mode place --rate " + hz + " --topic " + topic);
        publisher.place("A", 0, 0);
        publisher.place("B", 10, 0);
    }

    @Override
    public String label() {
        return "real rosbridge, " + hz + " Hz";
    }

    @Override
    public List<String> wssSettings() {
        return List.of("positions=rosbridge", "rosbridge.url=" + url, "rosbridge.topic=" + topic,
                "rosbridge.type=gazebo_msgs/ModelStates");
    }

    @Override
    public long move(double x) throws Exception {
        PositionFeed.pause(random, pollMs);
        return publisher.place("B", x, 0);
    }

    @Override
    public String finish() throws InterruptedException {
        return "the publisher " + publisher.stop();
    }

    @Override
    public void close() throws InterruptedException {
        publisher.close();
    }
}
