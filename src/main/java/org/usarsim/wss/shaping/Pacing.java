package org.usarsim.wss.shaping;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.WritableByteChannel;

/**
 * One direction of a link between reading and writing, as the link's one forwarding loop asks it
 * (docs/shaping.md, "Stages"): how many bytes may be read now ({@link #room}), how many of those
 * read may be written now ({@link #due}), and how long until either changes
 * ({@link #nanosUntilNext}). The loop reads at most the room, hands the bytes over
 * ({@link #accept}), writes what is due ({@link #writeTo}) and waits for its sockets at most until
 * the next change. {@link Unpaced} lets every byte go at once (wss.shaping = off); a
 * {@link ShapedFlow} composes a shaped direction's stages: its queue, its airtime at its rate,
 * and what follows the air (its delay).
 *
 * <p>Used by one thread; it never reads a clock nor blocks: the time is given.
 */
public interface Pacing {

    /** How many bytes may be read now; 0 means read nothing. */
    int room();

    /**
     * Takes the bytes read at {@code nowNs}: {@code bytes}' remaining ones, at most {@link #room()}.
     * A pacing may copy them or keep the buffer itself until they are written ({@link Unpaced} does):
     * the caller reads into it again only once {@link #room()} is above 0.
     *
     * @throws IllegalStateException if they are more than {@link #room()}
     */
    void accept(ByteBuffer bytes, long nowNs);

    /** How many of the bytes held may be written at {@code nowNs}. */
    long due(long nowNs);

    /**
     * Writes what is due at {@code nowNs} to {@code out}, in order, until all of it is written or
     * {@code out} takes no more (a non-blocking channel that is full).
     *
     * @return the bytes written
     */
    int writeTo(WritableByteChannel out, long nowNs) throws IOException;

    /**
     * How long from {@code nowNs} until something new is to be done: 0 if that is now,
     * {@link Long#MAX_VALUE} if nothing waits for time (bytes already due wait for the target,
     * not for time).
     */
    long nanosUntilNext(long nowNs);

    /** The bytes read and not yet written. */
    long held();

    /** Whether its answers depend on the time; a loop whose directions' do not reads no clock. */
    default boolean timed() {
        return true;
    }

    /** Ends the direction; what it still holds is dropped. */
    void close();
}
