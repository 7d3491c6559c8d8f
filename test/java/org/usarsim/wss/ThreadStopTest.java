package org.usarsim.wss;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.CountDownLatch;
import org.junit.jupiter.api.Test;

class ThreadStopTest {

    /** A started daemon thread that ends once the latch is counted down. */
    private static Thread waitingFor(CountDownLatch latch) {
        Thread thread = new Thread(() -> {
            try {
                latch.await();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        });
        thread.setDaemon(true);
        thread.start();
        return thread;
    }

    @Test
    void theSignalComesFirstThenTheThreadIsWaitedFor() {
        CountDownLatch told = new CountDownLatch(1);
        Thread thread = waitingFor(told);
        assertTrue(ThreadStop.stop(thread, told::countDown));
        assertFalse(thread.isAlive());
    }

    @Test
    void anInterruptedCallerStopsWaitingAndStaysInterrupted() throws InterruptedException {
        CountDownLatch never = new CountDownLatch(1);
        Thread thread = waitingFor(never);
        Thread.currentThread().interrupt();
        try {
            assertFalse(ThreadStop.stop(thread, () -> { }));
            assertTrue(Thread.interrupted());
        } finally {
            never.countDown();
            thread.join();
        }
    }
}
