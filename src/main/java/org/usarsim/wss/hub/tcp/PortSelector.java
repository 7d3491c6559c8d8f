package org.usarsim.wss.hub.tcp;

import java.io.IOException;
import java.nio.channels.ClosedChannelException;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.nio.channels.SocketChannel;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Queue;
import java.util.Set;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.TimeUnit;
import java.util.logging.Level;
import java.util.logging.Logger;
import org.usarsim.wss.hub.core.HubClock;

/**
 * Every listening WSS port, served by one thread ({@code wss-port-accept}) on one Selector: it
 * accepts on each port that has a connection waiting and queues the connection for the
 * {@link HandOver} thread, which gives it to the hub. A port's listening socket is registered with
 * it when the port starts listening and closed by it when the port stops ({@link Closes}): a
 * channel registered with a Selector is really closed only when that selector next runs, so the
 * thread closes it and runs the selector again before it says the close is done.
 *
 * <p>Its two threads start with the first port opened ({@link #start}, given where the connections
 * go: a hub whose start fails leaves none) and end with {@link #close}. The thread never waits for
 * the hub, nor for the hand-over thread.
 */
public final class PortSelector implements AutoCloseable {

    private static final Logger LOG = Logger.getLogger(PortSelector.class.getName());
    /** How many connections one port may have accepted in a row before the others get their turn. */
    private static final int ACCEPTS_PER_TURN = 64;
    /** How long a port whose accept failed waits before it accepts again (net.AcceptLoop's pause). */
    private static final long PAUSE_NS = TimeUnit.MILLISECONDS.toNanos(100);
    /** How long a close may take before the one waiting for it says so and goes on. */
    public static final long CLOSE_WAIT_NS = TimeUnit.SECONDS.toNanos(10);

    private final HubClock clock;
    /** Set as the threads start, before them; the accepting thread reads it. */
    private HandOver handOver;
    private final Queue<Runnable> tasks = new ConcurrentLinkedQueue<>();
    /** Opened with the first listener, under this object's monitor; read without it once open. */
    private volatile Selector selector;
    private Thread thread;
    private Thread handOverThread;
    private volatile boolean closed;
    /** The hand-over queue went down: ports held back may accept again. */
    private volatile boolean acceptAgain;
    // Only the selector's thread touches these:
    /** Listeners closed since the selector last ran: closed for real once it has run again. */
    private final Set<PortListener> closing = new LinkedHashSet<>();
    /** Ports held back while the hand-over queue is full. */
    private final Set<SelectionKey> heldBack = new HashSet<>();
    /** Ports whose accept failed, and when they accept again (the hub's clock). */
    private final Map<SelectionKey, Long> paused = new HashMap<>();

    public PortSelector(HubClock clock) {
        this.clock = clock;
    }

    /**
     * Opens the selector and starts its threads, which hand what they accept to {@code hub},
     * unless done: before the first port listens. Later calls give the same hub.
     */
    public void start(LinkHub hub) throws IOException {
        if (selector == null || closed) {
            openedFirst(hub);
        }
    }

    /** The hub's clock, which the waits for this selector's closes are on. */
    HubClock clock() {
        return clock;
    }

    /** The listeners a step closes: handed to the selector's thread at once and waited for once. */
    public Closes closes() {
        return new Closes(this);
    }

    /** Starts accepting on a bound, listening socket (the selector's thread registers it). */
    void register(PortListener listener) throws IOException {
        listener.channel.configureBlocking(false); // nothing to do for one bound by PortSockets: non-blocking already
        submit(() -> {
            try {
                listener.key = listener.channel.register(selector, SelectionKey.OP_ACCEPT, listener);
            } catch (ClosedChannelException e) {
                closing.add(listener); // closed meanwhile: it only needs saying so
            }
        });
    }

    /** Has the selector's thread close the listeners; the {@link Closes} waits for them. */
    void close(List<PortListener> listeners) {
        boolean running;
        synchronized (this) {
            running = selector != null && !closed;
        }
        if (!running) {
            // Never registered (no thread yet), or the selector is gone and closed them all.
            listeners.forEach(listener -> {
                listener.close();
                listener.closedNow();
                listener.ended();
            });
            return;
        }
        tasks.add(() -> listeners.forEach(this::closeListener));
        selector.wakeup();
        if (closed) {
            // The thread may have ended before it took them: a channel closed after its selector is closed at once.
            listeners.forEach(listener -> {
                listener.close();
                listener.closedNow();
                listener.ended();
            });
        }
    }

    /** The hand-over thread's queue went down to its low-water mark. */
    void acceptAgain() {
        acceptAgain = true;
        Selector current = selectorNow();
        if (current != null) {
            current.wakeup();
        }
    }

    private Selector selectorNow() {
        return selector;
    }

    private void submit(Runnable task) throws IOException {
        Selector current = opened();
        tasks.add(task);
        current.wakeup();
    }

    /**
     * The selector, open since {@link #start}. Without this object's monitor: every DNS asks
     * first, and a hundred robots asking at once queued on it.
     */
    private Selector opened() throws IOException {
        Selector open = selector;
        if (open != null && !closed) {
            return open;
        }
        throw new IOException(closed ? "the WSS has stopped" : "the WSS ports' selector has not started");
    }

    private synchronized void openedFirst(LinkHub hub) throws IOException {
        if (closed) {
            throw new IOException("the WSS has stopped");
        }
        if (selector == null) {
            Selector opened = Selector.open();
            HandOver handing = new HandOver(hub, this);
            handOver = handing; // before the threads start: they read it
            Thread accepting = new Thread(() -> run(opened), "wss-port-accept"); // before the field is set
            accepting.setDaemon(true);
            Thread handingThread = new Thread(handing, "wss-port-handover");
            handingThread.setDaemon(true);
            try {
                handingThread.start();
                accepting.start();
            } catch (Throwable e) {
                handing.stop();
                Closing.quietly(opened);
                throw e;
            }
            selector = opened;
            thread = accepting;
            handOverThread = handingThread;
        }
    }

    private void run(Selector selector) {
        while (!closed) {
            try {
                if (tasks.isEmpty() && !acceptAgain) {
                    selector.select(this::ready, timeoutMs());
                } else {
                    // finishCloses' selectNow cleared the wake-up that came with them: do not wait.
                    selector.selectNow(this::ready);
                }
                runTasks();
                resumePaused();
                if (acceptAgain) {
                    acceptAgain = false;
                    heldBack.forEach(key -> interest(key, SelectionKey.OP_ACCEPT));
                    heldBack.clear();
                }
                finishCloses(selector);
            } catch (IOException | RuntimeException e) {
                LOG.log(Level.SEVERE, "the WSS ports' selector failed, going on: " + e, e);
            }
        }
        for (SelectionKey key : selector.keys()) {
            closeListener((PortListener) key.attachment());
        }
        try {
            runTasks();
            finishCloses(selector);
        } catch (IOException | RuntimeException e) {
            LOG.log(Level.FINE, "closing the WSS ports' selector: " + e, e);
        }
        Closing.quietly(selector);
        handOver.stop();
    }

    private void runTasks() {
        Runnable task;
        while ((task = tasks.poll()) != null) {
            task.run();
        }
    }

    /** Runs the selector again until every listener closed meanwhile is closed for real, and says so. */
    private void finishCloses(Selector selector) throws IOException {
        while (!closing.isEmpty()) {
            List<PortListener> done = new ArrayList<>(closing);
            closing.clear();
            selector.selectNow(this::ready); // deregisters the cancelled keys: their sockets are closed now
            for (PortListener listener : done) {
                listener.closedNow();
                handOver.ended(listener);
            }
        }
    }

    private void closeListener(PortListener listener) {
        if (listener.isClosed() || closing.contains(listener)) {
            return;
        }
        if (listener.key != null) {
            heldBack.remove(listener.key);
            paused.remove(listener.key);
        }
        listener.close();
        closing.add(listener);
    }

    /** A port has a connection waiting: accept, and queue them for the hand-over. */
    private void ready(SelectionKey key) {
        PortListener listener = (PortListener) key.attachment();
        if (!key.isValid() || listener.isClosing() || listener.isDrained()) {
            return;
        }
        for (int i = 0; i < ACCEPTS_PER_TURN; i++) {
            if (handOver.backlog() >= HandOver.HIGH_WATER) {
                interest(key, 0);
                heldBack.add(key);
                return;
            }
            SocketChannel connection;
            try {
                connection = listener.channel.accept();
            } catch (IOException e) {
                interest(key, 0);
                paused.put(key, clock.nanoTime() + PAUSE_NS);
                handOver.acceptFailed(listener, e);
                return;
            }
            if (connection == null) {
                return;
            }
            if (listener.isMarker(connection)) {
                // Everything completed before the drain began is queued: accept no more. The socket
                // holds the number until the departure stops the port, at once (Hub.deregister).
                PortListener.reset(connection);
                heldBack.remove(key);
                paused.remove(key);
                listener.drained();
                handOver.ended(listener);
                return;
            }
            handOver.accepted(listener, connection);
        }
    }

    private static void interest(SelectionKey key, int ops) {
        if (key.isValid()) {
            key.interestOps(ops);
        }
    }

    private long timeoutMs() {
        if (paused.isEmpty()) {
            return 0; // until woken
        }
        long next = paused.values().stream().mapToLong(Long::longValue).min().getAsLong();
        return Math.max(1, TimeUnit.NANOSECONDS.toMillis(clock.waitNanos(next - clock.nanoTime())) + 1);
    }

    private void resumePaused() {
        if (paused.isEmpty()) {
            return;
        }
        long now = clock.nanoTime();
        paused.entrySet().removeIf(entry -> {
            if (entry.getValue() - now > 0) {
                return false;
            }
            interest(entry.getKey(), SelectionKey.OP_ACCEPT);
            return true;
        });
    }

    /** Closes every listening port and ends both threads. */
    @Override
    public void close() {
        Thread accepting;
        Thread handing;
        synchronized (this) {
            if (closed) {
                return;
            }
            closed = true;
            accepting = thread;
            handing = handOverThread;
            if (selector != null) {
                selector.wakeup();
            }
        }
        for (Thread ended : new Thread[] {accepting, handing}) {
            if (ended != null && ended != Thread.currentThread()) {
                try {
                    ended.join(TimeUnit.NANOSECONDS.toMillis(CLOSE_WAIT_NS));
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    return;
                }
            }
        }
    }

    /** The threads, for the tests: null before the first port listened. */
    synchronized List<Thread> threads() {
        return thread == null ? List.of() : List.of(thread, handOverThread);
    }
}
