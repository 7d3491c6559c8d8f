package org.usarsim.wss.shaping;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

/** The table from signal strength to rate: reading it, refusing it, and looking a strength up. */
class RateTableTest {

    @Test
    void theDefaultIsTheDataSheetsTable() {
        assertEquals("-72:54M,-73:48M,-77:36M,-81:24M,-83:18M,-85:12M,-86:9M,-87:6M", RateTable.DEFAULT.toString());
        assertEquals(RateTable.DEFAULT, RateTable.parse(RateTable.DEFAULT.toString()));
        assertEquals(54_000_000, RateTable.DEFAULT.topRate());
        assertEquals(6_000_000, RateTable.DEFAULT.lowestRate());
    }

    @Test
    void aStrengthGetsTheFirstStepItReaches() {
        RateTable table = RateTable.DEFAULT;
        assertEquals(54_000_000, table.rateFor(-50));
        assertEquals(54_000_000, table.rateFor(-72), "at a step's dBm: that step");
        assertEquals(48_000_000, table.rateFor(-72.5));
        assertEquals(48_000_000, table.rateFor(-73));
        assertEquals(36_000_000, table.rateFor(-73.01));
        assertEquals(9_000_000, table.rateFor(-86));
        assertEquals(6_000_000, table.rateFor(-87));
        assertEquals(6_000_000, table.rateFor(-92.9), "below the last step: the last step's rate");
        assertEquals(6_000_000, table.rateFor(Double.NEGATIVE_INFINITY));
        assertEquals(54_000_000, table.rateFor(0), "the Noop model's 0 dBm: the top rate");
        assertEquals(54_000_000, table.rateFor(Double.POSITIVE_INFINITY), "the same place");
        assertEquals(6_000_000, table.rateFor(Double.NaN), "a model that cannot say: the lowest rate");
    }

    @Test
    void aNanStrengthGetsTheLowestRateEvenWhenItIsNotTheLast() {
        RateTable table = RateTable.parse("-60:1M,-70:54M");
        assertEquals(1_000_000, table.rateFor(Double.NaN));
        assertEquals(54_000_000, table.rateFor(-80));
    }

    @Test
    void whitespaceAroundItemsIsToleratedAndTheTextComesBackCanonical() {
        RateTable table = RateTable.parse("  -72 : 54M ,\t-87.5:6000k , -90:512000 ");
        assertEquals("-72:54M,-87.5:6M,-90:512k", table.toString());
        assertEquals(512_000, table.rateFor(-95));
        assertEquals("3:11M,-80:1M", RateTable.parse("+3:11M,-80:1M").toString());
    }

    @Test
    void everyMistakeIsOneLineNamingTheTable() {
        assertRefused("-74:48M,-72:54M", "\"-74:48M,-72:54M\": steps must go from the strongest to the weakest signal");
        assertRefused("-72:54M,-72:48M", "\"-72:54M,-72:48M\": steps must go from the strongest to the weakest signal");
        assertRefused("", "\"\": no steps; give dBm:rate steps from the strongest signal to the weakest, e.g. -72:54M,-87:6M");
        assertRefused(" ", "\" \": no steps; give dBm:rate steps from the strongest signal to the weakest, e.g. -72:54M,-87:6M");
        assertRefused(null, "\"\": no steps; give dBm:rate steps from the strongest signal to the weakest, e.g. -72:54M,-87:6M");
        assertRefused("-72:54M,", "\"-72:54M,\": step 2 is empty");
        assertRefused("-72:54M,,-87:6M", "\"-72:54M,,-87:6M\": step 2 is empty");
        assertRefused("-72=54M", "\"-72=54M\": step 1 (-72=54M) is not dBm:rate");
        assertRefused("-72:54M:6M", "\"-72:54M:6M\": step 1 (-72:54M:6M) is not dBm:rate");
        assertRefused("strong:54M", "\"strong:54M\": step 1 (strong:54M): strong is not a number of dBm");
        assertRefused("NaN:54M", "\"NaN:54M\": step 1 (NaN:54M): NaN is not a number of dBm");
        assertRefused(":54M", "\":54M\": step 1 (:54M): the dBm is missing");
        assertRefused("-72:", "\"-72:\": step 1 (-72:): the rate is missing");
        assertRefused("-72:54M,-80:fast", "\"-72:54M,-80:fast\": step 2 (-80:fast): fast is not a bit rate"
                + " (a number of bit/s, with k for 1000 or M for 1000000: 800, 512k, 1.5M, 54M)");
        assertRefused("-72:0", "\"-72:0\": step 1 (-72:0): 0 is not above 0");
        assertRefused("-72:-6M", "\"-72:-6M\": step 1 (-72:-6M): -6M is not above 0");
        assertRefused("-72:1.5", "\"-72:1.5\": step 1 (-72:1.5): 1.5 is not a whole number of bit/s");
    }

    private static void assertRefused(String text, String message) {
        assertEquals(message, assertThrows(IllegalArgumentException.class, () -> RateTable.parse(text)).getMessage());
    }
}
