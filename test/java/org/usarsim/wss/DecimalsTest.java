package org.usarsim.wss;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.math.BigDecimal;
import org.junit.jupiter.api.Test;

class DecimalsTest {

    @Test
    void aDoubleIsWrittenPlainlyWithoutTrailingZeros() {
        assertEquals("0.25", Decimals.plain(0.25));
        assertEquals("4", Decimals.plain(4.0));
        assertEquals("1000000", Decimals.plain(1e6));
        assertEquals("-49.67", Decimals.plain(-49.67));
        assertEquals("0", Decimals.plain(0.0));
        assertEquals("0.0001", Decimals.plain(1e-4));
    }

    @Test
    void aBigDecimalLosesItsTrailingZerosAndItsExponent() {
        assertEquals("12.4", Decimals.plain(BigDecimal.valueOf(12400, 3)));
        assertEquals("60", Decimals.plain(BigDecimal.valueOf(60000, 3)));
        assertEquals("0", Decimals.plain(BigDecimal.valueOf(0, 3)));
        assertEquals("1000", Decimals.plain(new BigDecimal("1E+3")));
    }
}
