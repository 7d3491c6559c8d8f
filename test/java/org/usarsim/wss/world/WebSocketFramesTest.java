package org.usarsim.wss.world;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The WebSocket handshake and frames of RFC 6455, bytes in and out. */
class WebSocketFramesTest {

    /** What the reader found, in order, as words. */
    private static final class Found implements WebSocketFrames.Sink {
        final List<String> events = new ArrayList<>();

        @Override
        public void text(String message) {
            events.add("text " + message);
        }

        @Override
        public void binary(byte[] message) {
            events.add("binary " + message.length);
        }

        @Override
        public void ping(byte[] payload) {
            events.add("ping " + new String(payload, StandardCharsets.UTF_8));
        }

        @Override
        public void close(int code) {
            events.add("close " + code);
        }

        @Override
        public void failed(int code, String reason) {
            events.add("failed " + code + " " + reason);
        }
    }

    /** A client frame: masked with a fixed key, FIN as given. */
    static byte[] clientFrame(boolean fin, int opcode, byte[] payload) {
        ByteArrayOutputStream frame = new ByteArrayOutputStream();
        frame.write((fin ? 0x80 : 0) | opcode);
        int length = payload.length;
        if (length < 126) {
            frame.write(0x80 | length);
        } else if (length <= 0xFFFF) {
            frame.write(0x80 | 126);
            frame.write(length >>> 8);
            frame.write(length);
        } else {
            frame.write(0x80 | 127);
            for (int i = 7; i >= 0; i--) {
                frame.write((int) ((long) length >>> (8 * i)));
            }
        }
        byte[] mask = {0x37, (byte) 0xfa, 0x21, 0x3d};
        frame.write(mask, 0, 4);
        for (int i = 0; i < length; i++) {
            frame.write(payload[i] ^ mask[i & 3]);
        }
        return frame.toByteArray();
    }

    private static byte[] text(String s) {
        return s.getBytes(StandardCharsets.UTF_8);
    }

    private static List<String> read(int limit, byte[]... frames) {
        ByteArrayOutputStream all = new ByteArrayOutputStream();
        for (byte[] frame : frames) {
            all.writeBytes(frame);
        }
        byte[] bytes = all.toByteArray();
        // Fed a byte at a time: any split must give the same.
        Found oneByOne = new Found();
        WebSocketFrames reader = new WebSocketFrames(limit);
        for (byte b : bytes) {
            reader.feed(new byte[] {b}, 0, 1, oneByOne);
        }
        Found whole = new Found();
        new WebSocketFrames(limit).feed(bytes, 0, bytes.length, whole);
        assertEquals(whole.events, oneByOne.events);
        return whole.events;
    }

    @Test
    void theRfcsSampleKeyIsAccepted() {
        assertEquals("s3pPLMBiTxaQ9kYGzzhZRbK+xOo=", WebSocketHandshake.accept("dGhlIHNhbXBsZSBub25jZQ=="));
        byte[] request = ("GET /chat HTTP/1.1\r\nHost: server.example.com\r\nUpgrade: websocket\r\nConnection: keep-alive, Upgrade\r\n"
                + "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n\r\n").getBytes(StandardCharsets.ISO_8859_1);
        assertEquals(request.length, WebSocketHandshake.headEnd(request, request.length));
        assertEquals(-1, WebSocketHandshake.headEnd(request, request.length - 1));
        WebSocketHandshake.Answer answer = WebSocketHandshake.answer(request, request.length);
        assertTrue(answer.upgraded());
        assertEquals("HTTP/1.1 101 Switching Protocols\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
                + "Sec-WebSocket-Accept: s3pPLMBiTxaQ9kYGzzhZRbK+xOo=\r\n\r\n", new String(answer.response(), StandardCharsets.ISO_8859_1));
    }

    @Test
    void whatIsNotAWebSocketUpgradeIsRefused() {
        byte[] plain = "GET / HTTP/1.1\r\nHost: x\r\n\r\n".getBytes(StandardCharsets.ISO_8859_1);
        WebSocketHandshake.Answer answer = WebSocketHandshake.answer(plain, plain.length);
        assertFalse(answer.upgraded());
        assertTrue(new String(answer.response(), StandardCharsets.ISO_8859_1).startsWith("HTTP/1.1 400 Bad Request\r\n"));
        byte[] version8 = ("GET / HTTP/1.1\r\nUpgrade: websocket\r\nConnection: Upgrade\r\nSec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\n"
                + "Sec-WebSocket-Version: 8\r\n\r\n").getBytes(StandardCharsets.ISO_8859_1);
        assertTrue(new String(WebSocketHandshake.answer(version8, version8.length).response(), StandardCharsets.ISO_8859_1)
                .startsWith("HTTP/1.1 426 Upgrade Required\r\nSec-WebSocket-Version: 13\r\n"));
        byte[] badKey = ("GET / HTTP/1.1\r\nUpgrade: websocket\r\nConnection: Upgrade\r\nSec-WebSocket-Key: short\r\n"
                + "Sec-WebSocket-Version: 13\r\n\r\n").getBytes(StandardCharsets.ISO_8859_1);
        assertEquals("no Sec-WebSocket-Key of 16 bytes in Base64", WebSocketHandshake.answer(badKey, badKey.length).problem());
        byte[] post = "POST / HTTP/1.1\r\n\r\n".getBytes(StandardCharsets.ISO_8859_1);
        assertEquals("not an HTTP GET: POST / HTTP/1.1", WebSocketHandshake.answer(post, post.length).problem());
    }

    @Test
    void maskedTextOfEveryLengthForm() {
        String medium = "m".repeat(300);
        String large = "L".repeat(70_000);
        assertEquals(List.of("text {\"op\":\"subscribe\"}", "text " + medium, "text " + large, "text "),
                read(100_000, clientFrame(true, WebSocketFrames.TEXT, text("{\"op\":\"subscribe\"}")),
                        clientFrame(true, WebSocketFrames.TEXT, text(medium)), clientFrame(true, WebSocketFrames.TEXT, text(large)),
                        clientFrame(true, WebSocketFrames.TEXT, new byte[0])));
    }

    @Test
    void aFragmentedMessageIsReassembledWithControlFramesBetweenItsFragments() {
        assertEquals(List.of("ping p", "text {\"op\":\"subscribe\",\"topic\":\"/tf\"}"),
                read(1000, clientFrame(false, WebSocketFrames.TEXT, text("{\"op\":\"sub")),
                        clientFrame(false, 0, text("scribe\",")),
                        clientFrame(true, WebSocketFrames.PING, text("p")),
                        clientFrame(true, 0, text("\"topic\":\"/tf\"}"))));
        // A character split between fragments is whole once they are joined.
        byte[] e = text("é");
        assertEquals(List.of("text é"), read(1000, clientFrame(false, WebSocketFrames.TEXT, new byte[] {e[0]}),
                clientFrame(true, 0, new byte[] {e[1]})));
    }

    @Test
    void aMessageOverTheLimitEndsTheConnectionEvenInFragments() {
        assertEquals(List.of("failed 1009 a message over 100 bytes"), read(100, clientFrame(true, WebSocketFrames.TEXT, new byte[101])));
        assertEquals(List.of("failed 1009 a message over 100 bytes"), read(100, clientFrame(false, WebSocketFrames.TEXT, new byte[60]),
                clientFrame(true, 0, new byte[60])));
    }

    @Test
    void framesThatBreakTheProtocolEndTheConnection() {
        byte[] unmasked = {(byte) 0x81, 0x01, 'x'};
        assertEquals(List.of("failed 1002 a client frame without a mask"), read(100, unmasked));
        assertEquals(List.of("failed 1002 a continuation frame with no message begun"), read(100, clientFrame(true, 0, text("x"))));
        assertEquals(List.of("failed 1002 a new message before the last one's final fragment"),
                read(100, clientFrame(false, WebSocketFrames.TEXT, text("a")), clientFrame(true, WebSocketFrames.TEXT, text("b"))));
        assertEquals(List.of("failed 1002 a control frame fragmented or over 125 bytes"),
                read(1000, clientFrame(false, WebSocketFrames.PING, text("p"))));
        assertEquals(List.of("failed 1002 an unknown opcode 3"), read(100, clientFrame(true, 3, text("x"))));
        byte[] reserved = clientFrame(true, WebSocketFrames.TEXT, text("x"));
        reserved[0] |= 0x40;
        assertEquals(List.of("failed 1002 reserved bits set without an extension"), read(100, reserved));
        assertEquals(List.of("failed 1007 a text message that is not UTF-8"),
                read(100, clientFrame(true, WebSocketFrames.TEXT, new byte[] {(byte) 0xC3, 0x28})));
    }

    @Test
    void closeAndBinaryAndNothingAfterTheClose() {
        assertEquals(List.of("binary 3", "close 1000"), read(100, clientFrame(true, WebSocketFrames.BINARY, new byte[3]),
                clientFrame(true, WebSocketFrames.CLOSE, new byte[] {0x03, (byte) 0xE8}),
                clientFrame(true, WebSocketFrames.TEXT, text("after"))));
        assertEquals(List.of("close 1005"), read(100, clientFrame(true, WebSocketFrames.CLOSE, new byte[0])));
    }

    @Test
    void serverFramesAreUnmaskedAndWhole() {
        assertArrayEquals(new byte[] {(byte) 0x81, 2, 'h', 'i'}, WebSocketFrames.frame(WebSocketFrames.TEXT, text("hi")));
        byte[] medium = WebSocketFrames.frame(WebSocketFrames.TEXT, new byte[300]);
        assertArrayEquals(new byte[] {(byte) 0x81, 126, 1, 44}, java.util.Arrays.copyOf(medium, 4));
        byte[] large = WebSocketFrames.frame(WebSocketFrames.TEXT, new byte[70_000]);
        assertArrayEquals(new byte[] {(byte) 0x81, 127, 0, 0, 0, 0, 0, 1, 0x11, 0x70}, java.util.Arrays.copyOf(large, 10));
        assertArrayEquals(new byte[] {(byte) 0x88, 2, 0x03, (byte) 0xF1}, WebSocketFrames.close(1009));
    }
}
