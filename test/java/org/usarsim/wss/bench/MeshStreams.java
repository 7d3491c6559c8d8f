package org.usarsim.wss.bench;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;
import java.util.zip.CRC32C;

/**
 * Streams at a fixed rate through WSS ports, each written by one socket here and read by the
 * target robot's accepting socket here, every byte checksummed (CRC32C) as it is written and as
 * it is read: an 8-byte stream id, then seeded random bytes. One thread writes every stream's
 * share every {@link #TICK_MS} (non-blocking: a stream the WSS cannot take falls behind), one
 * thread accepts and reads every target side. At the end each stream ends its output, and its
 * length and checksum at both ends are compared.
 */
final class MeshStreams {

    private static final int TICK_MS = 100;
    private static final int CHUNK = 16 * 1024;

    /** One stream: written to {@code wssPort}, arriving at the target's accepting socket. */
    private static final class Sender {
        final int id;
        final SocketChannel channel;
        final Random bytes;
        final CRC32C crc = new CRC32C();
        ByteBuffer pending;
        long generated;

        Sender(int id, SocketChannel channel) {
            this.id = id;
            this.channel = channel;
            this.bytes = new Random(id);
            this.pending = ByteBuffer.allocate(Long.BYTES).putLong(id).flip();
        }
    }

    /** One stream's target side, known by the id it starts with. */
    private static final class Receiver {
        final ByteBuffer header = ByteBuffer.allocate(Long.BYTES);
        final CRC32C crc = new CRC32C();
        long received;
        boolean ended;
    }

    private final long bytesPerSecond;
    private final Selector selector;
    private final List<Sender> senders = new ArrayList<>();
    private final Map<Integer, Receiver> receivers = new ConcurrentHashMap<>();
    private final ByteBuffer readBuffer = ByteBuffer.allocateDirect(64 * 1024);
    private final java.util.concurrent.atomic.AtomicInteger arrived = new java.util.concurrent.atomic.AtomicInteger();
    private volatile boolean writing = true;
    private volatile boolean reading = true;
    private Thread writer;
    private Thread reader;
    private long startNs;

    MeshStreams(long bytesPerSecond) throws IOException {
        this.bytesPerSecond = bytesPerSecond;
        this.selector = Selector.open();
    }

    /** A robot's accepting socket, served by the reading thread. @return its port */
    int accepting() throws IOException {
        ServerSocketChannel server = ServerSocketChannel.open();
        server.bind(new InetSocketAddress("127.0.0.1", 0), 1024);
        server.configureBlocking(false);
        server.register(selector, SelectionKey.OP_ACCEPT);
        return ((InetSocketAddress) server.getLocalAddress()).getPort();
    }

    /** Starts reading (before any stream is opened: the WSS connects to the targets at once). */
    void startReading() {
        reader = new Thread(this::read, "mesh-reader");
        reader.setDaemon(true);
        reader.start();
    }

    /** Opens a stream to a WSS port (blocking connect); it writes once {@link #startWriting}. */
    void open(int wssPort) throws IOException {
        SocketChannel channel = SocketChannel.open(new InetSocketAddress("127.0.0.1", wssPort));
        channel.configureBlocking(false);
        senders.add(new Sender(senders.size(), channel));
    }

    int streams() {
        return senders.size();
    }

    /** Waits until the WSS has connected every stream to its target (at most {@code seconds}). @return how many it has */
    int awaitArrived(int seconds) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds);
        while (arrived.get() < senders.size() && System.nanoTime() < deadline) {
            Thread.sleep(10);
        }
        return arrived.get();
    }

    void startWriting() {
        startNs = System.nanoTime();
        writer = new Thread(this::write, "mesh-writer");
        writer.setDaemon(true);
        writer.start();
    }

    private void write() {
        while (writing) {
            long due = (System.nanoTime() - startNs) * bytesPerSecond / TimeUnit.SECONDS.toNanos(1);
            for (Sender sender : senders) {
                try {
                    writeSome(sender, due);
                } catch (IOException e) {
                    System.err.println("  stream " + sender.id + ": " + e);
                }
            }
            try {
                Thread.sleep(TICK_MS);
            } catch (InterruptedException e) {
                return;
            }
        }
    }

    private static void writeSome(Sender sender, long due) throws IOException {
        while (true) {
            if (!sender.pending.hasRemaining()) {
                int next = (int) Math.min(CHUNK, due - sender.generated);
                if (next <= 0) {
                    return;
                }
                byte[] chunk = new byte[next];
                sender.bytes.nextBytes(chunk);
                sender.crc.update(chunk);
                sender.generated += next;
                sender.pending = ByteBuffer.wrap(chunk);
            }
            sender.channel.write(sender.pending);
            if (sender.pending.hasRemaining()) {
                return; // the WSS takes no more now: the next tick
            }
        }
    }

    private void read() {
        while (reading) {
            try {
                selector.select(this::ready, 100);
            } catch (IOException e) {
                System.err.println("  reading: " + e);
            }
        }
    }

    private void ready(SelectionKey key) {
        try {
            if (key.isAcceptable()) {
                SocketChannel accepted;
                while ((accepted = ((ServerSocketChannel) key.channel()).accept()) != null) {
                    arrived.incrementAndGet();
                    accepted.configureBlocking(false);
                    accepted.register(selector, SelectionKey.OP_READ, new Receiver());
                }
                return;
            }
            SocketChannel channel = (SocketChannel) key.channel();
            Receiver receiver = (Receiver) key.attachment();
            int read;
            while ((read = channel.read(readBuffer.clear())) > 0) {
                readBuffer.flip();
                while (receiver.header.hasRemaining() && readBuffer.hasRemaining()) {
                    receiver.header.put(readBuffer.get());
                }
                if (!receiver.header.hasRemaining() && readBuffer.hasRemaining()) {
                    receiver.received += readBuffer.remaining();
                    receiver.crc.update(readBuffer);
                }
                if (!receiver.header.hasRemaining() && receivers.get((int) receiver.header.getLong(0)) != receiver) {
                    receivers.put((int) receiver.header.getLong(0), receiver);
                }
            }
            if (read < 0) {
                receiver.ended = true;
                key.cancel();
                channel.close();
            }
        } catch (IOException e) {
            System.err.println("  reading a stream: " + e);
            key.cancel();
        }
    }

    /** What the streams did: bytes each way, and how many arrived whole. */
    record Outcome(int streams, long written, long received, int whole, int damaged, int unfinished, long dueBytes) {
    }

    /**
     * Stops writing, writes what is pending, ends every stream, and waits (at most {@code waitSeconds})
     * for every target side to read its end; then compares each stream's length and checksum.
     */
    Outcome finish(int waitSeconds) throws Exception {
        writing = false;
        writer.join();
        long due = (System.nanoTime() - startNs) * bytesPerSecond / TimeUnit.SECONDS.toNanos(1);
        for (Sender sender : senders) {
            sender.channel.configureBlocking(true);
            while (sender.pending.hasRemaining()) {
                sender.channel.write(sender.pending);
            }
            sender.channel.shutdownOutput();
        }
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(waitSeconds);
        while (System.nanoTime() < deadline && receivers.values().stream().filter(r -> r.ended).count() < senders.size()) {
            Thread.sleep(50);
        }
        reading = false;
        reader.join();
        long written = 0;
        long received = 0;
        int whole = 0;
        int damaged = 0;
        int unfinished = 0;
        for (Sender sender : senders) {
            written += sender.generated;
            Receiver receiver = receivers.get(sender.id);
            if (receiver == null || !receiver.ended) {
                unfinished++;
                received += receiver == null ? 0 : receiver.received;
                continue;
            }
            received += receiver.received;
            if (receiver.received == sender.generated && receiver.crc.getValue() == sender.crc.getValue()) {
                whole++;
            } else {
                damaged++;
            }
        }
        for (Sender sender : senders) {
            sender.channel.close();
        }
        selector.keys().forEach(key -> {
            try {
                key.channel().close();
            } catch (IOException ignored) {
                // closing anyway
            }
        });
        selector.close();
        return new Outcome(senders.size(), written, received, whole, damaged, unfinished, due * senders.size());
    }
}
