package org.usarsim.wss;

import java.io.IOException;
import java.io.StringWriter;
import java.io.Writer;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

/**
 * A writer that blocks in every write until released, as a disk that hangs; what it was given is
 * in {@link #text} (readable while it is written to). {@link #stuck} opens at its first write.
 */
public final class StuckWriter extends Writer {
    public final CountDownLatch stuck = new CountDownLatch(1);
    public final CountDownLatch release = new CountDownLatch(1);
    public final StringWriter text = new StringWriter();
    public volatile boolean closed;

    @Override
    public void write(char[] chars, int offset, int length) throws IOException {
        stuck.countDown();
        try {
            if (!release.await(30, TimeUnit.SECONDS)) {
                throw new IOException("never released");
            }
        } catch (InterruptedException e) {
            throw new IOException(e);
        }
        text.write(chars, offset, length);
    }

    @Override
    public void flush() {
    }

    @Override
    public void close() {
        closed = true;
    }

    /** What it was given so far, line by line. */
    public List<String> lines() {
        String all = text.toString();
        return all.isEmpty() ? List.of() : List.of(all.split(System.lineSeparator()));
    }
}
