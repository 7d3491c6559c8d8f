package org.usarsim.wss.model;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/**
 * A model that polls as the simulator models do, when the test or benchmark says: the poll told
 * to the server's listener, then every pair's state in one go; GETSS answers the last polled
 * strength of a pair (NaN before). For routes (issue 34): a recording and its replay, a moving mesh.
 */
public final class PollingStub extends StubModel {

    private volatile WssEventListener listener;
    private final Map<RobotPair, Double> strengths = new ConcurrentHashMap<>();

    @Override
    public String name() {
        return "PollingStub";
    }

    @Override
    public List<Setting> settings() {
        return List.of();
    }

    @Override
    public void setEventListener(WssEventListener listener) {
        this.listener = listener;
    }

    @Override
    public double getSignalStrengthForPair(String from, String to) {
        return strengths.getOrDefault(RobotPair.of(from, to), Double.NaN);
    }

    /** One poll: these robots listed, these pairs decided (each up when {@code live}). */
    public void poll(List<ModelPoll.Robot> robots, List<ModelPoll.Pair> pairs) {
        Map<RobotPair, Boolean> states = new LinkedHashMap<>();
        for (ModelPoll.Pair pair : pairs) {
            RobotPair both = RobotPair.of(pair.first(), pair.second());
            strengths.put(both, pair.strength());
            states.put(both, pair.live());
        }
        listener.polled(new ModelPoll(robots, List.of(), pairs, List.of()));
        links().applyLinkStates(states);
    }
}
