package org.usarsim.wss.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** How the tables sort names: digits by value, letters ignoring case, a total order. */
class NameOrderTest {

    @Test
    void namesSortAsTheyAreRead() {
        List<String> names = new ArrayList<>(List.of("R10", "r2", "R1", "base", "R002", "Base", "R2a", "R", "", "Scout 9", "Scout 10",
                "R18446744073709551616", "R9"));
        names.sort(NameOrder.INSTANCE);
        assertEquals(List.of("", "Base", "base", "R", "R1", "R002", "r2", "R2a", "R9", "R10", "R18446744073709551616", "Scout 9",
                "Scout 10"), names);
    }

    @Test
    void itIsAConsistentTotalOrder() {
        List<String> names = List.of("a", "A", "a1", "a01", "a001", "A1", "b", "10", "9", "09", "x9y", "x10y", "x09y");
        for (String a : names) {
            assertEquals(0, NameOrder.INSTANCE.compare(a, a));
            for (String b : names) {
                assertEquals(Integer.signum(NameOrder.INSTANCE.compare(a, b)), -Integer.signum(NameOrder.INSTANCE.compare(b, a)), a + " " + b);
                assertTrue(a.equals(b) || NameOrder.INSTANCE.compare(a, b) != 0, a + " and " + b + " are different");
                for (String c : names) {
                    if (NameOrder.INSTANCE.compare(a, b) < 0 && NameOrder.INSTANCE.compare(b, c) < 0) {
                        assertTrue(NameOrder.INSTANCE.compare(a, c) < 0, a + " < " + b + " < " + c);
                    }
                }
            }
        }
    }
}
