package org.usarsim.wss.shaping;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class LossTableTest {

    private final LossTable table = LossTable.parse("-85:1,-88:10,-91:50");

    @ParameterizedTest(name = "{0} dBm loses {1} %")
    @CsvSource({"0,0", "-84.9,0", "-85,1", "-87.9,1", "-88,10", "-90,10", "-91,50", "-120,50", "-Infinity,50", "Infinity,0", "NaN,0"})
    void aStrengthAtOrBelowARowLosesTheLastSuchRowsPercent(double dBm, double percent) {
        assertEquals(percent, table.percentFor(dBm));
    }

    @Test
    void theTextIsReadBackCanonicalAndEmptyIsNoLoss() {
        assertEquals("-85:1,-88:10,-91:50", LossTable.parse(" -85 : 1 , -88:10.0,-91:50 ").toString());
        assertEquals(table, LossTable.parse("-85:1,-88:10,-91:50"));
        assertEquals(LossTable.NONE, LossTable.parse(" "));
        assertEquals(0, LossTable.NONE.percentFor(-200));
        assertEquals("-85:1,-87:10,-90:50", LossTable.DEFAULT.toString());
        assertEquals(List.of(-85.0, -88.0, -91.0), table.strengths());
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "-88:10,-85:1|rows must go from the strongest to the weakest signal",
        "-85:1,|row 2 is empty",
        "-85=1|row 1 (-85=1) is not dBm:percent",
        "loud:1|loud is not a number of dBm",
        "-85:101|101 is not a percent from 0 to 100",
        "-85:-1|-1 is not a percent from 0 to 100",
        "-85:|the percent is missing",
    })
    void aBadTableSaysWhatIsWrong(String text, String problem) {
        String message = assertThrows(IllegalArgumentException.class, () -> LossTable.parse(text)).getMessage();
        assertTrue(message.contains(problem), message);
        assertTrue(message.startsWith("\"" + text + "\""), message);
    }

    @Test
    void theShapingSettingsCarryTheTableAndOffLosesNothing() {
        ShapingConfig on = ShapingConfig.from(Map.of(ShapingConfig.SHAPING, "on", ShapingConfig.LOSS, "-85:1,-88:10,-91:50"));
        assertEquals(10, on.lossPercent(-89));
        ShapingConfig off = ShapingConfig.from(Map.of(ShapingConfig.LOSS, "-85:1,-88:10,-91:50"));
        assertEquals(0, off.lossPercent(-89));
        assertEquals(LossTable.DEFAULT, ShapingConfig.from(Map.of()).loss());
        String message = assertThrows(IllegalArgumentException.class,
                () -> ShapingConfig.from(Map.of(ShapingConfig.LOSS, "-85:x"))).getMessage();
        assertTrue(message.startsWith("wss.shaping.loss: "), message);
    }
}
