package org.usarsim.wss.app;

import java.util.concurrent.CountDownLatch;
import sun.misc.Signal;
import sun.misc.SignalHandler;

/**
 * What a running server waits on: SIGTERM, Ctrl-C (SIGINT) or {@link #stop()} (the window
 * closed) ends the wait. Closing puts back the signal handlers found.
 */
final class StopSignal implements AutoCloseable {

    private static final Signal TERM = new Signal("TERM");
    private static final Signal INT = new Signal("INT");

    private final CountDownLatch stopped = new CountDownLatch(1);
    private final SignalHandler termBefore;
    private final SignalHandler intBefore;

    StopSignal() {
        termBefore = Signal.handle(TERM, signal -> stop());
        intBefore = Signal.handle(INT, signal -> stop());
    }

    void stop() {
        stopped.countDown();
    }

    /** Until stopped; an interrupt ends the wait too. */
    void await() {
        try {
            stopped.await();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    @Override
    public void close() {
        Signal.handle(TERM, termBefore);
        Signal.handle(INT, intBefore);
    }
}
