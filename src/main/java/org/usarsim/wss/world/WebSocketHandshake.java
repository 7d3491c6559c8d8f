package org.usarsim.wss.world;

import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.Base64;
import java.util.Locale;

/**
 * The opening handshake of a WebSocket server (RFC 6455, section 4.2): a client's HTTP
 * {@code GET} with {@code Upgrade: websocket}, {@code Connection: Upgrade},
 * {@code Sec-WebSocket-Version: 13} and a {@code Sec-WebSocket-Key}, answered by
 * {@code 101 Switching Protocols} with {@code Sec-WebSocket-Accept}; anything else by a
 * {@code 400} (or {@code 426} for another version) and the connection closed. Pure: bytes in,
 * bytes out.
 */
final class WebSocketHandshake {

    /** The longest request head taken (the request line and the headers, up to the empty line). */
    static final int MAX_REQUEST_BYTES = 8 * 1024;
    /** RFC 6455's GUID, appended to the key before it is hashed. */
    private static final String GUID = "258EAFA5-E914-47DA-95CA-C5AB0DC85B11";

    /**
     * What the server answers: the bytes to send, and whether the connection is a WebSocket from
     * then on; {@code problem} says why not, for the log.
     */
    record Answer(byte[] response, boolean upgraded, String problem) {
    }

    private WebSocketHandshake() {
    }

    /** Where the request head ends in {@code buffer[0, length)} (just after its empty line), or -1 while it has not. */
    static int headEnd(byte[] buffer, int length) {
        for (int i = 3; i < length; i++) {
            if (buffer[i] == '\n' && buffer[i - 1] == '\r' && buffer[i - 2] == '\n' && buffer[i - 3] == '\r') {
                return i + 1;
            }
        }
        return -1;
    }

    /** The answer to a request head (ISO-8859-1 as HTTP's header bytes are, up to and with its empty line). */
    static Answer answer(byte[] head, int length) {
        String[] lines = new String(head, 0, length, StandardCharsets.ISO_8859_1).split("\r\n");
        String[] request = lines[0].split(" ");
        if (request.length != 3 || !request[0].equals("GET") || !request[2].startsWith("HTTP/1.")) {
            return refused(400, "Bad Request", "not an HTTP GET: " + lines[0]);
        }
        String upgrade = null;
        String connection = null;
        String version = null;
        String key = null;
        for (int i = 1; i < lines.length; i++) {
            int colon = lines[i].indexOf(':');
            if (colon <= 0) {
                continue;
            }
            String name = lines[i].substring(0, colon).trim().toLowerCase(Locale.ROOT);
            String value = lines[i].substring(colon + 1).trim();
            switch (name) {
                case "upgrade" -> upgrade = value;
                case "connection" -> connection = value;
                case "sec-websocket-version" -> version = value;
                case "sec-websocket-key" -> key = value;
                default -> {
                }
            }
        }
        if (upgrade == null || !upgrade.equalsIgnoreCase("websocket") || connection == null
                || !connection.toLowerCase(Locale.ROOT).contains("upgrade")) {
            return refused(400, "Bad Request", "not a WebSocket upgrade (rosbridge speaks WebSocket only)");
        }
        if (!"13".equals(version)) {
            return new Answer(("HTTP/1.1 426 Upgrade Required\r\nSec-WebSocket-Version: 13\r\nContent-Length: 0\r\n"
                    + "Connection: close\r\n\r\n").getBytes(StandardCharsets.ISO_8859_1), false,
                    "WebSocket version " + version + ", not 13");
        }
        if (key == null || decodedLength(key) != 16) {
            return refused(400, "Bad Request", "no Sec-WebSocket-Key of 16 bytes in Base64");
        }
        return new Answer(("HTTP/1.1 101 Switching Protocols\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
                + "Sec-WebSocket-Accept: " + accept(key) + "\r\n\r\n").getBytes(StandardCharsets.ISO_8859_1), true, null);
    }

    /** {@code Sec-WebSocket-Accept} for a key: Base64 of the SHA-1 of the key and the GUID. */
    static String accept(String key) {
        try {
            MessageDigest sha1 = MessageDigest.getInstance("SHA-1");
            return Base64.getEncoder().encodeToString(sha1.digest((key + GUID).getBytes(StandardCharsets.ISO_8859_1)));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("every JDK has SHA-1", e);
        }
    }

    /** The answer to a request head over {@link #MAX_REQUEST_BYTES}. */
    static Answer tooLarge() {
        return refused(431, "Request Header Fields Too Large", "a request head over " + MAX_REQUEST_BYTES + " bytes");
    }

    /** The answer when the server already serves as many clients as it may. */
    static Answer busy(int clients) {
        return refused(503, "Service Unavailable", "already " + clients + " rosbridge clients, the most served at once");
    }

    private static Answer refused(int status, String reason, String problem) {
        byte[] body = (problem + "\n").getBytes(StandardCharsets.ISO_8859_1);
        String head = "HTTP/1.1 " + status + " " + reason + "\r\nContent-Type: text/plain\r\nContent-Length: " + body.length
                + "\r\nConnection: close\r\n\r\n";
        byte[] response = new byte[head.length() + body.length];
        System.arraycopy(head.getBytes(StandardCharsets.ISO_8859_1), 0, response, 0, head.length());
        System.arraycopy(body, 0, response, head.length(), body.length);
        return new Answer(response, false, problem);
    }

    private static int decodedLength(String key) {
        try {
            return Base64.getDecoder().decode(key).length;
        } catch (IllegalArgumentException e) {
            return -1;
        }
    }
}
