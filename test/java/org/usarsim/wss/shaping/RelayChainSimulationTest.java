package org.usarsim.wss.shaping;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import org.junit.jupiter.api.Test;

/**
 * Issue 34's bound against the shaping itself, on a moved clock: a stream relayed over 1 to 3
 * hops of shared airtime gets the route's computed rate when the link threads wake on time, and
 * falls short of it only as far as they wake late (docs/routes.md, "The bound against reality").
 */
class RelayChainSimulationTest {

    private static final long SECOND = 1_000_000_000;
    private static final long RELAY_BUFFER = 160 * 1024;

    @Test
    void threadsWakingOnTimeGetEveryChainsComputedRate() {
        for (boolean lastFirst : new boolean[] {false, true}) {
            for (long[] rates : RelayChainSimulation.CHAINS) {
                long bound = RelayChainSimulation.bound(rates);
                double got = RelayChainSimulation.throughput(new RelayChainSimulation(rates, RELAY_BUFFER, 0, 34, lastFirst),
                        SECOND, 3 * SECOND);
                assertEquals(bound, got, bound * 0.005, Arrays.toString(rates) + (lastFirst ? ", the last hop's thread first" : ""));
            }
        }
    }

    @Test
    void theSlowMiddleHopFindsBothRelaysRadiosFreeAtOnce() {
        long[] rates = {12_000_000, 6_000_000, 12_000_000};
        assertEquals(4_000_000, RelayChainSimulation.bound(rates), "12 x 6 / (12 + 6) Mbit/s at each relay");
        for (long buffer : new long[] {16 * 1024, 32 * 1024, RELAY_BUFFER}) {
            double got = RelayChainSimulation.throughput(rates, buffer, 0, 2 * SECOND, 3 * SECOND);
            assertEquals(4_000_000, got, 20_000, "relays buffering " + buffer + " bytes");
        }
    }

    @Test
    void lateThreadsGetLessTheLaterTheyWake() {
        long[] rates = {12_000_000, 6_000_000, 12_000_000};
        double previous = RelayChainSimulation.throughput(rates, RELAY_BUFFER, 0, SECOND, 3 * SECOND);
        for (long lateMs : new long[] {1, 3}) {
            double got = RelayChainSimulation.throughput(rates, RELAY_BUFFER, lateMs * 1_000_000, SECOND, 3 * SECOND);
            assertTrue(got < previous, lateMs + " ms late: " + got + ", not less than " + previous);
            previous = got;
        }
        assertTrue(previous < 0.97 * 4_000_000, "3 ms late on average: " + previous + " bit/s");
    }

    @Test
    void relaysHandingRoomBackInStepsStillGetWithin5PercentOfEveryChainsComputedRate() {
        // Taking turns while its relay's socket was full, the hop into a relay took the turns of the
        // slow middle hop: 12M, 6M, 12M got 0.857 of its bound with 8 KiB steps (first come), and
        // filling gaps alone 1.000 with 8 KiB but 0.892 with 32 KiB, as the real relays' windows give.
        for (long step : new long[] {8192, 32768}) {
            for (long[] rates : RelayChainSimulation.CHAINS) {
                long bound = RelayChainSimulation.bound(rates);
                double got = RelayChainSimulation.throughput(new RelayChainSimulation(rates, RELAY_BUFFER, step, 0, 34, false),
                        SECOND, 3 * SECOND);
                assertTrue(got >= 0.95 * bound && got <= 1.005 * bound, Arrays.toString(rates) + " in steps of " + step + ": " + got);
            }
        }
    }
}
