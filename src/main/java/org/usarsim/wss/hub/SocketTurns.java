package org.usarsim.wss.hub;

import java.util.Map;
import java.util.Queue;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.locks.LockSupport;
import java.util.concurrent.locks.ReentrantLock;
import java.util.logging.Level;
import java.util.logging.Logger;

/**
 * The order in which the hub's steps do their socket work after its lock: each step that has
 * some takes a turn under the lock, with its work, so turns follow the order of the steps; after
 * the lock it {@link #complete}s its turn, and returns once its work is done. One thread at a
 * time does the work, every turn queued in order: a step that finds another thread at it leaves
 * its turn to that thread and waits for it to be done, and is woken alone when it is.
 * **Changed** from each step waiting for the turn before it and doing its own (woken all at once
 * by notifyAll): a hundred robots asking DNS at once handed the turn on a hundred times in a row,
 * one thread switch each, and 9,900 DNS of a full mesh took 14 to 20 s on a busy 2-core machine.
 */
final class SocketTurns {

    private static final Logger LOG = Logger.getLogger(SocketTurns.class.getName());

    private record Turn(long number, Runnable work) {
    }

    /** Guarded by this. */
    private long taken;
    private final Queue<Turn> queued = new ConcurrentLinkedQueue<>();
    private volatile long done;
    /** Held by the one thread doing the turns' work. */
    private final ReentrantLock working = new ReentrantLock();
    /** The thread waiting for each turn to be done. */
    private final Map<Long, Thread> waiting = new ConcurrentHashMap<>();

    /** Under the hub's lock: the step's work gets the next turn. @return the turn's number */
    synchronized long take(Runnable work) {
        long turn = ++taken;
        queued.add(new Turn(turn, work));
        return turn;
    }

    /**
     * After the lock: returns once the turn's work is done, and every turn's before it. Does the
     * queued turns itself while no other thread is at them.
     */
    void complete(long turn) {
        while (done < turn) {
            if (working.tryLock()) {
                try {
                    Turn next;
                    while ((next = queued.poll()) != null) {
                        run(next);
                    }
                } finally {
                    working.unlock();
                }
                // A turn queued after the last poll, by a thread that found this one at work: its thread takes over.
                Turn left = queued.peek();
                if (left != null) {
                    wake(left.number());
                }
            } else {
                awaitDone(turn);
            }
        }
    }

    private void wake(long turn) {
        Thread owner = waiting.get(turn);
        if (owner != null) {
            LockSupport.unpark(owner);
        }
    }

    private void run(Turn turn) {
        try {
            turn.work().run();
        } catch (RuntimeException | Error e) {
            // The turns behind wait for this one: it must be done whatever happens.
            LOG.log(Level.SEVERE, "the socket work of a step failed: " + e, e);
        } finally {
            done = turn.number();
            wake(turn.number());
        }
    }

    /** Waits until the turn is done, or until no thread is at the turns while some are queued (then this one takes them). */
    private void awaitDone(long turn) {
        waiting.put(turn, Thread.currentThread());
        boolean interrupted = false;
        try {
            // Checked after the put: a turn done meanwhile is seen here, or wakes this thread.
            while (done < turn && (working.isLocked() || queued.isEmpty())) {
                LockSupport.parkNanos(this, 100_000_000); // woken at once; the time is only a safety net
                interrupted |= Thread.interrupted(); // the turns behind wait for this one: it must be done whatever happens
            }
        } finally {
            waiting.remove(turn);
            if (interrupted) {
                Thread.currentThread().interrupt();
            }
        }
    }

    /** Whether the calling thread is doing turns' socket work now. */
    boolean heldByCurrentThread() {
        return working.isHeldByCurrentThread();
    }
}
