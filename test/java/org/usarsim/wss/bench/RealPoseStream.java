package org.usarsim.wss.bench;

import java.util.List;

/** The CPU run's robots published by a real ROS graph ({@code latency_publisher.py}) through a real rosbridge. */
final class RealPoseStream implements PoseStream {

    private final PublisherProcess publisher;
    private final List<String> settings;

    private RealPoseStream(PublisherProcess publisher, List<String> settings) {
        this.publisher = publisher;
        this.settings = settings;
    }

    /** {@code latency_publisher.py --mode model_states}: one node, all robots' ModelStates at {@code hz}. */
    static RealPoseStream modelStates(String url, String command, String topic, int robots, int hz) throws Exception {
        return new RealPoseStream(PublisherProcess.start(command, "--mode model_states --robots " + robots + " --rate " + hz
                + " --topic " + topic), List.of("positions=rosbridge", "rosbridge.url=" + url, "rosbridge.topic=" + topic,
                "rosbridge.type=gazebo_msgs/ModelStates"));
    }

    /** {@code latency_publisher.py --mode tf}: {@code publishers} nodes, each its share of the robots at {@code hz}. */
    static RealPoseStream tf(String url, String command, String topic, int robots, int publishers, int hz) throws Exception {
        return new RealPoseStream(PublisherProcess.start(command, "--mode tf --publishers " + publishers + " --robots " + robots
                + " --rate " + hz + " --topic " + topic), List.of("positions=rosbridge", "rosbridge.url=" + url,
                "rosbridge.topic=" + topic, "rosbridge.type=tf2_msgs/TFMessage"));
    }

    @Override
    public List<String> wssSettings() {
        return settings;
    }

    @Override
    public String finish() throws InterruptedException {
        return publisher.stop();
    }

    @Override
    public void close() throws InterruptedException {
        publisher.close();
    }
}
