package org.usarsim.wss.world;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.nio.charset.StandardCharsets;
import java.util.logging.Level;
import java.util.logging.Logger;

/**
 * One rosbridge client of the world server, on its own thread, which alone reads and writes its
 * socket: the WebSocket handshake (10 s at most), then its frames as they come, and between them
 * what its session has due (a publication to one of its subscriptions, a queued message's send):
 * the read waits until the next due instant at most, in the world's time, then the session sends
 * what is due. A client that does not read its messages holds up only its own thread. Its log
 * lines go through the server's limit ({@link RosbridgeServer#lines()}).
 */
final class RosbridgeClient extends ClientThread implements WebSocketFrames.Sink, RosbridgeSession.Out {

    private static final Logger LOG = Logger.getLogger(RosbridgeClient.class.getName());
    /** How long the handshake may take. */
    private static final int HANDSHAKE_MS = 10_000;

    private final RosbridgeServer server;
    /** Whether the server already serves as many clients as it may: this one is answered 503. */
    private final boolean busy;
    private final WebSocketFrames frames = new WebSocketFrames(RosbridgeServer.MAX_MESSAGE_BYTES);
    private final RosbridgeSession session;
    private OutputStream out;
    private boolean closing;

    RosbridgeClient(RosbridgeServer server, Socket socket, boolean busy) {
        super(socket, "world-rosbridge-client");
        this.server = server;
        this.busy = busy;
        this.session = server.session(this);
    }

    @Override
    public void run() {
        log(Level.INFO, "clients connected", "connected");
        try {
            socket.setTcpNoDelay(true);
            InputStream in = socket.getInputStream();
            out = socket.getOutputStream();
            if (handshake(in)) {
                serve(in);
            }
        } catch (SocketTimeoutException e) {
            log(Level.WARNING, "handshakes", "no WebSocket handshake within " + HANDSHAKE_MS / 1000 + " s: dropping it");
        } catch (IOException e) {
            LOG.fine(() -> "rosbridge client " + peer + ": " + e);
        } finally {
            close();
            log(Level.INFO, "clients left", "left");
            server.ended(this);
        }
    }

    /** Reads the request head and answers it; true when the connection is a WebSocket from then on. */
    private boolean handshake(InputStream in) throws IOException {
        socket.setSoTimeout(HANDSHAKE_MS);
        byte[] head = new byte[WebSocketHandshake.MAX_REQUEST_BYTES];
        int length = 0;
        int end;
        while ((end = WebSocketHandshake.headEnd(head, length)) < 0) {
            if (length == head.length) {
                return answered(WebSocketHandshake.tooLarge());
            }
            int n = in.read(head, length, head.length - length);
            if (n < 0) {
                return false;
            }
            length += n;
        }
        if (!answered(busy ? WebSocketHandshake.busy(RosbridgeServer.MAX_CLIENTS) : WebSocketHandshake.answer(head, end))) {
            return false;
        }
        frames.feed(head, end, length - end, this);
        return true;
    }

    private boolean answered(WebSocketHandshake.Answer answer) throws IOException {
        out.write(answer.response());
        if (!answer.upgraded()) {
            log(Level.WARNING, "refused handshakes", "refused: " + answer.problem());
        }
        return answer.upgraded();
    }

    /** Reads frames, and sends what is due when it is due, until either side closes. */
    private void serve(InputStream in) throws IOException {
        byte[] buffer = new byte[16 * 1024];
        while (!closing) {
            long now = server.now();
            session.advance(now);
            long due = session.nextDue();
            // the world's time runs as the wall clock does; 0: no due instant, wait for a request
            long waitMs = due == Long.MAX_VALUE ? 0 : Math.max(1, (due - now + 999_999) / 1_000_000);
            socket.setSoTimeout((int) Math.min(Integer.MAX_VALUE, waitMs));
            int n;
            try {
                n = in.read(buffer);
            } catch (SocketTimeoutException e) {
                continue;
            }
            if (n < 0) {
                return;
            }
            frames.feed(buffer, 0, n, this);
        }
    }

    @Override
    public void text(String message) {
        session.request(message, server.now());
    }

    @Override
    public void binary(byte[] message) {
        log(Level.INFO, "binary messages", "a binary message (BSON or CBOR) of " + message.length
                + " bytes: the world server reads JSON text only");
    }

    @Override
    public void ping(byte[] payload) {
        write(WebSocketFrames.frame(WebSocketFrames.PONG, payload));
    }

    @Override
    public void close(int code) {
        write(WebSocketFrames.close(code == 1005 ? 1000 : code));
        closing = true;
    }

    @Override
    public void failed(int code, String reason) {
        log(Level.WARNING, "protocol errors", reason + ": closing with " + code);
        write(WebSocketFrames.close(code));
        closing = true;
    }

    @Override
    public void send(String frame) {
        write(WebSocketFrames.frame(WebSocketFrames.TEXT, frame.getBytes(StandardCharsets.UTF_8)));
    }

    private void write(byte[] frame) {
        if (closing) {
            return;
        }
        try {
            out.write(frame);
        } catch (IOException e) {
            LOG.fine(() -> "rosbridge client " + peer + ": cannot write: " + e);
            closing = true;
            close();
        }
    }

    @Override
    public void log(Level level, String kind, String message) {
        server.lines().log(LOG, level, kind, socket.getInetAddress(), "rosbridge client " + peer + ": " + message, null);
    }
}
