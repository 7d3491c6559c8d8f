package org.usarsim.wss.world;

import static org.junit.jupiter.api.Assertions.assertNotNull;

import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.WebSocket;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

/**
 * What a test's WebSocket client (the JDK's) received from the world server's rosbridge: whole
 * text messages (fragments joined), pongs, and its close code.
 */
final class ReceivedFrames implements WebSocket.Listener {

    /** How long a message may take to come on a loaded machine. */
    static final long WAIT_S = 20;

    final BlockingQueue<String> texts = new LinkedBlockingQueue<>();
    final BlockingQueue<String> pongs = new LinkedBlockingQueue<>();
    final BlockingQueue<Integer> closes = new LinkedBlockingQueue<>();
    private final StringBuilder part = new StringBuilder();

    /** A client of the rosbridge on 127.0.0.1 at the port, its frames received here. */
    WebSocket connect(int port) {
        return HttpClient.newHttpClient().newWebSocketBuilder().buildAsync(URI.create("ws://127.0.0.1:" + port + "/"), this).join();
    }

    @Override
    public CompletionStage<?> onText(WebSocket webSocket, CharSequence data, boolean last) {
        part.append(data);
        if (last) {
            texts.add(part.toString());
            part.setLength(0);
        }
        webSocket.request(1);
        return null;
    }

    @Override
    public CompletionStage<?> onPong(WebSocket webSocket, ByteBuffer message) {
        pongs.add(StandardCharsets.UTF_8.decode(message).toString());
        webSocket.request(1);
        return null;
    }

    @Override
    public CompletionStage<?> onClose(WebSocket webSocket, int statusCode, String reason) {
        closes.add(statusCode);
        return null;
    }

    /** The next text message, waited for {@link #WAIT_S} at most. */
    String next() throws InterruptedException {
        String text = texts.poll(WAIT_S, TimeUnit.SECONDS);
        assertNotNull(text, "a message within " + WAIT_S + " s");
        return text;
    }
}
