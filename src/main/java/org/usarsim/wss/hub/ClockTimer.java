package org.usarsim.wss.hub;

import java.util.PriorityQueue;
import java.util.concurrent.TimeUnit;
import java.util.logging.Level;
import java.util.logging.Logger;
import org.usarsim.wss.hub.core.HubClock;
import org.usarsim.wss.net.LogLimiter;

/**
 * Runs tasks once the hub's {@link HubClock} reaches their time: the port memory's forgetting and
 * the warnings' summaries. One daemon thread, named as given, that lives while a task waits and a
 * second more (of the clock's time), started by the first task: a hub whose start fails leaves none.
 * A test's clock moved by hand runs the tasks as it passes their time.
 */
final class ClockTimer implements LogLimiter.Timer {

    private static final Logger LOG = Logger.getLogger(ClockTimer.class.getName());
    /** How long the thread waits for another task before it ends. */
    private static final long LINGER_NS = TimeUnit.SECONDS.toNanos(1);

    /** A task and when it is due (the clock's nanoseconds); {@code order} keeps tasks due together in the order given. */
    private record Task(long dueNs, long order, Runnable run) {
    }

    private final String threadName;
    private final HubClock clock;
    /** Guarded by this: the tasks by time (compared by difference, as the clock may wrap), the thread, the end. */
    private final PriorityQueue<Task> tasks = new PriorityQueue<>((a, b) -> a.dueNs == b.dueNs ? Long.compare(a.order, b.order)
            : Long.signum(a.dueNs - b.dueNs));
    private long given;
    private Thread thread;
    private boolean stopped;

    ClockTimer(String threadName, HubClock clock) {
        this.threadName = threadName;
        this.clock = clock;
    }

    @Override
    public synchronized void after(long delayNs, Runnable task) {
        if (stopped) {
            return; // stopped with the hub: what it would have done is done by the close, or not needed
        }
        tasks.add(new Task(clock.nanoTime() + delayNs, given++, task));
        if (thread == null) {
            thread = new Thread(this::run, threadName);
            thread.setDaemon(true);
            thread.start();
        } else {
            notifyAll();
        }
    }

    /** No task runs any more; the thread ends. */
    @Override
    public synchronized void stop() {
        stopped = true;
        tasks.clear();
        notifyAll();
    }

    private void run() {
        Runnable due;
        while ((due = nextDue()) != null) {
            try {
                due.run();
            } catch (RuntimeException e) {
                LOG.log(Level.SEVERE, threadName + ": a task failed: " + e, e);
            }
        }
    }

    /** The next task once it is due; null once stopped, or after {@link #LINGER_NS} without one (the thread ends then). */
    private synchronized Runnable nextDue() {
        long idleSince = clock.nanoTime();
        while (!stopped) {
            long now = clock.nanoTime();
            Task first = tasks.peek();
            long left = first == null ? idleSince + LINGER_NS - now : first.dueNs - now;
            if (left <= 0) {
                if (first != null) {
                    return tasks.poll().run;
                }
                break;
            }
            try {
                TimeUnit.NANOSECONDS.timedWait(this, clock.waitNanos(left));
            } catch (InterruptedException e) {
                break;
            }
        }
        thread = null;
        return null;
    }
}
