package org.usarsim.wss;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.CountDownLatch;
import org.junit.jupiter.api.Test;

class ThreadStopTest {

    @Test
    void theSignalComesFirstThenTheThreadIsWaitedFor() {
        CountDownLatch told = new CountDownLatch(1);
        Thread thread = new Thread(() -> {
            try {
                told.await();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        });
        thread.start();
        assertTrue(ThreadStop.stop(thread, told::countDown));
        assertFalse(thread.isAlive());
    }

    @Test
    void anInterruptedCallerStopsWaitingAndStaysInterrupted() throws InterruptedException {
        CountDownLatch never = new CountDownLatch(1);
        Thread thread = new Thread(() -> {
            try {
                never.await();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        });
        thread.setDaemon(true);
        thread.start();
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
