package org.usarsim.wss.hub.tcp;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.ArrayDeque;
import java.util.List;
import java.util.Queue;
import org.junit.jupiter.api.Test;

/** The one rule for running out of descriptors: give some back, try once more. */
class DescriptorsTest {

    private static final IOException RAN_OUT = new IOException("Too many open files");
    private static final IOException REFUSED = new IOException("Address already in use");

    private int givenBack;

    private Descriptors giving(boolean some) {
        return new Descriptors(() -> {
            givenBack++;
            return some;
        });
    }

    /** Work that fails with each of {@code failures} in turn, then answers how many times it ran. */
    private static Descriptors.Work<Integer> failing(IOException... failures) {
        Queue<IOException> left = new ArrayDeque<>(List.of(failures));
        int[] runs = new int[1];
        return () -> {
            runs[0]++;
            IOException next = left.poll();
            if (next != null) {
                throw next;
            }
            return runs[0];
        };
    }

    @Test
    void workThatSucceedsGivesNothingBack() throws IOException {
        assertEquals(1, giving(true).retrying(failing()));
        assertEquals(0, givenBack);
    }

    @Test
    void outOfDescriptorsSomeAreGivenBackAndTheWorkIsTriedOnceMore() throws IOException {
        assertEquals(2, giving(true).retrying(failing(RAN_OUT)));
        assertEquals(1, givenBack);
    }

    @Test
    void onlyOnceMore() {
        assertSame(RAN_OUT, assertThrows(IOException.class, () -> giving(true).retrying(failing(RAN_OUT, RAN_OUT))));
        assertEquals(1, givenBack);
    }

    @Test
    void nothingToGiveBackTheFailureStands() {
        assertSame(RAN_OUT, assertThrows(IOException.class, () -> giving(false).retrying(failing(RAN_OUT))));
        assertEquals(1, givenBack);
    }

    @Test
    void anotherFailureIsNotRetriedAndGivesNothingBack() {
        assertSame(REFUSED, assertThrows(IOException.class, () -> giving(true).retrying(failing(REFUSED))));
        assertEquals(0, givenBack);
    }

    @Test
    void anAcceptsOwnLoopAsksWhetherSomeWereGivenBack() {
        assertTrue(giving(true).gaveBack(RAN_OUT));
        assertFalse(giving(false).gaveBack(RAN_OUT));
        assertFalse(giving(true).gaveBack(REFUSED));
        assertFalse(giving(true).gaveBack(new IOException()));
        assertEquals(2, givenBack);
    }
}
