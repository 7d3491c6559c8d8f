package org.usarsim.wss.hub.tcp;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.NetworkInterface;
import java.net.StandardSocketOptions;
import java.nio.ByteBuffer;
import java.nio.channels.SocketChannel;
import java.nio.channels.WritableByteChannel;
import java.util.concurrent.TimeUnit;
import org.usarsim.wss.hub.core.LiveCondition;
import org.usarsim.wss.hub.core.PairCondition;
import org.usarsim.wss.shaping.Pacing;
import org.usarsim.wss.shaping.ShapedFlow;

/**
 * The pacing of one direction of a shaped link (wss.shaping = on, docs/shaping.md): its
 * {@link ShapedFlow}, following the pair's live condition that way, and the kernel's buffers of
 * its sockets sized by the rate. The condition is taken whenever the loop asks how much it may
 * read, what is due or how long it may wait, and a change wakes the loop ({@link LiveCondition}),
 * so a new rate or delay reaches the bytes still waiting at once.
 */
final class LiveShaping implements Pacing {

    /**
     * The kernel's buffers of a shaped direction (the WSS's receive buffer on its input, its send
     * buffer on its output), in time at the direction's rate: with the 4 MiB of
     * {@code wss.socketBuffer}, or the OS's own sizing, the kernel held seconds of a slow link's
     * stream besides the flow's queue (issue 27). 20 ms at the rate is the window a robot whose
     * round trip to the WSS takes up to 20 ms needs to fill the link.
     */
    static final long SOCKET_BUFFER_NS = TimeUnit.MILLISECONDS.toNanos(20);
    /**
     * The least buffer when the robot's end is on this machine (loopback, or one of its own
     * addresses: the path is the loopback device, whose segments are 64 KiB): a smaller one
     * stalls TCP on its delayed acknowledgements (4 KiB moved 0.76 Mbit/s on a 4 Mbit/s link).
     */
    static final int LEAST_LOCAL_BUFFER = 64 * 1024;
    /**
     * The least buffer when the robot is across a network (Ethernet or Wi-Fi frames of 1,500
     * bytes): a few segments, so that a slow link's window is not a second queue (64 KiB is half
     * a second at 1 Mbit/s).
     */
    static final int LEAST_REMOTE_BUFFER = 8 * 1024;

    private final ShapedFlow flow;
    private final LiveCondition condition;
    /** What wakes the link's loop at a change: watched from here, unwatched at {@link #close}. */
    private final Runnable wake;
    private final SocketChannel in;
    private final SocketChannel out;
    /** Whether each end's robot is on this machine: the input's, the output's. */
    private final boolean localIn;
    private final boolean localOut;
    private PairCondition followed;

    /**
     * The direction from robot {@code from} on {@code in} to robot {@code to} on {@code out}, at
     * {@code nowNs}; {@code wake} wakes its loop at every change of {@code condition} until it is closed.
     */
    LiveShaping(Shaping shaping, LiveCondition condition, SocketChannel in, SocketChannel out, String from, String to,
            Runnable wake, long nowNs) {
        this.condition = condition;
        this.wake = wake;
        this.in = in;
        this.out = out;
        this.followed = condition.get();
        this.flow = new ShapedFlow(shaping.airtime().open(from, to, nowNs), followed.bitsPerSecond(), followed.delayMs(),
                followed.jitterMs(), shaping.queueMs(), shaping.jitter().distribution(), shaping.jitter().seedFor(from, to, 0));
        // Watched after the first reading: a change in between differs from it, so the next reading takes it.
        condition.watch(wake);
        this.localIn = onThisMachineOrClosed(in);
        this.localOut = onThisMachineOrClosed(out);
        sizeBuffers();
    }

    /** The socket buffer size for a shaped direction at {@code bitsPerSecond}, its robot on this machine or not. */
    static int socketBuffer(long bitsPerSecond, boolean local) {
        long atRate = bitsPerSecond / 8 * SOCKET_BUFFER_NS / 1_000_000_000L;
        return (int) Math.max(local ? LEAST_LOCAL_BUFFER : LEAST_REMOTE_BUFFER, Math.min(1 << 22, atRate));
    }

    /** Whether the robot at the other end of {@code channel} is on this machine (so reached over the loopback device). */
    static boolean onThisMachine(SocketChannel channel) throws IOException {
        InetAddress robot = ((InetSocketAddress) channel.getRemoteAddress()).getAddress();
        return robot.isLoopbackAddress() || robot.isAnyLocalAddress() || NetworkInterface.getByInetAddress(robot) != null;
    }

    private static boolean onThisMachineOrClosed(SocketChannel channel) {
        try {
            return onThisMachine(channel);
        } catch (IOException | RuntimeException e) {
            return true; // closed already: the link is ending, any size does
        }
    }

    /** The input's receive buffer and the output's send buffer at the rate. */
    private void sizeBuffers() {
        try {
            in.setOption(StandardSocketOptions.SO_RCVBUF, socketBuffer(flow.rate(), localIn));
            out.setOption(StandardSocketOptions.SO_SNDBUF, socketBuffer(flow.rate(), localOut));
        } catch (IOException | RuntimeException e) {
            // A socket already closed: the link is ending anyway.
        }
    }

    /** Takes the pair's condition now: a new rate or delay applies to the bytes not yet on the air. */
    private void follow() {
        PairCondition now = condition.get();
        if (now != followed) {
            followed = now;
            if (now.shaped()) {
                boolean newRate = now.bitsPerSecond() != flow.rate();
                flow.setConditions(now.bitsPerSecond(), now.delayMs(), now.jitterMs());
                if (newRate) {
                    sizeBuffers();
                }
            }
        }
    }

    @Override
    public int room() {
        follow();
        return flow.room();
    }

    /** Takes what was read within the room just asked (no new condition in between, which could take the room away). */
    @Override
    public void accept(ByteBuffer bytes, long nowNs) {
        flow.accept(bytes, nowNs);
    }

    @Override
    public long due(long nowNs) {
        follow();
        return flow.due(nowNs);
    }

    @Override
    public int writeTo(WritableByteChannel target, long nowNs) throws IOException {
        return flow.writeTo(target, nowNs);
    }

    @Override
    public long nanosUntilNext(long nowNs) {
        follow();
        return flow.nanosUntilNext(nowNs);
    }

    @Override
    public long held() {
        return flow.held();
    }

    /** Stops following the condition and ends the flow (its hop). */
    @Override
    public void close() {
        condition.unwatch(wake);
        flow.close();
    }
}
