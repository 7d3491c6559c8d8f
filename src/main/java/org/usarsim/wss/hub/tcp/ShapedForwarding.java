package org.usarsim.wss.hub.tcp;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.NetworkInterface;
import java.net.StandardSocketOptions;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.nio.channels.SocketChannel;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import org.usarsim.wss.hub.core.LiveCondition;
import org.usarsim.wss.hub.core.PairCondition;
import org.usarsim.wss.shaping.ShapedFlow;

/**
 * The loop of a shaped link (wss.shaping = on, docs/shaping.md): each direction reads only what
 * its {@link ShapedFlow} has room for, and writes its bytes when they are due (once on the air,
 * plus the delay), waiting on the selector at most until the next is due. The pair's
 * condition is read at every turn, and a change wakes the selector ({@link LiveCondition}), so a
 * new rate or delay reaches the bytes still waiting at once. As unshaped, a side's end stops the
 * reading, and both streams end once what was read is written.
 */
final class ShapedForwarding extends Forwarding {

    private final Shaping shaping;
    private final Way upWay;
    private final Way downWay;
    /** Wakes this link's selector when either way's condition changes: the one instance watched, and unwatched at the end. */
    private final Runnable wake;

    ShapedForwarding(Link link, Selector selector, Direction up, Direction down, Shaping shaping) throws IOException {
        super(link, selector, up, down);
        this.shaping = shaping;
        long now = shaping.clock().getAsLong();
        this.upWay = new Way(up, shaping, shaping.up(), now);
        this.downWay = new Way(down, shaping, shaping.down(), now);
        this.wake = selector::wakeup;
    }

    @Override
    void forward() throws IOException {
        // Watched before the loop's first reading of the conditions: no change is missed.
        shaping.up().watch(wake);
        shaping.down().watch(wake);
        try {
            while (!link.isClosed()) {
                long now = shaping.clock().getAsLong();
                upWay.follow();
                downWay.follow();
                upWay.writeDue(now);
                downWay.writeDue(now);
                boolean ended = up.ended() || down.ended();
                if (ended && upWay.flow.held() == 0 && downWay.flow.held() == 0) {
                    finish();
                    return;
                }
                sourceKey.interestOps(interest(ended, upWay, downWay, now));
                targetKey.interestOps(interest(ended, downWay, upWay, now));
                waitAtMost(Math.min(upWay.flow.nanosUntilNext(now), downWay.flow.nanosUntilNext(now)));
                boolean sourceReadable = sourceKey.isValid() && selector.selectedKeys().contains(sourceKey) && sourceKey.isReadable();
                boolean targetReadable = targetKey.isValid() && selector.selectedKeys().contains(targetKey) && targetKey.isReadable();
                selector.selectedKeys().clear();
                if (link.isClosed()) {
                    return;
                }
                if (sourceReadable && !up.ended() && !down.ended()) {
                    upWay.read(shaping.clock().getAsLong());
                }
                if (targetReadable && !up.ended() && !down.ended()) {
                    downWay.read(shaping.clock().getAsLong());
                }
            }
        } finally {
            shaping.up().unwatch(wake);
            shaping.down().unwatch(wake);
            upWay.flow.close();
            downWay.flow.close();
        }
    }

    /**
     * Waits for the sockets, at most until something falls due: whole milliseconds on the
     * selector (rounded down, so it wakes no later than due), and the last fraction of a
     * millisecond parked, which the selector cannot wait for; rounding up instead made every hop
     * up to a millisecond late.
     */
    private void waitAtMost(long nanos) throws IOException {
        if (nanos == 0) {
            selector.selectNow();
        } else if (nanos == Long.MAX_VALUE) {
            selector.select();
        } else if (nanos >= 1_000_000) {
            selector.select(TimeUnit.NANOSECONDS.toMillis(nanos));
        } else {
            LockSupport.parkNanos(nanos);
            selector.selectNow();
        }
    }

    /** A channel is read while its direction has room, and written while bytes due for it wait. */
    private static int interest(boolean ended, Way from, Way to, long now) {
        int ops = !ended && from.flow.room() > 0 ? SelectionKey.OP_READ : 0;
        return to.flow.due(now) > 0 ? ops | SelectionKey.OP_WRITE : ops;
    }

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

    /** One direction's flow and its pair's live condition one way. */
    private static final class Way {
        private final Direction direction;
        private final ShapedFlow flow;
        /** Whether each end's robot is on this machine: the input's, the output's. */
        private final boolean localIn;
        private final boolean localOut;
        private final LiveCondition condition;
        private PairCondition followed;

        Way(Direction direction, Shaping shaping, LiveCondition condition, long now) {
            this.direction = direction;
            this.condition = condition;
            this.followed = condition.get();
            this.flow = new ShapedFlow(shaping.airtime().open(direction.fromRobot, direction.toRobot, now), followed.bitsPerSecond(),
                    followed.delayMs(), shaping.queueMs());
            this.localIn = onThisMachineOrClosed(direction.in);
            this.localOut = onThisMachineOrClosed(direction.out);
            sizeBuffers();
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
                direction.in.setOption(StandardSocketOptions.SO_RCVBUF, socketBuffer(flow.rate(), localIn));
                direction.out.setOption(StandardSocketOptions.SO_SNDBUF, socketBuffer(flow.rate(), localOut));
            } catch (IOException | RuntimeException e) {
                // A socket already closed: the link is ending anyway.
            }
        }

        /** Takes the pair's condition now: a new rate or delay applies to the bytes not yet on the air. */
        void follow() {
            PairCondition now = condition.get();
            if (now != followed) {
                followed = now;
                if (now.shaped()) {
                    boolean newRate = now.bitsPerSecond() != flow.rate();
                    flow.setConditions(now.bitsPerSecond(), now.delayMs());
                    if (newRate) {
                        sizeBuffers();
                    }
                }
            }
        }

        /** Reads what the flow has room for, a chunk at a time, while each read fills what it asked. */
        void read(long now) {
            for (int i = 0; i < Direction.CHUNKS_PER_TURN; i++) {
                int room = flow.room();
                if (room == 0) {
                    return;
                }
                direction.buffer.clear();
                direction.buffer.limit(Math.min(room, direction.buffer.capacity()));
                int asked = direction.buffer.limit();
                int read = direction.read();
                if (read <= 0) {
                    return; // drained for now, or ended
                }
                direction.buffer.flip();
                flow.accept(direction.buffer, now);
                if (read < asked) {
                    return;
                }
            }
        }

        /** Writes what is due, counted as unshaped. */
        void writeDue(long now) throws IOException {
            direction.send(flow, now);
        }
    }
}
