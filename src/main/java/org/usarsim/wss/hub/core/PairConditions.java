package org.usarsim.wss.hub.core;

import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Function;
import java.util.function.Predicate;
import org.usarsim.wss.model.LinkQuality;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.shaping.ShapingConfig;

/**
 * Each seen pair's condition one way ({@link PairCondition}: its state and, with links shaped,
 * its rate and delay), the one value the link threads read as they forward (a {@link LiveCondition} each),
 * the statistics and the snapshot too; with what the model last said of each way, and which
 * ways' rates the event log has been told. Part of the {@link HubCore}, under its lock.
 */
final class PairConditions {

    private final ShapingConfig shaping;
    /** The operator's pins: they win over what the model says. */
    private final ForcedPairs forcedPairs;
    /** The pair's state now, as the core decides it. */
    private final Function<RobotPair, PairState> stateOf;
    /** What the model last said of each pair one way (with shaping on). */
    private final Map<OrderedPair, Measurement> measured = new HashMap<>();
    private final Map<OrderedPair, LiveCondition> conditions = new HashMap<>();
    /** The ways whose rate the event log has been told (a RATE line): each is said once, then at each change. */
    private final Set<OrderedPair> said = new HashSet<>();

    PairConditions(ShapingConfig shaping, ForcedPairs forcedPairs, Function<RobotPair, PairState> stateOf) {
        this.shaping = shaping;
        this.forcedPairs = forcedPairs;
        this.stateOf = stateOf;
    }

    /** The pair is seen: its conditions both ways are kept from now on (their rates said, with shaping on). */
    void seen(RobotPair pair, Changes out) {
        for (OrderedPair way : ways(pair)) {
            if (!conditions.containsKey(way)) {
                PairCondition condition = conditionOf(way);
                conditions.put(way, new LiveCondition(condition));
                if (condition.shaped() && measured.containsKey(way)) { // otherwise said at the first measurement
                    said.add(way);
                    out.add(new HubEvent.RateChanged(way, condition.bitsPerSecond()));
                }
            }
        }
    }

    /** The live cell of a seen pair's condition one way. */
    LiveCondition cell(OrderedPair way) {
        return conditions.get(way);
    }

    private static List<OrderedPair> ways(RobotPair pair) {
        OrderedPair way = new OrderedPair(pair.first(), pair.second());
        return List.of(way, way.reversed());
    }

    /**
     * The one place a pair's condition one way is computed: its state (a force wins over the
     * model's verdict), and with shaping on its rate and delay: an operator's pin wins, then what
     * the model says of the link ({@code linkQualityForPair}), then the rate table for the
     * model's strength and the delay setting; the loss percent of datagrams from the loss table
     * for the model's strength (a pin pins rate and delay, not the loss).
     */
    private PairCondition conditionOf(OrderedPair way) {
        RobotPair pair = RobotPair.of(way.from(), way.to());
        PairState state = stateOf.apply(pair);
        if (!shaping.on()) {
            return new PairCondition(state, 0, 0);
        }
        RatePin pin = forcedPairs.pinOf(pair);
        Measurement measurement = measured.getOrDefault(way, Measurement.NONE);
        long rate = pin.pinsRate() ? pin.bitsPerSecond()
                : measurement.quality().map(LinkQuality::bitsPerSecond).orElseGet(() -> shaping.rates().rateFor(measurement.strength()));
        int delay = pin.pinsDelay() ? pin.delayMs() : measurement.quality().map(LinkQuality::delayMs).orElse(shaping.delayMs());
        int jitter = pin.pinsJitter() ? pin.jitterMs() : shaping.jitter().ms();
        return new PairCondition(state, rate, delay, shaping.lossPercent(measurement.strength()), jitter,
                measurement.quality().map(LinkQuality::datagramLoss).orElse(null));
    }

    /** Recomputes the pair's conditions both ways (those kept); a rate that changed is said. */
    void refresh(RobotPair pair, Changes out) {
        for (OrderedPair way : ways(pair)) {
            LiveCondition cell = conditions.get(way);
            if (cell != null) {
                PairCondition now = conditionOf(way);
                PairCondition before = cell.set(now);
                boolean firstSaid = measured.containsKey(way) && !said.contains(way);
                if (now.shaped() && (now.bitsPerSecond() != before.bitsPerSecond() || firstSaid)) {
                    said.add(way);
                    out.add(new HubEvent.RateChanged(way, now.bitsPerSecond()));
                }
            }
        }
    }

    /** The seen pairs, whose strength the hub asks the model for a few times a second with links shaped. */
    List<RobotPair> pairs() {
        return conditions.keySet().stream().map(way -> RobotPair.of(way.from(), way.to())).distinct().toList();
    }

    /** What the model said of these pairs, each way: their rates follow. */
    void measured(Map<OrderedPair, Measurement> measurements, Changes out) {
        measured.putAll(measurements);
        measurements.keySet().stream().map(way -> RobotPair.of(way.from(), way.to())).distinct().forEach(pair -> refresh(pair, out));
    }

    /** Every seen pair's condition one way, now. */
    Map<OrderedPair, PairCondition> now() {
        Map<OrderedPair, PairCondition> now = new HashMap<>();
        conditions.forEach((way, cell) -> now.put(way, cell.get()));
        return now;
    }

    /** The robot's ports were forgotten: so are the conditions of its pairs that are {@code gone}. */
    void forget(String name, Predicate<RobotPair> gone) {
        conditions.keySet().removeIf(way -> (way.from().equals(name) || way.to().equals(name)) && gone.test(RobotPair.of(way.from(), way.to())));
        measured.keySet().retainAll(conditions.keySet());
        said.retainAll(conditions.keySet());
    }
}
