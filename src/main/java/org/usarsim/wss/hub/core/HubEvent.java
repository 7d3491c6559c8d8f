package org.usarsim.wss.hub.core;

import java.net.InetAddress;
import java.util.List;
import java.util.logging.Level;
import org.usarsim.wss.model.ModelPoll;

/**
 * What happened in the hub, as data: the core appends these to {@link Changes} in the order the
 * changes happened, and the hub delivers them in that order after its lock ({@link #deliverTo}).
 */
public sealed interface HubEvent {

    void deliverTo(EventSink sink);

    record Registered(String robot, String address, List<Integer> ports) implements HubEvent {
        public void deliverTo(EventSink sink) {
            sink.robotRegistered(robot, address, ports);
        }
    }

    record Deregistered(String robot) implements HubEvent {
        public void deliverTo(EventSink sink) {
            sink.robotDeregistered(robot);
        }
    }

    record PortAllocated(PortKey key, int number, boolean listening) implements HubEvent {
        public void deliverTo(EventSink sink) {
            sink.portAllocated(key.from(), key.to(), key.targetPort(), number, listening);
        }
    }

    record PortListening(PortKey key, int number, boolean listening) implements HubEvent {
        public void deliverTo(EventSink sink) {
            sink.portListening(key.from(), key.to(), key.targetPort(), number, listening);
        }
    }

    record PortForgotten(PortKey key, int number) implements HubEvent {
        public void deliverTo(EventSink sink) {
            sink.portForgotten(key.from(), key.to(), key.targetPort(), number);
        }
    }

    record PairForced(String first, String second, boolean up) implements HubEvent {
        public void deliverTo(EventSink sink) {
            sink.pairForced(first, second, up);
        }
    }

    /** The shape an operator pinned on a pair forced up (issue 35: recorded, so that the jitter is too). */
    record PairPinned(String first, String second, RatePin pin) implements HubEvent {
        public void deliverTo(EventSink sink) {
            sink.pairPinned(first, second, pin.bitsPerSecond(), pin.delayMs(), pin.jitterMs());
        }
    }

    record PairReleased(String first, String second) implements HubEvent {
        public void deliverTo(EventSink sink) {
            sink.pairReleased(first, second);
        }
    }

    record Established(PortKey key) implements HubEvent {
        public void deliverTo(EventSink sink) {
            sink.connectionEstablished(key.from(), key.to(), key.targetPort());
        }
    }

    record Terminated(PortKey key) implements HubEvent {
        public void deliverTo(EventSink sink) {
            sink.connectionTerminated(key.from(), key.to(), key.targetPort());
        }
    }

    /** With links shaped: a pair's rate one way was set or changed. */
    record RateChanged(OrderedPair way, long bitsPerSecond) implements HubEvent {
        public void deliverTo(EventSink sink) {
            sink.rateChanged(way.from(), way.to(), bitsPerSecond);
        }
    }

    /** The model's: a pair out of range. */
    record OutOfRange(String from, String to, double strength, double distance) implements HubEvent {
        public void deliverTo(EventSink sink) {
            sink.connectionOutOfRange(from, to, strength, distance);
        }
    }

    /** The model's: a pair in range again. */
    record InRange(String from, String to) implements HubEvent {
        public void deliverTo(EventSink sink) {
            sink.connectionInRange(from, to);
        }
    }

    /** The model's: a robot out of battery. */
    record OutOfBattery(String robot) implements HubEvent {
        public void deliverTo(EventSink sink) {
            sink.robotOutOfBattery(robot);
        }
    }

    /** The model's: what one poll of the simulator learned and decided (a recording writes it). */
    record ReplayMoved(double timeSeconds, double speed, boolean playing) implements HubEvent {
        public void deliverTo(EventSink sink) {
            sink.replayMoved(timeSeconds, speed, playing);
        }
    }

    record Polled(ModelPoll poll) implements HubEvent {
        public void deliverTo(EventSink sink) {
            sink.polled(poll);
        }
    }

    /**
     * The links a step closes, closed as its events are delivered, before them: a pair's FORCED or
     * BROKEN is said once its links can write and report nothing more (issue 27: one DATA_SENT
     * after a FORCED DOWN, from a link whose close was still to come). The step's socket work
     * closes them too (a close is done once).
     */
    record LinksClosed(List<Changes.Close> closes) implements HubEvent {
        public void deliverTo(EventSink sink) {
            closes.forEach(close -> close.link().close(close.reason()));
        }
    }

    /**
     * A line of the hub's log about its own changes; {@code kind} names what such lines have in
     * common, for the limit on them ("allocated WSS ports": docs/reliability.md).
     */
    record Said(Level level, String kind, String line) implements HubEvent {
        public void deliverTo(EventSink sink) {
            sink.say(level, kind, line);
        }
    }

    /** A WARNING a client caused. */
    record Warned(String category, InetAddress client, String message) implements HubEvent {
        public void deliverTo(EventSink sink) {
            sink.warn(category, client, message);
        }
    }

    /** A robot is cut off from the base (docs/routes.md). */
    record CutOff(String robot) implements HubEvent {
        public void deliverTo(EventSink sink) {
            sink.cutOff(robot);
        }
    }

    /** A robot has a route to the base, or another one (docs/routes.md). */
    record RoutedToBase(String robot, int hops, String path, long bitsPerSecond) implements HubEvent {
        public void deliverTo(EventSink sink) {
            sink.routedToBase(robot, hops, path, bitsPerSecond);
        }
    }
}
