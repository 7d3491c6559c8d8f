package org.usarsim.wss.app;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.usarsim.wss.hub.core.RatePin;
import org.usarsim.wss.model.RobotPair;
import org.usarsim.wss.shaping.Bitrate;
import org.usarsim.wss.shaping.ShapingConfig;

/**
 * {@code wss.force.up}: the pairs forced up from the start, each {@code A:B}, and with links
 * shaped {@code A:B:RATE}, {@code A:B:RATE:DELAY} or {@code A:B:RATE:DELAY:JITTER} to pin the pair's
 * rate (bit/s, {@code k} and {@code M} allowed), delay and jitter (ms), as
 * {@code FORCE ... {State Up} {Rate r} {Delay d} {Jitter j}} does; an empty RATE ({@code A:B::50})
 * pins the delay only, an empty DELAY before a JITTER ({@code A:B:::20}) the jitter only.
 */
record ForcedUp(List<RobotPair> pairs, Map<RobotPair, RatePin> pins) {

    /** What {@link #parse} accepts, in words. */
    static final String WORDS = "a comma-separated list of robot pairs A:B, each with an optional :RATE, :DELAY and :JITTER"
            + " (R1:R2:1M:50:20; two different names without whitespace, braces, ':' or ',')";

    /** @throws IllegalArgumentException saying what the list should be, and which item is not */
    static ForcedUp parse(String text) {
        List<RobotPair> pairs = new ArrayList<>();
        Map<RobotPair, RatePin> pins = new LinkedHashMap<>();
        if (text == null || text.isBlank()) {
            return new ForcedUp(pairs, pins);
        }
        for (String item : text.split(",", -1)) {
            String[] parts = item.strip().split(":", -1);
            List<RobotPair> pair = parts.length >= 2 ? RobotPair.listOf(parts[0] + ":" + parts[1]) : null;
            if (pair == null || parts.length > 5) {
                throw new IllegalArgumentException(WORDS + ": '" + item.strip() + "' is not A:B, A:B:RATE, A:B:RATE:DELAY or"
                        + " A:B:RATE:DELAY:JITTER");
            }
            long rate = 0;
            int delay = -1;
            int jitter = -1;
            try {
                rate = parts.length > 2 && !parts[2].isBlank() ? Bitrate.parse(parts[2]) : 0;
                delay = parts.length > 3 && !(parts.length > 4 && parts[3].isBlank()) ? ShapingConfig.parseDelayMs(parts[3]) : -1;
                jitter = parts.length > 4 ? ShapingConfig.parseJitterMs(parts[4]) : -1;
            } catch (IllegalArgumentException e) {
                throw new IllegalArgumentException(WORDS + ": '" + item.strip() + "': " + e.getMessage(), e);
            }
            pairs.add(pair.get(0));
            RatePin pin = new RatePin(rate, delay, jitter);
            if (!pin.equals(RatePin.NONE)) {
                pins.put(pair.get(0), pin);
            }
        }
        return new ForcedUp(List.copyOf(pairs), Map.copyOf(pins));
    }
}
