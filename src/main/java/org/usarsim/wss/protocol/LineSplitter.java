package org.usarsim.wss.protocol;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;

/**
 * Cuts the bytes of a control connection into lines: LF or CR LF ends a line, lines may arrive
 * split across reads or several in one read. A line longer than {@link #MAX_LINE_BYTES} is
 * reported once, as soon as it is too long (a CR right past the limit waits for the next byte,
 * since it may be the line end's), and the rest of it is skipped up to its line end.
 */
public final class LineSplitter {

    /** The longest line accepted, line end not counted: 64 KiB. */
    public static final int MAX_LINE_BYTES = 64 * 1024;

    /** Receives what the splitter finds, in order. */
    public interface Sink {
        void line(String line);

        void lineTooLong();
    }

    private final ByteArrayOutputStream current = new ByteArrayOutputStream();
    private boolean skipping;

    /** Feeds the next bytes read from the connection. */
    public void feed(byte[] bytes, int offset, int length, Sink sink) {
        int start = offset;
        int end = offset + length;
        for (int i = offset; i < end; i++) {
            if (bytes[i] == '\n') {
                append(bytes, start, i - start, sink);
                finishLine(sink);
                start = i + 1;
            }
        }
        append(bytes, start, end - start, sink);
    }

    private void append(byte[] bytes, int offset, int length, Sink sink) {
        if (skipping || length == 0) {
            return;
        }
        // One byte of slack for the CR of a CR LF that may follow: a byte past the limit is too
        // long at once unless it is a CR; the byte after that CR decides.
        int size = current.size() + length;
        if (size > MAX_LINE_BYTES + 1 || size == MAX_LINE_BYTES + 1 && bytes[offset + length - 1] != '\r') {
            current.reset();
            skipping = true;
            sink.lineTooLong();
            return;
        }
        current.write(bytes, offset, length);
    }

    private void finishLine(Sink sink) {
        if (skipping) {
            skipping = false;
            return;
        }
        byte[] line = current.toByteArray();
        current.reset();
        int length = line.length;
        if (length > 0 && line[length - 1] == '\r') {
            length--;
        }
        if (length > MAX_LINE_BYTES) {
            sink.lineTooLong();
            return;
        }
        sink.line(new String(line, 0, length, StandardCharsets.UTF_8));
    }
}
