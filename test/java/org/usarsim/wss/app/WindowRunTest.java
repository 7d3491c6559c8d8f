package org.usarsim.wss.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Frame;
import java.awt.event.WindowEvent;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.net.ConnectException;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import javax.swing.JFrame;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.usarsim.wss.gui.Gui;
import org.usarsim.wss.hub.Wait;

/**
 * {@code Main.run} with the window, in the test JVM: closing the window ends the run (no
 * System.exit), with the server stopped and exit code 0.
 */
@Timeout(60)
@Tag("slow")
class WindowRunTest {

    private static final Pattern LISTENING = Pattern.compile("WSS listening for robots on 127\\.0\\.0\\.1:(\\d+)");

    @TempDir
    Path dir;

    @Test
    void closingTheWindowStopsTheServerAndRunReturnsZero() throws Exception {
        Gui.requireDisplay();
        Path config = Files.write(dir.resolve("wss.properties"), List.of("wss.bindAddress = 127.0.0.1", "wss.port = 0"));
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        PrintStream outStream = new PrintStream(out, true, StandardCharsets.UTF_8);
        PrintStream errStream = new PrintStream(err, true, StandardCharsets.UTF_8);
        List<Frame> before = List.of(Frame.getFrames());
        CompletableFuture<Integer> run = CompletableFuture.supplyAsync(
                () -> Main.run(outStream, errStream, "--config", config.toString(), "--start"));
        Wait.until("the window's server listens; out: " + out + "; err: " + err,
                () -> LISTENING.matcher(out.toString(StandardCharsets.UTF_8)).find());
        Matcher listening = LISTENING.matcher(out.toString(StandardCharsets.UTF_8));
        assertTrue(listening.find());
        int port = Integer.parseInt(listening.group(1));
        new Socket("127.0.0.1", port).close();

        JFrame frame = Gui.onEdt(() -> Stream.of(Frame.getFrames()).filter(Frame::isShowing).filter(f -> !before.contains(f))
                .filter(JFrame.class::isInstance).map(JFrame.class::cast).findFirst().orElseThrow());
        Gui.run(() -> frame.dispatchEvent(new WindowEvent(frame, WindowEvent.WINDOW_CLOSING)));
        assertEquals(0, run.get(ServerProcess.WAIT.toMillis(), TimeUnit.MILLISECONDS), "err: " + err);
        assertEquals("", err.toString(StandardCharsets.UTF_8));
        assertThrows(ConnectException.class, () -> new Socket("127.0.0.1", port).close(), "the control port is closed");
    }
}
