package org.usarsim.wss.model.simulator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Set;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.model.RobotPair;

/** The link-state rule with times given, not measured. */
class LinkStatesTest {

    private static final RobotPair PAIR = RobotPair.of("A", "B");
    private static final long SECOND = 1_000_000_000L;

    @Test
    void withoutMarginOrHoldTheStateFollowsTheCutoffExactly() {
        LinkStates states = new LinkStates(-93, 0, 0);
        assertNull(states.live(PAIR));
        assertTrue(states.decide(PAIR, -93, 0), "at the cutoff: up");
        assertFalse(states.decide(PAIR, -93.0001, 1));
        assertTrue(states.decide(PAIR, -92, 2));
        assertFalse(states.decide(PAIR, Double.NaN, 3), "unknown: down");
        assertTrue(states.decide(PAIR, Double.POSITIVE_INFINITY, 4), "same place: up");
        assertEquals(Boolean.TRUE, states.live(RobotPair.of("B", "A")));
    }

    @Test
    void aMarginDelaysOnlyTheReturn() {
        LinkStates states = new LinkStates(-93, 3, 0);
        assertTrue(states.decide(PAIR, -92, 0), "a first decision has no margin");
        assertTrue(states.decide(PAIR, -93, 1), "up until below the cutoff");
        assertFalse(states.decide(PAIR, -94, 2));
        assertFalse(states.decide(PAIR, -92, 3));
        assertFalse(states.decide(PAIR, -90.001, 4));
        assertTrue(states.decide(PAIR, -90, 5), "back at cutoff + margin");
    }

    @Test
    void aHoldTimeKeepsEveryStateThatLong() {
        LinkStates states = new LinkStates(-93, 0, 2);
        assertTrue(states.decide(PAIR, -80, 0));
        assertTrue(states.decide(PAIR, -100, SECOND), "held since 0");
        assertFalse(states.decide(PAIR, -100, 2 * SECOND), "2 s later it may change");
        assertFalse(states.decide(PAIR, -80, 3 * SECOND), "held since 2 s");
        assertTrue(states.decide(PAIR, -80, 4 * SECOND));
    }

    @Test
    void pairsOfRobotsThatLeftAreForgotten() {
        LinkStates states = new LinkStates(-93, 0, 0);
        states.decide(PAIR, -80, 0);
        states.decide(RobotPair.of("A", "C"), -80, 0);
        states.retainOnly(Set.of("A", "C"));
        assertNull(states.live(PAIR));
        assertEquals(Boolean.TRUE, states.live(RobotPair.of("C", "A")));
    }
}
