package org.usarsim.wss.replay;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import org.usarsim.wss.model.RobotLinkModel;
import org.usarsim.wss.model.RobotPair;

/** A server as a model sees it, without sockets: registered robots, broken pairs, and every call kept. */
final class FakeLinks implements RobotLinkModel {

    private final Set<String> registered = new TreeSet<>();
    private final Set<RobotPair> broken = new HashSet<>();
    private final List<String> kicked = new ArrayList<>();
    private final List<Map<RobotPair, Boolean>> applied = new ArrayList<>();
    /** Robots that register just after the next answer of {@link #getListOfRegisteredRobots}; none when empty. */
    private List<String> registerAfterNextList = List.of();

    synchronized void register(String... robots) {
        registered.addAll(List.of(robots));
    }

    /**
     * Registers {@code now}, and {@code next} just after the server next answers which robots are
     * registered: a robot that registers while the model acts on the list that has {@code now}.
     */
    synchronized void registerThenAnother(String now, String next) {
        registered.add(now);
        registerAfterNextList = List.of(next);
    }

    synchronized List<String> kicked() {
        return List.copyOf(kicked);
    }

    synchronized boolean isBroken(String a, String b) {
        return broken.contains(RobotPair.of(a, b));
    }

    /** Every applyLinkStates, in order. */
    synchronized List<Map<RobotPair, Boolean>> applied() {
        return List.copyOf(applied);
    }

    @Override
    public synchronized boolean breakConnectionsForPair(String robotA, String robotB) {
        return broken.add(RobotPair.of(robotA, robotB));
    }

    @Override
    public synchronized boolean resumeConnectionsForPair(String robotA, String robotB) {
        return broken.remove(RobotPair.of(robotA, robotB));
    }

    @Override
    public synchronized Set<RobotPair> applyLinkStates(Map<RobotPair, Boolean> inRange) {
        applied.add(new LinkedHashMap<>(inRange));
        Set<RobotPair> changed = new LinkedHashSet<>();
        inRange.forEach((pair, live) -> {
            if (live ? broken.remove(pair) : broken.add(pair)) {
                changed.add(pair);
            }
        });
        return changed;
    }

    @Override
    public synchronized void kickOutRobot(String robot) {
        kicked.add(robot);
        registered.remove(robot);
    }

    @Override
    public synchronized List<String> getListOfRegisteredRobots() {
        List<String> answer = List.copyOf(registered);
        registered.addAll(registerAfterNextList);
        registerAfterNextList = List.of();
        return answer;
    }
}
