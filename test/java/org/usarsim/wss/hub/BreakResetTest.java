package org.usarsim.wss.hub;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.SocketException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.usarsim.wss.hub.core.Force;

/**
 * Issue 27: a stream the WSS cuts (a FORCE Down mid-transfer) is told apart from a finished one
 * at both ends: both get a reset, not an end of stream. A stream its sender ends is still
 * delivered whole with a clean end of stream.
 */
@Tag("slow")
class BreakResetTest {

    @Test
    void aForcedDownMidTransferResetsBothEndsAndAFinishedStreamEndsCleanly() throws Exception {
        ExecutorService pool = Executors.newSingleThreadExecutor();
        try (TestHub server = new TestHub(); TestRobot r1 = server.robot(); TestRobot r2 = server.robot()) {
            ServerSocket r1Accepts = r1.initAccepting("R1");
            r2.init("R2", 6000);
            int port = r2.dns("R1", 0);

            try (Socket source = r2.connect(port); Socket target = r1Accepts.accept()) {
                source.getOutputStream().write(new byte[100_000]);
                source.shutdownOutput();
                assertEquals(100_000, target.getInputStream().readAllBytes().length, "a finished stream: all of it, then its end");
            }

            try (Socket source = r2.connect(port); Socket target = r1Accepts.accept()) {
                Future<IOException> writing = pool.submit(() -> {
                    OutputStream out = source.getOutputStream();
                    byte[] block = new byte[16 * 1024];
                    try {
                        while (true) {
                            out.write(block);
                        }
                    } catch (IOException e) {
                        return e;
                    }
                });
                InputStream in = target.getInputStream();
                byte[] buffer = new byte[64 * 1024];
                long got = 0;
                while (got < 1_000_000) {
                    int read = in.read(buffer);
                    assertTrue(read > 0, "the stream flows");
                    got += read;
                }
                server.hub.force("R1", "R2", Force.DOWN);
                assertThrows(SocketException.class, () -> {
                    while (in.read(buffer) >= 0) {
                        // what was in flight, then the reset
                    }
                }, "the target is told the stream was cut, not that it ended");
                IOException atSource = writing.get(10, TimeUnit.SECONDS);
                assertTrue(atSource instanceof SocketException, "the source is told too: " + atSource);
            }
        } finally {
            pool.shutdownNow();
        }
    }
}
