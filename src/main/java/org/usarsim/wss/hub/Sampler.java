package org.usarsim.wss.hub;

import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.logging.Level;
import java.util.logging.Logger;

/**
 * With links shaped: asks, every {@link #PERIOD_MS} ms, what the model says of the shaped pairs
 * now, so that a robot driving away slows its links within one such poll (docs/shaping.md). One
 * daemon thread, {@code wss-shaping}.
 */
final class Sampler {

    private static final Logger LOG = Logger.getLogger(Sampler.class.getName());
    /** As often as the simulator models poll by default. */
    static final long PERIOD_MS = 200;

    private final Runnable measure;
    private ScheduledThreadPoolExecutor timer;

    Sampler(Runnable measure) {
        this.measure = measure;
    }

    synchronized void start() {
        timer = new ScheduledThreadPoolExecutor(1, runnable -> {
            Thread thread = new Thread(runnable, "wss-shaping");
            thread.setDaemon(true);
            return thread;
        });
        timer.scheduleWithFixedDelay(this::measureQuietly, PERIOD_MS, PERIOD_MS, TimeUnit.MILLISECONDS);
    }

    private void measureQuietly() {
        try {
            measure.run();
        } catch (RuntimeException e) {
            LOG.log(Level.WARNING, "measuring the shaped links failed: " + e, e); // the next poll tries again
        }
    }

    synchronized void close() {
        if (timer != null) {
            timer.shutdownNow();
        }
    }
}
