package org.usarsim.wss.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;

class LineSplitterTest {

    private static final String TOO_LONG = "<too long>";
    private static final int MAX = LineSplitter.MAX_LINE_BYTES;

    /** Records lines and too-long events in order. */
    private static final class Recorder implements LineSplitter.Sink {
        final List<String> events = new ArrayList<>();

        @Override
        public void line(String line) {
            events.add(line);
        }

        @Override
        public void lineTooLong() {
            events.add(TOO_LONG);
        }
    }

    private final LineSplitter splitter = new LineSplitter();
    private final Recorder sink = new Recorder();

    private void feed(byte[] bytes) {
        splitter.feed(bytes, 0, bytes.length, sink);
    }

    private void feed(String text) {
        feed(text.getBytes(StandardCharsets.UTF_8));
    }

    private void feedInPieces(byte[] bytes, int pieceSize) {
        for (int offset = 0; offset < bytes.length; offset += pieceSize) {
            splitter.feed(bytes, offset, Math.min(pieceSize, bytes.length - offset), sink);
        }
    }

    private static byte[] repeat(char c, int count) {
        byte[] bytes = new byte[count];
        Arrays.fill(bytes, (byte) c);
        return bytes;
    }

    private static byte[] concat(byte[]... parts) {
        int length = 0;
        for (byte[] part : parts) {
            length += part.length;
        }
        byte[] all = new byte[length];
        int offset = 0;
        for (byte[] part : parts) {
            System.arraycopy(part, 0, all, offset, part.length);
            offset += part.length;
        }
        return all;
    }

    private static byte[] ascii(String text) {
        return text.getBytes(StandardCharsets.US_ASCII);
    }

    @Test
    void maxLineIs64KiB() {
        assertEquals(65536, LineSplitter.MAX_LINE_BYTES);
    }

    // --- line ends -----------------------------------------------------------------------------

    @Test
    void lfEndsALine() {
        feed("GETSS {Robot R1}\n");
        assertEquals(List.of("GETSS {Robot R1}"), sink.events);
    }

    @Test
    void crLfEndsALine() {
        feed("GETSS {Robot R1}\r\n");
        assertEquals(List.of("GETSS {Robot R1}"), sink.events);
    }

    @Test
    void mixedLineEnds() {
        feed("A\r\nB\nC\r\nD\n");
        assertEquals(List.of("A", "B", "C", "D"), sink.events);
    }

    @Test
    void bareCrDoesNotEndALine() {
        feed("A\rB\r\n");
        assertEquals(List.of("A\rB"), sink.events);
    }

    @Test
    void onlyOneTrailingCrIsRemoved() {
        feed("A\r\r\n");
        assertEquals(List.of("A\r"), sink.events);
    }

    @Test
    void incompleteLineIsNotDeliveredUntilItsEnd() {
        feed("GETSS {Robot R1}");
        assertEquals(List.of(), sink.events);
        feed("\r");
        assertEquals(List.of(), sink.events);
        feed("\n");
        assertEquals(List.of("GETSS {Robot R1}"), sink.events);
    }

    // --- splitting and joining -----------------------------------------------------------------

    @Test
    void lineSplitAcrossFeedsByteByByte() {
        feedInPieces(ascii("INIT {Robot R1} {Port 5000,5001}\r\nGETSS {Robot R2}\n"), 1);
        assertEquals(List.of("INIT {Robot R1} {Port 5000,5001}", "GETSS {Robot R2}"), sink.events);
    }

    @Test
    void crAndLfInDifferentFeeds() {
        feed("GETSS {Robot R1}\r");
        feed("\nGETSS {Robot R2}\r");
        feed("\n");
        assertEquals(List.of("GETSS {Robot R1}", "GETSS {Robot R2}"), sink.events);
    }

    @Test
    void lineSplitAcrossSeveralUnevenFeeds() {
        feed("GET");
        feed("SS {Rob");
        feed("ot R1");
        feed("}\r\nGE");
        feed("TSS {Robot R2}\r\n");
        assertEquals(List.of("GETSS {Robot R1}", "GETSS {Robot R2}"), sink.events);
    }

    @Test
    void severalLinesInOneFeed() {
        feed("GETSS {Robot R1}\r\nGETSS {Robot R2}\r\nGETSS {Robot R3}\r\nDNS {Robot R1}\r\n");
        assertEquals(List.of("GETSS {Robot R1}", "GETSS {Robot R2}", "GETSS {Robot R3}", "DNS {Robot R1}"),
                sink.events);
    }

    @Test
    void feedHonoursOffsetAndLength() {
        byte[] buffer = ascii("xxxxGETSS {Robot R1}\nGETSS {Robot R2}\nyyyy");
        splitter.feed(buffer, 4, buffer.length - 8, sink);
        assertEquals(List.of("GETSS {Robot R1}", "GETSS {Robot R2}"), sink.events);
    }

    @Test
    void feedOfNothingDoesNothing() {
        splitter.feed(new byte[0], 0, 0, sink);
        splitter.feed(ascii("abc"), 1, 0, sink);
        assertEquals(List.of(), sink.events);
        feed("\n");
        assertEquals(List.of(""), sink.events);
    }

    @Test
    void blankLinesArePassedThroughAsEmptyStrings() {
        feed("\n\r\nA\n\n  \r\n");
        assertEquals(List.of("", "", "A", "", "  "), sink.events);
    }

    // --- length limit ----------------------------------------------------------------------------

    @Test
    void lineOfExactlyTheLimitIsAcceptedWithLf() {
        feed(concat(repeat('a', MAX), ascii("\n")));
        assertEquals(1, sink.events.size());
        assertEquals("a".repeat(MAX), sink.events.get(0));
    }

    @Test
    void lineOfExactlyTheLimitIsAcceptedWithCrLf() {
        feed(concat(repeat('a', MAX), ascii("\r\nB\r\n")));
        assertEquals(List.of("a".repeat(MAX), "B"), sink.events);
    }

    @Test
    void lineOfExactlyTheLimitIsAcceptedWhenFedInPieces() {
        feedInPieces(concat(repeat('a', MAX), ascii("\r\nB\r\n")), 1000);
        assertEquals(List.of("a".repeat(MAX), "B"), sink.events);
    }

    @Test
    void lineOfExactlyTheLimitIsAcceptedWhenItsCrArrivesAlone() {
        feed(repeat('a', MAX));
        feed("\r");
        feed("\n");
        assertEquals(List.of("a".repeat(MAX)), sink.events);
    }

    @Test
    void lineOneByteOverTheLimitIsRejectedOnceAndTheNextLineStillDelivered() {
        feed(concat(repeat('a', MAX + 1), ascii("\nGETSS {Robot R1}\n")));
        assertEquals(List.of(TOO_LONG, "GETSS {Robot R1}"), sink.events);
    }

    @Test
    void lineOneByteOverTheLimitWithCrLfIsRejectedOnce() {
        feed(concat(repeat('a', MAX + 1), ascii("\r\nGETSS {Robot R1}\r\n")));
        assertEquals(List.of(TOO_LONG, "GETSS {Robot R1}"), sink.events);
    }

    @Test
    void lineOneByteOverTheLimitInSeparateFeedsIsRejectedOnce() {
        feed(repeat('a', MAX));
        feed("a");
        feed("\n");
        feed("GETSS {Robot R1}\n");
        assertEquals(List.of(TOO_LONG, "GETSS {Robot R1}"), sink.events);
    }

    @Test
    void lineOneByteOverTheLimitByteByByteIsRejectedOnce() {
        feedInPieces(concat(repeat('a', MAX + 1), ascii("\r\nGETSS {Robot R1}\r\n")), 1);
        assertEquals(List.of(TOO_LONG, "GETSS {Robot R1}"), sink.events);
    }

    @Test
    void tooLongIsReportedBeforeTheLineEndArrives() {
        feed(repeat('a', MAX + 2));
        assertEquals(List.of(TOO_LONG), sink.events);
        feed(repeat('a', 10_000));
        assertEquals(List.of(TOO_LONG), sink.events);
        feed("\nA\n");
        assertEquals(List.of(TOO_LONG, "A"), sink.events);
    }

    @Test
    void aLineOfExactlyOneByteOverTheLimitIsReportedAtOnce() {
        feed(repeat('a', MAX + 1));
        assertEquals(List.of(TOO_LONG), sink.events, "no need to wait for the line end");
        feed("\nA\n");
        assertEquals(List.of(TOO_LONG, "A"), sink.events);
    }

    @Test
    void aCrRightPastTheLimitWaitsForTheNextByte() {
        feed(concat(repeat('a', MAX), ascii("\r")));
        assertEquals(List.of(), sink.events, "that CR may be the line end's");
        feed("x");
        assertEquals(List.of(TOO_LONG), sink.events);
        feed("\nA\n");
        assertEquals(List.of(TOO_LONG, "A"), sink.events);
    }

    @Test
    void hugeLineInManyPiecesIsReportedOnlyOnce() {
        byte[] chunk = repeat('x', 4096);
        for (int i = 0; i < 300; i++) { // about 1.2 MB
            feed(chunk);
        }
        feed("\r\nGETSS {Robot R1}\r\n");
        assertEquals(List.of(TOO_LONG, "GETSS {Robot R1}"), sink.events);
    }

    @Test
    void hugeLineInOddPiecesIsReportedOnlyOnce() {
        byte[] huge = concat(ascii("A\n"), repeat('x', 5 * MAX + 123), ascii("\nB\n"));
        feedInPieces(huge, 777);
        assertEquals(List.of("A", TOO_LONG, "B"), sink.events);
    }

    @Test
    void twoTooLongLinesAreReportedTwice() {
        feed(concat(repeat('a', MAX + 1), ascii("\n"), repeat('b', 2 * MAX), ascii("\nC\n")));
        assertEquals(List.of(TOO_LONG, TOO_LONG, "C"), sink.events);
    }

    @Test
    void linesAroundATooLongLineAreUntouched() {
        feed(concat(ascii("A\r\n"), repeat('z', MAX + 50), ascii("\r\nB\r\n")));
        assertEquals(List.of("A", TOO_LONG, "B"), sink.events);
    }

    @Test
    void limitCountsBytesNotCharacters() {
        // 'ö' is two bytes in UTF-8: 32768 of them are exactly the limit, one more is over it.
        feed(("ö".repeat(MAX / 2) + "\n").getBytes(StandardCharsets.UTF_8));
        feed(("ö".repeat(MAX / 2) + "o\nA\n").getBytes(StandardCharsets.UTF_8));
        assertEquals(List.of("ö".repeat(MAX / 2), TOO_LONG, "A"), sink.events);
    }

    // --- UTF-8 ---------------------------------------------------------------------------------

    @Test
    void utf8NamesAreDecoded() {
        feed("GETSS {Robot Rödel}\r\nGETSS {Robot 機器人}\r\nGETSS {Robot \uD83E\uDD16}\r\n");
        assertEquals(List.of("GETSS {Robot Rödel}", "GETSS {Robot 機器人}", "GETSS {Robot \uD83E\uDD16}"),
                sink.events);
    }

    @Test
    void utf8CharacterSplitAcrossFeeds() {
        byte[] bytes = "GETSS {Robot 機ö\uD83E\uDD16}\r\n".getBytes(StandardCharsets.UTF_8);
        feedInPieces(bytes, 1);
        assertEquals(List.of("GETSS {Robot 機ö\uD83E\uDD16}"), sink.events);
    }
}
