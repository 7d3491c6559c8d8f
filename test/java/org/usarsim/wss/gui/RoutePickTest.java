package org.usarsim.wss.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** Issue 34, item 3: a click picks a route's start, a click on another its end, a third click clears. */
class RoutePickTest {

    @Test
    void aClickPicksTheStartAnotherTheEndAThirdClears() {
        RoutePick start = RoutePick.NONE.click("Alpha");
        assertEquals(new RoutePick("Alpha", null), start);
        assertFalse(start.complete());
        RoutePick both = start.click("Scout");
        assertEquals(new RoutePick("Alpha", "Scout"), both);
        assertTrue(both.complete());
        assertEquals(RoutePick.NONE, both.click("Relay"), "a third click clears");
        assertEquals(new RoutePick("Relay", null), both.click("Relay").click("Relay"), "and the next picks a start again");
    }

    @Test
    void aClickOnTheStartAgainClears() {
        assertEquals(RoutePick.NONE, RoutePick.NONE.click("Alpha").click("Alpha"));
    }
}
