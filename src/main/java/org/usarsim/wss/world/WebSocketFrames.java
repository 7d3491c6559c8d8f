package org.usarsim.wss.world;

import java.io.ByteArrayOutputStream;
import java.nio.ByteBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;

/**
 * A WebSocket server's frames (RFC 6455, section 5): the client's, read from bytes as they come
 * ({@link #feed}, any split), and the server's, written ({@link #frame}). Client frames must be
 * masked; a message in fragments (a first frame without FIN, then continuations) is reassembled
 * up to {@link #maxMessageBytes}, control frames (ping, pong, close) may come between its
 * fragments. A frame that breaks the protocol, a message over the limit or a text that is not
 * UTF-8 ends the connection with its close code (1002, 1009, 1007). Server frames are never
 * masked and never fragmented. No sockets, no threads.
 */
final class WebSocketFrames {

    static final int TEXT = 0x1;
    static final int BINARY = 0x2;
    static final int CLOSE = 0x8;
    static final int PING = 0x9;
    static final int PONG = 0xA;
    private static final int CONTINUATION = 0x0;

    static final int PROTOCOL_ERROR = 1002;
    static final int NOT_UTF8 = 1007;
    static final int TOO_BIG = 1009;

    /** What the reader finds. */
    interface Sink {
        /** A whole text message, its fragments joined. */
        void text(String message);

        /** A whole binary message (rosbridge's BSON or CBOR), its fragments joined. */
        void binary(byte[] message);

        void ping(byte[] payload);

        /** The client's close frame: its code (1005 when it gave none). */
        void close(int code);

        /** The client broke the protocol: the connection must be closed with this code. */
        void failed(int code, String reason);
    }

    private final int maxMessageBytes;
    private final byte[] header = new byte[14];
    private int headerLength;
    private int opcode;
    private boolean fin;
    private long payloadLength;
    private final byte[] mask = new byte[4];
    private byte[] payload;
    private int payloadRead;
    /** The opcode of the fragmented message being reassembled, or -1. */
    private int messageOpcode = -1;
    private final ByteArrayOutputStream message = new ByteArrayOutputStream();
    private boolean failed;

    WebSocketFrames(int maxMessageBytes) {
        this.maxMessageBytes = maxMessageBytes;
    }

    /** Reads what came; after {@link Sink#failed} or {@link Sink#close}, nothing more. */
    void feed(byte[] bytes, int offset, int length, Sink sink) {
        int at = offset;
        int end = offset + length;
        while (at < end && !failed) {
            if (payload == null) {
                header[headerLength++] = bytes[at++];
                if (headerLength == 2 && !firstBytesRead(sink)) {
                    return;
                }
                int needed = headerNeeded();
                if (needed > 0 && headerLength == needed && !headerRead(sink)) {
                    return;
                }
            } else {
                int n = Math.min(end - at, payload.length - payloadRead);
                System.arraycopy(bytes, at, payload, payloadRead, n);
                payloadRead += n;
                at += n;
                if (payloadRead == payload.length) {
                    frameRead(sink);
                }
            }
        }
    }

    /** How long this frame's header is, once enough of it is known to say; 0 until then. */
    private int headerNeeded() {
        if (headerLength < 2) {
            return 0;
        }
        int length = header[1] & 0x7F;
        return 2 + (length == 126 ? 2 : length == 127 ? 8 : 0) + 4;
    }

    /** The checks the first two bytes allow, made before the rest of the header comes. */
    private boolean firstBytesRead(Sink sink) {
        if ((header[0] & 0x70) != 0) {
            return fail(sink, PROTOCOL_ERROR, "reserved bits set without an extension");
        }
        if ((header[1] & 0x80) == 0) {
            return fail(sink, PROTOCOL_ERROR, "a client frame without a mask");
        }
        return true;
    }

    private boolean headerRead(Sink sink) {
        fin = (header[0] & 0x80) != 0;
        opcode = header[0] & 0x0F;
        int length = header[1] & 0x7F;
        int at = 2;
        if (length == 126) {
            payloadLength = ((header[2] & 0xFF) << 8) | (header[3] & 0xFF);
            at = 4;
        } else if (length == 127) {
            payloadLength = 0;
            for (int i = 2; i < 10; i++) {
                payloadLength = (payloadLength << 8) | (header[i] & 0xFF);
            }
            at = 10;
        } else {
            payloadLength = length;
        }
        System.arraycopy(header, at, mask, 0, 4);
        boolean control = opcode >= CLOSE;
        if (control && (!fin || payloadLength > 125)) {
            return fail(sink, PROTOCOL_ERROR, "a control frame fragmented or over 125 bytes");
        }
        if (opcode != CONTINUATION && opcode != TEXT && opcode != BINARY && !(opcode >= CLOSE && opcode <= PONG)) {
            return fail(sink, PROTOCOL_ERROR, "an unknown opcode " + opcode);
        }
        if (opcode == CONTINUATION && messageOpcode < 0) {
            return fail(sink, PROTOCOL_ERROR, "a continuation frame with no message begun");
        }
        if ((opcode == TEXT || opcode == BINARY) && messageOpcode >= 0) {
            return fail(sink, PROTOCOL_ERROR, "a new message before the last one's final fragment");
        }
        long total = (control ? 0 : message.size()) + payloadLength;
        if (payloadLength < 0 || total > maxMessageBytes) {
            return fail(sink, TOO_BIG, "a message over " + maxMessageBytes + " bytes");
        }
        payload = new byte[(int) payloadLength];
        payloadRead = 0;
        headerLength = 0;
        if (payload.length == 0) {
            frameRead(sink);
        }
        return !failed;
    }

    private void frameRead(Sink sink) {
        byte[] data = payload;
        payload = null;
        for (int i = 0; i < data.length; i++) {
            data[i] ^= mask[i & 3];
        }
        switch (opcode) {
            case PING -> sink.ping(data);
            case PONG -> {
            }
            case CLOSE -> {
                failed = true;
                sink.close(data.length >= 2 ? ((data[0] & 0xFF) << 8) | (data[1] & 0xFF) : 1005);
            }
            default -> {
                if (opcode != CONTINUATION) {
                    messageOpcode = opcode;
                }
                message.write(data, 0, data.length);
                if (fin) {
                    byte[] whole = message.toByteArray();
                    int kind = messageOpcode;
                    message.reset();
                    messageOpcode = -1;
                    delivered(kind, whole, sink);
                }
            }
        }
    }

    private void delivered(int kind, byte[] whole, Sink sink) {
        if (kind == BINARY) {
            sink.binary(whole);
            return;
        }
        try {
            sink.text(StandardCharsets.UTF_8.newDecoder().onMalformedInput(CodingErrorAction.REPORT)
                    .onUnmappableCharacter(CodingErrorAction.REPORT).decode(ByteBuffer.wrap(whole)).toString());
        } catch (CharacterCodingException e) {
            fail(sink, NOT_UTF8, "a text message that is not UTF-8");
        }
    }

    private boolean fail(Sink sink, int code, String reason) {
        failed = true;
        sink.failed(code, reason);
        return false;
    }

    /** A server frame: final, unmasked, the payload whole. */
    static byte[] frame(int opcode, byte[] payload) {
        int length = payload.length;
        int headerLength = length < 126 ? 2 : length <= 0xFFFF ? 4 : 10;
        byte[] frame = new byte[headerLength + length];
        frame[0] = (byte) (0x80 | opcode);
        if (length < 126) {
            frame[1] = (byte) length;
        } else if (length <= 0xFFFF) {
            frame[1] = 126;
            frame[2] = (byte) (length >>> 8);
            frame[3] = (byte) length;
        } else {
            frame[1] = 127;
            for (int i = 0; i < 8; i++) {
                frame[2 + i] = (byte) ((long) length >>> (56 - 8 * i));
            }
        }
        System.arraycopy(payload, 0, frame, headerLength, length);
        return frame;
    }

    /** A close frame with a status code. */
    static byte[] close(int code) {
        return frame(CLOSE, new byte[] {(byte) (code >>> 8), (byte) code});
    }
}
