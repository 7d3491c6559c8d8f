package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.fail;

import java.util.function.BooleanSupplier;
import java.util.function.LongPredicate;
import java.util.function.LongSupplier;

/** Waits for a condition with a deadline, polling: never a fixed sleep. */
public final class Wait {

    private Wait() {
    }

    private static final long DEADLINE_NS = 5_000_000_000L;

    public static void until(String what, BooleanSupplier condition) {
        until(what, DEADLINE_NS, condition);
    }

    /** As {@link #until(String, BooleanSupplier)}, for a condition that takes longer than 5 s by its nature. */
    public static void until(String what, long deadlineNs, BooleanSupplier condition) {
        long deadline = System.nanoTime() + deadlineNs;
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > deadline) {
                fail("timed out waiting until " + what);
            }
            pause(what);
        }
    }

    /** Polls a count until it satisfies the condition or the deadline passes; returns the last value (the caller asserts). */
    public static long settle(String what, LongSupplier count, LongPredicate done) {
        long deadline = System.nanoTime() + DEADLINE_NS;
        long value = count.getAsLong();
        while (!done.test(value) && System.nanoTime() < deadline) {
            pause(what);
            value = count.getAsLong();
        }
        return value;
    }

    private static void pause(String what) {
        try {
            Thread.sleep(2);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            fail("interrupted waiting until " + what);
        }
    }
}
