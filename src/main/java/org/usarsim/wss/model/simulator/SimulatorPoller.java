package org.usarsim.wss.model.simulator;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.logging.Level;
import org.usarsim.wss.ThreadStop;
import org.usarsim.wss.model.ModelPoll;
import org.usarsim.wss.model.RobotLinkModel;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.model.Wall;

/**
 * One run of polling, from a start to its shutdown: its own thread, configuration, connection
 * and trouble state, so that a run that is slow to stop can never touch the next one's.
 */
final class SimulatorPoller implements Runnable {

    private final SimulatorModel model;
    private final RobotLinkModel server;
    private final SimulatorConfig run;
    private final PositionSource.Opener opener;
    private final Thread thread;
    private volatile boolean stopped;
    private volatile PositionSource connection;
    /** Why the simulator is unusable since {@link #troubleSince}; null while it answers. */
    private String trouble;
    private long troubleSince;
    /** A failure that is not the simulator's, already logged; null after a good poll. */
    private String failure;
    /** The source's walls as the model holds them: learnt again when the source gives others. */
    private List<Wall> wallsFrom;
    /** Whether this run said that the simulator gives no walls. */
    private boolean saidNoWalls;

    /** Polls {@code source}; when it is null (unreachable at the start, for {@code unreachable}), opens one first. */
    SimulatorPoller(SimulatorModel model, RobotLinkModel server, SimulatorConfig run, PositionSource.Opener opener,
            PositionSource source, IOException unreachable) {
        this.model = model;
        this.server = server;
        this.run = run;
        this.opener = opener;
        this.connection = source;
        if (unreachable != null) {
            lost(unreachable);
        }
        thread = new Thread(this, model.name() + " poller");
        thread.setDaemon(true);
        thread.start();
    }

    void stop() {
        ThreadStop.stop(thread, () -> {
            stopped = true;
            thread.interrupt();
            close();
        });
    }

    @Override
    public void run() {
        long backoffMs = run.intervalMs();
        long next = model.clock().nanoTime();
        if (trouble != null) {
            // Unreachable at the start: the first attempt again after a pause, as after a loss.
            next += backoffMs * 1_000_000L;
            backoffMs = SimulatorModel.nextBackoff(backoffMs, run.intervalMs());
        }
        try {
            while (pause(next)) {
                next = model.clock().nanoTime() + run.intervalMs() * 1_000_000L;
                try {
                    PositionSource simulator = connection;
                    if (simulator == null) {
                        simulator = opener.open();
                        connection = simulator;
                    }
                    if (poll(simulator)) {
                        back();
                        backoffMs = run.intervalMs();
                    }
                } catch (IOException e) {
                    if (stopped) {
                        return;
                    }
                    lost(e);
                    close();
                    next = model.clock().nanoTime() + backoffMs * 1_000_000L;
                    backoffMs = SimulatorModel.nextBackoff(backoffMs, run.intervalMs());
                } catch (RuntimeException | Error e) {
                    failed(e);
                }
            }
        } finally {
            close();
        }
    }

    /** Waits until {@code deadline}; false when the run was stopped meanwhile. */
    private boolean pause(long deadline) {
        while (!stopped && deadline - model.clock().nanoTime() > 0) {
            try {
                model.clock().sleepUntil(deadline);
            } catch (InterruptedException e) {
                return false;
            }
        }
        return !stopped;
    }

    /**
     * One poll: positions, kicks, obstacle counts, then every pair of listed robots decided,
     * published, broken or resumed. False when the source gave none, being just opened (the
     * poll acts on nothing).
     */
    private boolean poll(PositionSource simulator) throws IOException {
        List<String> registered = server.getListOfRegisteredRobots();
        Map<String, ReportedRobot> listed = simulator.positions(registered);
        if (stopped || listed == null) {
            return false;
        }
        // A robot the source still waits for is neither kicked nor decided: as if it had not registered yet.
        Set<String> waited = simulator.waitedFor();
        List<String> registeredBefore = waited.isEmpty() ? registered
                : registered.stream().filter(robot -> !waited.contains(robot)).toList();
        if (model.ownWalls() == null) {
            learnWalls(simulator);
        }
        model.applyPoll(new PollingModel.Poll(registeredBefore, listed, model.kicksRobotsAbsentFrom(listed), "simulator", "",
                model.walls(), () -> stopped),
                present -> decide(present, listed, simulator));
        failure = null;
        return true;
    }

    /** The obstacle counts, then every pair of the present robots decided and published (GETSS reads it); null when stopped. */
    private List<ModelPoll.Pair> decide(List<String> present, Map<String, ReportedRobot> listed, PositionSource simulator)
            throws IOException {
        Map<RobotPair, Double> obstacles = model.obstacleCounts(listed, PollStep.pairs(present), simulator);
        if (stopped) {
            return null;
        }
        PollStep.Decision decision = PollStep.decide(present, listed, obstacles, model.clock().nanoTime(), model.snapshot().links(),
                model::signal);
        // Only now, whole: a GETSS meanwhile answers from the last poll's positions and counts.
        model.published(decision.snapshot());
        List<ModelPoll.Pair> pairs = new ArrayList<>(decision.links().size());
        for (PollStep.Link link : decision.links()) {
            RobotPair pair = link.pair();
            pairs.add(new ModelPoll.Pair(pair.first(), pair.second(), link.strength(), obstacles.getOrDefault(pair, Double.NaN),
                    link.live()));
        }
        return pairs;
    }

    /** Takes the source's walls once they are known, and says what they are, each time it gives others. */
    private void learnWalls(PositionSource simulator) {
        List<Wall> given = simulator.walls();
        if (given == null || given == wallsFrom) {
            return;
        }
        wallsFrom = given;
        model.walls(given);
        if (simulator.wallsProblem() != null) {
            model.log.warning("the simulator at " + run.where() + " gave its walls in a reply that cannot be read ("
                    + simulator.wallsProblem() + "): the map shows none");
        } else if (given.isEmpty()) {
            if (!saidNoWalls) {
                model.log.info("the simulator at " + run.where() + " gives no walls" + (run.rosbridge() == null
                        ? " (USARSim does not answer GETWALLS)" : "") + ": the map shows none");
                saidNoWalls = true;
            }
        } else {
            model.log.info("the simulator at " + run.where() + " gives " + given.size() + " walls");
        }
    }

    private void lost(IOException e) {
        String reason = e.getMessage() == null ? e.toString() : e.getMessage();
        if (trouble == null) {
            troubleSince = model.clock().nanoTime();
            model.log.warning("lost the simulator at " + run.where() + ": " + reason
                    + "; keeping the last known link state and reconnecting");
        } else if (!reason.equals(trouble)) {
            model.log.fine("the simulator at " + run.where() + " is still unusable: " + reason);
        }
        trouble = reason;
    }

    private void back() {
        if (trouble != null) {
            long seconds = TimeUnit.NANOSECONDS.toSeconds(model.clock().nanoTime() - troubleSince);
            model.log.info("the simulator at " + run.where() + " answers again after " + seconds + " s");
            trouble = null;
        }
    }

    /** A failure that is not the simulator's (a bug, a listener that throws): logged once, then polling goes on. */
    private void failed(Throwable e) {
        if (failure == null) {
            model.log.log(Level.WARNING, model.name() + ": a poll failed (" + e + "); polling goes on", e);
        }
        failure = e.toString();
    }

    private void close() {
        PositionSource open = connection;
        connection = null;
        if (open != null) {
            open.close();
        }
    }
}
