package org.usarsim.wss.hub;

import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.usarsim.wss.hub.core.HubEvent;
import org.usarsim.wss.hub.core.Measurement;
import org.usarsim.wss.hub.core.OrderedPair;
import org.usarsim.wss.model.ModelPoll;
import org.usarsim.wss.model.RobotLinkModel;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.model.WssEventListener;

/**
 * The hub as the propagation model sees it: what the model may do to robots and links
 * ({@link RobotLinkModel}: break, resume, kick, each one step through the {@link StepExecutor}),
 * where its own events join the hub's ({@link #events()}), and the sampler's questions to it.
 */
final class ModelSide implements RobotLinkModel {

    private final StepExecutor executor;
    private final ModelAnswers answers;
    /** Told after each verdict of the model on pairs (a pair first seen up says no event): the routes follow. */
    private final Runnable pairsDecided;

    ModelSide(StepExecutor executor, ModelAnswers answers, Runnable pairsDecided) {
        this.executor = executor;
        this.answers = answers;
        this.pairsDecided = pairsDecided;
    }

    @Override
    public boolean breakConnectionsForPair(String robotA, String robotB) {
        RobotPair pair = RobotPair.of(robotA, robotB);
        boolean changed = executor.step((core, now, out) -> core.breakPair(pair, now, out));
        pairsDecided.run();
        return changed;
    }

    @Override
    public boolean resumeConnectionsForPair(String robotA, String robotB) {
        RobotPair pair = RobotPair.of(robotA, robotB);
        boolean changed = executor.step((core, now, out) -> core.resumePair(pair, now, out));
        pairsDecided.run();
        return changed;
    }

    /** Every pair's break or resume in one step: their ports stop (or listen again) together, in one turn. */
    @Override
    public Set<RobotPair> applyLinkStates(Map<RobotPair, Boolean> inRange) {
        Set<RobotPair> changed = executor.step((core, now, out) -> {
            Set<RobotPair> those = new LinkedHashSet<>();
            inRange.forEach((pair, live) -> {
                if (live ? core.resumePair(pair, now, out) : core.breakPair(pair, now, out)) {
                    those.add(pair);
                }
            });
            return those;
        });
        pairsDecided.run();
        return changed;
    }

    @Override
    public void kickOutRobot(String name) {
        executor.run((core, now, out) -> core.kick(name, now, out));
    }

    @Override
    public List<String> getListOfRegisteredRobots() {
        return executor.locked(core -> core.robotNames());
    }

    /** The sampler's call: what the model says of each shaped pair now, both ways, asked without the lock. */
    void measure() {
        List<RobotPair> pairs = executor.locked(core -> core.pairsToMeasure());
        Map<OrderedPair, Measurement> measurements = answers.measure(pairs);
        executor.run((core, now, out) -> core.measured(measurements, out));
    }

    /** Where the model's own events go: they join the hub's, in order with them. */
    WssEventListener events() {
        return new WssEventListener() {
            @Override
            public void robotOutOfBattery(String robot) {
                executor.announce(new HubEvent.OutOfBattery(robot));
            }

            @Override
            public void connectionOutOfRange(String from, String to, double strength, double distance) {
                executor.announce(new HubEvent.OutOfRange(from, to, strength, distance));
            }

            @Override
            public void connectionInRange(String from, String to) {
                executor.announce(new HubEvent.InRange(from, to));
            }

            @Override
            public void polled(ModelPoll poll) {
                executor.announce(new HubEvent.Polled(poll));
            }

            @Override
            public void replayMoved(double timeSeconds, double speed, boolean playing) {
                executor.announce(new HubEvent.ReplayMoved(timeSeconds, speed, playing));
            }
        };
    }
}
