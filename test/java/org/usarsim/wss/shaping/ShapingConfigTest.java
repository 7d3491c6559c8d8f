package org.usarsim.wss.shaping;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashMap;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** The shaping settings of a run: defaults, values, and one line for each bad value. */
class ShapingConfigTest {

    @Test
    void theQueueIs20MsByDefaultAndFrom10To10000Ms() {
        assertEquals(20, ShapingConfig.from(Map.of()).queueMs());
        assertEquals(250, ShapingConfig.from(Map.of(ShapingConfig.QUEUE_MS, " 250 ")).queueMs());
        for (String bad : new String[] {"9", "10001", "soon", ""}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                    () -> ShapingConfig.from(Map.of(ShapingConfig.QUEUE_MS, bad)));
            assertTrue(e.getMessage().startsWith("wss.shaping.queueMs: "), e.getMessage());
        }
    }

    @Test
    void withNothingGivenShapingIsOff() {
        ShapingConfig config = ShapingConfig.from(Map.of("wss.chunkSize", "4096"));
        assertEquals(ShapingConfig.OFF, config);
        assertFalse(config.on());
        assertEquals(RateTable.DEFAULT, config.rates());
        assertEquals(2, config.delayMs());
        assertTrue(config.airtime(), "airtime is shared by default once shaping is on");
    }

    @Test
    void readsEveryKey() {
        ShapingConfig config = ShapingConfig.from(Map.of("wss.shaping", " ON ", "wss.shaping.rates", "-70:11M, -80:1M",
                "wss.shaping.delayMs", " 50", "wss.shaping.airtime", "False"));
        assertEquals(new ShapingConfig(true, RateTable.parse("-70:11M,-80:1M"), 50, false), config);
        assertEquals(0, ShapingConfig.from(Map.of("wss.shaping.delayMs", "0")).delayMs());
        assertEquals(10_000, ShapingConfig.from(Map.of("wss.shaping.delayMs", "10000")).delayMs());
    }

    @Test
    void eachBadValueIsOneLineNamingTheKeyAndTheValue() {
        assertRefused("wss.shaping", "maybe", "wss.shaping: maybe is not on or off");
        assertRefused("wss.shaping", "", "wss.shaping: an empty value is not on or off");
        assertRefused("wss.shaping.rates", "-74:48M,-72:54M",
                "wss.shaping.rates: \"-74:48M,-72:54M\": steps must go from the strongest to the weakest signal");
        assertRefused("wss.shaping.rates", "",
                "wss.shaping.rates: \"\": no steps; give dBm:rate steps from the strongest signal to the weakest, e.g. -72:54M,-87:6M");
        assertRefused("wss.shaping.rates", "-72:54M,-80:x", "wss.shaping.rates: \"-72:54M,-80:x\": step 2 (-80:x): x is not a bit rate"
                + " (a number of bit/s, with k for 1000 or M for 1000000: 800, 512k, 1.5M, 54M)");
        assertRefused("wss.shaping.rates", "-72:0", "wss.shaping.rates: \"-72:0\": step 1 (-72:0): 0 is not above 0");
        assertRefused("wss.shaping.rates", "-72:-54M", "wss.shaping.rates: \"-72:-54M\": step 1 (-72:-54M): -54M is not above 0");
        assertRefused("wss.shaping.rates", "loud:54M", "wss.shaping.rates: \"loud:54M\": step 1 (loud:54M): loud is not a number of dBm");
        assertRefused("wss.shaping.delayMs", "-1", "wss.shaping.delayMs: -1 is below 0");
        assertRefused("wss.shaping.delayMs", "10001", "wss.shaping.delayMs: 10001 is above 10000");
        assertRefused("wss.shaping.delayMs", "99999999999999999999", "wss.shaping.delayMs: 99999999999999999999 is above 10000");
        assertRefused("wss.shaping.delayMs", "2.5", "wss.shaping.delayMs: 2.5 is not a whole number of milliseconds");
        assertRefused("wss.shaping.delayMs", "soon", "wss.shaping.delayMs: soon is not a whole number of milliseconds");
        assertRefused("wss.shaping.delayMs", "", "wss.shaping.delayMs: an empty value is not a whole number of milliseconds");
        assertRefused("wss.shaping.airtime", "yes", "wss.shaping.airtime: yes is not true or false");
    }

    @Test
    void badValuesAreFoundWithShapingOffToo() {
        Map<String, String> values = new HashMap<>();
        values.put("wss.shaping", "off");
        values.put("wss.shaping.delayMs", "-1");
        assertEquals("wss.shaping.delayMs: -1 is below 0",
                assertThrows(IllegalArgumentException.class, () -> ShapingConfig.from(values)).getMessage());
    }

    @Test
    void aForcedDelayIsReadByTheSameRule() {
        assertEquals(50, ShapingConfig.parseDelayMs("50"));
        assertEquals(0, ShapingConfig.parseDelayMs(" 0 "));
        assertEquals("-1 is below 0", assertThrows(IllegalArgumentException.class, () -> ShapingConfig.parseDelayMs("-1")).getMessage());
        assertEquals("1s is not a whole number of milliseconds",
                assertThrows(IllegalArgumentException.class, () -> ShapingConfig.parseDelayMs("1s")).getMessage());
        assertEquals("wss.shaping.delayMs: 10001 is above 10000",
                assertThrows(IllegalArgumentException.class, () -> new ShapingConfig(true, RateTable.DEFAULT, 10_001, true)).getMessage());
    }

    private static void assertRefused(String key, String value, String message) {
        Map<String, String> values = new HashMap<>();
        values.put("wss.shaping", "on");
        values.put(key, value);
        assertEquals(message, assertThrows(IllegalArgumentException.class, () -> ShapingConfig.from(values)).getMessage());
    }

    @Test
    void theJitterIsOffInOrderAndSeededByDefaultAndEachKeyIsChecked() {
        assertEquals(new JitterConfig(0, JitterDistribution.UNIFORM, false, 0), ShapingConfig.from(Map.of()).jitter(),
                "no jitter; netem's default distribution; in order; a fixed seed: a run is repeatable");
        ShapingConfig set = ShapingConfig.from(Map.of("wss.shaping.jitter", "20", "wss.shaping.jitterDistribution", "Pareto",
                "wss.shaping.reorder", "TRUE", "wss.seed", "-12"));
        assertEquals(new JitterConfig(20, JitterDistribution.PARETO, true, -12), set.jitter());
        assertEquals(set.jitter(), set.withLoss(LossTable.DEFAULT).jitter());
        assertEquals("wss.shaping.jitter: 10001 is above 10000",
                assertThrows(IllegalArgumentException.class, () -> ShapingConfig.from(Map.of("wss.shaping.jitter", "10001"))).getMessage());
        assertEquals("wss.shaping.jitter: -1 is below 0", assertThrows(IllegalArgumentException.class,
                () -> ShapingConfig.from(Map.of("wss.shaping.jitter", "-1"))).getMessage());
        assertEquals("wss.shaping.jitterDistribution: gaussian is not uniform, normal, pareto or paretonormal", assertThrows(
                IllegalArgumentException.class, () -> ShapingConfig.from(Map.of("wss.shaping.jitterDistribution", "gaussian"))).getMessage());
        assertEquals("wss.shaping.reorder: yes is not true or false", assertThrows(IllegalArgumentException.class,
                () -> ShapingConfig.from(Map.of("wss.shaping.reorder", "yes"))).getMessage());
        assertEquals("wss.seed: 1.5 is not a whole number", assertThrows(IllegalArgumentException.class,
                () -> ShapingConfig.from(Map.of("wss.seed", "1.5"))).getMessage());
        assertEquals(20, ShapingConfig.parseJitterMs(" 20 "));
    }

    @Test
    void aDirectionsSeedFollowsTheRunsSeedAndItsRobots() {
        JitterConfig run = new JitterConfig(5, JitterDistribution.NORMAL, false, 1);
        assertEquals(run.seedFor("A", "B", 0), new JitterConfig(9, JitterDistribution.UNIFORM, true, 1).seedFor("A", "B", 0),
                "the same run seed, the same robots: the same draws");
        assertTrue(run.seedFor("A", "B", 0) != run.seedFor("B", "A", 0));
        assertTrue(run.seedFor("A", "B", 0) != run.seedFor("A", "B", 1));
        assertTrue(run.seedFor("A", "B", 0) != new JitterConfig(5, JitterDistribution.NORMAL, false, 2).seedFor("A", "B", 0));
    }
}
