package org.usarsim.wss.hub;

/**
 * The order in which the hub's steps do their socket work after its lock: each step that has
 * some takes a turn under the lock, so turns follow the order of the steps, and waits for the
 * turn before it to be done (without the hub's lock) before it does its own.
 */
final class SocketTurns {

    private long taken;
    private long done;
    /** The thread whose turn it is, or null between turns. */
    private Thread inTurn;

    /** Under the hub's lock. @return the new turn's number */
    synchronized long take() {
        return ++taken;
    }

    /** Returns once every turn before this one is done. */
    synchronized void await(long turn) {
        boolean interrupted = false;
        while (done < turn - 1) {
            try {
                wait();
            } catch (InterruptedException e) {
                interrupted = true; // the turns behind wait for this one: it must be done whatever happens
            }
        }
        if (interrupted) {
            Thread.currentThread().interrupt();
        }
        inTurn = Thread.currentThread();
    }

    synchronized void done(long turn) {
        done = turn;
        inTurn = null;
        notifyAll();
    }

    /** Whether the calling thread is doing its turn's socket work now. */
    synchronized boolean heldByCurrentThread() {
        return inTurn == Thread.currentThread();
    }
}
