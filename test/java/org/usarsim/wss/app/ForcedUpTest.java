package org.usarsim.wss.app;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Map;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.hub.core.RatePin;
import org.usarsim.wss.model.RobotPair;

/** {@code wss.force.up}'s pins: a rate, a delay and (issue 35) a jitter, each optional. */
class ForcedUpTest {

    @Test
    void aPairMayPinItsRateDelayAndJitterEachAlone() {
        ForcedUp up = ForcedUp.parse("A:B:1M:50:20, C:D:::15, E:F::30, G:H:2M, I:J");
        assertEquals(Map.of(RobotPair.of("A", "B"), new RatePin(1_000_000, 50, 20), RobotPair.of("C", "D"), new RatePin(0, -1, 15),
                RobotPair.of("E", "F"), new RatePin(0, 30, -1), RobotPair.of("G", "H"), new RatePin(2_000_000, -1, -1)), up.pins());
        assertEquals(5, up.pairs().size());
    }
}
