package org.usarsim.wss.hub;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalDouble;
import java.util.logging.Level;
import java.util.logging.Logger;
import org.usarsim.wss.hub.core.Measurement;
import org.usarsim.wss.hub.core.OrderedPair;
import org.usarsim.wss.model.PropagationModel;
import org.usarsim.wss.model.Replay;
import org.usarsim.wss.model.RobotPair;

/**
 * The hub's questions to the model, each with what a model that throws means: never asked under
 * the hub's lock (a model may call back into the hub from its own thread while holding its own).
 */
final class ModelAnswers {

    /** The hub's log: its model failures are the hub's lines. */
    private static final Logger LOG = Logger.getLogger("org.usarsim.wss.hub.Hub");

    private final PropagationModel model;

    ModelAnswers(PropagationModel model) {
        this.model = model;
    }

    String name() {
        return model.name();
    }

    /** The model's replay controls (REPLAY); a model that throws has none, and a WARNING says so. */
    Optional<Replay> replay() {
        try {
            return model.replay();
        } catch (RuntimeException e) {
            LOG.log(Level.WARNING, model.name() + " failed to give its replay controls: " + e, e);
            return Optional.empty();
        }
    }

    /** Whether {@code from} may connect to {@code to} now; a model that throws says no, and a WARNING says so. */
    boolean allows(String from, String to) {
        try {
            return model.connectionIsPossibleForPair(from, to);
        } catch (RuntimeException e) {
            LOG.log(Level.WARNING, model.name() + " failed to say whether " + from + " -> " + to + " may connect: " + e, e);
            return false;
        }
    }

    /** GETSS's strength; a model that throws gives NaN, and a WARNING says so. */
    OptionalDouble signalStrength(String from, String to) {
        try {
            return OptionalDouble.of(model.getSignalStrengthForPair(from, to));
        } catch (RuntimeException e) {
            LOG.log(Level.WARNING, model.name() + " failed to give the strength " + from + " -> " + to + ": " + e, e);
            return OptionalDouble.of(Double.NaN);
        }
    }

    /** The strength for the statistics: NaN for a robot the model does not know (gone, say). */
    double strength(String from, String to) {
        try {
            return model.getSignalStrengthForPair(from, to);
        } catch (RuntimeException e) {
            return Double.NaN;
        }
    }

    /** The distance between the robots' positions, NaN unless the model knows both. */
    double distance(String first, String second) {
        try {
            var a = model.positionOf(first);
            var b = model.positionOf(second);
            return a.isPresent() && b.isPresent() ? a.get().distanceTo(b.get()) : Double.NaN;
        } catch (RuntimeException e) {
            return Double.NaN;
        }
    }

    /** With links shaped: what the model says of the pairs, both ways (strength, and its own rate and delay if any). */
    Map<OrderedPair, Measurement> measure(List<RobotPair> pairs) {
        Map<OrderedPair, Measurement> measurements = new HashMap<>();
        for (RobotPair pair : pairs) {
            OrderedPair way = new OrderedPair(pair.first(), pair.second());
            measurements.put(way, measurement(way));
            measurements.put(way.reversed(), measurement(way.reversed()));
        }
        return measurements;
    }

    private Measurement measurement(OrderedPair way) {
        try {
            return new Measurement(model.getSignalStrengthForPair(way.from(), way.to()), model.linkQualityForPair(way.from(), way.to()));
        } catch (RuntimeException e) {
            return Measurement.NONE; // a robot the model does not know (gone, say): the lowest rate
        }
    }
}
