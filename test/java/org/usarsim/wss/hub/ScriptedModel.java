package org.usarsim.wss.hub;

import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import org.usarsim.wss.model.ModelStartException;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.RobotLinkModel;
import org.usarsim.wss.model.WssEventListener;

/**
 * A propagation model for tests: the test sets, per direction, whether a pair may connect and its
 * strength (by default every pair may connect, at 0 dBm), and drives break, resume and kick
 * through {@link #links()} itself. No threads, no simulator.
 */
public final class ScriptedModel implements PropagationModel {

    private final Map<String, Boolean> allowed = new ConcurrentHashMap<>();
    private final Map<String, Double> strengths = new ConcurrentHashMap<>();
    private volatile RobotLinkModel links;
    private volatile WssEventListener events;
    private volatile boolean active;
    private volatile String startFailure;
    /** What start() does first (a slow start: a simulator that takes its time); null: nothing. */
    private volatile Runnable whileStarting;
    /** The replay controls {@link #replay()} gives; null: none, as a model that replays nothing. */
    private volatile org.usarsim.wss.model.Replay replay;
    /** How many times a strength was asked (GETSS, the snapshot, the shaping's sampler). */
    private final java.util.concurrent.atomic.AtomicLong strengthsAsked = new java.util.concurrent.atomic.AtomicLong();

    private static String key(String from, String to) {
        return from + "\u0000" + to;
    }

    /** Whether {@code from} may connect to {@code to} from now on (one direction). */
    void allow(String from, String to, boolean allow) {
        allowed.put(key(from, to), allow);
    }

    /** Whether the two may connect, both directions. */
    void allowBoth(String a, String b, boolean allow) {
        allow(a, b, allow);
        allow(b, a, allow);
    }

    void strength(String from, String to, double dbm) {
        strengths.put(key(from, to), dbm);
    }

    long strengthsAsked() {
        return strengthsAsked.get();
    }

    /** From now on the model replays: {@link #replay()} gives these controls (null: none again). */
    public void replaying(org.usarsim.wss.model.Replay controls) {
        replay = controls;
    }

    @Override
    public java.util.Optional<org.usarsim.wss.model.Replay> replay() {
        return java.util.Optional.ofNullable(replay);
    }

    /** The hub, as the server gave it to the model. */
    public RobotLinkModel links() {
        return links;
    }

    /** The event listener the server gave the model. */
    WssEventListener events() {
        return events;
    }

    @Override
    public void setRobotLinkModel(RobotLinkModel linkModel) {
        this.links = linkModel;
    }

    @Override
    public void setEventListener(WssEventListener listener) {
        this.events = listener;
    }

    /** From now on start() fails with this reason (a simulator that cannot be reached, say); null: it starts. */
    public void failStarts(String reason) {
        startFailure = reason;
    }

    /** From now on start() runs this first, as a model whose start takes its time (a simulator's connection). */
    void whileStarting(Runnable during) {
        whileStarting = during;
    }

    @Override
    public void start() throws ModelStartException {
        Runnable during = whileStarting;
        if (during != null) {
            during.run();
        }
        if (startFailure != null) {
            throw new ModelStartException(startFailure);
        }
        active = true;
    }

    @Override
    public void shutdown() {
        active = false;
    }

    @Override
    public boolean isActive() {
        return active;
    }

    @Override
    public double getSignalStrengthForPair(String from, String to) {
        strengthsAsked.incrementAndGet();
        return strengths.getOrDefault(key(from, to), 0.0);
    }

    @Override
    public boolean connectionIsPossibleForPair(String from, String to) {
        return allowed.getOrDefault(key(from, to), true);
    }
}
