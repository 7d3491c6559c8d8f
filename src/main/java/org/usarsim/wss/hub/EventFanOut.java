package org.usarsim.wss.hub;

import java.net.InetAddress;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Consumer;
import java.util.logging.Level;
import java.util.logging.Logger;
import org.usarsim.wss.hub.core.EventSink;
import org.usarsim.wss.model.ModelPoll;
import org.usarsim.wss.model.WssEventListener;

/**
 * Hands every event to every listener, a listener that throws is logged, never fatal; and the
 * hub's own lines to its log, the WARNINGs a client caused through the limiter.
 */
final class EventFanOut implements EventSink {

    private static final Logger LOG = Logger.getLogger(EventFanOut.class.getName());

    private final List<WssEventListener> listeners = new CopyOnWriteArrayList<>();
    /** Where the hub's own lines go. */
    private final Logger hubLog;
    private final WarningLimiter warnings;

    EventFanOut(Logger hubLog, WarningLimiter warnings) {
        this.hubLog = hubLog;
        this.warnings = warnings;
    }

    @Override
    public void say(Level level, String kind, String line) {
        warnings.say(hubLog, level, kind, null, line);
    }

    @Override
    public void warn(String category, InetAddress client, String message) {
        warnings.warn(hubLog, category, client, message);
    }

    void add(WssEventListener listener) {
        listeners.add(listener);
    }

    void remove(WssEventListener listener) {
        listeners.remove(listener);
    }

    private void each(Consumer<WssEventListener> call) {
        for (WssEventListener listener : listeners) {
            try {
                call.accept(listener);
            } catch (RuntimeException | LinkageError | AssertionError e) {
                listenerFailed(e);
            }
        }
    }

    /** A listener (a plugin's) that fails at every event would fill the log: limited as clients' warnings. */
    private void listenerFailed(Throwable e) {
        warnings.warn(LOG, "failed event listeners", null, "an event listener failed: " + e, e);
    }

    @Override
    public void robotRegistered(String robot, String address, List<Integer> ports) {
        each(l -> l.robotRegistered(robot, address, ports));
    }

    @Override
    public void robotDeregistered(String robot) {
        each(l -> l.robotDeregistered(robot));
    }

    @Override
    public void robotOutOfBattery(String robot) {
        each(l -> l.robotOutOfBattery(robot));
    }

    @Override
    public void connectionOutOfRange(String from, String to, double strength, double distance) {
        each(l -> l.connectionOutOfRange(from, to, strength, distance));
    }

    @Override
    public void connectionInRange(String from, String to) {
        each(l -> l.connectionInRange(from, to));
    }

    @Override
    public void connectionEstablished(String from, String to, int targetPort) {
        each(l -> l.connectionEstablished(from, to, targetPort));
    }

    @Override
    public void connectionTerminated(String from, String to, int targetPort) {
        each(l -> l.connectionTerminated(from, to, targetPort));
    }

    @Override
    public void portAllocated(String from, String to, int targetPort, int wssPort, boolean listening) {
        each(l -> l.portAllocated(from, to, targetPort, wssPort, listening));
    }

    @Override
    public void portListening(String from, String to, int targetPort, int wssPort, boolean listening) {
        each(l -> l.portListening(from, to, targetPort, wssPort, listening));
    }

    @Override
    public void portForgotten(String from, String to, int targetPort, int wssPort) {
        each(l -> l.portForgotten(from, to, targetPort, wssPort));
    }

    @Override
    public void rateChanged(String from, String to, long bitsPerSecond) {
        each(l -> l.rateChanged(from, to, bitsPerSecond));
    }

    @Override
    public void replayMoved(double timeSeconds, double speed, boolean playing) {
        each(l -> l.replayMoved(timeSeconds, speed, playing));
    }

    @Override
    public void pairForced(String first, String second, boolean up) {
        each(l -> l.pairForced(first, second, up));
    }

    @Override
    public void pairPinned(String first, String second, long bitsPerSecond, int delayMs, int jitterMs) {
        each(l -> l.pairPinned(first, second, bitsPerSecond, delayMs, jitterMs));
    }

    @Override
    public void pairReleased(String first, String second) {
        each(l -> l.pairReleased(first, second));
    }

    @Override
    public void polled(ModelPoll poll) {
        each(l -> l.polled(poll));
    }

    @Override
    public void udpCounted(String from, String to, int fixedPort, long datagrams, long bytes, long droppedBroken, long droppedQueue,
            long lost) {
        each(l -> l.udpCounted(from, to, fixedPort, datagrams, bytes, droppedBroken, droppedQueue, lost));
    }

    /** Called per forwarded chunk: a plain loop, so that no lambda is made per chunk. */
    @Override
    public void dataSent(String from, String to, int bytes) {
        for (WssEventListener listener : listeners) {
            try {
                listener.dataSent(from, to, bytes);
            } catch (RuntimeException | LinkageError | AssertionError e) {
                listenerFailed(e);
            }
        }
    }

    @Override
    public void cutOff(String robot) {
        each(l -> l.cutOff(robot));
    }

    @Override
    public void routedToBase(String robot, int hops, String path, long bitsPerSecond) {
        each(l -> l.routedToBase(robot, hops, path, bitsPerSecond));
    }
}
