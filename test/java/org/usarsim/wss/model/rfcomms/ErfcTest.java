package org.usarsim.wss.model.rfcomms;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** erfc against known values: Python's math.erfc (the C library's), `python3 -c "import math; print(repr(math.erfc(x)))"`. */
class ErfcTest {

    private static final double[][] KNOWN = {
        {0, 1.0}, {1e-8, 0.9999999887162083}, {0.1, 0.8875370839817152}, {0.5, 0.4795001221869535},
        {1, 0.15729920705028513}, {1.5, 0.033894853524689274}, {1.99, 0.004888586800383003}, {2, 0.004677734981047265},
        {2.5, 0.0004069520174449589}, {3, 2.2090496998585438e-05}, {4, 1.541725790028002e-08}, {5, 1.5374597944280351e-12},
        {7, 4.183825607779414e-23}, {10, 2.088487583762545e-45}, {15, 7.212994172451206e-100}, {20, 5.3958656116079005e-176},
        {26, 5.663192408856143e-296}, {-0.5, 1.5204998778130465}, {-2, 1.9953222650189528}, {-5, 1.9999999999984626},
    };

    @Test
    void knownValuesToOnePartInATrillion() {
        for (double[] known : KNOWN) {
            double got = Erfc.erfc(known[0]);
            assertEquals(known[1], got, Math.abs(known[1]) * 1e-12, "erfc(" + known[0] + ")");
        }
    }

    @Test
    void theTwoMethodsMeetAtTwoAndTheFarTailIsZero() {
        double below = Erfc.erfc(Math.nextDown(2.0));
        double at = Erfc.erfc(2.0);
        assertTrue(below >= at && (below - at) / at < 1e-13, below + " then " + at);
        assertEquals(0, Erfc.erfc(30));
        assertEquals(2, Erfc.erfc(-30));
        assertTrue(Double.isNaN(Erfc.erfc(Double.NaN)));
        assertEquals(0, Erfc.erfc(Double.POSITIVE_INFINITY));
    }
}
